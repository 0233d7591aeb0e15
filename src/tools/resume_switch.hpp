// Which overrides thin_ice_run --resume DIR --set ... may switch on under a run that is under way.
#pragma once

#include <set>
#include <string>

#include "thin_ice_sim/scenario.hpp"

namespace thin_ice_tools {

/// The keys --set may switch at a resumption: the laws of the ice, the water and the rigid planes
/// (stiffness, friction), the friction's regularisation, and the thread count; a value that makes
/// the time step unstable is refused as for a fresh run. Not the mesh, the masses or the floating
/// level (thickness, densities), the geometry, the pusher's speed (the checkpoint holds it), the
/// time stepping (the rows are counted in steps from t = 0), or the calibration factor and the
/// structure's width (the statistics of the whole history use them).
inline const std::set<std::string> kSwitchableKeys = {
    "ice.flexural_strength", "ice.compressive_strength", "ice.youngs_modulus", "ice.vertical_modulus",
    "ice.poisson_ratio", "ice.smoothing_exponent_h", "ice.smoothing_exponent_v", "ice.compression_coupling",
    "ice.vertical_stress", "ice.curvature_failure", "ice.curvature_failure_scope", "ice.plate_bending",
    "ice.vertical_slip_friction", "ice.friction_ice_ice", "ice.contact_damping_ratio", "ice.bond_damping_ratio",
    "water.linear_drag", "water.quadratic_drag", "water.vertical_linear_drag", "water.vertical_quadratic_drag",
    "structure.friction", "structure.stiffness", "channel.friction", "channel.stiffness", "bottom.friction",
    "bottom.stiffness", "pusher.friction", "pusher.stiffness", "numerics.friction_regularisation",
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

}  // namespace thin_ice_tools
