#include <sstream>
#include <stdexcept>

#include "cuda_check.hpp"
#include "device_info.cuh"

namespace thin_ice {
namespace cuda {

void throwCudaError(cudaError_t status, const char* call, const char* file, int line) {
  std::ostringstream msg;
  msg << "CUDA error " << cudaGetErrorName(status) << " (" << cudaGetErrorString(status) << ") in "
      << call << " at " << file << ":" << line;
  throw std::runtime_error(msg.str());
}

int deviceCount() {
  int count = 0;
  if (cudaGetDeviceCount(&count) != cudaSuccess) {
    cudaGetLastError();  // clear the sticky error left by a missing driver
    return 0;
  }
  return count;
}

std::string deviceDescription() {
  if (deviceCount() == 0) return std::string();
  cudaDeviceProp prop;
  TIS_CUDA_CHECK(cudaGetDeviceProperties(&prop, 0));
  std::ostringstream out;
  out << prop.name << " (compute capability " << prop.major << "." << prop.minor << ", "
      << prop.totalGlobalMem / (1024.0 * 1024.0 * 1024.0) << " GiB)";
  return out.str();
}

double deviceMemoryInUse() {
  if (deviceCount() == 0) return 0.0;
  size_t free_bytes = 0, total_bytes = 0;
  TIS_CUDA_CHECK(cudaMemGetInfo(&free_bytes, &total_bytes));
  return static_cast<double>(total_bytes - free_bytes);
}

}  // namespace cuda
}  // namespace thin_ice
