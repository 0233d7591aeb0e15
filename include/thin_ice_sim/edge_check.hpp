// The edge-load check of SPEC-NOTES ("RMIB bonds"): how much vertical line load a free edge of the
// model's sheet carries before a bond fails, beside the floating-plate theory it should approach.
// Quasi-static: each bond's capacity comes from sweeping a pure vertical offset dz through the
// bond law itself (rmibBondForce, Eqs. 11-13), with no horizontal strain and no motion.
#pragma once

#include <vector>

#include "thin_ice_sim/ice_sheet.hpp"
#include "thin_ice_sim/model.hpp"

namespace thin_ice {

/// What one bond carries under a growing vertical offset of its two cells.
struct BondVerticalCapacity {
  double force = 0.0;       ///< [N] largest |F_v| before the bond fails
  double offset = 0.0;      ///< [m] dz at which it fails
  bool by_stress = false;   ///< Eq. (13) met (true), or torn through at |dz| = h (false)
};

/// Sweeps dz from 0 to h in `samples` steps through rmibBondForce.
BondVerticalCapacity bondVerticalCapacity(const BondRest& rest, const BondConstants& constants, int samples = 4000);

/// The floating semi-infinite plate of SPEC-NOTES: the characteristic length
/// l = [E h^3 / (12 (1 - nu^2) rho_w g)]^(1/4) [m] and the edge line load at first failure
/// P_crit = 0.665 sigma_f (rho_w g h^5 / E)^(1/4) [N/m] (the break about 1.1 l from the edge).
struct FloatingPlateEdge {
  double characteristic_length = 0.0;  ///< l [m]
  double critical_line_load = 0.0;     ///< P_crit [N/m]
};
FloatingPlateEdge floatingPlateEdge(const IceParams& ice, const WaterParams& water);

/// A straight cut across the sheet, parallel to its front edge (x = x_min + length): the bonds
/// whose cells lie on both sides carry all of a vertical line load applied beyond it, so the sum
/// of their capacities over the sheet width is the line load at which the cut fails.
struct EdgeCutCapacity {
  double distance_from_edge = 0.0;  ///< [m]
  int bonds = 0;                    ///< bonds crossing the cut
  int failing_by_stress = 0;        ///< of those, how many fail by Eq. (13) before tearing through
  double line_load = 0.0;           ///< [N/m] sum of the bonds' capacities / sheet width
};

/// Cuts at 1, 2, ..., `cuts` cell sizes from the front edge.
std::vector<EdgeCutCapacity> edgeCutCapacities(const Model& model, const IceSheet& sheet, int cuts);

}  // namespace thin_ice
