// Scenario files (scenario.hpp): YAML -> Params, with one-line errors that name the file, the key,
// the value and what is allowed.
//
// Layout: top-level sections ice, sheet, water, bottom, structure, pusher, channel, numerics, each
// a map whose keys are the snake_case field names of the matching struct in params.hpp
// (IceParams, IceSheetSpec, WaterParams, BottomParams, StructureParams, PusherParams,
// ChannelParams, NumericsParams), plus an optional top-level `description:` text and an optional
// top-level `base:` naming another scenario file (relative to this file's folder) that is read
// first and whose keys this file's override (config/scenarios/base/).
//   Enums:    sheet.layout: jittered_grid | poisson_disk
//   Integers: structure.panels, sheet.lloyd_iterations, numerics.max_steps_between_rebuilds,
//             numerics.structure_substeps,
//             numerics.threads (signed), sheet.seed (unsigned 64 bit); decimal digits only.
//   Booleans: bottom.enabled, channel.enabled (true/false;
//             yaml-cpp also takes yes/no, on/off).
//
// Required keys (what makes one experiment differ from another; no silent default for them):
//   ice.thickness ice.density ice.flexural_strength ice.compressive_strength
//   ice.youngs_modulus ice.vertical_modulus ice.poisson_ratio ice.smoothing_exponent_h
//   ice.smoothing_exponent_v ice.compression_coupling
//   sheet.length sheet.width sheet.cell_size structure.toe_x numerics.time_step
// They must be in the file or one of its bases (an override cannot stand in for one). Every other key
// (ice.friction_ice_ice and the two damping ratios included) takes its params.hpp default; the
// sections water, bottom, pusher and channel may be left out altogether.
//
// Ranges: every numeric key has a physical range (unit, bounds and the reason, in the key
// table of scenario_keys.cpp); a value outside it is refused naming that key before anything is
// derived from it, and a derived condition (ice that floats, cells no smaller than the thickness, the toe beyond the
// front) names every key it comes from.
//
// Overrides "section.key=value" are applied after the file; the value is read as a YAML scalar
// and goes through the same type checks. validateParams runs once, on the final Params; an error
// it reports names the override(s) that set one of the keys involved.
#include "thin_ice_sim/scenario.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <type_traits>

#include "scenario_keys.hpp"
#include "thin_ice_sim/fnv_hash.hpp"

namespace thin_ice {
namespace {

using scenario_keys::BadValue;
using scenario_keys::deriveRuleValues;
using scenario_keys::describe;
using scenario_keys::Field;
using scenario_keys::findField;
using scenario_keys::findSection;
using scenario_keys::printable;
using scenario_keys::Range;
using scenario_keys::Section;
using scenario_keys::sections;

// ----- Internal errors, turned into ScenarioError with the file (and override) prefix -------

/// A value outside its allowed range; `keys` are every key the check depends on.
struct RangeError : std::runtime_error {
  RangeError(std::vector<std::string> involved, const std::string& text)
      : std::runtime_error(text), keys(std::move(involved)) {}
  std::vector<std::string> keys;
};

/// Shortest text that reads back as `v` (so 0.051 prints as 0.051, not 0.050999999999999997).
std::string fmt(double v) {
  std::ostringstream s;
  for (int precision = 6; precision <= 17; ++precision) {
    s.str("");
    s << std::setprecision(precision) << v;
    if (!std::isfinite(v) || std::strtod(s.str().c_str(), nullptr) == v) break;
  }
  return s.str();
}

/// A derived value for a message, to 4 significant digits.
std::string approx(double v) {
  std::ostringstream s;
  s << std::setprecision(4) << v;
  return s.str();
}

void applyValue(Params& params, const Section& section, const Field& f, const YAML::Node& value,
                const std::string& where) {
  try {
    f.set(params, value);
  } catch (const BadValue& e) {
    throw ScenarioError(where + section.name + "." + f.key + ": expected " + f.expected + ", got " +
                        e.what());
  }
}

// ----- Reading the file and the overrides ----------------------------------------------------

/// The largest scenario file read [bytes]: the shipped ones are about 6 kB; a file a thousand
/// times that is not a scenario, and /dev/zero would be read until memory ran out.
constexpr std::uintmax_t kMaxScenarioBytes = 1 << 20;

std::string readFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw ScenarioError(path + ": no such scenario file; expected a YAML file such as " +
                        "config/scenarios/quick.yaml");
  }
  if (std::filesystem::is_directory(path, ec)) {
    throw ScenarioError(path + ": is a directory; expected a scenario YAML file");
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw ScenarioError(path + ": is not a regular file (a device, a pipe or a socket); expected a scenario YAML file");
  }
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxScenarioBytes) {
    throw ScenarioError(path + ": " + (ec ? "cannot tell its size" : std::to_string(size) + " bytes") +
                        "; allowed: a scenario file of at most " + std::to_string(kMaxScenarioBytes) + " bytes");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open()) throw ScenarioError(path + ": cannot open the scenario file for reading");
  std::string text(static_cast<size_t>(size), '\0');
  in.read(&text[0], static_cast<std::streamsize>(size));
  if (in.bad() || in.gcount() != static_cast<std::streamsize>(size)) {
    throw ScenarioError(path + ": cannot read the scenario file");
  }
  return text;
}

