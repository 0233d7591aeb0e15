// Separating edges of two convex polygons (physics/pair_separation.hpp): unit squares by hand, and
// the claim the contact loop rests on, on random pairs: when an edge keeps two polygons more than
// 2^-12 of (r_a + r_b) apart, the integer clip (polygon_clip.hpp) finds no overlap, thin polygons
// with sharp vertices and gaps just above that bound included; and no edge separates two polygons
// that the clip finds overlapping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "random_polygons.hpp"
#include "thin_ice_sim/physics/pair_separation.hpp"
#include "thin_ice_sim/physics/polygon_clip.hpp"

namespace thin_ice {
namespace {

using Polygon = std::vector<Vec2>;

/// The fraction of r_a + r_b the contact loops ask for.
constexpr double kGapFraction = kSeparationGapFraction;

Polygon square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};  // counter-clockwise
}

double farthestVertex(const Polygon& p, Vec2 centre) {
  double r = 0.0;
  for (const Vec2& v : p) r = std::max(r, norm(v - centre));
  return r;
}

TEST(PairSeparation, UnitSquaresByHand) {
  const Polygon a = square(0.0, 0.0, 1.0), b = square(2.0, 0.0, 1.0);  // 1 m apart along x
  // a's edge 1 runs (1, 0) -> (1, 1), outward normal +x: b's nearest vertices are 1 m beyond it.
  EXPECT_TRUE(edgeSeparates(a.data(), 4, b.data(), 4, 1, 0.999));
  EXPECT_FALSE(edgeSeparates(a.data(), 4, b.data(), 4, 1, 1.0));  // not more than 1 m
  EXPECT_EQ(findSeparatingEdge(a.data(), 4, b.data(), 4, 0.5), 1);
  // b's edge 3 runs (2, 1) -> (2, 0), outward normal -x: the same gap, found from b's side.
  EXPECT_TRUE(edgeSeparates(a.data(), 4, b.data(), 4, 4 + 3, 0.999));
  EXPECT_EQ(findSeparatingEdge(b.data(), 4, a.data(), 4, 0.5), 3);
  // a's other edges have b on their inner side, at least partly.
  for (int edge : {0, 2, 3}) EXPECT_FALSE(edgeSeparates(a.data(), 4, b.data(), 4, edge, 0.0)) << edge;
  EXPECT_EQ(findSeparatingEdge(a.data(), 4, b.data(), 4, 1.0), kNoSeparatingEdge);
  // No edge, or one past both polygons: nothing is claimed.
  EXPECT_FALSE(edgeSeparates(a.data(), 4, b.data(), 4, kNoSeparatingEdge, 0.0));
  EXPECT_FALSE(edgeSeparates(a.data(), 4, b.data(), 4, 8, 0.0));
  // Overlapping, and touching along a side: no separating edge for any gap >= 0.
  const Polygon c = square(0.5, 0.5, 1.0), d = square(1.0, 0.0, 1.0);
  EXPECT_EQ(findSeparatingEdge(a.data(), 4, c.data(), 4, 0.0), kNoSeparatingEdge);
  EXPECT_EQ(findSeparatingEdge(a.data(), 4, d.data(), 4, 0.0), kNoSeparatingEdge);
}

TEST(PairSeparation, TheClipFindsNoOverlapWherePromised) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> place(-15.0, 15.0);  // a 30 m domain
  std::uniform_real_distribution<double> size(0.05, 0.4);
  std::uniform_int_distribution<int> vertices(3, kMaxPolygonVertices);
  constexpr double kTwoPi = 6.283185307179586;
  constexpr int kPairs = 200000;
  int promised = 0, near_the_bound = 0, overlapping = 0;
  for (int trial = 0; trial < kPairs; ++trial) {
    // Thin polygons too (semi-axes down to 1:50), so some vertices are sharp.
    const double ra = size(rng), rb = size(rng);
    const double thin_a = trial % 2 ? 0.02 + 0.98 * unit(rng) : 1.0, thin_b = trial % 3 ? 1.0 : 0.02 + 0.98 * unit(rng);
    const Vec2 centre_a = {place(rng), place(rng)};
    const Polygon a = testing::randomConvexPolygon(rng, vertices(rng), centre_a, ra, thin_a * ra);
    Polygon b = testing::randomConvexPolygon(rng, vertices(rng), {0.0, 0.0}, rb, thin_b * rb);
    // Put b along a random direction u with the gap between the projections set, from 0.1 to
    // 1000 times the bound, most of them within a few times the bound; every fifth pair instead
    // has b's centre within half of a's size from a's centre, so most of those overlap.
    const double angle = kTwoPi * unit(rng);
    const Vec2 u = {std::cos(angle), std::sin(angle)};
    double a_far = -1e300, b_near = 1e300;
    for (const Vec2& p : a) a_far = std::max(a_far, dot(u, p));
    for (const Vec2& q : b) b_near = std::min(b_near, dot(u, q));
    const double bound = kGapFraction * (farthestVertex(a, centre_a) + farthestVertex(b, {0.0, 0.0}));
    const double gap = bound * std::pow(10.0, -1.0 + 4.0 * unit(rng));
    const Vec2 shift = trial % 5 == 0 ? centre_a + (0.5 * thin_a * ra * unit(rng)) * u : (a_far - b_near + gap) * u;
    for (Vec2& q : b) q = q + shift;
    const int na = static_cast<int>(a.size()), nb = static_cast<int>(b.size());

    const double clipped = intersectConvexPolygons(a.data(), na, b.data(), nb).area;
    // Every edge, not just the first found: the contact loop trusts whichever one it remembered.
    int separating = 0;
    for (int edge = 0; edge < na + nb; ++edge) {
      if (!edgeSeparates(a.data(), na, b.data(), nb, edge, bound)) continue;
      ++separating;
      ASSERT_EQ(clipped, 0.0) << "pair " << trial << ": edge " << edge << " keeps them " << gap / bound
                              << " bounds apart along u, yet the clip gives " << clipped << " m^2";
    }
    ASSERT_EQ(separating > 0, findSeparatingEdge(a.data(), na, b.data(), nb, bound) != kNoSeparatingEdge);
    if (separating > 0) {
      ++promised;
      near_the_bound += gap < 2.0 * bound ? 1 : 0;
    }
    if (clipped > 0.0) {
      ++overlapping;
      ASSERT_EQ(findSeparatingEdge(a.data(), na, b.data(), nb, 0.0), kNoSeparatingEdge) << "pair " << trial;
    }
  }
  // The draw must reach both sides and the bound itself.
  EXPECT_GT(promised, kPairs / 4);
  EXPECT_GT(near_the_bound, kPairs / 100);
  EXPECT_GT(overlapping, kPairs / 10);
}

}  // namespace
}  // namespace thin_ice
