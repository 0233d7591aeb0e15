// thin_ice_bond_offset: what the model's bond law makes of a height step alone, for one scenario,
// as JSON. The bond is the one of the scenario's sheet whose length (centroid to centroid) is
// nearest the cell size. The tool gives:
//   - sigma_v / sigma_f at each height step dz asked for (Eq. 13's sigma_v in the scenario's
//     reading, with no horizontal strain), and whether the bond breaks there;
//   - the largest sigma_v / sigma_f that any step 0 < dz < h gives it, and where;
//   - the least step at which Eq. (13) breaks it (null where no step alone can: it is then torn
//     through at dz = h);
//   - the curvature at which an elastic plate of the ice's E, nu and h reaches sigma_f at its
//     surface, sigma_f / (E h / (2 (1 - nu^2))).
// scripts/sheet_bending reads it, so that the thresholds it sets the sheet's shape against are
// the engine's own laws (thin_ice_sim/edge_check.hpp, physics/bond.hpp, physics/sheet_curvature.hpp).
//   thin_ice_bond_offset --scenario FILE [--set section.key=value]... [--offset DZ]...
// Exit status: 0 done; 2 bad arguments or scenario.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "thin_ice_sim/edge_check.hpp"
#include "thin_ice_sim/physics/sheet_curvature.hpp"
#include "thin_ice_sim/scenario.hpp"

namespace {

const char* kUsage =
    "usage: thin_ice_bond_offset --scenario FILE [--set section.key=value]... [--offset DZ]...\n"
    "  DZ: a height step between the bond's two cells [m]\n";

int refuse(const std::string& message) {
  std::fprintf(stderr, "thin_ice_bond_offset: %s\n", message.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scenario_path;
  std::vector<std::string> overrides;
  std::vector<double> offsets;
  for (int a = 1; a < argc; ++a) {
    const std::string flag = argv[a];
    if (flag == "-h" || flag == "--help") {
      std::printf("%s", kUsage);
      return 0;
    }
    if (a + 1 >= argc) return refuse(flag + " needs a value\n" + kUsage);
    const std::string value = argv[++a];
    if (flag == "--scenario") {
      scenario_path = value;
    } else if (flag == "--set") {
      overrides.push_back(value);
    } else if (flag == "--offset") {
      char* end = nullptr;
      const double dz = std::strtod(value.c_str(), &end);
      if (end == value.c_str() || *end != '\0' || !std::isfinite(dz)) {
        return refuse("--offset " + value + "; allowed: a finite height step in metres");
      }
      offsets.push_back(dz);
    } else {
      return refuse("unknown flag " + flag + "\n" + kUsage);
    }
  }
  if (scenario_path.empty()) return refuse(std::string("--scenario is required\n") + kUsage);

  try {
    const thin_ice::Scenario scenario = thin_ice::loadScenario(scenario_path, overrides);
    const thin_ice::Params& p = scenario.params;
    const thin_ice::IceSheet sheet = thin_ice::generateIceSheet(p.sheet);
    const thin_ice::Model model = thin_ice::buildModel(p, sheet, scenario_path);
    const int b = thin_ice::bondNearestLength(model, p.sheet.cell_size);
    if (b < 0) return refuse(scenario_path + ": the sheet has no bond");
    const thin_ice::BondRest& rest = model.bond_rest[b];
    const thin_ice::BondConstants& law = model.constants.bond;
    const double sigma_f = p.ice.flexural_strength;
    const thin_ice::LargestVerticalStress top = thin_ice::largestVerticalStress(rest, law);
    const thin_ice::BondVerticalCapacity capacity = thin_ice::bondVerticalCapacity(rest, law);
    const double plate_curvature =
        sigma_f / thin_ice::plateStressPerCurvature(p.ice.youngs_modulus, p.ice.poisson_ratio, p.ice.thickness);

    std::printf("{\"thickness_m\": %.17g, \"flexural_strength_Pa\": %.17g,\n", p.ice.thickness, sigma_f);
    std::printf(" \"bond\": {\"index\": %d, \"distance_m\": %.17g, \"edge_length_m\": %.17g},\n", b, rest.distance,
                rest.edge_length);
    std::printf(" \"largest_stress_ratio\": %.17g, \"largest_at_offset_m\": %.17g,\n", top.stress / sigma_f, top.offset);
    if (capacity.by_stress) {
      std::printf(" \"breaking_offset_m\": %.17g,\n", capacity.offset);
    } else {
      std::printf(" \"breaking_offset_m\": null,\n");
    }
    std::printf(" \"plate_breaking_curvature_per_m\": %.17g,\n \"offsets\": [", plate_curvature);
    for (size_t k = 0; k < offsets.size(); ++k) {
      const thin_ice::BondForce f = thin_ice::bondUnderOffset(rest, law, offsets[k]);
      std::printf("%s\n  {\"offset_m\": %.17g, \"stress_ratio\": %.17g, \"breaks\": %s}", k ? "," : "", offsets[k],
                  f.sigma_v / sigma_f, f.breaks ? "true" : "false");
    }
    std::printf("]}\n");
  } catch (const std::exception& e) {
    return refuse(e.what());
  }
  return 0;
}
