// Every CUDA runtime call goes through TIS_CUDA_CHECK, which throws std::runtime_error naming the
// call, the file and the line (as DEM-Engine's DEME_GPU_CALL does). Include only from .cu files.
#pragma once

#include <cuda_runtime.h>

namespace thin_ice {
namespace cuda {

/// Throws std::runtime_error "CUDA error <name> (<text>) in <call> at <file>:<line>".
void throwCudaError(cudaError_t status, const char* call, const char* file, int line);

}  // namespace cuda
}  // namespace thin_ice

#define TIS_CUDA_CHECK(call)                                                        \
  do {                                                                              \
    const cudaError_t tis_cuda_status_ = (call);                                    \
    if (tis_cuda_status_ != cudaSuccess) {                                          \
      ::thin_ice::cuda::throwCudaError(tis_cuda_status_, #call, __FILE__, __LINE__); \
    }                                                                               \
  } while (0)
