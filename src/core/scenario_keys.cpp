// The scenario loader's key table (scenario_keys.hpp): the conversions of values, the keys with
// their ranges, and the retired keys.
#include "scenario_keys.hpp"

#include <cstdint>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <type_traits>

#include "thin_ice_sim/ice_sheet.hpp"
#include "thin_ice_sim/physics/bond.hpp"
#include "thin_ice_sim/scenario.hpp"

namespace thin_ice {
namespace scenario_keys {

constexpr size_t kEchoedChars = 80;  ///< see printable() in scenario_keys.hpp

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

namespace {

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

constexpr bool kRequired = true;

// ----- Values as text that reads back to the same bits -------------------------------------

/// The shortest of 15, 16 and 17 significant digits that reads back to v ("0.052", not
/// "0.051999999999999998"); 17 always does.
std::string showValue(double v) {
  char text[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    if (std::strtod(text, nullptr) == v) break;
  }
  return text;
}
std::string showValue(int v) { return std::to_string(v); }
std::string showValue(std::uint64_t v) { return std::to_string(v); }
std::string showValue(bool v) { return v ? "true" : "false"; }
std::string showValue(SeedLayout v) { return toString(v); }

template <class S, class T, class Convert>
Field field(S Params::*section, T S::*member, const char* key, const char* expected,
            Convert convert, bool required) {
  Field f;
  f.key = key;
  f.expected = expected;
  f.required = required;
  f.set = [=](Params& p, const YAML::Node& n) { (p.*section).*member = convert(n); };
  f.show = [=](const Params& p) { return showValue((p.*section).*member); };
  return f;
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
/// A value that a rule may derive instead (`factor`, NaN when unused), and the rule's factor: each
/// setter clears the other's way, so that whichever of the two the file chain and the overrides
/// give last holds (a file's rule, a --set value over it; or the other way round).
Field ruledNumber(double IceParams::*member, double IceParams::*factor, const char* key, Range range,
                  const char* factor_key) {
  Field f = number(&Params::ice, member, key, range, kRequired);
  f.set = [=](Params& p, const YAML::Node& n) {
    p.ice.*member = viaYaml<double>(n);
    p.ice.*factor = std::numeric_limits<double>::quiet_NaN();
  };
  f.derived = [=](const Params& p) { return !std::isnan(p.ice.*factor); };
  f.alternative = factor_key;
  return f;
}
Field ruleFactor(double IceParams::*factor, const char* key, Range range, const char* value_key) {
  Field f = number(&Params::ice, factor, key, range);
  f.set = [=](Params& p, const YAML::Node& n) {
    const double v = viaYaml<double>(n);
    if (std::isnan(v)) throw BadValue(describe(n));  // NaN would read as "no rule", not as a bad value
    p.ice.*factor = v;
  };
  f.show = [=](const Params& p) { return std::isnan(p.ice.*factor) ? std::string() : showValue(p.ice.*factor); };
  f.rule_factor = true;
  f.alternative = value_key;
  return f;
}

/// Marks a key that `thin_ice run --resume DIR --set` may change under a run that is under way:
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

}  // namespace

const std::vector<Section>& sections() {
  using P = Params;
  static const std::vector<Section> table = {
      {"ice",
       {number(&P::ice, &IceParams::thickness, "thickness", kThickness, kRequired),
        number(&P::ice, &IceParams::density, "density", kIceDensity, kRequired),
        onResume(number(&P::ice, &IceParams::flexural_strength, "flexural_strength", kStrength, kRequired)),
        onResume(number(&P::ice, &IceParams::compressive_strength, "compressive_strength", kStrength, kRequired)),
        onResume(number(&P::ice, &IceParams::youngs_modulus, "youngs_modulus", kModulus, kRequired)),
        onResume(ruledNumber(&IceParams::vertical_modulus, &IceParams::vertical_modulus_floating_plate_multiple,
                             "vertical_modulus", kModulus, "vertical_modulus_floating_plate_multiple")),
        onResume(ruleFactor(&IceParams::vertical_modulus_floating_plate_multiple,
                            "vertical_modulus_floating_plate_multiple",
                            {0.0, 1e6, kOpen, kClosed, "", "E_v as a multiple of the floating plate's (docs/model.md)"},
                            "vertical_modulus")),
        onResume(number(&P::ice, &IceParams::poisson_ratio, "poisson_ratio",
                        {0.0, 0.5, kClosed, kOpen, "", "3E/(1-nu) and G = E/(2(1+nu)) need nu in [0, 0.5)"},
                        kRequired)),
        onResume(number(&P::ice, &IceParams::smoothing_exponent_h, "smoothing_exponent_h", kExponent, kRequired)),
        onResume(number(&P::ice, &IceParams::smoothing_exponent_v, "smoothing_exponent_v", kExponent, kRequired)),
        onResume(ruledNumber(&IceParams::compression_coupling, &IceParams::compression_coupling_strength_fraction,
                             "compression_coupling", kCoupling, "compression_coupling_strength_fraction")),
        onResume(ruleFactor(&IceParams::compression_coupling_strength_fraction, "compression_coupling_strength_fraction",
                            {0.0, 10.0, kClosed, kClosed, "", "k of Eq. (13) as a fraction of sigma_f / sigma_comp"},
                            "compression_coupling")),
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
void deriveRuleValues(Params& p) {
  IceParams& ice = p.ice;
  if (!std::isnan(ice.vertical_modulus_floating_plate_multiple)) {
    ice.vertical_modulus = ice.vertical_modulus_floating_plate_multiple *
                           floatingPlateVerticalModulus(ice.youngs_modulus, ice.poisson_ratio, ice.thickness,
                                                        p.water.density, p.water.gravity);
  }
  if (!std::isnan(ice.compression_coupling_strength_fraction)) {
    ice.compression_coupling = ice.compression_coupling_strength_fraction * ice.flexural_strength /
                               ice.compressive_strength;
  }
}

const Section& findSection(const std::string& name, const std::string& where) {
  std::string allowed;
  for (const Section& s : sections()) {
    if (s.name == name) return s;
    allowed += " " + s.name;
  }
  throw ScenarioError(where + "unknown section '" + printable(name) + "'; allowed:" + allowed);
}

namespace {

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

}  // namespace

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

}  // namespace scenario_keys
}  // namespace thin_ice
