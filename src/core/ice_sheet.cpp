// Voronoi ice sheet generation (paper Section 2.1).
//
//   seeds  <- jittered grid or Poisson-disk set (deterministic RNG)
//   repeat lloyd_iterations + 1 times:
//     T    <- Delaunay triangulation of the seeds (CGAL, exact predicates)
//     cell <- sheet rectangle clipped by the bisector half-plane of every Delaunay neighbour
//     seed <- centroid(cell)                      (Lloyd step, skipped after the last pass)
//   shared edges <- edges of cell i labelled with neighbour j > i, of non-zero length
// The Voronoi cell of a seed is the intersection of the half-planes closer to it than to each
// Delaunay neighbour; clipping the rectangle by them bounds every cell exactly by the sheet rim.
#include "thin_ice_sim/ice_sheet.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace thin_ice {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, DataStructure>;

/// Largest cell count a sheet may have (memory guard: ~10^7 cells fill a large GPU).
constexpr double kMaxCells = 2.0e7;

/// Uniform double in [0, 1) from 53 random bits: the same on every standard library.
double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

std::vector<Vec2> jitteredGridSeeds(const IceSheetSpec& spec, std::mt19937_64& rng) {
  const int nx = std::max(1, static_cast<int>(std::lround(spec.length / spec.cell_size)));
  const int ny = std::max(1, static_cast<int>(std::lround(spec.width / spec.cell_size)));
  const double px = spec.length / nx, py = spec.width / ny;
  const double y_min = -0.5 * spec.width;
  std::vector<Vec2> seeds;
  seeds.reserve(static_cast<size_t>(nx) * ny);
  for (int iy = 0; iy < ny; ++iy) {
    for (int ix = 0; ix < nx; ++ix) {
      const double jx = spec.jitter * px * (2.0 * uniform01(rng) - 1.0);
      const double jy = spec.jitter * py * (2.0 * uniform01(rng) - 1.0);
      seeds.push_back({spec.x_min + (ix + 0.5) * px + jx, y_min + (iy + 0.5) * py + jy});
    }
  }
  return seeds;
}

/// Bridson (2007), "Fast Poisson disk sampling in arbitrary dimensions". A maximal Poisson-disk
/// set of radius r holds about 0.68 / r^2 points per unit area, so r = sqrt(0.68) * cell_size
/// gives a mean cell area near cell_size^2 (the measured value is in computeStats()).
std::vector<Vec2> poissonDiskSeeds(const IceSheetSpec& spec, std::mt19937_64& rng) {
  constexpr int kAttemptsPerPoint = 30;
  constexpr double kPi = 3.14159265358979323846;
  const double r = std::sqrt(0.68) * spec.cell_size;
  const double bin = r / std::sqrt(2.0);
  const int nx = static_cast<int>(std::ceil(spec.length / bin));
  const int ny = static_cast<int>(std::ceil(spec.width / bin));
  const double y_min = -0.5 * spec.width;
  std::vector<int> grid(static_cast<size_t>(nx) * ny, -1);
  std::vector<Vec2> points;
  std::vector<int> active;
  auto binOf = [&](Vec2 p, int& bx, int& by) {
    bx = std::min(nx - 1, static_cast<int>((p.x - spec.x_min) / bin));
    by = std::min(ny - 1, static_cast<int>((p.y - y_min) / bin));
  };
  auto accept = [&](Vec2 p) {
    int bx, by;
    binOf(p, bx, by);
    grid[static_cast<size_t>(by) * nx + bx] = static_cast<int>(points.size());
    active.push_back(static_cast<int>(points.size()));
    points.push_back(p);
  };
  accept({spec.x_min + uniform01(rng) * spec.length, y_min + uniform01(rng) * spec.width});
  while (!active.empty()) {
    const size_t pick = static_cast<size_t>(uniform01(rng) * active.size());
    const Vec2 centre = points[active[pick]];
    bool placed = false;
    for (int attempt = 0; attempt < kAttemptsPerPoint && !placed; ++attempt) {
      const double angle = 2.0 * kPi * uniform01(rng);
      const double radius = r * (1.0 + uniform01(rng));
      const Vec2 p = {centre.x + radius * std::cos(angle), centre.y + radius * std::sin(angle)};
      if (p.x < spec.x_min || p.x >= spec.x_min + spec.length || p.y < y_min ||
          p.y >= y_min + spec.width) {
        continue;
      }
      int bx, by;
      binOf(p, bx, by);
      bool clear = true;
      for (int dy = -2; dy <= 2 && clear; ++dy) {
        for (int dx = -2; dx <= 2 && clear; ++dx) {
          const int cx = bx + dx, cy = by + dy;
          if (cx < 0 || cy < 0 || cx >= nx || cy >= ny) continue;
          const int other = grid[static_cast<size_t>(cy) * nx + cx];
          if (other >= 0 && norm(points[other] - p) < r) clear = false;
        }
      }
      if (clear) {
        accept(p);
        placed = true;
      }
    }
    if (!placed) {
      active[pick] = active.back();
      active.pop_back();
    }
  }
  return points;
}

