// Scenario files (scenario.hpp): the shipped scenarios load and carry Table 5's numbers,
// overrides work, and every kind of bad input gives a one-line ScenarioError naming the file,
// the key and what is allowed or expected. Bad files are made by editing the text of quick.yaml.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iomanip>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "thin_ice_sim/ice_sheet.hpp"
#include "thin_ice_sim/model.hpp"
#include "thin_ice_sim/scenario.hpp"
#include "thin_ice_sim/simulation.hpp"
#include "scenario_file_test.hpp"

namespace thin_ice {
namespace {

using namespace scenario_test;

// Relative tolerance on numbers read from YAML text (they parse to the nearest double).
constexpr double kTolRead = 1e-12;

/// Reference 64-bit FNV-1a, as documented in scenario.cpp.
std::string fnv1a(const std::string& bytes) {
  std::uint64_t h = 14695981039346656037ULL;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  std::ostringstream hex;
  hex << std::hex << std::setw(16) << std::setfill('0') << h;
  return hex.str();
}

void expectNear(double expected, double actual, const char* what) {
  EXPECT_NEAR(actual, expected, kTolRead * std::abs(expected)) << what;
}

// ----- Shipped scenarios ----------------------------------------------------------------------

/// The texts a scenario's hash covers: its bases' (followed through their `base` keys), then its own.
std::string chainText(const std::string& path) {
  const YAML::Node root = YAML::LoadFile(path);
  if (!root["base"]) return readText(path);
  return chainText((fs::path(path).parent_path() / root["base"].as<std::string>()).string()) + readText(path);
}

TEST(Scenario, EveryShippedScenarioLoads) {
  std::set<std::string> found;
  for (const auto& entry : fs::directory_iterator(kScenarioDir)) {
    if (entry.path().extension() != ".yaml") continue;
    const std::string path = entry.path().string();
    Scenario s;
    ASSERT_NO_THROW(s = loadScenario(path)) << path;
    EXPECT_EQ(s.name, entry.path().stem().string());
    EXPECT_EQ(s.source, path);
    EXPECT_EQ(s.hash, fnv1a(chainText(path)));
    EXPECT_NO_THROW(validateParams(s.params, path));
    found.insert(s.name);
  }
  for (const char* name : {"W-1", "W-2", "W-3", "M-1", "M-2", "S-1", "S-2", "quick"}) {
    EXPECT_EQ(found.count(name), 1u) << name << ".yaml is missing";
  }
}

TEST(Scenario, M2ReproducesTable5AndTable4) {
  const Params p = loadScenario(kScenarioDir + "M-2.yaml").params;
  expectNear(0.051, p.ice.thickness, "h");
  expectNear(920.0, p.ice.density, "rho");
  expectNear(108e3, p.ice.flexural_strength, "sigma_f");
  expectNear(130e3, p.ice.compressive_strength, "sigma_c");
  expectNear(328e6, p.ice.youngs_modulus, "E");
  // E_v, the phase-2 reading (docs/model.md, "The choice of E_v"): four times the E_v whose sheet of
  // vertical shear springs has the floating-plate length l = [E h^3 / (12 (1 - nu^2) rho_w g)]^(1/4),
  // G_v = rho_w g l^2 / h, E_v = 2 (1 + nu) G_v. The file gives it to four significant digits.
  const double plate_length = std::pow(328e6 * std::pow(0.051, 3) / (12.0 * (1.0 - 0.09) * 1000.0 * 9.81), 0.25);
  EXPECT_NEAR(p.ice.vertical_modulus, 4.0 * 2.0 * 1.3 * 1000.0 * 9.81 * plate_length * plate_length / 0.051,
              2e-3 * 1.276e6);
  expectNear(1.0, p.ice.smoothing_exponent_h, "n (Table 1, medium)");
  expectNear(1.0, p.ice.smoothing_exponent_v, "n_v");
  EXPECT_NEAR(p.ice.compression_coupling, 0.5 * 108.0 / 130.0, 1e-3);
  // Table 4 set-up.
  expectNear(10.0, p.structure.width, "structure width");
  expectNear(1.0, p.structure.height, "structure height");
  expectNear(60.0, p.structure.angle_deg, "angle");
  expectNear(0.5, p.structure.side_panel_length, "side panels");
  expectNear(1.7e11, p.structure.stiffness, "K_struct");
  expectNear(0.63, p.structure.calibration_factor, "alpha");  // Eq. (18), the paper's one factor
  expectNear(0.05, p.pusher.velocity, "pusher");
  expectNear(0.0, p.pusher.friction, "ice-pusher friction");  // a smooth plate, as before the key
  EXPECT_TRUE(p.bottom.enabled);
  expectNear(4.0, p.bottom.distance_from_structure, "false bottom");
  expectNear(0.55, p.bottom.friction, "ice-bottom friction");
  // The sheet and the numerics of the validation runs.
  expectNear(24.0, p.sheet.length, "sheet length");
  expectNear(10.0, p.sheet.width, "sheet width");
  expectNear(10.0, p.channel.width, "channel width");
  expectNear(24.05, p.structure.toe_x, "toe");  // 5 cm in front of the 24 m sheet
  expectNear(0.2, p.sheet.cell_size, "cell size");
  EXPECT_EQ(p.sheet.layout, SeedLayout::kJitteredGrid);
  EXPECT_EQ(p.sheet.seed, 1u);
  // dt within the ice's critical step, the 1.7e11 Pa structure in five sub-steps of 5e-6 s
  expectNear(2.5e-5, p.numerics.time_step, "dt");
  EXPECT_EQ(p.numerics.structure_substeps, 5);
}

TEST(Scenario, S1ReproducesTable5) {
  const Params p = loadScenario(kScenarioDir + "S-1.yaml").params;
  expectNear(0.052, p.ice.thickness, "h");
  expectNear(915.0, p.ice.density, "rho");
  expectNear(211e3, p.ice.flexural_strength, "sigma_f");
  expectNear(214e3, p.ice.compressive_strength, "sigma_c");
  expectNear(2023e6, p.ice.youngs_modulus, "E");
  expectNear(0.5, p.ice.smoothing_exponent_h, "n (Table 1, strong)");
  expectNear(0.5, p.ice.smoothing_exponent_v, "n_v");
  EXPECT_NEAR(p.ice.compression_coupling, 0.5 * 211.0 / 214.0, 1e-3);
}

TEST(Scenario, WeakIceUsesSmoothingExponentTwo) {
  for (const char* name : {"W-1", "W-2", "W-3"}) {
    const Params p = loadScenario(kScenarioDir + name + ".yaml").params;
    expectNear(2.0, p.ice.smoothing_exponent_h, name);
    expectNear(2.0, p.ice.smoothing_exponent_v, name);
  }
}

TEST(Scenario, QuickIsMediumIceOnASmallStrip) {
  const Params quick = loadScenario(kScenarioDir + "quick.yaml").params;
  const Params m2 = loadScenario(kScenarioDir + "M-2.yaml").params;
  EXPECT_EQ(quick.ice.thickness, m2.ice.thickness);
  EXPECT_EQ(quick.ice.flexural_strength, m2.ice.flexural_strength);
  EXPECT_EQ(quick.ice.youngs_modulus, m2.ice.youngs_modulus);
  const double cells =
      quick.sheet.length * quick.sheet.width / (quick.sheet.cell_size * quick.sheet.cell_size);
  EXPECT_LE(cells, 300.0);
  EXPECT_GT(quick.structure.toe_x, quick.sheet.x_min + quick.sheet.length);
  // The ice front reaches the structure within a couple of seconds.
  const double gap = quick.structure.toe_x - (quick.sheet.x_min + quick.sheet.length);
  EXPECT_LE(gap / quick.pusher.velocity, 2.0);
}

TEST(Scenario, ValidateParamsAcceptsDefaultsAndNamesTheSource) {
  EXPECT_NO_THROW(validateParams(Params{}, "built in code"));
  Params p;
  p.ice.poisson_ratio = 0.5;
  try {
    validateParams(p, "built in code");
    FAIL() << "nu = 0.5 accepted";
  } catch (const ScenarioError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("built in code: ice.poisson_ratio = 0.5", 0), 0u) << m;
    EXPECT_NE(m.find("allowed: [0, 0.5)"), std::string::npos) << m;
  }
}

// ----- Overrides and defaults -----------------------------------------------------------------

TEST_F(ScenarioFileTest, FilesAreReadWithinBoundsAndEchoedReadably) {
  // Each refused in one line naming the file: a device read until memory ran out, a file over
  // 1 MiB, a second YAML document that was ignored, a long scalar echoed whole, raw bytes echoed.
  auto refusal = [](const std::string& path) {
    try {
      loadScenario(path);
    } catch (const ScenarioError& e) {
      return std::string(e.what());
    }
    ADD_FAILURE() << path << " was accepted";
    return std::string();
  };
  std::string m = refusal("/dev/zero");
  EXPECT_NE(m.find("/dev/zero: is not a regular file"), std::string::npos) << m;
  m = refusal(write("big.yaml", std::string((1 << 20) + 1, '#')));
  EXPECT_NE(m.find("1048577 bytes; allowed: a scenario file of at most 1048576 bytes"), std::string::npos) << m;
  m = refusal(write("two.yaml", quick_ + "\n---\nice: {thickness: 1}\n"));
  EXPECT_NE(m.find("2 YAML documents"), std::string::npos) << m;
  m = refusal(write("scalar.yaml", std::string(500000, 'x') + "\n"));
  EXPECT_LT(m.size(), 400u) << "the message echoes the long scalar whole";
  EXPECT_NE(m.find(std::string(80, 'x') + "..."), std::string::npos) << m.substr(0, 200);
  m = refusal(write("bytes.yaml", std::string("ice:\n  \x01\xfe: 1\n")));
  for (const char c : m) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "a raw byte in: " << m;
}

TEST_F(ScenarioFileTest, TheThreadCountIsBoundedAtLoadAndCappedAtTheCoresPresent) {
  // Above 1024 no machine has the cores: refused at load, naming the key (2147483647 used to end in
  // std::bad_alloc, 1000 in a libgomp abort). A valid count above the cores present runs on the
  // cores present, and the backend's note says so.
  const std::string path = kScenarioDir + "quick.yaml";
  for (const char* bad : {"numerics.threads=1025", "numerics.threads=2147483647", "numerics.threads=-1"}) {
    try {
      loadScenario(path, {bad});
      ADD_FAILURE() << bad << " was accepted";
    } catch (const ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find("numerics.threads"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("[0, 1024]"), std::string::npos) << e.what();
    }
  }
  const Simulation many(loadScenario(path, {"numerics.threads=1024"}), BackendKind::kCpu);
  EXPECT_NE(many.backendNote().find("numerics.threads = 1024 capped at the"), std::string::npos) << many.backendNote();
}

TEST_F(ScenarioFileTest, TheReadingsTheRunsRejectedAreRefusedWithTheReason) {
  // Issue #31's readings b, c, d and the shallower Eq. (3) left the engine: the key is gone, and a
  // file or a --set naming it is told why instead of "unknown key".
  const std::string path = kScenarioDir + "quick.yaml";
  struct Bad { const char* set; const char* key; const char* allowed; };
  for (const Bad& bad : {Bad{"ice.failure_compression=strength", "ice.failure_compression",
                             "was removed: sigma_comp of Eq. (13) is the bond's present compression"},
                         Bad{"ice.bond_smoothing=strength", "ice.bond_smoothing",
                             "was removed: K of Eq. (6) scales the bond's springs"},
                         Bad{"ice.contact_face=thickness", "ice.contact_face", "was removed: Eq. (1) with the face h"},
                         Bad{"ice.curvature_failure=false", "ice.curvature_failure",
                             "was removed: the curvature criterion (beyond the paper)"},
                         Bad{"ice.curvature_failure_scope=all", "ice.curvature_failure_scope", "was removed"},
                         Bad{"ice.plate_bending=false", "ice.plate_bending",
                             "was removed: the Kirchhoff plate term (beyond the paper)"},
                         Bad{"ice.vertical_contact_depth=shallower", "ice.vertical_contact_depth",
                             "was removed: the depth min(Z, S/L)"},
                         Bad{"ice.vertical_stress=shear", "ice.vertical_stress",
                             "was removed: sigma_v of Eq. (13) is the bending stress"},
                         Bad{"ice.vertical_slip_friction=level_only", "ice.vertical_slip_friction",
                             "was removed: the edge face of offset cells always resists"}}) {
    try {
      loadScenario(path, {bad.set});
      ADD_FAILURE() << bad.set << " was accepted";
    } catch (const ScenarioError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(bad.key), std::string::npos) << m;
      EXPECT_NE(m.find(bad.allowed), std::string::npos) << m;
    }
  }
}

