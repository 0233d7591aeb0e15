// Scenario files (scenario.hpp): YAML -> Params, with one-line errors that name the file, the key,
// the value and what is allowed.
//
// Layout: top-level sections ice, sheet, water, bottom, structure, pusher, channel, numerics, each
// a map whose keys are the snake_case field names of the matching struct in params.hpp
// (IceParams, IceSheetSpec, WaterParams, BottomParams, StructureParams, PusherParams,
// ChannelParams, NumericsParams), plus an optional top-level `description:` text.
//   Enums:    ice.vertical_stress: shear | bending | plate;  sheet.layout: jittered_grid | poisson_disk;
//             ice.vertical_slip_friction: level_only | edge_face;  ice.curvature_failure_scope: all | sheet
//   Integers: structure.panels, sheet.lloyd_iterations, numerics.max_steps_between_rebuilds,
//             numerics.structure_substeps,
//             numerics.threads (signed), sheet.seed (unsigned 64 bit); decimal digits only.
//   Booleans: ice.curvature_failure, ice.plate_bending, bottom.enabled, channel.enabled (true/false;
//             yaml-cpp also takes yes/no, on/off).
//
// Required keys (what makes one experiment differ from another; no silent default for them):
//   ice.thickness ice.density ice.flexural_strength ice.compressive_strength
//   ice.youngs_modulus ice.vertical_modulus ice.poisson_ratio ice.smoothing_exponent_h
//   ice.smoothing_exponent_v ice.compression_coupling ice.vertical_stress
//   sheet.length sheet.width sheet.cell_size structure.toe_x numerics.time_step
// They must be in the file itself (an override cannot stand in for one). Every other key
// (ice.friction_ice_ice and the two damping ratios included) takes its params.hpp default; the
// sections water, bottom, pusher and channel may be left out altogether.
//
// Overrides "section.key=value" are applied after the file; the value is read as a YAML scalar
// and goes through the same type checks. validateParams runs once, on the final Params; an error
// it reports names the override(s) that set one of the keys involved.
#include "thin_ice_sim/scenario.hpp"

#include <yaml-cpp/yaml.h>

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

#include "thin_ice_sim/fnv_hash.hpp"

namespace thin_ice {
namespace {

// ----- Internal errors, turned into ScenarioError with the file (and override) prefix -------

/// A value of the wrong type or form; `got` describes what was found.
struct BadValue : std::runtime_error {
  explicit BadValue(const std::string& got) : std::runtime_error(got) {}
};

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

/// Text from a file as it may be echoed in one message line: bytes outside printable ASCII as
/// \xNN, and at most kEchoedChars characters (then "...").
constexpr size_t kEchoedChars = 80;

std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (out.size() >= kEchoedChars) return out + "...";
    const unsigned char u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      out += c;
    } else {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02x", u);
      out += hex;
    }
  }
  return out;
}

std::string describe(const YAML::Node& n) {
  if (!n.IsDefined() || n.IsNull()) return "nothing";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a map";
  if (n.Tag() == "!") return "the quoted text '" + printable(n.Scalar()) + "'";
  return "'" + printable(n.Scalar()) + "'";
}

// ----- Conversions: each throws BadValue ----------------------------------------------------

/// Plain (unquoted) scalar text; a quoted "0.05" is text, not a number.
const std::string& plainScalar(const YAML::Node& n) {
  if (!n.IsScalar() || n.Tag() == "!") throw BadValue(describe(n));
  return n.Scalar();
}

/// Numbers and booleans through yaml-cpp (which also takes .inf/.nan, yes/no, on/off).
template <class T>
T viaYaml(const YAML::Node& n) {
  plainScalar(n);
  try {
    return n.as<T>();
  } catch (const YAML::Exception&) {
    throw BadValue(describe(n));
  }
}