YAML::Node parseYaml(const std::string& text, const std::string& where) {
  try {
    // One document: a second one (after "---") would otherwise be ignored without a word.
    const std::vector<YAML::Node> documents = YAML::LoadAll(text);
    if (documents.size() > 1) {
      throw ScenarioError(where + std::to_string(documents.size()) +
                          " YAML documents (separated by ---); allowed: one document per scenario file");
    }
    return documents.empty() ? YAML::Node() : documents.front();
  } catch (const YAML::ParserException& e) {
    std::ostringstream msg;
    msg << where << "YAML syntax error";
    if (!e.mark.is_null()) msg << " at line " << e.mark.line + 1 << ", col " << e.mark.column + 1;
    msg << ": " << printable(e.msg);
    throw ScenarioError(msg.str());
  }
}

/// Applies the keys of one scenario file (its `base` resolved by the caller) to `params` and adds
/// each "section.key" to `keys`. A key may appear once per file; a file's key overrides its base's.
void applyFile(const YAML::Node& root, const std::string& path, Params& params, std::set<std::string>& keys) {
  const std::string where = path + ": ";
  std::string all_sections;
  for (const Section& s : sections()) all_sections += " " + s.name;
  if (!root.IsMap()) {
    throw ScenarioError(where + "expected a map of sections, got " + describe(root) +
                        "; allowed sections: description base" + all_sections);
  }
  std::set<std::string> seen;  // sections and "section.key" of this file
  for (const auto& entry : root) {
    const std::string name = entry.first.Scalar();
    if (!seen.insert(name).second) throw ScenarioError(where + printable(name) + " appears twice");
    if (name == "description" || name == "base") {
      if (!entry.second.IsScalar()) {
        throw ScenarioError(where + name + ": expected a text, got " + describe(entry.second));
      }
      continue;
    }
    const Section& section = findSection(name, where);
    if (!entry.second.IsMap()) {
      throw ScenarioError(where + "section '" + name + "': expected a map of keys, got " +
                          describe(entry.second));
    }
    for (const auto& item : entry.second) {
      const std::string key = item.first.Scalar();
      const Field& f = findField(section, key, where);
      if (!seen.insert(name + "." + key).second) {
        throw ScenarioError(where + name + "." + key + " appears twice");
      }
      applyValue(params, section, f, item.second, where);
      keys.insert(name + "." + key);
    }
  }
}

/// Every required key must have been given by the file or one of its bases.
void checkRequiredKeys(const std::set<std::string>& keys, const std::string& path) {
  std::string missing, others;
  for (const Section& s : sections()) {
    for (const Field& f : s.fields) {
      if (!f.required || keys.count(s.name + "." + f.key)) continue;
      if (f.alternative && keys.count(s.name + "." + f.alternative)) continue;
      if (missing.empty()) {
        missing = "missing required key " + s.name + "." + f.key + " (expected " + f.expected +
                  (f.alternative ? std::string(", or ") + s.name + "." + f.alternative + " for its rule" : "") + ")";
      } else {
        others += (others.empty() ? "; also missing: " : ", ") + s.name + "." + f.key;
      }
    }
  }
  if (!missing.empty()) throw ScenarioError(path + ": " + missing + others);
}

/// How deep `base` files may chain (a series, its ice type, the test set-up: 3).
constexpr int kMaxBaseDepth = 8;

/// Reads the scenario file at `path` into `params`: first the file its `base` key names (a path
/// relative to this file's folder, itself read the same way), then its own keys. Appends each
/// file's text to `texts`, bases first; `chain` holds the files being read, for the cycle check.
void applyScenarioFile(const std::string& path, Params& params, std::set<std::string>& keys,
                       std::vector<std::string>& texts, std::vector<std::string>& chain) {
  std::error_code ec;
  std::string canonical = std::filesystem::weakly_canonical(path, ec).string();
  if (ec || canonical.empty()) canonical = path;  // compared as given: no false cycle between two such files
  for (const std::string& c : chain) {
    if (c == canonical) throw ScenarioError(path + ": base: the files name each other in a cycle");
  }
  if (static_cast<int>(chain.size()) >= kMaxBaseDepth) {
    throw ScenarioError(path + ": base: more than " + std::to_string(kMaxBaseDepth) +
                        " files deep; allowed: a chain of at most that many bases");
  }
  chain.push_back(canonical);
  const std::string text = readFile(path);
  const YAML::Node root = parseYaml(text, path + ": ");
  if (root.IsMap() && root["base"] && root["base"].IsScalar()) {
    const std::string base = root["base"].Scalar();
    if (base.empty()) throw ScenarioError(path + ": base: empty; allowed: the path of a scenario file");
    const std::filesystem::path resolved =
        std::filesystem::path(base).is_absolute() ? std::filesystem::path(base)
                                                  : std::filesystem::path(path).parent_path() / base;
    try {
      applyScenarioFile(resolved.string(), params, keys, texts, chain);
    } catch (const ScenarioError& e) {
      throw ScenarioError(path + ": base: " + e.what());
    }
  }
  texts.push_back(text);
  applyFile(root, path, params, keys);
  chain.pop_back();
}

