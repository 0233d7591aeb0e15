// Intersection of two convex polygons in integer arithmetic (paper, Section 3 "Polygon
// intersection kernel"; docs/geometry.md).
//
// What it returns feeds Eqs. (1)-(4): the overlap area S_ij, the centroid of the overlap (where
// the contact force acts), and the chord joining the two points where the boundaries cross,
// whose length is L_ij and whose unit normal N_ij points from the first polygon to the second.
//
// Algorithm (Sutherland-Hodgman clipping of A by the half-planes of B, on an integer grid):
//   order (A, B) canonically             -> S(A,B) and S(B,A) are computed by the same operations
//   reject if the bounding boxes miss    -> most candidate pairs end here
//   origin = centre of the union box; scale = 2^k with half-extent * scale <= 2^29 (~ +-5.4e8)
//   round every vertex to the grid       -> the rest is exact integer orientation tests
//   for each edge e of B: keep the part of the current polygon left of e; a crossing point is
//     rounded to the grid (it is the only rounding after the first); each output edge carries the
//     polygon it came from, so a vertex where the owner changes is a boundary crossing
//   area and centroid by the shoelace formula (a fan from the first vertex, int64 exact area)
//   chord = the two boundary crossings farthest apart; none (nested, identical) -> L = sqrt(S)
// Bounds: |coordinate| <= 2^29 + 1, so an orientation test is <= 2^61 and the doubled area of a
// convex polygon inside the box is <= 2^61: no int64 overflow. Degenerate input (fewer than three
// vertices, more than kMaxPolygonVertices, non-finite coordinates) gives an empty overlap.
//
// Usable from CUDA kernels: no allocation, no STL, fixed-size arrays on the stack.
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/host_device.hpp"
#include "thin_ice_sim/physics/scalar.hpp"
#include "thin_ice_sim/physics/vec2.hpp"

