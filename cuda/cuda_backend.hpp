// The CUDA backend of Simulation (cuda_backend.cu). Plain C++: the host compiler never sees CUDA.
#pragma once

namespace thin_ice {
namespace cuda {

/// Makes backend 'cuda' (and 'auto' on a machine with a GPU) available to Simulation.
void registerCudaBackend();

}  // namespace cuda
}  // namespace thin_ice