/// Strict decimal integer that fits T ("12", "-3"; not "1.0", "1e3" or "0x10"; yaml-cpp's own
/// conversion would read "010" as octal).
template <class T>
T toInteger(const YAML::Node& n) {
  const std::string& s = plainScalar(n);
  const size_t first_digit = s.find_first_not_of(std::is_signed<T>::value ? "+-" : "+");
  std::istringstream in(s);
  T value{};
  if (first_digit > 1 || s.find_first_not_of("0123456789", first_digit) != std::string::npos ||
      !(in >> value)) {
    throw BadValue(describe(n));
  }
  return value;
}

VerticalStressModel toVerticalStress(const YAML::Node& n) {
  const std::string& s = plainScalar(n);
  if (s == "shear") return VerticalStressModel::kShear;
  if (s == "bending") return VerticalStressModel::kBending;
  if (s == "plate") return VerticalStressModel::kPlate;
  throw BadValue(describe(n));
}

/// The conversion of a key that names one of two readings: `first` or `second`.
template <class Reading>
auto eitherOf(const char* first, Reading first_value, const char* second, Reading second_value) {
  return [=](const YAML::Node& n) {
    const std::string& s = plainScalar(n);
    if (s == first) return first_value;
    if (s == second) return second_value;
    throw BadValue(describe(n));
  };
}

SeedLayout toLayout(const YAML::Node& n) {
  try {
    return parseSeedLayout(plainScalar(n), "sheet.layout");
  } catch (const std::invalid_argument&) {
    throw BadValue(describe(n));
  }
}

// ----- The key table --------------------------------------------------------------------------

using Setter = std::function<void(Params&, const YAML::Node&)>;

struct Field {
  std::string key;
  std::string expected;  ///< "a number", "an integer", ... for the messages
  bool required;
  Setter set;
};

struct Section {
  std::string name;
  std::vector<Field> fields;
};

constexpr bool kRequired = true;

template <class S, class T, class Convert>
Field field(S Params::*section, T S::*member, const char* key, const char* expected,
            Convert convert, bool required) {
  return {key, expected, required,
          [=](Params& p, const YAML::Node& n) { (p.*section).*member = convert(n); }};
}
template <class S>
Field number(S Params::*section, double S::*member, const char* key, bool required = false) {
  return field(section, member, key, "a number", viaYaml<double>, required);
}
template <class S>
Field integer(S Params::*section, int S::*member, const char* key) {
  return field(section, member, key, "an integer", toInteger<int>, false);
}
template <class S>
Field flag(S Params::*section, bool S::*member, const char* key) {
  return field(section, member, key, "true or false", viaYaml<bool>, false);
}

