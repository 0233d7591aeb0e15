// Random convex polygons for tests and benchmarks: vertices on an ellipse at sorted random angles.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "thin_ice_sim/physics/vec2.hpp"

namespace thin_ice {
namespace testing {

/// A convex counter-clockwise polygon with `count` vertices on an ellipse of semi-axes (a, b),
/// turned by a random angle, centred at `centre`. Angles are kept at least 2 % of a turn apart
/// so that no three vertices are nearly collinear.
inline std::vector<Vec2> randomConvexPolygon(std::mt19937_64& rng, int count, Vec2 centre, double a,
                                             double b) {
  constexpr double kTwoPi = 6.283185307179586;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> angles;
  while (static_cast<int>(angles.size()) < count) {
    angles.clear();
    for (int k = 0; k < count; ++k) angles.push_back(kTwoPi * unit(rng));
    std::sort(angles.begin(), angles.end());
    bool spaced = true;
    for (int k = 0; k < count; ++k) {
      const double gap = k + 1 < count ? angles[k + 1] - angles[k] : angles[0] + kTwoPi - angles[k];
      if (gap < 0.02 * kTwoPi) spaced = false;
    }
    if (!spaced) angles.clear();
  }
  const double turn = kTwoPi * unit(rng);
  std::vector<Vec2> polygon;
  for (double t : angles) {
    const Vec2 p = {a * std::cos(t), b * std::sin(t)};
    polygon.push_back(centre + rotate(p, std::cos(turn), std::sin(turn)));
  }
  return polygon;
}

/// The polygon pairs that PolygonClipGpu.MatchesTheCpu hands the GPU clip: 20000 pairs of 3-12
/// vertices near (12, -3) m, the second moved by up to 0.4 m, so that some overlap and some do not.
/// Its CPU half (test_polygon_clip: PolygonClip.TheGpuTestsPairsAreAMeaningfulCpuReference) checks
/// the CPU clip on the same pairs against exact arithmetic, without a GPU.
struct PolygonPair {
  std::vector<Vec2> first, second;
};

inline std::vector<PolygonPair> gpuClipTestPairs() {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> offset(-0.4, 0.4);
  std::vector<PolygonPair> pairs;
  for (int k = 0; k < 20000; ++k) {
    PolygonPair pair;
    pair.first = randomConvexPolygon(rng, 3 + k % 10, {12.0, -3.0}, 0.3, 0.2);
    pair.second = randomConvexPolygon(rng, 3 + (k / 10) % 10, {12.0 + offset(rng), -3.0 + offset(rng)}, 0.25, 0.3);
    pairs.push_back(pair);
  }
  return pairs;
}

}  // namespace testing
}  // namespace thin_ice
