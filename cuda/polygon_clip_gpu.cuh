// Batched convex polygon intersection on the GPU: the kernel calls the same inline
// intersectConvexPolygons() as the CPU (include/thin_ice_sim/physics/polygon_clip.hpp).
// Plain C++ interface: the host compiler never sees CUDA syntax.
#pragma once

#include <vector>

#include "thin_ice_sim/physics/polygon_clip.hpp"

namespace thin_ice {
namespace cuda {

/// A polygon with at most kMaxPolygonVertices vertices, in a fixed-size record for the device.
struct PackedPolygon {
  Vec2 vertices[kMaxPolygonVertices];
  int count;
};

/// overlaps[k] = intersectConvexPolygons(first[k], second[k]) computed on device 0.
/// Throws std::invalid_argument when the sizes differ, std::runtime_error on a CUDA error.
std::vector<PolygonOverlap> intersectPolygonPairs(const std::vector<PackedPolygon>& first,
                                                  const std::vector<PackedPolygon>& second);

}  // namespace cuda
}  // namespace thin_ice
