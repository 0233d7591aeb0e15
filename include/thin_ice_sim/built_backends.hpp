// Registers the backends this build has with Simulation. Called once at the top of main() by
// every program (node, runner, benchmarks, tests): the CPU backend is always there; the CUDA one
// only when the program links thin_ice_cuda, which defines THIN_ICE_HAVE_CUDA for it. The core
// library itself never includes this header, so it stays free of CUDA.
#pragma once

#ifdef THIN_ICE_HAVE_CUDA
#include "cuda_backend.hpp"
#endif

namespace thin_ice {

inline void registerBuiltBackends() {
#ifdef THIN_ICE_HAVE_CUDA
  cuda::registerCudaBackend();
#endif
}

}  // namespace thin_ice
