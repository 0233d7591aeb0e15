// Minimum and maximum of two doubles for the hot loops. fmin/fmax are library calls on x86-64
// (their NaN rules keep the compiler from using minsd/maxsd); these are single instructions.
// They agree with fmin/fmax for every finite argument; a NaN state is caught by the blow-up check
// of the per-cell step, not here.
#pragma once

#include "thin_ice_sim/physics/host_device.hpp"

namespace thin_ice {

TIS_HD double minOf(double a, double b) { return b < a ? b : a; }
TIS_HD double maxOf(double a, double b) { return b > a ? b : a; }

}  // namespace thin_ice