TEST_F(ScenarioFileTest, OverridesApplyAfterTheFileAndChangeTheHash) {
  const std::string path = kScenarioDir + "quick.yaml";
  const Scenario base = loadScenario(path);
  const std::vector<std::string> overrides = {"ice.thickness=0.06", "ice.friction_ice_ice=0.25",
                                              "structure.panels=4", "bottom.enabled=false",
                                              "sheet.seed=42"};
  const Scenario s = loadScenario(path, overrides);
  EXPECT_EQ(s.params.ice.thickness, 0.06);
  EXPECT_EQ(s.params.ice.friction_ice_ice, 0.25);
  EXPECT_EQ(s.params.structure.panels, 4);
  EXPECT_FALSE(s.params.bottom.enabled);
  EXPECT_EQ(s.params.sheet.seed, 42u);
  EXPECT_EQ(s.params.ice.density, base.params.ice.density);  // untouched keys stay
  EXPECT_EQ(s.overrides, overrides);
  std::string hashed = readText(path);
  for (const std::string& o : overrides) hashed += o + "\n";
  EXPECT_EQ(s.hash, fnv1a(hashed));
  EXPECT_NE(s.hash, base.hash);
  EXPECT_EQ(loadScenario(path, overrides).hash, s.hash);
}

TEST_F(ScenarioFileTest, OptionalKeysAndSectionsTakeTheDefaults) {
  std::string text = withLine(quick_, "ice", "friction_ice_ice", "");
  text = withLine(text, "numerics", "threads", "");
  const Params p = loadScenario(write("optional.yaml", text)).params;
  EXPECT_EQ(p.ice.friction_ice_ice, IceParams{}.friction_ice_ice);
  EXPECT_EQ(p.numerics.threads, NumericsParams{}.threads);
}

