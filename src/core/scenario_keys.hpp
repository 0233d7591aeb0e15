// The scenario loader's key table (internal to the core: src/core/scenario.cpp reads files and
// overrides through it): every key with its section, type, unit, physical range, whether it is
// required and whether a resumption may switch it, and the keys that readings of the paper once
// had and the runs rejected. One registry: the loader, the range checks, the resume policy
// (switchableOnResumeKeys) and the key list of the docs all read it.
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

struct Field {
  std::string key;
  std::string expected;  ///< "a number", "an integer", ... for the messages
  bool required;
  Setter set;                                ///< throws BadValue
  std::function<double(const Params&)> get;  ///< the value, for the range check (numbers only)
  Range range;                               ///< unused where `get` is empty
  bool integer = false;                      ///< the range reads "integer in [lo, hi]"
  bool switchable = false;                   ///< may change at a resumption (switchableOnResume)
};

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
