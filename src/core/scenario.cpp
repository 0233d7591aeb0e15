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
// Ranges: every numeric key has a physical range (unit, bounds and the reason, in the key table
// below); a value outside it is refused naming that key before anything is derived from it, and a
// derived condition (ice that floats, cells no smaller than the thickness, the toe beyond the
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

SeedLayout toLayout(const YAML::Node& n) {
  try {
    return parseSeedLayout(plainScalar(n), "sheet.layout");
  } catch (const std::invalid_argument&) {
    throw BadValue(describe(n));
  }
}

// ----- The key table --------------------------------------------------------------------------

/// The most OpenMP threads a scenario may ask for [-].
constexpr int kMaxThreads = 1024;

using Setter = std::function<void(Params&, const YAML::Node&)>;

/// A numeric key's physical range [lo, hi] (either end open where the flag says so), its unit
/// for the messages, and why: the loader refuses a value outside it, naming the key, before any
/// derived quantity (a cell count, a critical time step) is worked out from it.
struct Range {
  double lo, hi;
  bool lo_open, hi_open;
  const char* unit;  ///< " m", " Pa", "" (dimensionless); for an integer key, a note after the range
  const char* why;   ///< the reason for the bounds, in a few words
};

struct Field {
  std::string key;
  std::string expected;  ///< "a number", "an integer", ... for the messages
  bool required;
  Setter set;
  std::function<double(const Params&)> get;  ///< the value, for the range check (numbers only)
  Range range;                               ///< unused where `get` is empty
  bool integer = false;                      ///< the range reads "integer in [lo, hi]"
  bool switchable = false;                   ///< may change at a resumption (switchableOnResume)
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
          [=](Params& p, const YAML::Node& n) { (p.*section).*member = convert(n); }, {}, {}};
}
template <class S>
Field number(S Params::*section, double S::*member, const char* key, Range range, bool required = false) {
  Field f = field(section, member, key, "a number", viaYaml<double>, required);
  f.get = [=](const Params& p) { return (p.*section).*member; };
  f.range = range;
  return f;
}
template <class S>
Field integer(S Params::*section, int S::*member, const char* key, Range range) {
  Field f = field(section, member, key, "an integer", toInteger<int>, false);
  f.get = [=](const Params& p) { return static_cast<double>((p.*section).*member); };
  f.range = range;
  f.integer = true;
  return f;
}
template <class S>
Field flag(S Params::*section, bool S::*member, const char* key) {
  return field(section, member, key, "true or false", viaYaml<bool>, false);
}
/// Marks a key that `thin_ice_run --resume DIR --set` may change under a run that is under way:
/// the laws of the ice, the water and the rigid planes (stiffness, friction), the friction's
/// regularisation, the thread count, and the depth of the false bottom (not in the paper, so the
/// one piece of geometry whose effect on a grown pile is worth testing; the runner refuses a depth
/// that would cut ice already over the bottom). Not the mesh, the masses or the floating level
/// (thickness, densities), the rest of the geometry, the pusher's speed (the checkpoint holds it),
/// the time stepping (the rows are counted in steps from t = 0), or the calibration factor and the
/// structure's width (the statistics of the whole history use them).
Field onResume(Field f) {
  f.switchable = true;
  return f;
}

