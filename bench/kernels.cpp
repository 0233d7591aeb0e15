// Kernel micro-benchmarks (Google Benchmark), each against an independent library on the same
// inputs:
//   polygon intersection: this project's integer-grid convex clip (physics/polygon_clip.hpp)
//     against Boost.Geometry's intersection() + area() + centroid(), on pairs of Voronoi cells of
//     a generated sheet pushed into their neighbours as in a contact. Counters: pairs per second,
//     and the largest overlap-area difference between the two over all pairs.
//   neighbour search: the cell list of the CPU backend (neighbour_search.hpp) against a
//     nanoflann KD-tree (build + one radius query per point) and brute force, on a jittered
//     grid of cell centroids. Counters: points per second, and whether the pair sets agree.
//   thin_ice_bench_kernels [--benchmark_format=json] [--benchmark_out=FILE] ...
#include <benchmark/benchmark.h>

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <cmath>
#include <nanoflann.hpp>
#include <random>
#include <vector>

#include "thin_ice_sim/ice_sheet.hpp"
#include "thin_ice_sim/neighbour_search.hpp"
#include "thin_ice_sim/physics/polygon_clip.hpp"

namespace {

using thin_ice::Vec2;
namespace bg = boost::geometry;
using BgPoint = bg::model::d2::point_xy<double>;
using BgPolygon = bg::model::polygon<BgPoint, false /*counter-clockwise*/, false /*open*/>;

// --- Polygon pairs ------------------------------------------------------------------------------

/// Cell size [m] and pushes [m] of the pair set: M-2's 0.2 m cells, overlaps of 1-30 mm.
constexpr double kCellSize = 0.2;
constexpr double kMinPush = 0.001, kMaxPush = 0.03;
constexpr int kPairCount = 4096;

struct PolygonPair {
  std::vector<Vec2> a, b;
  BgPolygon bg_a, bg_b;
};

BgPolygon toBoost(const std::vector<Vec2>& poly) {
  BgPolygon p;
  for (const Vec2& v : poly) bg::append(p.outer(), BgPoint(v.x, v.y));
  return p;
}

/// Bonded neighbours of a 10 m x 10 m sheet; the second cell of each pair is pushed towards the
/// first by a random 1-30 mm and turned by up to 2 degrees about its centroid.
const std::vector<PolygonPair>& polygonPairs() {
  static const std::vector<PolygonPair> pairs = [] {
    thin_ice::IceSheetSpec spec;
    spec.length = 10.0;
    spec.width = 10.0;
    spec.cell_size = kCellSize;
    const thin_ice::IceSheet sheet = thin_ice::generateIceSheet(spec);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> push(kMinPush, kMaxPush), turn(-2.0, 2.0);
    std::vector<PolygonPair> out;
    for (const thin_ice::SharedEdge& e : sheet.edges) {
      if (static_cast<int>(out.size()) == kPairCount) break;
      const thin_ice::CellGeometry& ci = sheet.cells[e.i];
      const thin_ice::CellGeometry& cj = sheet.cells[e.j];
      const Vec2 towards_i = ci.centroid - cj.centroid;
      const Vec2 shift = (push(rng) / thin_ice::norm(towards_i)) * towards_i;
      const double angle = turn(rng) * 3.141592653589793 / 180.0;
      PolygonPair p;
      for (const Vec2& v : ci.vertices) p.a.push_back(ci.centroid + v);
      for (const Vec2& v : cj.vertices) {
        p.b.push_back(cj.centroid + shift + thin_ice::rotate(v, std::cos(angle), std::sin(angle)));
      }
      p.bg_a = toBoost(p.a);
      p.bg_b = toBoost(p.b);
      out.push_back(std::move(p));
    }
    return out;
  }();
  return pairs;
}

double boostOverlapArea(const PolygonPair& p, BgPoint* centroid) {
  std::vector<BgPolygon> out;
  bg::intersection(p.bg_a, p.bg_b, out);
  double area = 0.0;
  for (const BgPolygon& piece : out) area += bg::area(piece);
  if (!out.empty() && centroid != nullptr) bg::centroid(out.front(), *centroid);
  return area;
}

void BM_PolygonOverlap_IntegerClip(benchmark::State& state) {
  const std::vector<PolygonPair>& pairs = polygonPairs();
  for (auto _ : state) {
    for (const PolygonPair& p : pairs) {
      const thin_ice::PolygonOverlap o = thin_ice::intersectConvexPolygons(
          p.a.data(), static_cast<int>(p.a.size()), p.b.data(), static_cast<int>(p.b.size()));
      benchmark::DoNotOptimize(o);
    }
  }
  state.counters["pairs_per_s"] = benchmark::Counter(static_cast<double>(pairs.size()), benchmark::Counter::kIsIterationInvariantRate);
  // Agreement with Boost.Geometry over the whole set (not timed).
  double worst = 0.0, largest = 0.0;
  for (const PolygonPair& p : pairs) {
    const double ours = thin_ice::intersectConvexPolygons(p.a.data(), static_cast<int>(p.a.size()), p.b.data(),
                                                          static_cast<int>(p.b.size()))
                            .area;
    const double theirs = boostOverlapArea(p, nullptr);
    worst = std::max(worst, std::fabs(ours - theirs));
    largest = std::max(largest, theirs);
  }
  state.counters["max_area_diff_m2"] = worst;
  state.counters["largest_overlap_m2"] = largest;
}
BENCHMARK(BM_PolygonOverlap_IntegerClip)->Unit(benchmark::kMicrosecond);

void BM_PolygonOverlap_BoostGeometry(benchmark::State& state) {
  const std::vector<PolygonPair>& pairs = polygonPairs();
  for (auto _ : state) {
    for (const PolygonPair& p : pairs) {
      BgPoint centroid;
      benchmark::DoNotOptimize(boostOverlapArea(p, &centroid));
      benchmark::DoNotOptimize(centroid);
    }
  }
  state.counters["pairs_per_s"] = benchmark::Counter(static_cast<double>(pairs.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PolygonOverlap_BoostGeometry)->Unit(benchmark::kMicrosecond);

// --- Neighbour search ---------------------------------------------------------------------------

/// Search radius [m]: twice the largest cell radius plus the margin, as for 0.2 m cells.
constexpr double kSearchRadius = 0.5;

/// N centroids on a jittered square grid of pitch kCellSize (jitter 0.35 of the pitch).
std::vector<Vec2> jitteredCentroids(int n) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> jitter(-0.35 * kCellSize, 0.35 * kCellSize);
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  std::vector<Vec2> points;
  for (int k = 0; k < n; ++k) {
    points.push_back({(k % columns) * kCellSize + jitter(rng), (k / columns) * kCellSize + jitter(rng)});
  }
  return points;
}

struct PointCloud {
  const std::vector<Vec2>* points;
  size_t kdtree_get_point_count() const { return points->size(); }
  double kdtree_get_pt(size_t k, size_t dim) const { return dim == 0 ? (*points)[k].x : (*points)[k].y; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const { return false; }
};
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud, 2>;

/// Every pair (i < j) within the radius from a nanoflann KD-tree, sorted by (i, j).
std::vector<thin_ice::CandidatePair> kdTreePairs(const std::vector<Vec2>& points, double radius) {
  const PointCloud cloud{&points};
  KdTree tree(2, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  std::vector<thin_ice::CandidatePair> pairs;
  std::vector<std::pair<uint32_t, double>> found;
  const nanoflann::SearchParams unsorted(32, 0.0f, false);
  for (size_t i = 0; i < points.size(); ++i) {
    const double query[2] = {points[i].x, points[i].y};
    found.clear();
    tree.radiusSearch(query, radius * radius, found, unsorted);  // L2_Simple: squared radius
    const size_t begin = pairs.size();
    for (const auto& f : found) {
      if (f.first > i) pairs.push_back({static_cast<int>(i), static_cast<int>(f.first)});
    }
    std::sort(pairs.begin() + static_cast<long>(begin), pairs.end(),
              [](const thin_ice::CandidatePair& a, const thin_ice::CandidatePair& b) { return a.j < b.j; });
  }
  return pairs;
}

void BM_NeighbourSearch_CellList(benchmark::State& state) {
  const std::vector<Vec2> points = jitteredCentroids(static_cast<int>(state.range(0)));
  thin_ice::FixedRadiusNeighbourSearch search;
  size_t found = 0;
  for (auto _ : state) {
    found = search.findPairs(points, kSearchRadius).size();
    benchmark::DoNotOptimize(found);
  }
  state.counters["points_per_s"] = benchmark::Counter(static_cast<double>(points.size()), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["pairs"] = static_cast<double>(found);
  // Agreement with the KD-tree (not timed): 1 when the two pair lists are identical.
  state.counters["same_pairs_as_kdtree"] = search.findPairs(points, kSearchRadius) == kdTreePairs(points, kSearchRadius);
}
BENCHMARK(BM_NeighbourSearch_CellList)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);

void BM_NeighbourSearch_NanoflannKdTree(benchmark::State& state) {
  const std::vector<Vec2> points = jitteredCentroids(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(kdTreePairs(points, kSearchRadius).size());
  state.counters["points_per_s"] = benchmark::Counter(static_cast<double>(points.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_NeighbourSearch_NanoflannKdTree)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);

void BM_NeighbourSearch_BruteForce(benchmark::State& state) {
  const std::vector<Vec2> points = jitteredCentroids(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(thin_ice::findPairsBruteForce(points, kSearchRadius).size());
  state.counters["points_per_s"] = benchmark::Counter(static_cast<double>(points.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_NeighbourSearch_BruteForce)->RangeMultiplier(10)->Range(1000, 10000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
