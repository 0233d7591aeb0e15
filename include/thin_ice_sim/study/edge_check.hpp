// The edge-load check (docs/model.md, "RMIB bonds"): how much vertical line load a free edge of the
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
  double last_intact = 0.0; ///< [m] the largest dz found at which it still holds (just below offset)
  bool by_stress = false;   ///< Eq. (13) met (true), or torn through at |dz| = h (false)
};

/// Sweeps dz from 0 to h in `samples` steps through rmibBondForce; the failure offset is then
/// bisected, so that a bond that fails within the first step is not under-read.
BondVerticalCapacity bondVerticalCapacity(const BondRest& rest, const BondConstants& constants, int samples = 4000);

/// The bond law (rmibBondForce, Eqs. 11-13) for the bond at a pure vertical offset dz [m] of its
/// two cells: no horizontal strain, both at rest and unturned.
BondForce bondUnderOffset(const BondRest& rest, const BondConstants& constants, double dz);

/// |F_v| [N] of the bond at a pure vertical offset dz [m] (bondUnderOffset); `breaks` says whether
/// Eq. (13) or the tear-through is met there.
double bondVerticalForce(const BondRest& rest, const BondConstants& constants, double dz, bool& breaks);

/// The largest sigma_v of Eq. (13) that the bond law gives under a vertical offset alone,
/// 0 < dz < h: the smoothing K_v of Eq. (6) falls as the offset grows, so for n > 0 sigma_v has a
/// top inside the range. The top is the law's, whether or not the bond would hold to it: above
/// sigma_f it breaks on the way (bondVerticalCapacity says where).
struct LargestVerticalStress {
  double stress = 0.0;  ///< [Pa] sigma_v at its top
  double offset = 0.0;  ///< [m] dz there
};
/// Sampled at `samples` offsets through bondUnderOffset, then refined by golden-section search
/// about the best sample (sigma_v ~ u (1 - u)^n rises and falls once).
LargestVerticalStress largestVerticalStress(const BondRest& rest, const BondConstants& constants, int samples = 4000);

/// Index of the model's bond whose centroid distance d is nearest `distance` [m] (the lowest index
/// among equals); -1 where the model has no bond.
int bondNearestLength(const Model& model, double distance);

/// The floating semi-infinite plate: the characteristic length
/// l = [E h^3 / (12 (1 - nu^2) rho_w g)]^(1/4) [m] and the edge line load at first failure
/// P_crit = sigma_f h^2 / (6 e^(-pi/4) l) [N/m]: the largest moment under an edge load P is
/// e^(-pi/4) P l, 1.11 l from the edge. For nu = 0.3 this is the rounded
/// 0.665 sigma_f (rho_w g h^5 / E)^(1/4) (0.6645); written through l it holds for any nu.
struct FloatingPlateEdge {
  double characteristic_length = 0.0;  ///< l [m]
  double critical_line_load = 0.0;     ///< P_crit [N/m]
};
FloatingPlateEdge floatingPlateEdge(const IceParams& ice, const WaterParams& water);

/// A straight cut across the sheet, parallel to its front edge (x = x_min + length): the bonds
/// whose cells lie on both sides carry all of a vertical line load applied beyond it. The part in
/// front is taken as a rigid strip pushed down by a growing offset dz, the same for every bond;
/// a bond that failed at a smaller offset carries nothing. The largest total force, over the
/// width, is the line load at which the cut fails. The bending stress of a bond at a given offset
/// does not depend on its length d, so its bonds peak at the same offset and the cut carries the
/// sum of their peaks, unless some break by tension or tear through first.
struct EdgeCutCapacity {
  double distance_from_edge = 0.0;  ///< [m]
  int bonds = 0;                    ///< bonds crossing the cut
  int failing_by_stress = 0;        ///< of those, how many fail by Eq. (13) before tearing through
  double line_load = 0.0;           ///< [N/m] the rigid strip's largest total force / sheet width
  double sum_of_peaks = 0.0;        ///< [N/m] sum of each bond's own peak / width (an upper bound)
};

/// Cuts at 1, 2, ..., `cuts` cell sizes from the front edge.
std::vector<EdgeCutCapacity> edgeCutCapacities(const Model& model, const IceSheet& sheet, int cuts);

}  // namespace thin_ice
