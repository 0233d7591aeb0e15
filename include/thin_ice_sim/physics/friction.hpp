// Regularised Coulomb friction shared by every contact law: a force opposing the slip velocity
// with magnitude mu N once the slip is faster than v_reg, and viscous (proportional) below, so
// that it never reverses sign within a step and needs no per-contact history.
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/host_device.hpp"

namespace thin_ice {

/// Scale s such that the friction force is -s * slip (slip is 3-D, components given).
/// normal_force >= 0 [N], regularisation speed > 0 [m/s].
TIS_HD double frictionScale(double mu, double normal_force, double slip_x, double slip_y,
                            double slip_z, double regularisation_speed) {
  const double speed = sqrt(slip_x * slip_x + slip_y * slip_y + slip_z * slip_z);
  return mu * normal_force / fmax(speed, regularisation_speed);
}

}  // namespace thin_ice
