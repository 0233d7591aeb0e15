// Voronoi ice sheet generation (ice_sheet.hpp): tiling, convexity, shared edges, determinism,
// bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <string>

#include "thin_ice_sim/ice_sheet.hpp"

namespace thin_ice {
namespace {

// Relative tolerance on the summed cell area (the tiling criterion).
constexpr double kTolTiling = 1e-9;
// Two cells see their shared edge through independent double clipping: endpoints agree to
constexpr double kTolSharedVertex = 1e-9;  // x cell_size

IceSheetSpec smallSpec(SeedLayout layout) {
  IceSheetSpec spec;
  spec.length = 6.0;
  spec.width = 2.5;
  spec.x_min = -1.0;
  spec.cell_size = 0.2;
  spec.layout = layout;
  spec.seed = 3;
  return spec;
}

void expectValidTiling(const IceSheet& sheet) {
  const IceSheetSpec& s = sheet.spec;
  const double y_min = -0.5 * s.width, y_max = 0.5 * s.width, x_max = s.x_min + s.length;
  double total = 0.0;
  for (size_t i = 0; i < sheet.cells.size(); ++i) {
    const CellGeometry& c = sheet.cells[i];
    total += c.area;
    const size_t n = c.vertices.size();
    ASSERT_GE(n, 3u);
    ASSERT_LE(n, 12u);
    ASSERT_EQ(c.edge_neighbour.size(), n);
    ASSERT_GT(c.area, 0.0);
    ASSERT_GT(c.polar_moment, 0.0);
    for (size_t k = 0; k < n; ++k) {
      // Convex and counter-clockwise: every turn is to the left.
      const Vec2 a = c.vertices[k], b = c.vertices[(k + 1) % n], d = c.vertices[(k + 2) % n];
      ASSERT_GT(cross(b - a, d - b), 0.0) << "cell " << i << " vertex " << k;
      // Inside the rectangle.
      const Vec2 w = c.centroid + a;
      ASSERT_GE(w.x, s.x_min - 1e-12);
      ASSERT_LE(w.x, x_max + 1e-12);
      ASSERT_GE(w.y, y_min - 1e-12);
      ASSERT_LE(w.y, y_max + 1e-12);
      const Vec2 p = c.centroid + c.vertices[k], q = c.centroid + c.vertices[(k + 1) % n];
      const int j = c.edge_neighbour[k];
      if (j < 0) {
        // A rim edge lies on one side of the rectangle.
        const bool on_side = (p.x == s.x_min && q.x == s.x_min) || (p.x == x_max && q.x == x_max) ||
                             (p.y == y_min && q.y == y_min) || (p.y == y_max && q.y == y_max);
        ASSERT_TRUE(on_side) << "cell " << i << " rim edge " << k;
        continue;
      }
      // An interior edge is shared by exactly one other cell, which sees it reversed.
      const CellGeometry& other = sheet.cells[j];
      int matches = 0;
      for (size_t m = 0; m < other.vertices.size(); ++m) {
        if (other.edge_neighbour[m] != static_cast<int>(i)) continue;
        const Vec2 op = other.centroid + other.vertices[m];
        const Vec2 oq = other.centroid + other.vertices[(m + 1) % other.vertices.size()];
        const double tol = kTolSharedVertex * s.cell_size;
        if (norm(op - q) < tol && norm(oq - p) < tol) ++matches;
      }
      ASSERT_EQ(matches, 1) << "edge " << k << " of cell " << i << " towards cell " << j;
    }
  }
  EXPECT_NEAR(total, s.length * s.width, kTolTiling * s.length * s.width);

  // Every random point of the sheet lies in exactly one cell (away from edges).
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> ux(s.x_min, x_max), uy(y_min, y_max);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec2 p = {ux(rng), uy(rng)};
    int inside = 0;
    for (const CellGeometry& c : sheet.cells) {
      bool in = true;
      const size_t n = c.vertices.size();
      for (size_t k = 0; k < n && in; ++k) {
        in = cross(c.vertices[(k + 1) % n] - c.vertices[k], p - c.centroid - c.vertices[k]) > 1e-12;
      }
      inside += in;
    }
    ASSERT_LE(inside, 1);
  }
}

TEST(IceSheet, JitteredGridTilesTheSheet) {
  const IceSheet sheet = generateIceSheet(smallSpec(SeedLayout::kJitteredGrid));
  EXPECT_EQ(sheet.cells.size(), 30u * 13u);  // round(6/0.2) x round(2.5/0.2)
  expectValidTiling(sheet);
  const IceSheetStats stats = computeStats(sheet);
  EXPECT_NEAR(stats.mean_cell_size, 0.2, 0.01);
  EXPECT_GT(stats.mean_neighbours, 5.0);  // interior Voronoi cells have about 6 neighbours
  EXPECT_LT(stats.mean_neighbours, 6.0);
}

TEST(IceSheet, PoissonDiskTilesTheSheet) {
  const IceSheet sheet = generateIceSheet(smallSpec(SeedLayout::kPoissonDisk));
  expectValidTiling(sheet);
  const IceSheetStats stats = computeStats(sheet);
  EXPECT_NEAR(stats.mean_cell_size, 0.2, 0.02);
}

TEST(IceSheet, PerfectGridWithCocircularSeeds) {
  // jitter 0 and no relaxation: four seeds on every circle, zero-length Voronoi edges.
  IceSheetSpec spec = smallSpec(SeedLayout::kJitteredGrid);
  spec.jitter = 0.0;
  spec.lloyd_iterations = 0;
  const IceSheet sheet = generateIceSheet(spec);
  expectValidTiling(sheet);
  const double cell_area = (6.0 / 30.0) * (2.5 / 13.0);  // pitches of the 30 x 13 grid
  for (const CellGeometry& c : sheet.cells) {
    EXPECT_EQ(c.vertices.size(), 4u);
    EXPECT_NEAR(c.area, cell_area, 1e-12);
  }
}

TEST(IceSheet, SameSeedSameSheetOtherSeedOtherSheet) {
  const IceSheetSpec spec = smallSpec(SeedLayout::kJitteredGrid);
  const IceSheet a = generateIceSheet(spec), b = generateIceSheet(spec);
  ASSERT_EQ(a.cells.size(), b.cells.size());
  ASSERT_EQ(a.edges.size(), b.edges.size());
  for (size_t i = 0; i < a.cells.size(); ++i) {
    ASSERT_EQ(a.cells[i].centroid.x, b.cells[i].centroid.x);
    ASSERT_EQ(a.cells[i].centroid.y, b.cells[i].centroid.y);
    ASSERT_EQ(a.cells[i].vertices.size(), b.cells[i].vertices.size());
  }
  IceSheetSpec other = spec;
  other.seed = 4;
  const IceSheet c = generateIceSheet(other);
  EXPECT_NE(a.cells[0].centroid.x, c.cells[0].centroid.x);
}

TEST(IceSheet, SharedEdgesAreListedOnceSortedWithLengths) {
  const IceSheet sheet = generateIceSheet(smallSpec(SeedLayout::kJitteredGrid));
  std::map<std::pair<int, int>, int> seen;
  for (size_t k = 0; k < sheet.edges.size(); ++k) {
    const SharedEdge& e = sheet.edges[k];
    ASSERT_LT(e.i, e.j);
    ASSERT_GT(e.length, 0.0);
    ASSERT_NEAR(e.length, norm(e.end - e.start), 1e-15);
    ASSERT_EQ(seen[std::make_pair(e.i, e.j)]++, 0);
    if (k > 0) {
      const SharedEdge& p = sheet.edges[k - 1];
      ASSERT_TRUE(p.i < e.i || (p.i == e.i && p.j < e.j));
    }
  }
}

TEST(IceSheet, PolygonGeometryByHand) {
  // Square of side 2 centred at (3, 1): A = 4, J = a^4 / 6 = 16 / 6.
  CellGeometry c;
  setCellGeometryFromPolygon({{2, 0}, {4, 0}, {4, 2}, {2, 2}}, c);
  EXPECT_NEAR(c.area, 4.0, 1e-12);
  EXPECT_NEAR(c.centroid.x, 3.0, 1e-12);
  EXPECT_NEAR(c.centroid.y, 1.0, 1e-12);
  EXPECT_NEAR(c.polar_moment, 16.0 / 6.0, 1e-12);
  // Right triangle legs 3 and 3: centroid (1, 1), J = b h (b^2 + h^2) / 36 = 9 * 18 / 36 = 4.5.
  setCellGeometryFromPolygon({{0, 0}, {3, 0}, {0, 3}}, c);
  EXPECT_NEAR(c.area, 4.5, 1e-12);
  EXPECT_NEAR(c.centroid.x, 1.0, 1e-12);
  EXPECT_NEAR(c.polar_moment, 4.5, 1e-12);
}

void expectRejected(IceSheetSpec spec, const std::string& name) {
  try {
    generateIceSheet(spec);
    FAIL() << "accepted an invalid " << name;
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(name), std::string::npos) << what;
    EXPECT_NE(what.find("allowed"), std::string::npos) << what;
  }
}

TEST(IceSheet, InvalidParametersNameTheParameterAndRange) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  IceSheetSpec s = smallSpec(SeedLayout::kJitteredGrid);
  s.length = -1.0;
  expectRejected(s, "length");
  s = smallSpec(SeedLayout::kJitteredGrid);
  s.width = nan;
  expectRejected(s, "width");
  s = smallSpec(SeedLayout::kJitteredGrid);
  s.cell_size = 0.0;
  expectRejected(s, "cell_size");
  s = smallSpec(SeedLayout::kJitteredGrid);
  s.cell_size = 3.0;  // larger than the 2.5 m width
  expectRejected(s, "cell_size");
  s = smallSpec(SeedLayout::kJitteredGrid);
  s.cell_size = nan;
  expectRejected(s, "cell_size");
  s = smallSpec(SeedLayout::kJitteredGrid);
  s.jitter = 0.7;
  expectRejected(s, "jitter");
  s = smallSpec(SeedLayout::kJitteredGrid);
  s.lloyd_iterations = -2;
  expectRejected(s, "lloyd_iterations");
  EXPECT_THROW(parseSeedLayout("hexagonal", "sheet.layout"), std::invalid_argument);
}

}  // namespace
}  // namespace thin_ice
