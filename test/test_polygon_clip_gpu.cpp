// The polygon intersection kernel against the CPU call of the same inline function.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

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
  // The pairs' CPU half (the CPU clip on them against exact arithmetic) is
  // PolygonClip.TheGpuTestsPairsAreAMeaningfulCpuReference, which runs without a GPU.
  std::vector<cuda::PackedPolygon> first, second;
  for (const testing::PolygonPair& pair : testing::gpuClipTestPairs()) {
    cuda::PackedPolygon pa{}, pb{};
    pa.count = static_cast<int>(pair.first.size());
    pb.count = static_cast<int>(pair.second.size());
    std::copy(pair.first.begin(), pair.first.end(), pa.vertices);
    std::copy(pair.second.begin(), pair.second.end(), pb.vertices);
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
