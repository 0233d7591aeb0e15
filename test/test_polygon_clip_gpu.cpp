// The polygon intersection kernel against the CPU call of the same inline function.
#include <gtest/gtest.h>

#include <random>

#include "device_info.cuh"
#include "polygon_clip_gpu.cuh"
#include "random_polygons.hpp"

namespace thin_ice {
namespace {

// nvcc may contract a*b+c into one fused multiply-add where the host compiler rounds twice; the
// rounded grid points can then differ by one step (~1e-9 of the pair extent):
constexpr double kTolDeviceArea = 1e-8;  // relative to the larger polygon area

TEST(PolygonClipGpu, MatchesTheCpu) {
  if (cuda::deviceCount() == 0) GTEST_SKIP() << "no CUDA device on this machine: GPU test skipped";
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> offset(-0.4, 0.4);
  std::vector<cuda::PackedPolygon> first, second;
  for (int k = 0; k < 20000; ++k) {
    const auto a = testing::randomConvexPolygon(rng, 3 + k % 10, {12.0, -3.0}, 0.3, 0.2);
    const auto b = testing::randomConvexPolygon(rng, 3 + (k / 10) % 10,
                                                {12.0 + offset(rng), -3.0 + offset(rng)}, 0.25, 0.3);
    cuda::PackedPolygon pa{}, pb{};
    pa.count = static_cast<int>(a.size());
    pb.count = static_cast<int>(b.size());
    std::copy(a.begin(), a.end(), pa.vertices);
    std::copy(b.begin(), b.end(), pb.vertices);
    first.push_back(pa);
    second.push_back(pb);
  }
  const std::vector<PolygonOverlap> gpu = cuda::intersectPolygonPairs(first, second);
  for (size_t k = 0; k < first.size(); ++k) {
    const PolygonOverlap cpu = intersectConvexPolygons(first[k].vertices, first[k].count,
                                                       second[k].vertices, second[k].count);
    const double scale = 0.3 * 0.3 * 3.2;
    ASSERT_NEAR(gpu[k].area, cpu.area, kTolDeviceArea * scale) << "pair " << k;
  }
}

}  // namespace
}  // namespace thin_ice
