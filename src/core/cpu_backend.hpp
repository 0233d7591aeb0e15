// The CPU backend: the laws of include/thin_ice_sim/physics/ in OpenMP loops.
#pragma once

#include <memory>

#include "thin_ice_sim/backend.hpp"

namespace thin_ice {

std::unique_ptr<Backend> makeCpuBackend(const Model& model, int threads);

}  // namespace thin_ice