/// A convex polygon whose edge k (vertex k -> k+1) remembers which neighbour made it.
struct LabelledPolygon {
  std::vector<Vec2> vertices;
  std::vector<int> labels;
};

/// Keeps the part of `poly` where dot(x - m, d) <= 0; the new edge along the line gets `label`.
void clipByHalfPlane(LabelledPolygon& poly, Vec2 m, Vec2 d, int label) {
  const size_t n = poly.vertices.size();
  LabelledPolygon out;
  out.vertices.reserve(n + 1);
  out.labels.reserve(n + 1);
  for (size_t k = 0; k < n; ++k) {
    const Vec2 p = poly.vertices[k];
    const Vec2 q = poly.vertices[(k + 1) % n];
    const double sp = dot(p - m, d);
    const double sq = dot(q - m, d);
    if (sp <= 0.0) {
      out.vertices.push_back(p);
      out.labels.push_back((sp == 0.0 && sq > 0.0) ? label : poly.labels[k]);
      if (sp < 0.0 && sq > 0.0) {
        out.vertices.push_back(p + (sp / (sp - sq)) * (q - p));
        out.labels.push_back(label);
      }
    } else if (sq < 0.0) {
      out.vertices.push_back(p + (sp / (sp - sq)) * (q - p));
      out.labels.push_back(poly.labels[k]);
    }
  }
  poly = std::move(out);
}

/// Drops vertices closer than `tolerance` to their successor (co-circular seeds make zero-length
/// Voronoi edges); the surviving vertex keeps the label of the edge that leaves it.
void removeShortEdges(LabelledPolygon& poly, double tolerance) {
  bool changed = true;
  while (changed && poly.vertices.size() > 3) {
    changed = false;
    const size_t n = poly.vertices.size();
    for (size_t k = 0; k < n; ++k) {
      const size_t next = (k + 1) % n;
      if (norm(poly.vertices[next] - poly.vertices[k]) < tolerance) {
        poly.vertices.erase(poly.vertices.begin() + static_cast<long>(k));
        poly.labels.erase(poly.labels.begin() + static_cast<long>(k));
        changed = true;
        break;
      }
    }
  }
}

std::vector<LabelledPolygon> voronoiCells(const IceSheetSpec& spec, const std::vector<Vec2>& seeds) {
  std::vector<std::pair<Kernel::Point_2, int>> points;
  points.reserve(seeds.size());
  for (size_t k = 0; k < seeds.size(); ++k) {
    points.emplace_back(Kernel::Point_2(seeds[k].x, seeds[k].y), static_cast<int>(k));
  }
  Delaunay triangulation(points.begin(), points.end());
  if (triangulation.number_of_vertices() != seeds.size()) {
    throw std::runtime_error("ice sheet: duplicate Voronoi seeds (a random-generator fault)");
  }
  const double y_min = -0.5 * spec.width, y_max = 0.5 * spec.width;
  const double x_max = spec.x_min + spec.length;
  const LabelledPolygon rectangle{
      {{spec.x_min, y_min}, {x_max, y_min}, {x_max, y_max}, {spec.x_min, y_max}}, {-1, -1, -1, -1}};
  const double tolerance = 1e-9 * spec.cell_size;

  std::vector<LabelledPolygon> cells(seeds.size());
  for (auto v = triangulation.finite_vertices_begin(); v != triangulation.finite_vertices_end(); ++v) {
    const int i = v->info();
    LabelledPolygon cell = rectangle;
    auto neighbour = triangulation.incident_vertices(v), done = neighbour;
    if (neighbour != nullptr) {
      do {
        if (triangulation.is_infinite(neighbour)) continue;
        const int j = neighbour->info();
        const Vec2 d = seeds[j] - seeds[i];
        clipByHalfPlane(cell, 0.5 * (seeds[i] + seeds[j]), d, j);
      } while (++neighbour != done);
    }
    removeShortEdges(cell, tolerance);
    cells[i] = std::move(cell);
  }
  return cells;
}

}  // namespace

