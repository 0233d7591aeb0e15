// Scenario files: commented YAML (config/scenarios/*.yaml) read once, validated, and turned into
// the core's Params. Configuration lives at the edges; the engine never sees YAML.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "thin_ice_sim/params.hpp"

namespace thin_ice {

/// A scenario that cannot be loaded. what() is one line: "FILE: KEY: what is wrong; allowed: ...".
class ScenarioError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Scenario {
  std::string name;         ///< file stem, e.g. "M-2"
  std::string source;       ///< path the scenario was read from ("" when built in code)
  Params params;
  std::vector<std::string> overrides;  ///< "section.key=value" applied after the file
  std::string hash;         ///< 16 hex digits of a hash of the file's text (its bases' first) and the overrides
};

/// Reads `path` (after the file its top-level `base` key names, a path relative to its folder,
/// read the same way: the file's keys override its base's), applies `overrides`
/// ("section.key=value", as the runner's --set), validates
/// every value, and returns the scenario. Throws ScenarioError naming the file, the key, the
/// value and what is allowed on: unknown section or key, missing required key, wrong type,
/// non-physical value (h <= 0, nu outside [0, 0.5), negative density, cell size below the
/// thickness, ...). Nothing is simulated or written when it throws.
Scenario loadScenario(const std::string& path, const std::vector<std::string>& overrides = {});

/// The key an override sets, as "section.key" with the spaces the parser ignores removed
/// (" ice . friction_ice_ice = 0.4" gives "ice.friction_ice_ice"). Throws ScenarioError, prefixed with
/// `source`, for text that is not section.key=value or names no key of the scenario format.
std::string overrideKey(const std::string& text, const std::string& source);

/// Whether `key` ("section.key") may change at a resumption of a run under way (`thin_ice run
/// --resume DIR --set`): the laws and the contact planes' stiffness and friction may, the mesh, the
/// geometry, the time stepping and the calibration may not. The registry of keys marks them.
bool switchableOnResume(const std::string& key);

/// Every key switchableOnResume allows, in the order of the scenario format.
std::vector<std::string> switchableOnResumeKeys();

/// One key of the scenario format and its value in a parameter set.
struct ParameterValue {
  std::string key;    ///< "section.key"
  std::string value;  ///< as the loader reads it back to the same bits ("0.052", "true", "jittered_grid")
};

/// Every key of the scenario format with its value in `params`, in the order of the format: the
/// whole parameter set of a run, which "section.key=value" overrides give back bit for bit.
std::vector<ParameterValue> scenarioParameters(const Params& params);

/// Checks the physical and numerical ranges of `params` (everything that can be checked without
/// building the sheet); `source` prefixes the message. Throws ScenarioError.
void validateParams(const Params& params, const std::string& source);

}  // namespace thin_ice
