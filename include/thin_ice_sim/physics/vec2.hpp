// A plain 2-D vector for the host/device physics (no Eigen inside kernels: Eigen under nvcc needs
// extra flags and brings nothing to 2-D arithmetic).
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/host_device.hpp"

namespace thin_ice {

struct Vec2 {
  double x;
  double y;
};

TIS_HD Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
TIS_HD Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
TIS_HD Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
TIS_HD Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
TIS_HD Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
TIS_HD double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// z-component of the 3-D cross product (a, 0) x (b, 0).
TIS_HD double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
TIS_HD double norm(Vec2 a) { return sqrt(a.x * a.x + a.y * a.y); }
/// a turned by +90 degrees about z.
TIS_HD Vec2 perpendicular(Vec2 a) { return {-a.y, a.x}; }
/// a turned by the angle whose cosine and sine are given (yaw about +z, counter-clockwise).
TIS_HD Vec2 rotate(Vec2 a, double cos_yaw, double sin_yaw) {
  return {cos_yaw * a.x - sin_yaw * a.y, sin_yaw * a.x + cos_yaw * a.y};
}

}  // namespace thin_ice
