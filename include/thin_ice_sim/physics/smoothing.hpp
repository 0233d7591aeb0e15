// Smoothing functions of the vertical offset, paper Eqs. (5)-(7):
//   K_n(z) = (1 - z)^n * Theta(1 - z),  z = |z_j - z_i| / h,  K(0) = 1, K(z >= 1) = 0.
// n = 2 (weak), 1 (medium), 1/2 (strong), Table 1; the values of Table 2 are a unit test.
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/host_device.hpp"

namespace thin_ice {

/// K_n(z) of Eq. (6) for the normalised offset z = |dz| / h >= 0 and exponent n > 0.
TIS_HD double smoothing(double normalised_offset, double exponent) {
  const double remaining = 1.0 - normalised_offset;
  if (!(remaining > 0.0)) return 0.0;  // Theta(1 - z); also catches NaN
  if (remaining >= 1.0) return 1.0;
  // The three exponents of Table 1 without pow() (hot loop).
  if (exponent == 1.0) return remaining;
  if (exponent == 2.0) return remaining * remaining;
  if (exponent == 0.5) return sqrt(remaining);
  return pow(remaining, exponent);
}

}  // namespace thin_ice
