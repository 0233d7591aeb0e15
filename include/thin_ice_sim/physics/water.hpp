// Gravity, buoyancy and water drag on one cell (docs/model.md "Water, bottom, walls"; the paper's
// damping matrix [C] of Eq. (16)). Water level at z = 0, z up; a cell spans z - h/2 .. z + h/2.
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/host_device.hpp"
#include "thin_ice_sim/physics/vec2.hpp"

namespace thin_ice {

struct WaterConstants {
  double water_density;          ///< rho_w [kg/m^3]
  double gravity;                ///< g [m/s^2]
  double thickness;              ///< h [m]
  double linear_drag;            ///< horizontal, per wetted area [N s/m^3]
  double quadratic_drag;         ///< horizontal coefficient [-] (force 0.5 rho_w C A |v| v)
  double vertical_linear_drag;   ///< [N s/m^3]
  double vertical_quadratic_drag;///< [-]
};

/// Part of the thickness below the waterline [m], in [0, h].
TIS_HD double submergedThickness(double z, double h) {
  const double below = 0.5 * h - z;
  return below <= 0.0 ? 0.0 : (below >= h ? h : below);
}

/// Height [m] of the centroid of a cell floating at rest: its draft is rho_i / rho_w h, so the
/// centroid sits at h/2 - draft (z = 0 at the waterline).
TIS_HD double floatingCentroidHeight(double thickness, double ice_density, double water_density) {
  return 0.5 * thickness - ice_density / water_density * thickness;
}

struct WaterForce {
  Vec2 horizontal;  ///< [N]
  double vertical;  ///< [N], gravity + buoyancy + heave drag
  double torque;    ///< [N m] about z, yaw drag
};

/// Gravity m g, buoyancy rho_w g A (submerged thickness), and linear-plus-quadratic drag on the
/// wetted part: horizontal on the area A, vertical on A, yaw on the polar moment J.
TIS_HD WaterForce waterForce(const WaterConstants& w, double mass, double area, double polar_moment,
                             double z, Vec2 velocity, double vz, double wz) {
  const double wet_fraction = submergedThickness(z, w.thickness) / w.thickness;
  WaterForce f;
  const double speed = norm(velocity);
  const double horizontal_coefficient =
      wet_fraction * area * (w.linear_drag + 0.5 * w.water_density * w.quadratic_drag * speed);
  f.horizontal = -horizontal_coefficient * velocity;
  const double heave_coefficient =
      wet_fraction * area *
      (w.vertical_linear_drag + 0.5 * w.water_density * w.vertical_quadratic_drag * fabs(vz));
  f.vertical = w.water_density * w.gravity * area * submergedThickness(z, w.thickness) -
               mass * w.gravity - heave_coefficient * vz;
  f.torque = -wet_fraction * w.linear_drag * polar_moment * wz;
  return f;
}

}  // namespace thin_ice