SeedLayout parseSeedLayout(const std::string& text, const std::string& key) {
  if (text == "jittered_grid") return SeedLayout::kJitteredGrid;
  if (text == "poisson_disk") return SeedLayout::kPoissonDisk;
  throw std::invalid_argument(key + " = '" + text +
                              "': allowed values are 'jittered_grid' and 'poisson_disk'");
}

std::string toString(SeedLayout layout) {
  return layout == SeedLayout::kJitteredGrid ? "jittered_grid" : "poisson_disk";
}

void validate(const IceSheetSpec& spec) {
  auto fail = [](const std::string& name, double value, const std::string& allowed) {
    std::ostringstream msg;
    msg << "ice sheet: " << name << " = " << value << " is invalid; allowed: " << allowed;
    throw std::invalid_argument(msg.str());
  };
  if (!(std::isfinite(spec.length) && spec.length > 0.0)) fail("length", spec.length, "finite > 0 m");
  if (!(std::isfinite(spec.width) && spec.width > 0.0)) fail("width", spec.width, "finite > 0 m");
  if (!std::isfinite(spec.x_min)) fail("x_min", spec.x_min, "finite m");
  const double smaller_side = std::min(spec.length, spec.width);
  if (!(std::isfinite(spec.cell_size) && spec.cell_size > 0.0 && spec.cell_size <= smaller_side)) {
    std::ostringstream allowed;
    allowed << "finite, > 0 m and <= the smaller sheet side (" << smaller_side << " m)";
    fail("cell_size", spec.cell_size, allowed.str());
  }
  if (spec.length * spec.width / (spec.cell_size * spec.cell_size) > kMaxCells) {
    std::ostringstream allowed;
    allowed << ">= " << std::sqrt(spec.length * spec.width / kMaxCells)
            << " m for this sheet (at most " << kMaxCells << " cells)";
    fail("cell_size", spec.cell_size, allowed.str());
  }
  if (!(spec.jitter >= 0.0 && spec.jitter <= 0.5)) fail("jitter", spec.jitter, "[0, 0.5]");
  if (spec.lloyd_iterations < 0 || spec.lloyd_iterations > 50) {
    fail("lloyd_iterations", spec.lloyd_iterations, "integer in [0, 50]");
  }
}

void setCellGeometryFromPolygon(const std::vector<Vec2>& world_vertices, CellGeometry& cell) {
  // Shoelace relative to the first vertex (keeps the sums well conditioned far from the origin).
  const size_t n = world_vertices.size();
  const Vec2 v0 = world_vertices[0];
  double twice_area = 0.0, mx = 0.0, my = 0.0;
  for (size_t k = 0; k < n; ++k) {
    const Vec2 a = world_vertices[k] - v0, b = world_vertices[(k + 1) % n] - v0;
    const double c = cross(a, b);
    twice_area += c;
    mx += (a.x + b.x) * c;
    my += (a.y + b.y) * c;
  }
  cell.area = 0.5 * twice_area;
  cell.centroid = v0 + Vec2{mx / (3.0 * twice_area), my / (3.0 * twice_area)};
  cell.vertices.resize(n);
  for (size_t k = 0; k < n; ++k) cell.vertices[k] = world_vertices[k] - cell.centroid;
  // Polar moment about the centroid: J = sum c_k (a.a + a.b + b.b) / 12 over the edges.
  double j = 0.0;
  for (size_t k = 0; k < n; ++k) {
    const Vec2 a = cell.vertices[k], b = cell.vertices[(k + 1) % n];
    j += cross(a, b) * (dot(a, a) + dot(a, b) + dot(b, b));
  }
  cell.polar_moment = j / 12.0;
}