const std::vector<Section>& sections() {
  using P = Params;
  static const std::vector<Section> table = {
      {"ice",
       {number(&P::ice, &IceParams::thickness, "thickness", kRequired),
        number(&P::ice, &IceParams::density, "density", kRequired),
        number(&P::ice, &IceParams::flexural_strength, "flexural_strength", kRequired),
        number(&P::ice, &IceParams::compressive_strength, "compressive_strength", kRequired),
        number(&P::ice, &IceParams::youngs_modulus, "youngs_modulus", kRequired),
        number(&P::ice, &IceParams::vertical_modulus, "vertical_modulus", kRequired),
        number(&P::ice, &IceParams::poisson_ratio, "poisson_ratio", kRequired),
        number(&P::ice, &IceParams::smoothing_exponent_h, "smoothing_exponent_h", kRequired),
        number(&P::ice, &IceParams::smoothing_exponent_v, "smoothing_exponent_v", kRequired),
        number(&P::ice, &IceParams::compression_coupling, "compression_coupling", kRequired),
        field(&P::ice, &IceParams::vertical_stress, "vertical_stress", "shear, bending or plate",
              toVerticalStress, kRequired),
        flag(&P::ice, &IceParams::curvature_failure, "curvature_failure"),
        field(&P::ice, &IceParams::curvature_failure_scope, "curvature_failure_scope", "all or sheet",
              eitherOf("all", CurvatureFailureScope::kAll, "sheet", CurvatureFailureScope::kSheet), false),
        flag(&P::ice, &IceParams::plate_bending, "plate_bending"),
        number(&P::ice, &IceParams::friction_ice_ice, "friction_ice_ice"),
        field(&P::ice, &IceParams::vertical_slip_friction, "vertical_slip_friction", "level_only or edge_face",
              eitherOf("level_only", VerticalSlipFrictionModel::kLevelOnly, "edge_face",
                       VerticalSlipFrictionModel::kEdgeFace),
              false),
        number(&P::ice, &IceParams::contact_damping_ratio, "contact_damping_ratio"),
        number(&P::ice, &IceParams::bond_damping_ratio, "bond_damping_ratio")}},
      {"sheet",
       {number(&P::sheet, &IceSheetSpec::length, "length", kRequired),
        number(&P::sheet, &IceSheetSpec::width, "width", kRequired),
        number(&P::sheet, &IceSheetSpec::x_min, "x_min"),
        number(&P::sheet, &IceSheetSpec::cell_size, "cell_size", kRequired),
        field(&P::sheet, &IceSheetSpec::layout, "layout", "jittered_grid or poisson_disk", toLayout,
              false),
        number(&P::sheet, &IceSheetSpec::jitter, "jitter"),
        integer(&P::sheet, &IceSheetSpec::lloyd_iterations, "lloyd_iterations"),
        field(&P::sheet, &IceSheetSpec::seed, "seed", "a non-negative integer",
              toInteger<std::uint64_t>, false)}},
      {"water",
       {number(&P::water, &WaterParams::density, "density"),
        number(&P::water, &WaterParams::gravity, "gravity"),
        number(&P::water, &WaterParams::linear_drag, "linear_drag"),
        number(&P::water, &WaterParams::quadratic_drag, "quadratic_drag"),
        number(&P::water, &WaterParams::vertical_linear_drag, "vertical_linear_drag"),
        number(&P::water, &WaterParams::vertical_quadratic_drag, "vertical_quadratic_drag")}},
      {"bottom",
       {flag(&P::bottom, &BottomParams::enabled, "enabled"),
        number(&P::bottom, &BottomParams::distance_from_structure, "distance_from_structure"),
        number(&P::bottom, &BottomParams::depth, "depth"),
        number(&P::bottom, &BottomParams::friction, "friction"),
        number(&P::bottom, &BottomParams::stiffness, "stiffness")}},
      {"structure",
       {number(&P::structure, &StructureParams::toe_x, "toe_x", kRequired),
        number(&P::structure, &StructureParams::angle_deg, "angle_deg"),
        number(&P::structure, &StructureParams::width, "width"),
        number(&P::structure, &StructureParams::height, "height"),
        integer(&P::structure, &StructureParams::panels, "panels"),
        number(&P::structure, &StructureParams::side_panel_length, "side_panel_length"),
        number(&P::structure, &StructureParams::stiffness, "stiffness"),
        number(&P::structure, &StructureParams::calibration_factor, "calibration_factor"),
        number(&P::structure, &StructureParams::friction, "friction")}},
      {"pusher",
       {number(&P::pusher, &PusherParams::velocity, "velocity"),
        number(&P::pusher, &PusherParams::stiffness, "stiffness"),
        number(&P::pusher, &PusherParams::friction, "friction")}},
      {"channel",
       {flag(&P::channel, &ChannelParams::enabled, "enabled"),
        number(&P::channel, &ChannelParams::width, "width"),
        number(&P::channel, &ChannelParams::stiffness, "stiffness"),
        number(&P::channel, &ChannelParams::friction, "friction")}},
      {"numerics",
       {number(&P::numerics, &NumericsParams::time_step, "time_step", kRequired),
        number(&P::numerics, &NumericsParams::critical_step_safety, "critical_step_safety"),
        integer(&P::numerics, &NumericsParams::max_steps_between_rebuilds,
                "max_steps_between_rebuilds"),
        integer(&P::numerics, &NumericsParams::structure_substeps, "structure_substeps"),
        number(&P::numerics, &NumericsParams::rebuild_displacement, "rebuild_displacement"),
        number(&P::numerics, &NumericsParams::rebuild_rotation_deg, "rebuild_rotation_deg"),
        number(&P::numerics, &NumericsParams::friction_regularisation, "friction_regularisation"),
        number(&P::numerics, &NumericsParams::friction_viscous_limit, "friction_viscous_limit"),
        integer(&P::numerics, &NumericsParams::threads, "threads")}},
  };
  return table;
}

