// Regularised Coulomb friction shared by every contact law: a force opposing the slip velocity
// with magnitude mu N once the slip is faster than v_reg, and viscous (proportional) below, so
// that it needs no per-contact history; the viscous branch is bounded so that an explicit step
// never reverses the slip.
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/host_device.hpp"
#include "thin_ice_sim/physics/scalar.hpp"

namespace thin_ice {

/// Scale s such that the friction force is -s * slip (slip is 3-D, components given).
/// normal_force >= 0 [N], regularisation speed > 0 [m/s], max_scale > 0 [N s/m]: the viscous
/// branch mu N / v_reg is bounded by max_scale (= beta m_eff / dt from the caller), because an
/// explicit step of a viscous force c v is only stable for c dt / m_eff < 2.
TIS_HD double frictionScale(double mu, double normal_force, double slip_x, double slip_y,
                            double slip_z, double regularisation_speed, double max_scale) {
  const double speed = sqrt(slip_x * slip_x + slip_y * slip_y + slip_z * slip_z);
  return minOf(mu * normal_force / maxOf(speed, regularisation_speed), max_scale);
}

}  // namespace thin_ice
