// Vertical force balance of the sheet's front row in a run (docs/journal/calibration.md, "Where
// the rest of the vertical load goes"): what holds the front row down while the structure lifts
// it, from the cell poses of a snapshot, through the model's own laws (no velocities: the elastic
// and static parts only).
//   bonds across the cut: the vertical force of every bond from a front-row cell to a cell behind
//                         it, rmibBondForce (Eq. 12, K_v of Eq. 6), as if the bond were intact;
//   lost buoyancy:        waterForce at the cell's rest height minus at its present height, summed
//                         over the front row: its whole weight once it is out of the water.
// The structure's vertical load on the ice should be about their sum; the rest is bond damping,
// heave drag and inertia.
#pragma once

#include <vector>

#include "thin_ice_sim/ice_sheet.hpp"
#include "thin_ice_sim/model.hpp"

namespace thin_ice {

/// The cells that touch the sheet's front edge (x = x_min + length) at rest, and the bonds that
/// tie them to the cells behind.
struct FrontRow {
  std::vector<int> cells;       ///< front-row cells
  std::vector<int> rear_cells;  ///< the cells behind that share a bond with the front row
  std::vector<int> cut_bonds;   ///< bonds with one cell in the front row and one behind it
  double area = 0.0;            ///< [m^2] of the front row
  double weight = 0.0;          ///< [N] of the front row, sum of m g
};
FrontRow frontRow(const Model& model, const IceSheet& sheet);

/// Pose of one cell in a snapshot.
struct CellPose {
  double x = 0.0, y = 0.0, z = 0.0;  ///< [m]
  double yaw = 0.0;                  ///< [rad]
};

struct FrontRowBalance {
  double bond_force = 0.0;     ///< [N] downward pull of the cut bonds on the front row (Eq. 12)
  double lost_buoyancy = 0.0;  ///< [N] buoyancy the front row lost against rest (Eq. 16's buoyancy)
  double front_lift = 0.0;     ///< [m] mean height of the front row above its rest height
  double rear_lift = 0.0;      ///< [m] likewise for the rear cells
};

/// The balance for one snapshot; `poses` has one entry per cell of the model (std::invalid_argument
/// otherwise).
FrontRowBalance frontRowBalance(const Model& model, const FrontRow& row, const std::vector<CellPose>& poses);

}  // namespace thin_ice