std::string trim(const std::string& t) {
  const size_t first = t.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return t.substr(first, t.find_last_not_of(" \t") - first + 1);
}

/// The section and field an override names; `where` prefixes the message.
std::pair<const Section*, const Field*> overrideTarget(const std::string& text, const std::string& where) {
  const size_t eq = text.find('=');
  const size_t dot = text.find('.');
  if (eq == std::string::npos || dot == std::string::npos || dot > eq) {
    throw ScenarioError(where + "expected section.key=value");
  }
  const Section& section = findSection(trim(text.substr(0, dot)), where);
  return {&section, &findField(section, trim(text.substr(dot + 1, eq - dot - 1)), where)};
}

/// Applies "section.key=value"; returns "section.key".
std::string applyOverride(const std::string& text, const std::string& path, Params& params) {
  const std::string where = path + ": override '" + text + "': ";
  const auto [section, f] = overrideTarget(text, where);
  const YAML::Node value = parseYaml(text.substr(text.find('=') + 1), where);
  applyValue(params, *section, *f, value, where);
  return section->name + "." + f->key;
}

// ----- Range checks ---------------------------------------------------------------------------

/// Throws RangeError "KEY = VALUE is invalid: REASON; allowed: ALLOWED" unless `ok` and finite.
void require(bool ok, const std::string& key, double value, const std::string& reason,
             const std::string& allowed, std::vector<std::string> keys = {}) {
  if (ok && std::isfinite(value)) return;
  keys.insert(keys.begin(), key);
  throw RangeError(keys, key + " = " + fmt(value) + " is invalid: " +
                             (std::isfinite(value) ? reason : "not a finite number") +
                             "; allowed: " + allowed);
}

void checkSheet(const Params& p) {
  try {
    validate(p.sheet);
  } catch (const std::invalid_argument& e) {
    // "ice sheet: cell_size = 0.01 is invalid; allowed: ..." -> "sheet.cell_size = 0.01 ..."
    std::string text = e.what();
    const std::string prefix = "ice sheet: ";
    if (text.compare(0, prefix.size(), prefix) == 0) text = "sheet." + text.substr(prefix.size());
    throw RangeError({text.substr(0, text.find(" = "))}, text);
  }
  const double h = p.ice.thickness, cell = p.sheet.cell_size;
  const std::string min_cell = approx(std::sqrt(10.0) * h);
  require(cell >= h, "sheet.cell_size", cell,
          "the cells would be smaller than the ice thickness h = " + fmt(h) +
              " m (the paper requires A/h^2 > 10)",
          ">= sqrt(10) h = " + min_cell + " m", {"ice.thickness"});
  require(cell * cell >= 10.0 * h * h, "sheet.cell_size", cell,
          "A/h^2 = " + approx(cell * cell / (h * h)) + " for h = " + fmt(h) +
              " m, but the paper requires A/h^2 > 10 (area to thickness ratio)",
          ">= sqrt(10) h = " + min_cell + " m", {"ice.thickness"});
  const double front = p.sheet.x_min + p.sheet.length;
  require(p.structure.toe_x >= front, "structure.toe_x", p.structure.toe_x,
          "the sheet's front edge (sheet.x_min + sheet.length = " + fmt(front) +
              " m) would lie beyond the structure's toe",
          ">= " + fmt(front) + " m", {"sheet.x_min", "sheet.length"});
  if (p.channel.enabled) {
    require(p.channel.width >= p.sheet.width, "channel.width", p.channel.width,
            "the channel is narrower than the sheet (sheet.width = " + fmt(p.sheet.width) + " m)",
            ">= " + fmt(p.sheet.width) + " m, or channel.enabled: false", {"sheet.width"});
  }
}

/// "[0.001, 5] m", "(0, 90) deg", "integer in [1, 1000]": a key's range as the messages print it.
std::string rangeText(const Field& f) {
  const Range& r = f.range;
  if (f.integer) return "integer in [" + fmt(r.lo) + ", " + fmt(r.hi) + "]" + r.unit;
  return std::string(r.lo_open ? "(" : "[") + fmt(r.lo) + ", " + fmt(r.hi) + (r.hi_open ? ")" : "]") + r.unit;
}