/// The section called `name`; throws ScenarioError (after `where`) when there is none.
const Section& findSection(const std::string& name, const std::string& where) {
  std::string allowed;
  for (const Section& s : sections()) {
    if (s.name == name) return s;
    allowed += " " + s.name;
  }
  throw ScenarioError(where + "unknown section '" + printable(name) + "'; allowed:" + allowed);
}

/// Keys that readings of the paper once had and that the runs rejected (their evidence is in
/// docs/model.md, "Readings tried and rejected"): a file or a run record naming one is told so.
struct RetiredKey {
  const char* section;
  const char* key;
  const char* why;
};
constexpr RetiredKey kRetiredKeys[] = {
    {"ice", "contact_face", "Eq. (1) with the face h shattered the sheet (issue #31, reading b)"},
    {"ice", "vertical_contact_depth",
     "the depth min(Z, S/L) of Eq. (3) served only E_v = E, which the runs rejected (issue #31)"},
    {"ice", "failure_compression",
     "sigma_comp of Eq. (13) is the bond's present compression; the compressive strength there (issue #31, "
     "reading c) changed the load within the seed spread, and with k ~ sigma_f/sigma_comp would leave no threshold"},
    {"ice", "bond_smoothing",
     "K of Eq. (6) scales the bond's springs, as Eqs. (1) and (3) write it; K on the strength (issue #31, "
     "reading d) changed the load within the seed spread"},
};

