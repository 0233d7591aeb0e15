// Which overrides thin_ice_run --resume DIR --set ... may switch on under a run that is under way.
#pragma once

#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "thin_ice_sim/scenario.hpp"
#include "thin_ice_sim/simulation.hpp"

namespace thin_ice_tools {

/// The keys --set may switch at a resumption: the laws of the ice, the water and the rigid planes
/// (stiffness, friction), the friction's regularisation, the thread count, and the depth of the
/// false bottom (not in the paper, so the one piece of geometry whose effect on a grown pile is
/// worth testing; a depth that would cut ice already under it is refused, whyBottomCutsIce). A
/// value that makes the time step unstable is refused as for a fresh run. Not the mesh, the masses
/// or the floating level (thickness, densities), the rest of the geometry, the pusher's speed (the
/// checkpoint holds it), the time stepping (the rows are counted in steps from t = 0), or the
/// calibration factor and the structure's width (the statistics of the whole history use them).
inline const std::set<std::string> kSwitchableKeys = {
    "ice.flexural_strength", "ice.compressive_strength", "ice.youngs_modulus", "ice.vertical_modulus",
    "ice.poisson_ratio", "ice.smoothing_exponent_h", "ice.smoothing_exponent_v", "ice.compression_coupling",
    "ice.vertical_stress", "ice.curvature_failure", "ice.curvature_failure_scope", "ice.plate_bending",
    "ice.vertical_slip_friction", "ice.friction_ice_ice", "ice.contact_damping_ratio", "ice.bond_damping_ratio",
    "water.linear_drag", "water.quadratic_drag", "water.vertical_linear_drag", "water.vertical_quadratic_drag",
    "structure.friction", "structure.stiffness", "channel.friction", "channel.stiffness", "bottom.friction",
    "bottom.stiffness", "bottom.depth", "pusher.friction", "pusher.stiffness", "numerics.friction_regularisation",
    "numerics.friction_viscous_limit", "numerics.threads"};

/// Why --resume cannot take the override `set` ("" when it can: its key is in kSwitchableKeys).
/// Throws ScenarioError (naming `scenario_file`) for text that names no key of the format.
inline std::string whyNotSwitchable(const std::string& set, const std::string& scenario_file) {
  const std::string key = thin_ice::overrideKey(set, scenario_file);
  if (kSwitchableKeys.count(key)) return "";
  std::string allowed;
  for (const std::string& k : kSwitchableKeys) allowed += (allowed.empty() ? "" : " ") + k;
  return "--set '" + set + "' with --resume: " + key + " cannot change under a run that is under way "
         "(its checkpoint, rows or statistics are tied to it); allowed there: " + allowed;
}

/// Why the resumed simulation `sim` cannot take the false bottom's depth that `sets` switch to ("" when
/// it can, or when none of them names bottom.depth): a bottom moved up through ice already below it
/// would start the segment with cells deep inside a penalty plane. Counts the cells over the bottom
/// (within one cell size of where it starts, so as not to miss one that reaches over its edge) whose
/// slab bottom z - h/2 [m] lies below the new plane.
inline std::string whyBottomCutsIce(const thin_ice::Simulation& sim, const std::vector<std::string>& sets,
                                    const std::string& scenario_file) {
  std::string depth_set;
  for (const std::string& set : sets) {
    if (thin_ice::overrideKey(set, scenario_file) == "bottom.depth") depth_set = set;
  }
  const thin_ice::Params& p = sim.params();
  if (depth_set.empty() || !p.bottom.enabled) return "";
  const double bottom_z = -p.bottom.depth;                                          // [m]
  const double reach_x = p.structure.toe_x - p.bottom.distance_from_structure - p.sheet.cell_size;  // [m]
  const double half_h = 0.5 * p.ice.thickness;                                      // [m]
  long below = 0;
  double deepest = bottom_z;  // [m] the lowest slab bottom found over the bottom
  for (const thin_ice::CellSnapshot& cell : sim.cells()) {
    if (cell.x < reach_x) continue;
    deepest = std::min(deepest, cell.z - half_h);
    if (cell.z - half_h < bottom_z) ++below;
  }
  if (below == 0) return "";
  std::ostringstream msg;
  msg << "--set '" << depth_set << "' with --resume: " << below << " cells over the false bottom already reach "
      << "below z = " << bottom_z << " m (the lowest slab bottom at z = " << deepest << " m); a bottom may move "
      << "down under a run, not up through its ice; allowed: bottom.depth >= " << -deepest << " m";
  return msg.str();
}

}  // namespace thin_ice_tools
