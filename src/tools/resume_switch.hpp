// Which overrides `thin_ice run --resume DIR --set ...` may switch on under a run that is under way,
// and the refusals of values that run cannot take (an unstable step, a bottom raised through its ice).
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "thin_ice_sim/ice_sheet.hpp"
#include "thin_ice_sim/model.hpp"
#include "thin_ice_sim/scenario.hpp"
#include "thin_ice_sim/simulation.hpp"

namespace thin_ice_tools {

/// Why --resume cannot take the override `set` ("" when it can: the registry of keys marks its key
/// switchable, thin_ice::switchableOnResume).
/// Throws ScenarioError (naming `scenario_file`) for text that names no key of the format.
inline std::string whyNotSwitchable(const std::string& set, const std::string& scenario_file) {
  const std::string key = thin_ice::overrideKey(set, scenario_file);
  if (thin_ice::switchableOnResume(key)) return "";
  std::string allowed;
  for (const std::string& k : thin_ice::switchableOnResumeKeys()) allowed += (allowed.empty() ? "" : " ") + k;
  return "--set '" + set + "' with --resume: " + key + " cannot change under a run that is under way "
         "(its checkpoint, rows or statistics are tied to it); allowed there: " + allowed;
}

/// Why the resumed simulation `sim` cannot take the false bottom's depth that `sets` switch to ("" when
/// it can, or when none of them names bottom.depth). A bottom moved up through ice already below it
/// would start the segment with cells deep inside a penalty plane, and one that is not there
/// (bottom.enabled false) would take the switch without effect. The cells counted are those the
/// bottom acts on (physics/cell_forces.hpp: a polygon reaching past where it starts) whose slab
/// bottom z - h/2 [m] lies below the new plane by more than 1e-3 h: ice resting on the bottom sinks
/// into its penalty plane by far less, so the run's own depth is always taken.
inline std::string whyBottomCutsIce(const thin_ice::Simulation& sim, const std::vector<std::string>& sets,
                                    const std::string& scenario_file) {
  std::string depth_set;
  for (const std::string& set : sets) {
    if (thin_ice::overrideKey(set, scenario_file) == "bottom.depth") depth_set = set;
  }
  if (depth_set.empty()) return "";
  const thin_ice::Params& p = sim.params();
  if (!p.bottom.enabled) {
    return "--set '" + depth_set + "' with --resume: the run has no false bottom (bottom.enabled: false), so its "
           "depth would change nothing; allowed: bottom.depth only where bottom.enabled is true";
  }
  const double bottom_z = sim.scene().bottom_z;               // [m]
  const double bottom_x_start = sim.scene().bottom_x_start;   // [m]
  const double half_h = 0.5 * p.ice.thickness;                                           // [m]
  const double resting = 1e-3 * p.ice.thickness;  // [m] deeper than ice resting on the bottom sinks
  long below = 0;
  double deepest = bottom_z;  // [m] the lowest slab bottom found over the bottom
  const std::vector<thin_ice::CellSnapshot> cells = sim.cells();
  for (int k = 0; k < static_cast<int>(cells.size()); ++k) {
    double reach = -1e300;  // [m] the polygon's largest x
    for (const thin_ice::Vec2& v : sim.cellPolygon(k, cells[k])) reach = std::max(reach, v.x);
    if (!(reach > bottom_x_start)) continue;
    const double slab_bottom = cells[k].z - half_h;
    if (slab_bottom < bottom_z - resting) {
      ++below;
      deepest = std::min(deepest, slab_bottom);
    }
  }
  if (below == 0) return "";
  // The least depth allowed, rounded up to 0.1 mm so that the value printed is taken as it reads.
  const double least = std::ceil(-deepest * 1e4) * 1e-4;  // [m]
  std::ostringstream msg;
  msg << "--set '" << depth_set << "' with --resume: " << below << " cells over the false bottom already reach "
      << "below z = " << bottom_z << " m (the lowest slab bottom at z = " << deepest << " m); a bottom may move "
      << "down under a run, not up through the ice over it; allowed: bottom.depth >= " << least << " m";
  return msg.str();
}

/// Whether the model of `scenario` can be built (its time step and structure sub-step stable,
/// among the model's other checks).
inline bool modelBuilds(const thin_ice::Scenario& scenario) {
  try {
    thin_ice::buildModel(scenario.params, thin_ice::generateIceSheet(scenario.params.sheet), scenario.source);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

/// What made a resumed run's model refuse its scenario, and the scenario to reckon the refusal on:
/// the switches given with --resume, or, where the run's scenario as it reads now is refused
/// without them (its file changed under --accept-changed-scenario, or no switch was given), that
/// scenario alone, so that the figures of the refusal are the file's.
struct RefusedScenario {
  const thin_ice::Scenario* scenario;
  std::string cause;  ///< the words naming it, for the head of the refusal
};
inline RefusedScenario whatWasRefused(const thin_ice::Scenario& unswitched, const thin_ice::Scenario& switched,
                                      const std::vector<std::string>& sets) {
  if (sets.empty() || !modelBuilds(unswitched)) {
    return {&unswitched, "the run's scenario as it reads now (" + unswitched.source +
                             (unswitched.overrides.empty() ? "" : ", with the run's own overrides") + ")"};
  }
  std::string given;
  for (const std::string& set : sets) given += (given.empty() ? "'" : ", '") + set + "'";
  return {&switched, "--set " + given};
}

/// The refusal of the resumption of the run in `dir` when the model of `refused` cannot hold the
/// run's time step (or its structure sub-step); "" when its refusal is about something else (the
/// caller then passes the model's own message on). The model's own message offers a smaller
/// numerics.time_step or more sub-steps, which a run under way cannot take. This one gives the
/// stable step now, against the run's, and how much softer the stiffest spring would have to be (a
/// spring's critical step goes as 1/sqrt(stiffness)).
inline std::string whyTheStepCannotHold(const RefusedScenario& refused, const std::string& dir) {
  const thin_ice::Scenario& scenario = *refused.scenario;
  const std::string head = refused.cause + " with --resume " + dir + ": ";
  const std::string keeps = "a run under way keeps its numerics.time_step and numerics.structure_substeps (its "
                            "rows count steps from t = 0)";
  const thin_ice::NumericsParams& n = scenario.params.numerics;
  thin_ice::Params unchecked = scenario.params;
  unchecked.numerics.critical_step_safety = 1e300;  // only to read the critical steps off the model
  double critical = 0.0, structure_critical = 0.0;  // [s]
  try {
    const thin_ice::Model model =
        thin_ice::buildModel(unchecked, thin_ice::generateIceSheet(unchecked.sheet), scenario.source);
    critical = model.critical_time_step;
    structure_critical = model.structure_critical_time_step;
  } catch (const std::exception&) {
    return "";  // refused without the time-step check as well: not the time step
  }
  // The binding one: dt against the ice's springs, or dt/n against the structure's too.
  const double step = n.time_step, substep = n.time_step / n.structure_substeps;      // [s]
  const double stable = n.critical_step_safety * critical;                            // [s]
  const double stable_substep = n.critical_step_safety * structure_critical;          // [s]
  const bool ice_binds = stable / step <= stable_substep / substep;
  const double ratio = ice_binds ? stable / step : stable_substep / substep;          // < 1 when refused
  if (!(ratio < 1.0)) return "";  // the step holds: the refusal was about something else
  std::ostringstream msg;
  msg.precision(3);
  msg << head << "with it the stable " << (ice_binds ? "time step" : "structure sub-step") << " (critical_step_safety "
      << n.critical_step_safety << " x the critical step " << (ice_binds ? critical : structure_critical)
      << " s of the stiffest spring" << (ice_binds ? "" : ", the structure's included") << ") is "
      << (ice_binds ? stable : stable_substep) << " s, under the run's " << (ice_binds ? step : substep) << " s, and "
      << keeps << "; allowed: values under which that spring has at most " << ratio * ratio
      << " of the stiffness these give it (a critical step goes as 1/sqrt(stiffness)), or a new run with these values";
  return msg.str();
}

}  // namespace thin_ice_tools
