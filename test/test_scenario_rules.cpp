// Rules for derived values (E_v from the floating plate, k from the strengths) and the whole
// parameter set a run records (scenarioParameters): worked out by hand, the later of a value and
// its rule holding, a bad rule refused by its own key, and the set reading back bit for bit.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "scenario_file_test.hpp"
#include "thin_ice_sim/scenario.hpp"

namespace thin_ice {
namespace {

using namespace scenario_test;

// ----- Rules for derived values, and the whole parameter set --------------------------------

TEST_F(ScenarioFileTest, EvAndKAreWorkedOutByTheirRulesFromTheSeriesIce) {
  // W-3 (h = 0.052 m, E = 103 MPa, sigma_f = 42 kPa, sigma_comp = 54 kPa; nu = 0.3, rho_w = 1000
  // kg/m^3, g = 9.81 m/s^2). The floating plate: D = E h^3 / (12 (1 - nu^2)) = 1326.2476 N m,
  // l^2 = sqrt(D / (rho_w g)) = 0.367687 m^2; E_v = 4 x 2 (1 + nu) rho_w g l^2 / h = 721401.11 Pa.
  // k = 0.5 x 42 / 54 = 0.388889.
  const std::string path = kScenarioDir + "W-3.yaml";
  const Params p = loadScenario(path, {"ice.vertical_modulus_floating_plate_multiple=4",
                                       "ice.compression_coupling_strength_fraction=0.5"}).params;
  EXPECT_NEAR(p.ice.vertical_modulus, 721401.11, 0.01);
  EXPECT_NEAR(p.ice.compression_coupling, 0.388889, 1e-6);
  // The rule follows its inputs: E four times stiffer gives l^2 twice, so E_v twice.
  const Params stiffer = loadScenario(path, {"ice.youngs_modulus=412e6", "ice.vertical_modulus_floating_plate_multiple=4"}).params;
  EXPECT_NEAR(stiffer.ice.vertical_modulus, 2.0 * 721401.11, 0.02);
}

TEST_F(ScenarioFileTest, WhicheverOfAValueAndItsRuleComesLastHolds) {
  // quick.yaml gives E_v by its rule (M-2's ice: 1.27491e6 Pa, where a value of 1.276e6, the rule
  // rounded, stood before). Then a value given by --set: the value (a sensitivity run at a stated E_v).
  const std::string ruled = write("ruled.yaml", quick_);
  const double rule_value = loadScenario(ruled).params.ice.vertical_modulus;
  EXPECT_NEAR(rule_value, 1.274907e6, 1.0);
  EXPECT_EQ(loadScenario(ruled, {"ice.vertical_modulus=103e6"}).params.ice.vertical_modulus, 103e6);
  // A file's value, then a rule given by --set: the rule.
  const std::string stated = write("stated.yaml", withLine(quick_, "ice", "vertical_modulus_floating_plate_multiple",
                                                           "  vertical_modulus: 1.276e6"));
  EXPECT_EQ(loadScenario(stated).params.ice.vertical_modulus, 1.276e6);
  EXPECT_EQ(loadScenario(stated, {"ice.vertical_modulus_floating_plate_multiple=4"}).params.ice.vertical_modulus,
            rule_value);
  // In a chain: the base's rule, the series' value; and the base alone, its rule (k = 1 x 108/130).
  write("rule_base.yaml", withLine(quick_, "ice", "compression_coupling_strength_fraction",
                                   "  compression_coupling_strength_fraction: 1"));
  const Params chained = loadScenario(write("on_rule.yaml", "base: rule_base.yaml\nice:\n  compression_coupling: 0.2\n")).params;
  EXPECT_EQ(chained.ice.compression_coupling, 0.2);
  EXPECT_NEAR(loadScenario((dir_ / "rule_base.yaml").string()).params.ice.compression_coupling,
              108.0 / 130.0, 1e-12);
}

TEST_F(ScenarioFileTest, AValueGivenNeitherWayOrABadRuleIsRefusedByItsOwnKey) {
  expectError("neither.yaml", withLine(quick_, "ice", "vertical_modulus_floating_plate_multiple", ""),
              {"missing required key ice.vertical_modulus", "or ice.vertical_modulus_floating_plate_multiple"});
  expectError("zero-rule.yaml", quick_, {"ice.vertical_modulus_floating_plate_multiple", "0"},
              {"ice.vertical_modulus_floating_plate_multiple=0"});
  // NaN would read as "no rule": refused as a bad value.
  expectError("nan-rule.yaml", quick_, {"ice.compression_coupling_strength_fraction", "expected a number"},
              {"ice.compression_coupling_strength_fraction=.nan"});
  // A bad input of the rule is blamed on that input, not on the E_v it would give.
  const std::string message = errorOf(write("bad-input.yaml", quick_), {"ice.poisson_ratio=0.7"});
  EXPECT_NE(message.find("ice.poisson_ratio"), std::string::npos) << message;
  EXPECT_EQ(message.find("ice.vertical_modulus"), std::string::npos) << message;
}

TEST(ScenarioParameters, TheWholeSetGivenAsOverridesGivesTheSameParametersBitForBit) {
  // What a run records (summary.json "parameters") must give back its parameters exactly, whatever
  // the file says: every shipped scenario, and one with both rules in use.
  std::vector<std::pair<std::string, std::vector<std::string>>> cases;
  for (const auto& entry : fs::directory_iterator(kScenarioDir)) {
    if (entry.path().extension() == ".yaml") cases.push_back({entry.path().string(), {}});
  }
  cases.push_back({kScenarioDir + "W-3.yaml",
                   {"ice.vertical_modulus_floating_plate_multiple=4", "ice.compression_coupling_strength_fraction=0.5",
                    "ice.poisson_ratio=0.33", "sheet.seed=7"}});
  ASSERT_GE(cases.size(), 9u);
  for (const auto& [path, overrides] : cases) {
    const Params original = loadScenario(path, overrides).params;
    const std::vector<ParameterValue> recorded = scenarioParameters(original);
    std::vector<std::string> as_overrides;
    for (const ParameterValue& v : recorded) as_overrides.push_back(v.key + "=" + v.value);
    // Onto a different scenario's file: nothing of it may survive.
    const Params again = loadScenario(kScenarioDir + "S-2.yaml", as_overrides).params;
    const std::vector<ParameterValue> given_back = scenarioParameters(again);
    ASSERT_EQ(given_back.size(), recorded.size()) << path;
    for (size_t k = 0; k < recorded.size(); ++k) {
      EXPECT_EQ(given_back[k].key, recorded[k].key) << path;
      EXPECT_EQ(given_back[k].value, recorded[k].value) << path << " " << recorded[k].key;
    }
    EXPECT_EQ(again.ice.vertical_modulus, original.ice.vertical_modulus) << path;
    EXPECT_EQ(again.ice.compression_coupling, original.ice.compression_coupling) << path;
    EXPECT_EQ(again.ice.thickness, original.ice.thickness) << path;
    EXPECT_EQ(again.water.gravity, original.water.gravity) << path;
    EXPECT_EQ(again.sheet.seed, original.sheet.seed) << path;
  }
}

TEST(ScenarioParameters, EveryKeyOfTheFormatIsListedOnceAndAnUnusedRuleNotAtAll) {
  // E_v stated as a value (its rule unused), k by its rule.
  const Params p = loadScenario(kScenarioDir + "quick.yaml", {"ice.vertical_modulus=1.276e6"}).params;
  std::set<std::string> keys;
  for (const ParameterValue& v : scenarioParameters(p)) {
    EXPECT_TRUE(keys.insert(v.key).second) << v.key << " twice";
    EXPECT_FALSE(v.value.empty()) << v.key;
  }
  EXPECT_EQ(keys.count("ice.vertical_modulus"), 1u);
  EXPECT_EQ(keys.count("ice.vertical_modulus_floating_plate_multiple"), 0u);
  EXPECT_EQ(keys.count("ice.compression_coupling"), 1u);
  EXPECT_EQ(keys.count("ice.compression_coupling_strength_fraction"), 1u);
  EXPECT_EQ(keys.count("sheet.layout"), 1u);
  EXPECT_EQ(keys.count("bottom.enabled"), 1u);
  EXPECT_EQ(keys.count("numerics.threads"), 1u);
  // The shortest text that reads back: 0.052, not 0.051999999999999998.
  for (const ParameterValue& v : scenarioParameters(loadScenario(kScenarioDir + "W-3.yaml").params)) {
    if (v.key == "ice.thickness") EXPECT_EQ(v.value, "0.052");
  }
}

}  // namespace
}  // namespace thin_ice