// Ranges: wide enough for every ice a test rig or a tank sees, from model-scale ice (tens of mm,
// kPa strengths) to thick sea ice, and narrow enough to refuse what no ice or rig is (a value of
// 1e300 passed a sign check and blew up at the first step, or was blamed on another key).
constexpr bool kOpen = true, kClosed = false;
constexpr double kMaxStiffness = 1e13;  // [Pa] contact stiffnesses: steel is 2e11
constexpr double kMaxFriction = 2.0;    // [-] Coulomb coefficients of ice on ice or steel are below 1
constexpr double kMaxLength = 1e4;      // [m] a tank or a test rig, with room
constexpr Range kThickness{1e-3, 5.0, kClosed, kClosed, " m", "from model-scale ice (mm) to thick sea ice (m)"};
constexpr Range kIceDensity{500.0, 1000.0, kClosed, kClosed, " kg/m^3", "ice, porous model ice included"};
constexpr Range kStrength{1e3, 1e8, kClosed, kClosed, " Pa", "model-scale ice (kPa) to the strongest ice (MPa)"};
constexpr Range kModulus{1e3, 2e10, kClosed, kClosed, " Pa", "at most twice the stiffest ice's 9-10 GPa"};
constexpr Range kExponent{0.0, 10.0, kOpen, kClosed, "", "the paper's n of Eq. (6) is 0.5-2 (Table 1)"};
constexpr Range kCoupling{0.0, 10.0, kClosed, kClosed, "", "k of Eq. (13) is about sigma_f / sigma_comp"};
constexpr Range kFriction{0.0, kMaxFriction, kClosed, kClosed, "", "a Coulomb friction coefficient"};
constexpr Range kDamping{0.0, 1.0, kClosed, kClosed, "", "a damping ratio is a fraction of critical damping"};
constexpr Range kContactStiffness{0.0, kMaxStiffness, kOpen, kClosed, " Pa", "a contact stiffness (steel: 2e11 Pa)"};
constexpr Range kSize{0.0, kMaxLength, kOpen, kClosed, " m", "a tank's or a test rig's size"};
constexpr Range kPosition{-kMaxLength, kMaxLength, kClosed, kClosed, " m", "a position in a tank or a test rig"};
constexpr Range kDistance{0.0, kMaxLength, kClosed, kClosed, " m", "a distance in a tank or a test rig"};
constexpr Range kDrag{0.0, 1e6, kClosed, kClosed, "", "a drag coefficient"};

