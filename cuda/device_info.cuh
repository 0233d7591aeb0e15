// Plain C++ view of the CUDA devices: safe to include from host-only code.
#pragma once

#include <string>

namespace thin_ice {
namespace cuda {

/// Number of usable CUDA devices; 0 when there is no GPU or no driver (with the static runtime
/// and no GPU, cudaGetDeviceCount returns an error: that counts as zero devices).
int deviceCount();

/// "NAME (compute capability X.Y, N GiB)" of device 0, or an empty string without one.
std::string deviceDescription();

/// Bytes in use on device 0 (cudaMemGetInfo: total minus free); 0 without a device.
double deviceMemoryInUse();

}  // namespace cuda
}  // namespace thin_ice
