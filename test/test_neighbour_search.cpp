// Fixed-radius neighbour search (neighbour_search.hpp) against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "thin_ice_sim/neighbour_search.hpp"

namespace thin_ice {
namespace {

std::vector<Vec2> randomPoints(std::mt19937_64& rng, int count, double lx, double ly) {
  std::uniform_real_distribution<double> ux(0.0, lx), uy(-0.5 * ly, 0.5 * ly);
  std::vector<Vec2> points(count);
  for (Vec2& p : points) p = {ux(rng), uy(rng)};
  return points;
}

TEST(NeighbourSearch, SamePairsAsBruteForce) {
  std::mt19937_64 rng(9);
  FixedRadiusNeighbourSearch search;  // reused across sets, as between rebuilds
  for (int count : {0, 1, 2, 50, 800, 3000}) {
    for (double radius : {0.05, 0.3, 1.0, 25.0}) {
      const std::vector<Vec2> points = randomPoints(rng, count, 20.0, 4.0);
      const std::vector<CandidatePair> expected = findPairsBruteForce(points, radius);
      const std::vector<CandidatePair>& found = search.findPairs(points, radius);
      ASSERT_EQ(found.size(), expected.size()) << count << " points, radius " << radius;
      for (size_t k = 0; k < found.size(); ++k) ASSERT_EQ(found[k], expected[k]);
    }
  }
}

TEST(NeighbourSearch, SplittingThePointsOverThreadsGivesTheSameList) {
  // Ranges of i searched in parallel and joined in order: the same sorted list as brute force,
  // for more ranges than threads, for ranges with no point, and reused between calls.
  std::mt19937_64 rng(11);
  FixedRadiusNeighbourSearch search;
  for (int count : {2, 3, 7, 2500}) {
    const std::vector<Vec2> points = randomPoints(rng, count, 12.0, 3.0);
    const std::vector<CandidatePair> expected = findPairsBruteForce(points, 0.4);
    for (int threads : {1, 2, 3, 5}) {
      const std::vector<CandidatePair>& found = search.findPairs(points, 0.4, threads);
      ASSERT_EQ(found.size(), expected.size()) << count << " points, " << threads << " threads";
      for (size_t k = 0; k < found.size(); ++k) ASSERT_EQ(found[k], expected[k]);
    }
  }
}

TEST(NeighbourSearch, PairAtExactlyTheRadiusIsFound) {
  FixedRadiusNeighbourSearch search;
  const std::vector<Vec2> points = {{0.0, 0.0}, {0.5, 0.0}, {1.25, 0.0}};
  const auto& pairs = search.findPairs(points, 0.5);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0], (CandidatePair{0, 1}));
}

TEST(NeighbourSearch, OutliersAndNonFinitePointsAreHandled) {
  std::mt19937_64 rng(10);
  std::vector<Vec2> points = randomPoints(rng, 1000, 10.0, 3.0);
  points[17] = {1e7, -3e6};  // a cell flung far away must not allocate 10^14 bins
  points[18] = {std::numeric_limits<double>::quiet_NaN(), 0.0};
  points[19] = {0.0, std::numeric_limits<double>::infinity()};
  FixedRadiusNeighbourSearch search;
  const auto& found = search.findPairs(points, 0.2);
  const auto expected = findPairsBruteForce(points, 0.2);
  ASSERT_EQ(found.size(), expected.size());
  for (size_t k = 0; k < found.size(); ++k) {
    ASSERT_EQ(found[k], expected[k]);
    ASSERT_NE(found[k].i, 18);
    ASSERT_NE(found[k].j, 19);
  }
}

TEST(NeighbourSearch, InvalidRadiusIsRejected) {
  FixedRadiusNeighbourSearch search;
  const std::vector<Vec2> points = {{0, 0}, {1, 1}};
  EXPECT_THROW(search.findPairs(points, 0.0), std::invalid_argument);
  EXPECT_THROW(search.findPairs(points, -1.0), std::invalid_argument);
  EXPECT_THROW(search.findPairs(points, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

}  // namespace
}  // namespace thin_ice