const std::vector<Section>& sections() {
  using P = Params;
  static const std::vector<Section> table = {
      {"ice",
       {number(&P::ice, &IceParams::thickness, "thickness", kThickness, kRequired),
        number(&P::ice, &IceParams::density, "density", kIceDensity, kRequired),
        onResume(number(&P::ice, &IceParams::flexural_strength, "flexural_strength", kStrength, kRequired)),
        onResume(number(&P::ice, &IceParams::compressive_strength, "compressive_strength", kStrength, kRequired)),
        onResume(number(&P::ice, &IceParams::youngs_modulus, "youngs_modulus", kModulus, kRequired)),
        onResume(number(&P::ice, &IceParams::vertical_modulus, "vertical_modulus", kModulus, kRequired)),
        onResume(number(&P::ice, &IceParams::poisson_ratio, "poisson_ratio",
                        {0.0, 0.5, kClosed, kOpen, "", "3E/(1-nu) and G = E/(2(1+nu)) need nu in [0, 0.5)"},
                        kRequired)),
        onResume(number(&P::ice, &IceParams::smoothing_exponent_h, "smoothing_exponent_h", kExponent, kRequired)),
        onResume(number(&P::ice, &IceParams::smoothing_exponent_v, "smoothing_exponent_v", kExponent, kRequired)),
        onResume(number(&P::ice, &IceParams::compression_coupling, "compression_coupling", kCoupling, kRequired)),
        onResume(number(&P::ice, &IceParams::friction_ice_ice, "friction_ice_ice", kFriction)),
        onResume(number(&P::ice, &IceParams::contact_damping_ratio, "contact_damping_ratio", kDamping)),
        onResume(number(&P::ice, &IceParams::bond_damping_ratio, "bond_damping_ratio", kDamping))}},
      {"sheet",
       {number(&P::sheet, &IceSheetSpec::length, "length", kSize, kRequired),
        number(&P::sheet, &IceSheetSpec::width, "width", kSize, kRequired),
        number(&P::sheet, &IceSheetSpec::x_min, "x_min", kPosition),
        number(&P::sheet, &IceSheetSpec::cell_size, "cell_size",
               {0.0, 100.0, kOpen, kClosed, " m", "a cell of a sheet (the paper: A/h^2 > 10)"}, kRequired),
        field(&P::sheet, &IceSheetSpec::layout, "layout", "jittered_grid or poisson_disk", toLayout,
              false),
        number(&P::sheet, &IceSheetSpec::jitter, "jitter",
               {0.0, 0.5, kClosed, kClosed, "", "a fraction of the cell size that keeps the seeds apart"}),
        integer(&P::sheet, &IceSheetSpec::lloyd_iterations, "lloyd_iterations",
                {0.0, 50.0, kClosed, kClosed, "", "Lloyd relaxation steps"}),
        field(&P::sheet, &IceSheetSpec::seed, "seed", "a non-negative integer",
              toInteger<std::uint64_t>, false)}},
      {"water",
       {number(&P::water, &WaterParams::density, "density",
               {900.0, 1100.0, kClosed, kClosed, " kg/m^3", "fresh to sea water, with room"}),
        number(&P::water, &WaterParams::gravity, "gravity",
               {1.0, 30.0, kClosed, kClosed, " m/s^2", "a test rig on Earth has 9.81"}),
        onResume(number(&P::water, &WaterParams::linear_drag, "linear_drag", kDrag)),
        onResume(number(&P::water, &WaterParams::quadratic_drag, "quadratic_drag", kDrag)),
        onResume(number(&P::water, &WaterParams::vertical_linear_drag, "vertical_linear_drag", kDrag)),
        onResume(number(&P::water, &WaterParams::vertical_quadratic_drag, "vertical_quadratic_drag", kDrag))}},
      {"bottom",
       {flag(&P::bottom, &BottomParams::enabled, "enabled"),
        number(&P::bottom, &BottomParams::distance_from_structure, "distance_from_structure", kDistance),
        onResume(number(&P::bottom, &BottomParams::depth, "depth",
               {0.0, 100.0, kOpen, kClosed, " m", "the water depth over a false bottom"})),
        onResume(number(&P::bottom, &BottomParams::friction, "friction", kFriction)),
        onResume(number(&P::bottom, &BottomParams::stiffness, "stiffness", kContactStiffness))}},
      {"structure",
       {number(&P::structure, &StructureParams::toe_x, "toe_x", kPosition, kRequired),
        number(&P::structure, &StructureParams::angle_deg, "angle_deg",
               {0.0, 90.0, kOpen, kOpen, " deg", "the face must be inclined, neither flat nor vertical"}),
        number(&P::structure, &StructureParams::width, "width", kSize),
        number(&P::structure, &StructureParams::height, "height", kSize),
        integer(&P::structure, &StructureParams::panels, "panels",
                {1.0, 1000.0, kClosed, kClosed, "", "the structure needs at least one panel"}),
        number(&P::structure, &StructureParams::side_panel_length, "side_panel_length", kDistance),
        onResume(number(&P::structure, &StructureParams::stiffness, "stiffness", kContactStiffness)),
        number(&P::structure, &StructureParams::calibration_factor, "calibration_factor",
               {0.0, 10.0, kOpen, kClosed, "", "alpha of Eq. (18) is 0.63 in the paper"}),
        onResume(number(&P::structure, &StructureParams::friction, "friction", kFriction))}},
      {"pusher",
       {number(&P::pusher, &PusherParams::velocity, "velocity",
               {-10.0, 10.0, kClosed, kClosed, " m/s", "test rigs push at mm/s to a few m/s (the paper: 0.05)"}),
        onResume(number(&P::pusher, &PusherParams::stiffness, "stiffness", kContactStiffness)),
        onResume(number(&P::pusher, &PusherParams::friction, "friction", kFriction))}},
      {"channel",
       {flag(&P::channel, &ChannelParams::enabled, "enabled"),
        number(&P::channel, &ChannelParams::width, "width", kSize),
        onResume(number(&P::channel, &ChannelParams::stiffness, "stiffness", kContactStiffness)),
        onResume(number(&P::channel, &ChannelParams::friction, "friction", kFriction))}},
      {"numerics",
       {number(&P::numerics, &NumericsParams::time_step, "time_step",
               {0.0, 1.0, kOpen, kClosed, " s", "an explicit step (the critical step refuses more, naming it)"},
               kRequired),
        // Above 1 an unstable step gets through: allowed (up to 1000) only so that fault handling
        // can be tested with a deliberate blow-up (test/node_fault.test).
        number(&P::numerics, &NumericsParams::critical_step_safety, "critical_step_safety",
               {0.0, 1000.0, kOpen, kClosed, "", "a fraction of the critical step (above 1 only to provoke a blow-up in tests)"}),
        integer(&P::numerics, &NumericsParams::max_steps_between_rebuilds, "max_steps_between_rebuilds",
                {1.0, 1e9, kClosed, kClosed, "", "N_iter counts steps"}),
        integer(&P::numerics, &NumericsParams::structure_substeps, "structure_substeps",
                {1.0, static_cast<double>(kMaxStructureSubsteps), kClosed, kClosed, "",
                 "sub-steps of the structure contact per step (1: none)"}),
        number(&P::numerics, &NumericsParams::rebuild_displacement, "rebuild_displacement",
               {0.0, 10.0, kOpen, kClosed, "", "a fraction of l-bar"}),
        number(&P::numerics, &NumericsParams::rebuild_rotation_deg, "rebuild_rotation_deg",
               {0.0, 45.0, kOpen, kClosed, " deg", "delta_rot must be a small positive angle"}),
        onResume(number(&P::numerics, &NumericsParams::friction_regularisation, "friction_regularisation",
               {0.0, 10.0, kOpen, kClosed, " m/s", "a slip speed"})),
        onResume(number(&P::numerics, &NumericsParams::friction_viscous_limit, "friction_viscous_limit",
               {0.0, 2.0, kOpen, kOpen, "", "an explicit step of viscous friction is stable below 2 m_eff/dt"})),
        // At load time, whatever the machine: above kMaxThreads is no machine's core count (the
        // runner caps a valid count at the cores present, and says so).
        onResume(integer(&P::numerics, &NumericsParams::threads, "threads",
                {0.0, static_cast<double>(kMaxThreads), kClosed, kClosed,
                 " (0 = all cores; more than the cores present are capped at them)",
                 "a thread count"}))}},
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
    {"ice", "curvature_failure",
     "the curvature criterion (beyond the paper) unzipped the sheet from every free edge and raised the load above "
     "the paper's law"},
    {"ice", "curvature_failure_scope", "it limited the curvature criterion, which was removed"},
    {"ice", "plate_bending",
     "the Kirchhoff plate term (beyond the paper) gave medium ice 1.4-1.9 times the paper's load to 3 m"},
    {"ice", "vertical_stress",
     "sigma_v of Eq. (13) is the bending stress 6 M/(L_e h^2), M = |F_v| d/2; the paper's |F_v|/(h L_e) (shear) "
     "carried the same load but let the sheet slide to the toe, and the floating plate's arm (plate) served only "
     "an edge check"},
    {"ice", "vertical_slip_friction",
     "the edge face of offset cells always resists their vertical slip; without it (level_only) a piece pressed "
     "edge-on against another slid past it held by its buoyancy alone, and the piles did not form"},
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
      if (missing.empty()) {
        missing = "missing required key " + s.name + "." + f.key + " (expected " + f.expected + ")";
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
void checkRanges(const Params& p) {
  for (const Section& section : sections()) {
    for (const Field& f : section.fields) {
      if (!f.get) continue;
      const double v = f.get(p);
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

