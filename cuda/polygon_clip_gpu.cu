#include "polygon_clip_gpu.cuh"

#include <stdexcept>

#include "cuda_check.hpp"

namespace thin_ice {
namespace cuda {
namespace {

__global__ void intersectPairsKernel(const PackedPolygon* first, const PackedPolygon* second,
                                     PolygonOverlap* overlaps, int count) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= count) return;
  overlaps[k] = intersectConvexPolygons(first[k].vertices, first[k].count, second[k].vertices,
                                        second[k].count);
}

/// Device buffer freed on scope exit, so an exception leaks nothing.
template <typename T>
class DeviceBuffer {
 public:
  explicit DeviceBuffer(size_t count) { TIS_CUDA_CHECK(cudaMalloc(&data_, count * sizeof(T) + 1)); }
  ~DeviceBuffer() { cudaFree(data_); }
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
  T* get() const { return data_; }

 private:
  T* data_ = nullptr;
};

}  // namespace

std::vector<PolygonOverlap> intersectPolygonPairs(const std::vector<PackedPolygon>& first,
                                                  const std::vector<PackedPolygon>& second) {
  if (first.size() != second.size()) {
    throw std::invalid_argument("intersectPolygonPairs: first and second differ in size");
  }
  const int count = static_cast<int>(first.size());
  std::vector<PolygonOverlap> overlaps(first.size());
  if (count == 0) return overlaps;
  DeviceBuffer<PackedPolygon> d_first(first.size()), d_second(second.size());
  DeviceBuffer<PolygonOverlap> d_overlaps(first.size());
  TIS_CUDA_CHECK(cudaMemcpy(d_first.get(), first.data(), first.size() * sizeof(PackedPolygon),
                            cudaMemcpyHostToDevice));
  TIS_CUDA_CHECK(cudaMemcpy(d_second.get(), second.data(), second.size() * sizeof(PackedPolygon),
                            cudaMemcpyHostToDevice));
  constexpr int kThreads = 128;
  intersectPairsKernel<<<(count + kThreads - 1) / kThreads, kThreads>>>(d_first.get(), d_second.get(),
                                                                        d_overlaps.get(), count);
  TIS_CUDA_CHECK(cudaGetLastError());
  TIS_CUDA_CHECK(cudaMemcpy(overlaps.data(), d_overlaps.get(), overlaps.size() * sizeof(PolygonOverlap),
                            cudaMemcpyDeviceToHost));
  return overlaps;
}

}  // namespace cuda
}  // namespace thin_ice