/// Every numeric key of the table within its physical range, in the table's order.
/// The ranges of every number; with `before_rules`, those of the values rules will derive are left
/// for after deriveRuleValues, so that a bad input of a rule is blamed on its own key.
void checkRanges(const Params& p, bool before_rules = false) {
  for (const Section& section : sections()) {
    for (const Field& f : section.fields) {
      if (!f.get) continue;
      if (before_rules && f.derived && f.derived(p)) continue;
      const double v = f.get(p);
      if (f.rule_factor && std::isnan(v)) continue;  // the value is given, not derived
      const Range& r = f.range;
      const bool above_lo = r.lo_open ? v > r.lo : v >= r.lo;
      const bool below_hi = r.hi_open ? v < r.hi : v <= r.hi;
      require(above_lo && below_hi, section.name + "." + f.key, v, r.why, rangeText(f));
    }
  }
}

void checkParams(const Params& p) {
  checkRanges(p);
  const IceParams& ice = p.ice;
  require(ice.density < p.water.density, "ice.density", ice.density,
          "ice denser than the water (water.density = " + fmt(p.water.density) + " kg/m^3) does not float",
          "< water.density = " + fmt(p.water.density) + " kg/m^3", {"water.density"});
  checkSheet(p);
}

/// 64-bit FNV-1a over the files' bytes (the bases' first, then the file's: a file without a base
/// hashes as its text alone), then each override followed by a newline.
std::string scenarioHash(const std::vector<std::string>& texts, const std::vector<std::string>& overrides) {
  std::uint64_t h = 0;
  for (size_t k = 0; k < texts.size(); ++k) {
    h = k == 0 ? fnv1a64(texts[k].data(), texts[k].size()) : fnv1a64(texts[k].data(), texts[k].size(), h);
  }
  for (const std::string& o : overrides) {
    const std::string line = o + "\n";
    h = fnv1a64(line.data(), line.size(), h);
  }
  std::ostringstream hex;
  hex << std::hex << std::setw(16) << std::setfill('0') << h;
  return hex.str();
}

}  // namespace

void validateParams(const Params& params, const std::string& source) {
  try {
    checkParams(params);
  } catch (const RangeError& e) {
    throw ScenarioError(source + ": " + e.what());
  }
}

std::string overrideKey(const std::string& text, const std::string& source) {
  const auto [section, field] = overrideTarget(text, source + ": override '" + text + "': ");
  return section->name + "." + field->key;
}

std::vector<std::string> switchableOnResumeKeys() {
  std::vector<std::string> keys;
  for (const Section& s : sections()) {
    for (const Field& f : s.fields) {
      if (f.switchable) keys.push_back(s.name + "." + f.key);
    }
  }
  return keys;
}

std::vector<ParameterValue> scenarioParameters(const Params& params) {
  std::vector<ParameterValue> values;
  for (const Section& s : sections()) {
    for (const Field& f : s.fields) {
      const std::string value = f.show(params);
      if (!value.empty()) values.push_back({s.name + "." + f.key, value});  // an unused rule factor: nothing
    }
  }
  return values;
}

bool switchableOnResume(const std::string& key) {
  const std::vector<std::string> keys = switchableOnResumeKeys();
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

Scenario loadScenario(const std::string& path, const std::vector<std::string>& overrides) {
  Scenario scenario;
  std::vector<std::string> texts;  // the file's and its bases' texts, bases first
  std::map<std::string, std::string> overridden;  // "section.key" -> the override that set it
  try {
    std::set<std::string> keys;
    std::vector<std::string> chain;
    applyScenarioFile(path, scenario.params, keys, texts, chain);
    checkRequiredKeys(keys, path);
    for (const std::string& o : overrides) overridden[applyOverride(o, path, scenario.params)] = o;
  } catch (const YAML::Exception& e) {  // anything yaml-cpp throws that the checks above missed
    throw ScenarioError(path + ": " + e.what());
  }
  try {
    checkRanges(scenario.params, /*before_rules=*/true);
    deriveRuleValues(scenario.params);
    checkParams(scenario.params);
  } catch (const RangeError& e) {
    std::string by;
    for (const std::string& key : e.keys) {
      if (overridden.count(key)) by += (by.empty() ? "" : ", ") + ("'" + overridden[key] + "'");
    }
    throw ScenarioError(path + ": " + (by.empty() ? "" : "override " + by + ": ") + e.what());
  }
  scenario.name = std::filesystem::path(path).stem().string();
  scenario.source = path;
  scenario.overrides = overrides;
  scenario.hash = scenarioHash(texts, overrides);
  return scenario;
}

}  // namespace thin_ice

