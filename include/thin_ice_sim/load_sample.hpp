// What a simulation gives out: the loads on the structure (Eqs. 17-18) and the cells as seen from
// outside. Below the backends, which fill them, and the Simulation facade, which hands them out;
// the one place where alpha of Eq. (18) multiplies a load.
#pragma once

#include <cstddef>
#include <vector>

namespace thin_ice {

/// A torque [N m].
struct Torque3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

/// Loads on the structure at one instant (the output of the model, Eqs. 17-18).
struct LoadSample {
  double time = 0.0;                   ///< [s] simulated time
  double pushed_length = 0.0;          ///< [m] distance the pusher has moved
  double horizontal_raw = 0.0;         ///< F of Eq. (17) [N], +x (ice pushing the structure)
  double horizontal_calibrated = 0.0;  ///< F_cal = alpha F, Eq. (18) [N]
  double vertical_raw = 0.0;           ///< [N], +z
  double lateral_raw = 0.0;            ///< [N], +y
  std::vector<double> panel_horizontal;  ///< (panels) raw x-load per panel [N]
  std::vector<double> panel_vertical;    ///< (panels) raw z-load per panel [N]
  std::vector<double> panel_lateral;     ///< (panels) raw y-load per panel [N]
  Torque3 torque;                        ///< raw, about the structure frame's origin (the toe on
                                         ///< the waterline at y = 0) [N m]
  std::vector<Torque3> panel_torque;     ///< (panels) raw, about each panel's centre on the waterline
  double pusher_force = 0.0;           ///< [N] force the pusher exerts on the ice, +x
  int intact_bonds = 0;
  int broken_bonds = 0;
  int contacts = 0;                    ///< DEM contacts whose slabs touch (S > 0 and Z > 0) in the last step
};

/// One cell as the node and the runner see it.
struct CellSnapshot {
  double x, y, z, yaw;     ///< [m], [m], [m], [rad]
  double vx, vy, vz, wz;   ///< [m/s], [rad/s]
  bool in_intact_sheet;    ///< still bonded to at least one neighbour
  int piece_cells;         ///< cells in the piece held together by intact bonds that this cell
                           ///< belongs to: 1 for a free block; the pushed sheet is the largest
};

/// F_cal = alpha F, Eq. (18): alpha [-] multiplies a raw load [N] or torque [N m] here and nowhere
/// else, so that every reported load (the runner's F_cal, the node's wrenches and markers) is the
/// same product.
inline double calibrated(double raw, double alpha) { return alpha * raw; }

/// Turns loads summed over `steps` time steps into their mean, the LoadSample of those steps:
/// every raw component times 1/steps (zeros when none was taken), and F_cal of Eq. (18) from the
/// mean F. Both backends finish a sample here; the caller sets time, length, bonds and contacts.
inline void averageSummedLoads(LoadSample& sum, long steps, double alpha) {
  const double inv = steps > 0 ? 1.0 / static_cast<double>(steps) : 0.0;
  auto mean = [inv](double& v) { v *= inv; };
  auto meanTorque = [&](Torque3& t) { mean(t.x); mean(t.y); mean(t.z); };
  mean(sum.horizontal_raw);
  mean(sum.vertical_raw);
  mean(sum.lateral_raw);
  mean(sum.pusher_force);
  meanTorque(sum.torque);
  for (double& v : sum.panel_horizontal) mean(v);
  for (double& v : sum.panel_vertical) mean(v);
  for (double& v : sum.panel_lateral) mean(v);
  for (Torque3& t : sum.panel_torque) meanTorque(t);
  sum.horizontal_calibrated = calibrated(sum.horizontal_raw, alpha);
}

/// A force [N] and a torque [N m] with alpha of Eq. (18) applied to every component.
struct CalibratedWrench {
  double fx = 0.0, fy = 0.0, fz = 0.0;
  Torque3 torque;
};

/// The whole structure's load as F_cal: (x, y, z) = (horizontal, lateral, vertical), about the
/// structure frame's origin.
inline CalibratedWrench calibratedTotal(const LoadSample& l, double alpha) {
  return {calibrated(l.horizontal_raw, alpha), calibrated(l.lateral_raw, alpha), calibrated(l.vertical_raw, alpha),
          {calibrated(l.torque.x, alpha), calibrated(l.torque.y, alpha), calibrated(l.torque.z, alpha)}};
}

/// Panel `p`'s load as F_cal, about the panel's centre on the waterline.
inline CalibratedWrench calibratedPanel(const LoadSample& l, int p, double alpha) {
  const Torque3& t = l.panel_torque[static_cast<std::size_t>(p)];
  return {calibrated(l.panel_horizontal[static_cast<std::size_t>(p)], alpha),
          calibrated(l.panel_lateral[static_cast<std::size_t>(p)], alpha),
          calibrated(l.panel_vertical[static_cast<std::size_t>(p)], alpha),
          {calibrated(t.x, alpha), calibrated(t.y, alpha), calibrated(t.z, alpha)}};
}

}  // namespace thin_ice