// ----- Bad input: one line naming the file, the key and what is allowed/expected --------------

TEST_F(ScenarioFileTest, UnknownKey) {
  expectError("unknown-key.yaml", withLine(quick_, "ice", "thickness", "  thicknes: 0.05"),
              {"unknown key 'thicknes'", "section 'ice'", "allowed:", "thickness"});
}

TEST_F(ScenarioFileTest, UnknownSection) {
  expectError("unknown-section.yaml", quick_ + "waves:\n  height: 1.0\n",
              {"unknown section 'waves'", "allowed:", "numerics"});
}

TEST_F(ScenarioFileTest, MissingRequiredKey) {
  expectError("missing-key.yaml", withLine(quick_, "ice", "thickness", ""),
              {"missing required key ice.thickness", "expected a number"});
  expectError("missing-toe.yaml", withLine(quick_, "structure", "toe_x", ""),
              {"missing required key structure.toe_x", "expected"});
}

TEST_F(ScenarioFileTest, WrongTypes) {
  expectError("text-for-number.yaml", withValue(quick_, "ice", "thickness", "abc"),
              {"ice.thickness", "expected a number", "'abc'"});
  expectError("quoted-number.yaml", withValue(quick_, "ice", "thickness", "\"0.05\""),
              {"ice.thickness", "expected a number", "quoted"});
  expectError("list-for-number.yaml", withValue(quick_, "ice", "density", "[920, 930]"),
              {"ice.density", "expected a number", "a list"});
  expectError("float-for-integer.yaml", withValue(quick_, "structure", "panels", "2.5"),
              {"structure.panels", "expected an integer", "'2.5'"});
  expectError("negative-seed.yaml", withValue(quick_, "sheet", "seed", "-1"),
              {"sheet.seed", "expected a non-negative integer"});
  expectError("non-bool.yaml", withValue(quick_, "bottom", "enabled", "maybe"),
              {"bottom.enabled", "expected true or false", "'maybe'"});
  expectError("bad-layout.yaml", withValue(quick_, "sheet", "layout", "hexagonal"),
              {"sheet.layout", "expected jittered_grid or poisson_disk"});
}

