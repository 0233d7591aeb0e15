// The scenario loader's key table (internal to the core: src/core/scenario.cpp reads files and
// overrides through it): every key with its section, type, unit, physical range, whether it is
// required and whether a resumption may switch it, and the keys that readings of the paper once
// had and the runs rejected. One registry: the loader, the range checks, the resume policy
// (switchableOnResumeKeys) and `thin_ice parameters` (every key of a scenario as resolved, the
// list the README points to) all read it.
#pragma once

#include <yaml-cpp/yaml.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "thin_ice_sim/params.hpp"

namespace thin_ice {
namespace scenario_keys {

/// A value of the wrong type or form; `got` describes what was found.
struct BadValue : std::runtime_error {
  explicit BadValue(const std::string& got) : std::runtime_error(got) {}
};

/// Text from a file as it may be echoed in one message line: bytes outside printable ASCII as
/// \xNN, and at most 80 characters (then "...").
std::string printable(const std::string& text);

/// What a YAML node is, for a message: "nothing", "a list", "a map" or its text quoted.
std::string describe(const YAML::Node& n);

/// A numeric key's physical range [lo, hi] (either end open where the flag says so), its unit
/// for the messages, and why: the loader refuses a value outside it, naming the key, before any
/// derived quantity (a cell count, a critical time step) is worked out from it.
struct Range {
  double lo, hi;
  bool lo_open, hi_open;
  const char* unit;  ///< " m", " Pa", "" (dimensionless); for an integer key, a note after the range
  const char* why;   ///< the reason for the bounds, in a few words
};

using Setter = std::function<void(Params&, const YAML::Node&)>;
/// The value as scenario text that reads back to the same bits (doubles to 17 digits).
using Shower = std::function<std::string(const Params&)>;

struct Field {
  std::string key;
  std::string expected;  ///< "a number", "an integer", ... for the messages
  bool required = false;
  Setter set;                                ///< throws BadValue
  Shower show;                               ///< the value as the loader would read it back
  std::function<double(const Params&)> get;  ///< the value, for the range check (numbers only)
  Range range{};                             ///< unused where `get` is empty
  bool integer = false;                      ///< the range reads "integer in [lo, hi]"
  bool switchable = false;                   ///< may change at a resumption (switchableOnResume)
  /// A rule's factor (e.g. ice.vertical_modulus_floating_plate_multiple): NaN when the value it
  /// derives is given as a number instead; then it has no range to check and nothing to show.
  bool rule_factor = false;
  /// For a value a rule may derive (e.g. ice.vertical_modulus): whether it is derived in `params`
  /// (its factor is set), so that its range is checked after deriveRuleValues, not before.
  std::function<bool(const Params&)> derived;
  /// A required key is also satisfied by this other key of its section (its rule's factor).
  const char* alternative = nullptr;
};

/// Works out the values given by rules (a factor set, not NaN) from the rest of `params`: E_v
/// (ice.vertical_modulus_floating_plate_multiple) and k (ice.compression_coupling_strength_fraction).
void deriveRuleValues(Params& params);

struct Section {
  std::string name;
  std::vector<Field> fields;
};

/// Every section and its keys, in the order the docs list them.
const std::vector<Section>& sections();

/// The section called `name`; throws ScenarioError (after `where`) naming the allowed ones.
const Section& findSection(const std::string& name, const std::string& where);

/// The key of `section`; throws ScenarioError (after `where`) naming the allowed ones, or why a
/// retired key was removed.
const Field& findField(const Section& section, const std::string& key, const std::string& where);

}  // namespace scenario_keys
}  // namespace thin_ice
