// A typed device buffer (cudaMalloc'd, freed with its owner) and the launch size the CUDA
// backend's kernels share. Include only from .cu files.
#pragma once

#include <cuda_runtime.h>

#include <algorithm>
#include <vector>

#include "cuda_check.hpp"

namespace thin_ice {
namespace cuda {

constexpr int kThreads = 128;  ///< threads per block: the polygon kernels keep ~1 kB on the stack

template <class T>
class DeviceArray {
 public:
  DeviceArray() = default;
  DeviceArray(const DeviceArray&) = delete;
  DeviceArray& operator=(const DeviceArray&) = delete;
  ~DeviceArray() { if (data_ != nullptr) cudaFree(data_); }
  /// Room for `count` elements; when it must grow, the contents are dropped.
  void resize(size_t count) {
    if (count <= capacity_) { size_ = count; return; }
    if (data_ != nullptr) TIS_CUDA_CHECK(cudaFree(data_));
    data_ = nullptr;
    TIS_CUDA_CHECK(cudaMalloc(&data_, std::max<size_t>(count, 1) * sizeof(T)));
    capacity_ = std::max<size_t>(count, 1);
    size_ = count;
  }
  void upload(const std::vector<T>& host) {
    resize(host.size());
    if (!host.empty()) TIS_CUDA_CHECK(cudaMemcpy(data_, host.data(), host.size() * sizeof(T), cudaMemcpyHostToDevice));
  }
  std::vector<T> download() const {
    std::vector<T> host(size_);
    if (size_ > 0) TIS_CUDA_CHECK(cudaMemcpy(host.data(), data_, size_ * sizeof(T), cudaMemcpyDeviceToHost));
    return host;
  }
  T* get() const { return data_; }
  size_t size() const { return size_; }
  size_t bytes() const { return capacity_ * sizeof(T); }

 private:
  T* data_ = nullptr;
  size_t size_ = 0, capacity_ = 0;
};

inline int blocksFor(long long count) { return static_cast<int>(std::max<long long>(1, (count + kThreads - 1) / kThreads)); }

}  // namespace cuda
}  // namespace thin_ice