TEST_F(ScenarioFileTest, NonPositiveThickness) {
  expectError("zero-thickness.yaml", withValue(quick_, "ice", "thickness", "0"),
              {"ice.thickness = 0 is invalid", "allowed: [0.001, 5] m"});
  expectError("negative-thickness.yaml", withValue(quick_, "ice", "thickness", "-0.05"),
              {"ice.thickness = -0.05 is invalid", "allowed: [0.001, 5] m"});
}

TEST_F(ScenarioFileTest, PoissonRatioOfOneHalf) {
  expectError("nu.yaml", withValue(quick_, "ice", "poisson_ratio", "0.5"),
              {"ice.poisson_ratio = 0.5 is invalid", "allowed: [0, 0.5)"});
}

TEST_F(ScenarioFileTest, NegativeDensity) {
  expectError("density.yaml", withValue(quick_, "ice", "density", "-920"),
              {"ice.density = -920 is invalid", "allowed: [500, 1000] kg/m^3"});
}

// Values that passed a sign check and then blew up at the first step, ran on with absurd
// geometry, or were blamed on another key (sheet.cell_size, numerics.time_step): each is refused
// by its own key's physical range, before anything is derived from it.
TEST_F(ScenarioFileTest, HugeOrTinyFiniteValuesAreRefusedByTheirOwnKey) {
  struct Case {
    const char *section, *key, *value, *refused, *allowed;
  };
  for (const Case& c : {Case{"ice", "thickness", "1e300", "1e+300", "[0.001, 5] m"},
                        Case{"ice", "youngs_modulus", "1e300", "1e+300", "[1000, 2e+10] Pa"},
                        Case{"sheet", "length", "1e300", "1e+300", "(0, 10000] m"},
                        Case{"ice", "flexural_strength", "1e-300", "1e-300", "[1000, 1e+08] Pa"},
                        Case{"pusher", "velocity", "1e6", "1e+06", "[-10, 10] m/s"},
                        Case{"water", "gravity", "1e300", "1e+300", "[1, 30] m/s^2"},
                        Case{"structure", "width", "1e300", "1e+300", "(0, 10000] m"},
                        Case{"structure", "toe_x", "1e300", "1e+300", "[-10000, 10000] m"},
                        Case{"water", "linear_drag", "1e300", "1e+300", "[0, 1e+06]"}}) {
    const std::string key = std::string(c.section) + "." + c.key;
    expectError(key + ".yaml", withValue(quick_, c.section, c.key, c.value),
                {key + " = " + c.refused + " is invalid", std::string("allowed: ") + c.allowed});
  }
}