IceSheet generateIceSheet(const IceSheetSpec& spec) {
  validate(spec);
  std::mt19937_64 rng(spec.seed);
  std::vector<Vec2> seeds = spec.layout == SeedLayout::kJitteredGrid ? jitteredGridSeeds(spec, rng)
                                                                     : poissonDiskSeeds(spec, rng);
  std::vector<LabelledPolygon> polygons;
  for (int pass = 0; pass <= spec.lloyd_iterations; ++pass) {
    polygons = voronoiCells(spec, seeds);
    if (pass == spec.lloyd_iterations) break;
    for (size_t k = 0; k < seeds.size(); ++k) {
      CellGeometry g;
      setCellGeometryFromPolygon(polygons[k].vertices, g);
      seeds[k] = g.centroid;
    }
  }

  IceSheet sheet;
  sheet.spec = spec;
  sheet.cells.resize(polygons.size());
  for (size_t k = 0; k < polygons.size(); ++k) {
    if (polygons[k].vertices.size() > 12) {
      std::ostringstream msg;
      msg << "ice sheet: cell " << k << " has " << polygons[k].vertices.size()
          << " vertices; at most 12 are supported (raise lloyd_iterations or jitter)";
      throw std::runtime_error(msg.str());
    }
    setCellGeometryFromPolygon(polygons[k].vertices, sheet.cells[k]);
    sheet.cells[k].edge_neighbour = polygons[k].labels;
  }
  for (size_t i = 0; i < polygons.size(); ++i) {
    const LabelledPolygon& p = polygons[i];
    const size_t n = p.vertices.size();
    for (size_t k = 0; k < n; ++k) {
      const int j = p.labels[k];
      if (j <= static_cast<int>(i)) continue;
      SharedEdge e;
      e.i = static_cast<int>(i);
      e.j = j;
      e.start = p.vertices[k];
      e.end = p.vertices[(k + 1) % n];
      e.length = norm(e.end - e.start);
      sheet.edges.push_back(e);
    }
  }
  std::sort(sheet.edges.begin(), sheet.edges.end(), [](const SharedEdge& a, const SharedEdge& b) {
    return a.i != b.i ? a.i < b.i : a.j < b.j;
  });
  return sheet;
}

IceSheetStats computeStats(const IceSheet& sheet) {
  IceSheetStats s;
  s.cell_count = static_cast<int>(sheet.cells.size());
  s.edge_count = static_cast<int>(sheet.edges.size());
  if (sheet.cells.empty()) return s;
  s.min_cell_area = sheet.cells[0].area;
  s.max_cell_area = sheet.cells[0].area;
  s.min_vertices = static_cast<int>(sheet.cells[0].vertices.size());
  s.max_vertices = s.min_vertices;
  for (const CellGeometry& c : sheet.cells) {
    s.total_area += c.area;
    s.min_cell_area = std::min(s.min_cell_area, c.area);
    s.max_cell_area = std::max(s.max_cell_area, c.area);
    s.min_vertices = std::min(s.min_vertices, static_cast<int>(c.vertices.size()));
    s.max_vertices = std::max(s.max_vertices, static_cast<int>(c.vertices.size()));
  }
  s.mean_cell_area = s.total_area / s.cell_count;
  s.mean_cell_size = std::sqrt(s.mean_cell_area);
  double edge_sum = 0.0;
  for (const SharedEdge& e : sheet.edges) edge_sum += e.length;
  s.mean_edge_length = sheet.edges.empty() ? 0.0 : edge_sum / s.edge_count;
  s.mean_neighbours = 2.0 * s.edge_count / s.cell_count;
  return s;
}

}  // namespace thin_ice