namespace thin_ice {

/// Largest vertex count of one polygon (a cell) accepted by the intersection routine.
constexpr int kMaxPolygonVertices = 12;

/// Half-width of the integer grid the pair is mapped onto (paper: "scaled to 5e8").
constexpr double kIntegerGridHalfWidth = 536870912.0;  // 2^29

struct PolygonOverlap {
  double area;         ///< S_ij [m^2]; 0 when the polygons are disjoint or only touch
  Vec2 centroid;       ///< centroid of the overlap polygon, world frame [m]
  double chord_length; ///< L_ij [m]: length of the chord, or sqrt(S_ij) when none was found
  Vec2 normal;         ///< N_ij, unit, from the first argument towards the second
  bool chord_found;    ///< false: nested/identical polygons, L and N come from the fallback
  int vertex_count;    ///< vertices of the overlap polygon (0 when area is 0)
};

namespace polygon_clip_detail {

struct GridPoint {
  long long x;
  long long y;
};

/// Twice the signed area of (a, b, p): > 0 when p lies left of a->b. Exact for |coords| <= 2^30.
TIS_HD long long orientation(GridPoint a, GridPoint b, GridPoint p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

/// The integer grid of one pair: world point p maps to round((p - origin) * scale).
struct PairGrid {
  Vec2 origin;   ///< centre of the union bounding box [m]
  double scale;  ///< grid steps per metre, a power of two (exact to apply and to undo)
  double step;   ///< 1 / scale [m]: the rounding unit of every vertex and crossing point
};

/// Grid for the union bounding box [x0, x1] x [y0, y1]: the largest power-of-two scale with
/// half-extent * scale <= 2^29. scale = 0 for an empty or non-finite box.
TIS_HD PairGrid makePairGrid(double x0, double x1, double y0, double y1) {
  PairGrid g;
  g.origin = {0.5 * (x0 + x1), 0.5 * (y0 + y1)};
  const double half_extent = maxOf(0.5 * (x1 - x0), 0.5 * (y1 - y0));
  if (!(half_extent > 0.0) || !isfinite(half_extent)) {
    g.scale = 0.0;
    g.step = 0.0;
    return g;
  }
  int exponent = 0;
  frexp(half_extent, &exponent);  // half_extent <= 2^exponent
  g.scale = ldexp(1.0, 29 - exponent);
  g.step = ldexp(1.0, exponent - 29);
  return g;
}

/// Capacity of the working polygon: a convex n-gon clipped by m half-planes has <= n + m
/// vertices; the slack absorbs the rare extra vertex that rounding can create.
constexpr int kClipCapacity = 2 * kMaxPolygonVertices + 4;

/// True when polygon b should be clipped by polygon a rather than the other way round: a fixed
/// total order on polygons (vertex count, then coordinates) makes the result order-independent.
TIS_HD bool comesBefore(const Vec2* a, int na, const Vec2* b, int nb) {
  if (na != nb) return na < nb;
  for (int k = 0; k < na; ++k) {
    if (a[k].x != b[k].x) return a[k].x < b[k].x;
    if (a[k].y != b[k].y) return a[k].y < b[k].y;
  }
  return true;  // identical: either order gives the same result
}

TIS_HD bool isUsablePolygon(const Vec2* p, int n) {
  if (n < 3 || n > kMaxPolygonVertices) return false;
  for (int k = 0; k < n; ++k) {
    if (!isfinite(p[k].x) || !isfinite(p[k].y)) return false;
  }
  return true;
}

TIS_HD PolygonOverlap emptyOverlap() {
  PolygonOverlap r;
  r.area = 0.0;
  r.centroid = {0.0, 0.0};
  r.chord_length = 0.0;
  r.normal = {1.0, 0.0};
  r.chord_found = false;
  r.vertex_count = 0;
  return r;
}

/// Intersection of `first` and `second`, which the caller has put in canonical order.
TIS_HD PolygonOverlap intersectOrdered(const Vec2* first, int n_first, const Vec2* second,
                                       int n_second) {
  // Bounding boxes: reject early, and the union box sets the grid.
  double fx0 = first[0].x, fx1 = first[0].x, fy0 = first[0].y, fy1 = first[0].y;
  for (int k = 1; k < n_first; ++k) {
    fx0 = minOf(fx0, first[k].x); fx1 = maxOf(fx1, first[k].x);
    fy0 = minOf(fy0, first[k].y); fy1 = maxOf(fy1, first[k].y);
  }
  double sx0 = second[0].x, sx1 = second[0].x, sy0 = second[0].y, sy1 = second[0].y;
  for (int k = 1; k < n_second; ++k) {
    sx0 = minOf(sx0, second[k].x); sx1 = maxOf(sx1, second[k].x);
    sy0 = minOf(sy0, second[k].y); sy1 = maxOf(sy1, second[k].y);
  }
  if (fx1 <= sx0 || sx1 <= fx0 || fy1 <= sy0 || sy1 <= fy0) return emptyOverlap();

  const PairGrid grid = makePairGrid(minOf(fx0, sx0), maxOf(fx1, sx1), minOf(fy0, sy0), maxOf(fy1, sy1));
  if (!(grid.scale > 0.0)) return emptyOverlap();
  const Vec2 origin = grid.origin;
  const double scale = grid.scale;
  const double inverse_scale = grid.step;

  GridPoint clip[kMaxPolygonVertices];
  for (int k = 0; k < n_second; ++k) {
    clip[k] = {llrint((second[k].x - origin.x) * scale), llrint((second[k].y - origin.y) * scale)};
  }
  // Working polygon, and for each vertex k the owner of the edge k -> k+1
  // (0: boundary of `first`, 1: boundary of `second`). Two buffers, swapped after each clip edge.
  GridPoint buffer_poly[2][kClipCapacity];
  unsigned char buffer_owner[2][kClipCapacity];
  GridPoint* poly = buffer_poly[0];
  unsigned char* owner = buffer_owner[0];
  GridPoint* next_poly = buffer_poly[1];
  unsigned char* next_owner = buffer_owner[1];
  int count = n_first;
  for (int k = 0; k < n_first; ++k) {
    poly[k] = {llrint((first[k].x - origin.x) * scale), llrint((first[k].y - origin.y) * scale)};
    owner[k] = 0;
  }

  // side[k]: orientation of working vertex k against the current clip edge, each computed once
  // (vertex k is the end of edge k-1 and the start of edge k).
  long long side[kClipCapacity];
  for (int e = 0; e < n_second && count > 0; ++e) {
    const GridPoint a = clip[e];
    const GridPoint b = clip[e + 1 < n_second ? e + 1 : 0];
    if (a.x == b.x && a.y == b.y) continue;  // duplicate vertex of `second`: no half-plane
    bool all_inside = true;
    for (int k = 0; k < count; ++k) {
      side[k] = orientation(a, b, poly[k]);
      all_inside = all_inside && side[k] >= 0;
    }
    // Nothing strictly outside: the pass below would copy every vertex and owner unchanged
    // (an owner changes only at a vertex on the line whose successor is outside).
    if (all_inside) continue;
    int out = 0;
    for (int k = 0; k < count; ++k) {
      const int k_next = k + 1 < count ? k + 1 : 0;
      const GridPoint p = poly[k];
      const GridPoint q = poly[k_next];
      const long long sp = side[k];
      const long long sq = side[k_next];
      if (sp >= 0) {
        if (out < kClipCapacity) {
          next_poly[out] = p;
          // From p the boundary leaves along p->q unless p sits on the clip line and q is outside.
          next_owner[out] = (sp == 0 && sq < 0) ? 1 : owner[k];
          ++out;
        }
        if (sp > 0 && sq < 0 && out < kClipCapacity) {
          const double t = static_cast<double>(sp) / (static_cast<double>(sp) - static_cast<double>(sq));
          next_poly[out] = {p.x + llrint(t * static_cast<double>(q.x - p.x)),
                            p.y + llrint(t * static_cast<double>(q.y - p.y))};
          next_owner[out] = 1;  // leaves along the clip line
          ++out;
        }
      } else if (sq > 0 && out < kClipCapacity) {
        const double t = static_cast<double>(sp) / (static_cast<double>(sp) - static_cast<double>(sq));
        next_poly[out] = {p.x + llrint(t * static_cast<double>(q.x - p.x)),
                          p.y + llrint(t * static_cast<double>(q.y - p.y))};
        next_owner[out] = owner[k];  // re-enters along the clipped edge p->q
        ++out;
      }
    }
    count = out;
    GridPoint* const spare_poly = poly;
    unsigned char* const spare_owner = owner;
    poly = next_poly;
    owner = next_owner;
    next_poly = spare_poly;
    next_owner = spare_owner;
  }
  if (count < 3) return emptyOverlap();

  // Shoelace over a fan from vertex 0: exact doubled area, centroid in double.
  long long doubled_area = 0;
  double moment_x = 0.0, moment_y = 0.0;
  const GridPoint v0 = poly[0];
  for (int k = 1; k + 1 < count; ++k) {
    const long long rx1 = poly[k].x - v0.x, ry1 = poly[k].y - v0.y;
    const long long rx2 = poly[k + 1].x - v0.x, ry2 = poly[k + 1].y - v0.y;
    const long long c = rx1 * ry2 - ry1 * rx2;
    doubled_area += c;
    moment_x += static_cast<double>(rx1 + rx2) * static_cast<double>(c);
    moment_y += static_cast<double>(ry1 + ry2) * static_cast<double>(c);
  }
  if (doubled_area <= 0) return emptyOverlap();

  PolygonOverlap r;
  const double area_grid = 0.5 * static_cast<double>(doubled_area);
  r.area = area_grid * inverse_scale * inverse_scale;
  const double cx_grid = static_cast<double>(v0.x) + moment_x / (3.0 * static_cast<double>(doubled_area));
  const double cy_grid = static_cast<double>(v0.y) + moment_y / (3.0 * static_cast<double>(doubled_area));
  r.centroid = {origin.x + cx_grid * inverse_scale, origin.y + cy_grid * inverse_scale};
  r.vertex_count = count;

  // Reference direction first -> second: from the vertex mean of `first` to that of `second`.
  double mfx = 0.0, mfy = 0.0, msx = 0.0, msy = 0.0;
  for (int k = 0; k < n_first; ++k) { mfx += first[k].x; mfy += first[k].y; }
  for (int k = 0; k < n_second; ++k) { msx += second[k].x; msy += second[k].y; }
  Vec2 reference = {msx / n_second - mfx / n_first, msy / n_second - mfy / n_first};

  // Boundary crossings: vertices whose incoming and outgoing edges belong to different polygons.
  // Keep the two farthest apart (two for a plain overlap; more only in degenerate touching).
  long long best_d2 = 0;
  GridPoint c0 = {0, 0}, c1 = {0, 0};
  GridPoint crossings[kClipCapacity];
  int n_crossings = 0;
  for (int k = 0; k < count; ++k) {
    const unsigned char incoming = owner[(k + count - 1) % count];
    if (incoming != owner[k]) crossings[n_crossings++] = poly[k];
  }
  for (int a = 0; a < n_crossings; ++a) {
    for (int b = a + 1; b < n_crossings; ++b) {
      const long long dx = crossings[b].x - crossings[a].x, dy = crossings[b].y - crossings[a].y;
      const long long d2 = dx * dx + dy * dy;  // <= 2^61: crossings lie in the grid box
      if (d2 > best_d2) { best_d2 = d2; c0 = crossings[a]; c1 = crossings[b]; }
    }
  }
  if (best_d2 > 0) {
    const Vec2 chord = {static_cast<double>(c1.x - c0.x), static_cast<double>(c1.y - c0.y)};
    const double chord_grid = norm(chord);
    r.chord_length = chord_grid * inverse_scale;
    Vec2 n = (1.0 / chord_grid) * perpendicular(chord);
    if (dot(n, reference) < 0.0) n = -n;
    r.normal = n;
    r.chord_found = true;
  } else {
    r.chord_length = sqrt(r.area);
    const double ref_len = norm(reference);
    r.normal = ref_len > 0.0 ? (1.0 / ref_len) * reference : Vec2{1.0, 0.0};
    r.chord_found = false;
  }
  return r;
}

}  // namespace polygon_clip_detail

/// Overlap of two convex polygons given by their vertices in counter-clockwise order (world
/// frame, metres). Symmetric: swapping the arguments gives the same area, centroid and chord
/// length bit for bit, and the opposite normal.
TIS_HD PolygonOverlap intersectConvexPolygons(const Vec2* a, int na, const Vec2* b, int nb) {
  using namespace polygon_clip_detail;
  if (!isUsablePolygon(a, na) || !isUsablePolygon(b, nb)) return emptyOverlap();
  if (comesBefore(a, na, b, nb)) return intersectOrdered(a, na, b, nb);
  PolygonOverlap r = intersectOrdered(b, nb, a, na);
  r.normal = -r.normal;
  return r;
}

/// The rounding unit [m] of the integer grid used for the pair (a, b): every vertex of the
/// overlap polygon lies within step / sqrt(2) of the exact one, so the area is exact to about
/// (perimeter of a + perimeter of b) * step.
TIS_HD double integerGridStep(const Vec2* a, int na, const Vec2* b, int nb) {
  double x0 = a[0].x, x1 = a[0].x, y0 = a[0].y, y1 = a[0].y;
  for (int k = 0; k < na; ++k) {
    x0 = minOf(x0, a[k].x); x1 = maxOf(x1, a[k].x); y0 = minOf(y0, a[k].y); y1 = maxOf(y1, a[k].y);
  }
  for (int k = 0; k < nb; ++k) {
    x0 = minOf(x0, b[k].x); x1 = maxOf(x1, b[k].x); y0 = minOf(y0, b[k].y); y1 = maxOf(y1, b[k].y);
  }
  return polygon_clip_detail::makePairGrid(x0, x1, y0, y1).step;
}

/// Signed area [m^2] (> 0 for counter-clockwise order) of a simple polygon, in double.
TIS_HD double polygonArea(const Vec2* p, int n) {
  double twice = 0.0;
  for (int k = 0; k < n; ++k) twice += cross(p[k], p[(k + 1) % n]);
  return 0.5 * twice;
}

}  // namespace thin_ice