// A derived condition names every key it comes from: ice must float on the water.
TEST_F(ScenarioFileTest, IceDenserThanTheWaterIsRefusedNamingBoth) {
  expectError("sinks.yaml", withValue(quick_, "water", "density", "910"),
              {"ice.density = 920 is invalid", "does not float", "water.density = 910"});
}

TEST_F(ScenarioFileTest, NotFinite) {
  expectError("nan.yaml", withValue(quick_, "water", "gravity", ".nan"),
              {"water.gravity = nan is invalid", "finite", "allowed"});
}

TEST_F(ScenarioFileTest, CellSizeBelowThicknessAndAreaRatio) {
  expectError("tiny-cells.yaml", withValue(quick_, "sheet", "cell_size", "0.04"),
              {"sheet.cell_size = 0.04 is invalid", "thickness", "allowed: >= sqrt(10) h"});
  expectError("small-cells.yaml", withValue(quick_, "sheet", "cell_size", "0.12"),
              {"sheet.cell_size = 0.12 is invalid", "A/h^2 > 10", "allowed"});
}

TEST_F(ScenarioFileTest, SheetChecksFromIceSheetValidate) {
  expectError("jitter.yaml", withValue(quick_, "sheet", "jitter", "0.7"),
              {"sheet.jitter = 0.7 is invalid", "allowed: [0, 0.5]"});
}

TEST_F(ScenarioFileTest, RangeChecksOnOtherSections) {
  expectError("angle.yaml", withValue(quick_, "structure", "angle_deg", "90"),
              {"structure.angle_deg = 90 is invalid", "allowed: (0, 90)"});
  expectError("damping.yaml", withValue(quick_, "ice", "bond_damping_ratio", "1.5"),
              {"ice.bond_damping_ratio = 1.5 is invalid", "allowed: [0, 1]"});
  expectError("toe.yaml", withValue(quick_, "structure", "toe_x", "2.0"),
              {"structure.toe_x = 2 is invalid", "allowed: >= 3 m"});
  expectError("substeps.yaml", withValue(quick_, "numerics", "structure_substeps", "0"),
              {"numerics.structure_substeps = 0 is invalid", "allowed: integer in [1, 1000]"});
  expectError("pusher.yaml", withValue(quick_, "pusher", "friction", "-0.1"),
              {"pusher.friction = -0.1 is invalid", "allowed: [0, 2]"});
}

