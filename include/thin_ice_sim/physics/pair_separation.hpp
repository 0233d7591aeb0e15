// A separating edge of two convex polygons: the test that lets the contact loop skip the polygon
// clip (polygon_clip.hpp) for a pair whose overlap S_ij (Eq. 1) is zero, by remembering from one
// step to the next which edge kept the pair apart. It is not a law of the model: a pair it skips is
// one whose clip would have given no overlap, so the force and S_ref are those of "apart"
// (contact.hpp), bit for bit.
//
// Separating axes: for convex polygons with counter-clockwise vertices, the outward normal of the
// edge p_k -> p_k+1 is n = (dy, -dx). When every vertex q of the other polygon has
// n . (q - p_k) > gap |n|, that polygon lies wholly beyond the edge's line, more than `gap` from
// the first one. Two disjoint convex polygons always have such an edge among the two polygons'
// edges, for some gap > 0 (the separating axis theorem in the plane).
//
// Why a gap and not just > 0: the clip runs on an integer grid whose step is under 2^-28 of the
// half-extent of the pair's bounding box, and rounds every vertex and every crossing point to it,
// so polygons a few steps apart could still give a sliver. Each of the at most 12 clip stages moves
// a vertex by at most 0.71 step, so the clip's output lies within 9 steps of the first polygon and
// of each half-plane of the second; near a vertex of interior angle theta those relaxed
// half-planes reach 9 / sin(theta / 2) steps beyond it. The contact loop asks for a gap of 2^-12 of
// r_i + r_j (r: the farthest vertex from the centroid), and a pair whose boxes overlap has a
// half-extent under r_i + r_j, so the gap is at least 2^16 steps: no sliver for any angle above
// 0.02 degrees (test_pair_separation checks the claim on random pairs, thin ones too).
//
// Usable from CUDA kernels: no allocation, no STL.
#pragma once

#include "thin_ice_sim/physics/host_device.hpp"
#include "thin_ice_sim/physics/polygon_clip.hpp"
#include "thin_ice_sim/physics/vec2.hpp"

namespace thin_ice {

/// No edge is known to separate the pair.
constexpr int kNoSeparatingEdge = -1;

/// The gap the contact loops ask of a separating edge, as a fraction of r_i + r_j [-]: at least
/// 2^16 steps of the clip's grid (above), 0.07 mm for two 0.2 m cells. buildModel puts it in
/// ModelConstants::separation_gap_fraction, which the loops read (a test sets it infinite).
constexpr double kSeparationGapFraction = 1.0 / 4096.0;

namespace pair_separation_detail {

/// Whether edge k of `p` (p[k] -> p[k+1]) has every vertex of `q` more than `gap` [m] beyond its line.
TIS_HD bool edgeOfFirstSeparates(const Vec2* p, int np, const Vec2* q, int nq, int k, double gap) {
  const Vec2 start = p[k];
  const Vec2 edge = p[k + 1 < np ? k + 1 : 0] - start;
  const Vec2 outward = {edge.y, -edge.x};
  double nearest = dot(outward, q[0] - start);
  for (int m = 1; m < nq; ++m) {
    const double d = dot(outward, q[m] - start);
    nearest = d < nearest ? d : nearest;
  }
  // nearest / |outward| > gap, without the square root (both sides positive).
  return nearest > 0.0 && nearest * nearest > gap * gap * dot(outward, outward);
}

}  // namespace pair_separation_detail

/// Whether `edge` separates a (na vertices) and b (nb vertices) by more than `gap` [m]: edge k < na
/// is a's edge k, edge na + k is b's edge k. kNoSeparatingEdge, or an index past both: false.
TIS_HD bool edgeSeparates(const Vec2* a, int na, const Vec2* b, int nb, int edge, double gap) {
  using pair_separation_detail::edgeOfFirstSeparates;
  if (edge < 0 || edge >= na + nb) return false;
  return edge < na ? edgeOfFirstSeparates(a, na, b, nb, edge, gap)
                   : edgeOfFirstSeparates(b, nb, a, na, edge - na, gap);
}

/// The first edge (a's edges, then b's) that separates a and b by more than `gap` [m], or
/// kNoSeparatingEdge when none does (the polygons overlap, touch, or are closer than `gap`).
TIS_HD int findSeparatingEdge(const Vec2* a, int na, const Vec2* b, int nb, double gap) {
  for (int edge = 0; edge < na + nb; ++edge) {
    if (edgeSeparates(a, na, b, nb, edge, gap)) return edge;
  }
  return kNoSeparatingEdge;
}

/// The contact loops' use of the above (both backends): false, without clipping, while `edge`
/// (the pair's remembered edge) still separates a and b by more than `gap` [m]: the pair is apart.
/// Otherwise true, with the clip's overlap (Eq. 1) in `overlap` and `edge` set to one that
/// separates the pair when it is apart (kNoSeparatingEdge when it overlaps or none is far enough).
TIS_HD bool clipUnlessApart(const Vec2* a, int na, const Vec2* b, int nb, double gap, int& edge,
                            PolygonOverlap& overlap) {
  if (edgeSeparates(a, na, b, nb, edge, gap)) return false;
  overlap = intersectConvexPolygons(a, na, b, nb);
  edge = overlap.area > 0.0 ? kNoSeparatingEdge : findSeparatingEdge(a, na, b, nb, gap);
  return true;
}

}  // namespace thin_ice
