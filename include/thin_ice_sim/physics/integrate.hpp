// Time integration, paper Eqs. (14)-(15): symplectic (semi-implicit) Euler,
//   v(t + dt) = v(t) + F/m dt,   u(t + dt) = u(t) + v(t + dt) dt,
// for the three translations and the yaw (omega += tau / I dt, theta += omega dt).
#pragma once

#include "thin_ice_sim/physics/host_device.hpp"

namespace thin_ice {

struct CellMotion {
  double x, y, z, yaw;     ///< [m], [rad]
  double vx, vy, vz, wz;   ///< [m/s], [rad/s]
};

TIS_HD void integrateSymplecticEuler(CellMotion& c, double fx, double fy, double fz, double torque,
                                     double inverse_mass, double inverse_inertia, double dt) {
  c.vx += fx * inverse_mass * dt;
  c.vy += fy * inverse_mass * dt;
  c.vz += fz * inverse_mass * dt;
  c.wz += torque * inverse_inertia * dt;
  c.x += c.vx * dt;
  c.y += c.vy * dt;
  c.z += c.vz * dt;
  c.yaw += c.wz * dt;
}

}  // namespace thin_ice