const Field& findField(const Section& section, const std::string& key, const std::string& where) {
  std::string allowed;
  for (const Field& f : section.fields) {
    if (f.key == key) return f;
    allowed += " " + f.key;
  }
  for (const RetiredKey& r : kRetiredKeys) {
    if (section.name == r.section && key == r.key) {
      throw ScenarioError(where + "key '" + section.name + "." + key + "' was removed: " + r.why +
                          "; docs/model.md, \"Readings tried and rejected\"");
    }
  }
  throw ScenarioError(where + "unknown key '" + printable(key) + "' in section '" + section.name +
                      "'; allowed:" + allowed);
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

void applyFile(const YAML::Node& root, const std::string& path, Params& params) {
  const std::string where = path + ": ";
  std::string all_sections;
  for (const Section& s : sections()) all_sections += " " + s.name;
  if (!root.IsMap()) {
    throw ScenarioError(where + "expected a map of sections, got " + describe(root) +
                        "; allowed sections: description" + all_sections);
  }
  std::set<std::string> seen;  // sections and "section.key"
  for (const auto& entry : root) {
    const std::string name = entry.first.Scalar();
    if (!seen.insert(name).second) throw ScenarioError(where + printable(name) + " appears twice");
    if (name == "description") {
      if (!entry.second.IsScalar()) {
        throw ScenarioError(where + "description: expected a text, got " + describe(entry.second));
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
    }
  }
  std::string missing, others;
  for (const Section& s : sections()) {
    for (const Field& f : s.fields) {
      if (!f.required || seen.count(s.name + "." + f.key)) continue;
      if (missing.empty()) {
        missing = "missing required key " + s.name + "." + f.key + " (expected " + f.expected + ")";
      } else {
        others += (others.empty() ? "; also missing: " : ", ") + s.name + "." + f.key;
      }
    }
  }
  if (!missing.empty()) throw ScenarioError(where + missing + others);
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
void positive(const std::string& key, double v, const std::string& what, const std::string& unit) {
  require(v > 0.0, key, v, what + " must be positive", "> 0" + unit);
}
void nonNegative(const std::string& key, double v, const std::string& what,
                 const std::string& unit) {
  require(v >= 0.0, key, v, what + " cannot be negative", ">= 0" + unit);
}
void dampingRatio(const std::string& key, double zeta) {
  require(zeta >= 0.0 && zeta <= 1.0, key, zeta,
          "a damping ratio is a fraction of critical damping", "[0, 1]");
}
void finite(const std::string& key, double v) { require(true, key, v, "", "a finite number"); }

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

/// The most OpenMP threads a scenario may ask for [-].
constexpr int kMaxThreads = 1024;

void checkParams(const Params& p) {
  const IceParams& ice = p.ice;
  positive("ice.thickness", ice.thickness, "the ice thickness h", " m");
  positive("ice.density", ice.density, "the ice density", " kg/m^3");
  positive("ice.flexural_strength", ice.flexural_strength, "the flexural strength", " Pa");
  positive("ice.compressive_strength", ice.compressive_strength, "the compressive strength", " Pa");
  positive("ice.youngs_modulus", ice.youngs_modulus, "Young's modulus E", " Pa");
  positive("ice.vertical_modulus", ice.vertical_modulus, "the vertical modulus E_v", " Pa");
  require(ice.poisson_ratio >= 0.0 && ice.poisson_ratio < 0.5, "ice.poisson_ratio",
          ice.poisson_ratio, "Poisson's ratio must lie in [0, 0.5) (3E/(1-nu) and G need it)",
          "[0, 0.5)");
  positive("ice.smoothing_exponent_h", ice.smoothing_exponent_h, "the smoothing exponent n", "");
  positive("ice.smoothing_exponent_v", ice.smoothing_exponent_v, "the smoothing exponent n", "");
  nonNegative("ice.compression_coupling", ice.compression_coupling, "k of Eq. (13)", "");
  nonNegative("ice.friction_ice_ice", ice.friction_ice_ice, "a friction coefficient", "");
  dampingRatio("ice.contact_damping_ratio", ice.contact_damping_ratio);
  dampingRatio("ice.bond_damping_ratio", ice.bond_damping_ratio);
  if (ice.curvature_failure_scope == CurvatureFailureScope::kSheet && !ice.curvature_failure) {
    throw RangeError({"ice.curvature_failure_scope", "ice.curvature_failure"},
                     "ice.curvature_failure_scope = sheet is invalid: it limits the curvature criterion, which is "
                     "off (ice.curvature_failure = false); allowed: all, or sheet with ice.curvature_failure: true");
  }
  positive("water.density", p.water.density, "the water density", " kg/m^3");
  positive("water.gravity", p.water.gravity, "gravity", " m/s^2");
  nonNegative("water.linear_drag", p.water.linear_drag, "drag", " N s/m^3");
  nonNegative("water.quadratic_drag", p.water.quadratic_drag, "drag", "");
  nonNegative("water.vertical_linear_drag", p.water.vertical_linear_drag, "drag", " N s/m^3");
  nonNegative("water.vertical_quadratic_drag", p.water.vertical_quadratic_drag, "drag", "");
  nonNegative("bottom.distance_from_structure", p.bottom.distance_from_structure,
              "the distance in front of the structure", " m");
  positive("bottom.depth", p.bottom.depth, "the water depth over the false bottom", " m");
  nonNegative("bottom.friction", p.bottom.friction, "a friction coefficient", "");
  positive("bottom.stiffness", p.bottom.stiffness, "a contact stiffness", " Pa");
  const StructureParams& s = p.structure;
  finite("structure.toe_x", s.toe_x);
  require(s.angle_deg > 0.0 && s.angle_deg < 90.0, "structure.angle_deg", s.angle_deg,
          "the face must be inclined, neither flat nor vertical", "(0, 90) deg");
  positive("structure.width", s.width, "the structure width", " m");
  positive("structure.height", s.height, "the structure height", " m");
  require(s.panels >= 1 && s.panels <= 1000, "structure.panels", s.panels,
          "the structure needs at least one panel", "integer in [1, 1000]");
  nonNegative("structure.side_panel_length", s.side_panel_length, "a length", " m");
  positive("structure.stiffness", s.stiffness, "K_struct", " Pa");
  positive("structure.calibration_factor", s.calibration_factor, "alpha of Eq. (18)", "");
  nonNegative("structure.friction", s.friction, "a friction coefficient", "");
  finite("pusher.velocity", p.pusher.velocity);
  positive("pusher.stiffness", p.pusher.stiffness, "a contact stiffness", " Pa");
  nonNegative("pusher.friction", p.pusher.friction, "a friction coefficient", "");
  positive("channel.width", p.channel.width, "the channel width", " m");
  positive("channel.stiffness", p.channel.stiffness, "a contact stiffness", " Pa");
  nonNegative("channel.friction", p.channel.friction, "a friction coefficient", "");
  const NumericsParams& n = p.numerics;
  positive("numerics.time_step", n.time_step, "the time step", " s");
  // Above 1 an unstable step gets through: allowed (up to 1000) only so that fault handling can
  // be tested with a deliberate blow-up (test/node_fault.test).
  require(n.critical_step_safety > 0.0 && n.critical_step_safety <= 1000.0,
          "numerics.critical_step_safety", n.critical_step_safety,
          "a fraction of the critical step (above 1 only to provoke a blow-up in tests)", "(0, 1000]");
  require(n.max_steps_between_rebuilds >= 1, "numerics.max_steps_between_rebuilds",
          n.max_steps_between_rebuilds, "N_iter counts steps", "integer >= 1");
  require(n.structure_substeps >= 1 && n.structure_substeps <= kMaxStructureSubsteps, "numerics.structure_substeps",
          n.structure_substeps, "sub-steps of the structure contact per step (1: none)",
          "integer in [1, " + std::to_string(kMaxStructureSubsteps) + "]");
  positive("numerics.rebuild_displacement", n.rebuild_displacement, "a fraction of l-bar", "");
  require(n.rebuild_rotation_deg > 0.0 && n.rebuild_rotation_deg <= 45.0,
          "numerics.rebuild_rotation_deg", n.rebuild_rotation_deg,
          "delta_rot must be a small positive angle", "(0, 45] deg");
  positive("numerics.friction_regularisation", n.friction_regularisation, "a slip speed", " m/s");
  require(n.friction_viscous_limit > 0.0 && n.friction_viscous_limit < 2.0, "numerics.friction_viscous_limit",
          n.friction_viscous_limit, "an explicit step of viscous friction is stable below 2 m_eff/dt",
          "(0, 2)");
  // At load time, whatever the machine: above kMaxThreads is no machine's core count (the runner
  // caps a valid count at the cores present, and says so).
  require(n.threads >= 0 && n.threads <= kMaxThreads, "numerics.threads", n.threads,
          "a thread count is between 0 (all cores) and " + std::to_string(kMaxThreads),
          "integer in [0, " + std::to_string(kMaxThreads) + "] (0 = all cores; more than the cores present are "
          "capped at them)");
  checkSheet(p);
}

/// 64-bit FNV-1a over the file bytes, then each override followed by a newline.
std::string scenarioHash(const std::string& text, const std::vector<std::string>& overrides) {
  std::uint64_t h = fnv1a64(text.data(), text.size());
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

Scenario loadScenario(const std::string& path, const std::vector<std::string>& overrides) {
  Scenario scenario;
  const std::string text = readFile(path);
  std::map<std::string, std::string> overridden;  // "section.key" -> the override that set it
  try {
    applyFile(parseYaml(text, path + ": "), path, scenario.params);
    for (const std::string& o : overrides) overridden[applyOverride(o, path, scenario.params)] = o;
  } catch (const YAML::Exception& e) {  // anything yaml-cpp throws that the checks above missed
    throw ScenarioError(path + ": " + e.what());
  }
  try {
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
  scenario.hash = scenarioHash(text, overrides);
  return scenario;
}

}  // namespace thin_ice