TEST_F(ScenarioFileTest, DuplicateKey) {
  const std::string twice =
      withLine(quick_, "ice", "thickness", "  thickness: 0.05\n  thickness: 0.06");
  expectError("duplicate.yaml", twice, {"ice.thickness", "twice"});
}

TEST_F(ScenarioFileTest, BadOverrides) {
  const std::string path = write("override.yaml", quick_);
  const std::string no_value = errorOf(path, {"ice.thickness"});
  for (const char* part : {"override.yaml", "ice.thickness", "expected section.key=value"}) {
    EXPECT_NE(no_value.find(part), std::string::npos) << no_value;
  }
  const std::string bad_value = errorOf(path, {"ice.thickness=abc"});
  EXPECT_NE(bad_value.find("override 'ice.thickness=abc'"), std::string::npos) << bad_value;
  EXPECT_NE(bad_value.find("expected a number"), std::string::npos) << bad_value;
  const std::string out_of_range = errorOf(path, {"ice.thickness=-0.06"});
  EXPECT_NE(out_of_range.find("override 'ice.thickness=-0.06': ice.thickness = -0.06 is invalid"),
            std::string::npos)
      << out_of_range;
  const std::string cross = errorOf(path, {"ice.thickness=0.1"});  // cell 0.2 < sqrt(10) 0.1
  EXPECT_NE(cross.find("override 'ice.thickness=0.1': sheet.cell_size"), std::string::npos)
      << cross;
  const std::string unknown = errorOf(path, {"ice.thicknes=0.06"});
  EXPECT_NE(unknown.find("unknown key 'thicknes'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("allowed:"), std::string::npos) << unknown;
}

TEST(OverrideKey, NamesTheKeyAsTheParserReadsIt) {
  EXPECT_EQ(overrideKey("ice.friction_ice_ice=0.3", "f.yaml"), "ice.friction_ice_ice");
  EXPECT_EQ(overrideKey(" sheet . jitter = 0.2", "f.yaml"), "sheet.jitter");  // spaces, as applied
  EXPECT_EQ(overrideKey("numerics.threads=2", "f.yaml"), "numerics.threads");
  auto message = [](const std::string& text) {
    try {
      overrideKey(text, "f.yaml");
    } catch (const ScenarioError& e) {
      return std::string(e.what());
    }
    return std::string("no ScenarioError");
  };
  const std::string no_value = message("ice.friction_ice_ice");
  EXPECT_NE(no_value.find("f.yaml: override 'ice.friction_ice_ice': expected section.key=value"), std::string::npos)
      << no_value;
  const std::string unknown = message("ice.friction_ice_ic=0.3");
  EXPECT_NE(unknown.find("unknown key 'friction_ice_ic'"), std::string::npos) << unknown;
  const std::string section = message("icee.thickness=1");
  EXPECT_NE(section.find("f.yaml: override 'icee.thickness=1': unknown section 'icee'"), std::string::npos)
      << section;
}


// The registry of keys says which may change under a run that is under way: the laws and the
// contact planes may, the mesh, the masses, the geometry, the stepping and the calibration may not.
TEST(SwitchableOnResume, TheRegistryMarksTheLawsAndNotTheMeshOrTheCalibration) {
  for (const char* key : {"ice.friction_ice_ice", "ice.vertical_modulus", "ice.flexural_strength", "bottom.depth",
                          "structure.friction", "water.quadratic_drag", "numerics.threads"}) {
    EXPECT_TRUE(switchableOnResume(key)) << key;
  }
  for (const char* key : {"ice.thickness", "ice.density", "sheet.cell_size", "sheet.seed", "structure.toe_x",
                          "structure.width", "structure.calibration_factor", "pusher.velocity",
                          "numerics.time_step", "numerics.structure_substeps", "no.such_key", "ice"}) {
    EXPECT_FALSE(switchableOnResume(key)) << key;
  }
  const std::vector<std::string> keys = switchableOnResumeKeys();
  EXPECT_EQ(keys.size(), 29u);
  // Every key listed is one the format knows, spelt as the override parser names it.
  for (const std::string& key : keys) EXPECT_EQ(overrideKey(key + "=1", "f.yaml"), key);
  EXPECT_EQ(keys.front(), "ice.flexural_strength");  // the order of the format, ice first
}
TEST_F(ScenarioFileTest, NonexistentFile) {
  const std::string path = (dir_ / "no-such-scenario.yaml").string();
  const std::string message = errorOf(path);
  EXPECT_NE(message.find("no-such-scenario.yaml"), std::string::npos) << message;
  EXPECT_NE(message.find("no such scenario file"), std::string::npos) << message;
}

TEST_F(ScenarioFileTest, YamlSyntaxError) {
  expectError("syntax.yaml", withLine(quick_, "ice", "thickness", "  thickness: [0.05"),
              {"YAML syntax error", "line"});
  expectError("not-a-map.yaml", "- just\n- a list\n", {"expected a map of sections"});
  expectError("empty.yaml", "", {"expected a map of sections", "got nothing"});
}


// ----- Bases: a file names another whose keys it starts from ---------------------------------

TEST_F(ScenarioFileTest, ABaseGivesItsKeysAndTheFileOverridesThem) {
  // quick.yaml as the base; the file changes one key of it and adds none.
  write("quick_base.yaml", quick_);
  const std::string path = write("child.yaml", "base: quick_base.yaml\nice:\n  thickness: 0.04\n");
  const Scenario child = loadScenario(path);
  const Scenario base = loadScenario((dir_ / "quick_base.yaml").string());
  EXPECT_EQ(child.params.ice.thickness, 0.04);                         // the file's own value
  EXPECT_EQ(child.params.ice.density, base.params.ice.density);        // from the base
  EXPECT_EQ(child.params.structure.toe_x, base.params.structure.toe_x);
  EXPECT_EQ(child.name, "child");
  // The hash covers the base's text, then the file's: a change to the base is seen on resume.
  EXPECT_EQ(child.hash, fnv1a(quick_ + readText(path)));
  write("quick_base.yaml", quick_ + "# a comment\n");
  EXPECT_NE(loadScenario(path).hash, child.hash);
}

TEST_F(ScenarioFileTest, ABaseChainsAndRequiredKeysMayComeFromAnyFileOfIt) {
  write("a.yaml", quick_);
  write("b.yaml", "base: a.yaml\nsheet:\n  seed: 7\n");
  const Scenario c = loadScenario(write("c.yaml", "base: b.yaml\nsheet:\n  seed: 9\n"));
  EXPECT_EQ(c.params.sheet.seed, 9u);
  EXPECT_EQ(loadScenario((dir_ / "b.yaml").string()).params.sheet.seed, 7u);
}

TEST_F(ScenarioFileTest, ABaseThatIsMissingCyclesOrIsNotATextIsRefused) {
  expectError("orphan.yaml", "base: nowhere.yaml\n", {"base:", "nowhere.yaml", "no such scenario file"});
  write("x.yaml", "base: y.yaml\n");
  write("y.yaml", "base: x.yaml\n");
  const std::string cycle = errorOf((dir_ / "x.yaml").string());
  EXPECT_NE(cycle.find("cycle"), std::string::npos) << cycle;
  expectError("listed.yaml", "base: [a.yaml, b.yaml]\n", {"base: expected a text"});
  expectError("empty_base.yaml", "base: \"\"\n", {"base: empty"});
  // A key given twice in one file is still refused; once in the base and once in the file is not.
  write("quick_base.yaml", quick_);
  expectError("twice.yaml", "base: quick_base.yaml\nice:\n  thickness: 0.04\n  thickness: 0.05\n",
              {"ice.thickness appears twice"});
}

TEST_F(ScenarioFileTest, RequiredKeysMissingFromTheWholeChainAreNamed) {
  write("partial.yaml", "ice:\n  thickness: 0.05\n");
  expectError("on_partial.yaml", "base: partial.yaml\n", {"missing required key ice.density"});
}

}  // namespace
}  // namespace thin_ice
