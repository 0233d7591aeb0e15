// `thin_ice probe bond-offset`: what the model's bond law makes of a slope of the sheet alone, for
// one scenario, as JSON. The bond is the one of the scenario's sheet whose length d (centroid to
// centroid) is nearest the cell size; a slope s sets its two cells a height step dz = s d apart,
// with no horizontal strain. The probe gives:
//   - sigma_v / sigma_f at each slope asked for (Eq. 13's sigma_v, the bond law's bending stress), and
//     whether the bond breaks there;
//   - the largest sigma_v / sigma_f that any step 0 < dz < h gives it, and at which slope (above 1
//     the bond breaks on the way there, at the breaking slope);
//   - the least slope at which Eq. (13) breaks it (null where no step alone can: it is then torn
//     through at dz = h);
//   - the curvature at which an elastic plate of the ice's E, nu and h reaches sigma_f at its
//     surface, sigma_f / (E h / (2 (1 - nu^2)));
//   - the height at which a cell's centroid floats at rest.
// scripts/study sheet_bending reads it, so that the thresholds it sets the sheet's shape against are
// the engine's own laws (thin_ice_sim/study/edge_check.hpp, physics/bond.hpp, water.hpp). The model is built without the time-step check: a stiffer ice asked about here need
// not be one a run could step.
//   thin_ice probe bond-offset --scenario FILE [--set section.key=value]... [--slope S]...
// Exit status: 0 done; 2 bad arguments or scenario.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "thin_ice_sim/study/edge_check.hpp"
#include "thin_ice_sim/physics/water.hpp"
#include "thin_ice_sim/scenario.hpp"

namespace {

const char* kUsage =
    "usage: thin_ice probe bond-offset --scenario FILE [--set section.key=value]... [--slope S]...\n"
    "  S: a slope of the sheet across the bond [-] (height step over the bond's length)\n";

/// Surface stress [Pa] of an elastic (Kirchhoff) plate per unit curvature [1/m]: sigma = 6 M / h^2
/// with M = D kappa, D = E h^3 / (12 (1 - nu^2)), so sigma / kappa = E h / (2 (1 - nu^2)).
double plateStressPerCurvature(double youngs_modulus, double poisson_ratio, double thickness) {
  return youngs_modulus * thickness / (2.0 * (1.0 - poisson_ratio * poisson_ratio));
}

int refuse(const std::string& message) {
  std::fprintf(stderr, "thin_ice probe bond-offset: %s\n", message.c_str());
  return 2;
}

/// A JSON number; throws naming `what` where the value is not finite (JSON has no inf or NaN).
std::string number(double value, const std::string& what) {
  if (!std::isfinite(value)) {
    throw std::runtime_error(what + " comes out " + std::to_string(value) +
                             "; allowed: ice values for which it is finite (ice.flexural_strength, "
                             "ice.youngs_modulus and ice.thickness of a physical size)");
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

}  // namespace

int thin_ice::cli::probeBondOffset(int argc, char** argv) {
  std::string scenario_path;
  std::vector<std::string> overrides;
  std::vector<double> slopes;
  for (int a = 1; a < argc; ++a) {
    const std::string flag = argv[a];
    if (flag == "-h" || flag == "--help") {
      std::printf("%s", kUsage);
      return 0;
    }
    if (flag != "--scenario" && flag != "--set" && flag != "--slope") {
      return refuse("unknown argument " + flag + "\n" + kUsage);
    }
    if (a + 1 >= argc) return refuse(flag + " needs a value\n" + kUsage);
    const std::string value = argv[++a];
    if (flag == "--scenario") {
      scenario_path = value;
    } else if (flag == "--set") {
      overrides.push_back(value);
    } else {
      char* end = nullptr;
      const double slope = std::strtod(value.c_str(), &end);
      if (end == value.c_str() || *end != '\0' || !std::isfinite(slope)) {
        return refuse("--slope " + value + "; allowed: a finite number (height step over length)");
      }
      slopes.push_back(slope);
    }
  }
  if (scenario_path.empty()) return refuse(std::string("--scenario is required\n") + kUsage);

  try {
    const thin_ice::Scenario scenario = thin_ice::loadScenario(scenario_path, overrides);
    thin_ice::Params p = scenario.params;
    p.numerics.critical_step_safety = 1e300;  // the bond law only: no time step is taken here
    const thin_ice::IceSheet sheet = thin_ice::generateIceSheet(p.sheet);
    const thin_ice::Model model = thin_ice::buildModel(p, sheet, scenario_path);
    const int b = thin_ice::bondNearestLength(model, p.sheet.cell_size);
    if (b < 0) {
      return refuse(scenario_path + ": the sheet of sheet.length x sheet.width at sheet.cell_size has no bond; "
                    "allowed: a sheet of at least two cells");
    }
    const thin_ice::BondRest& rest = model.bond_rest[b];
    const thin_ice::BondConstants& law = model.constants.bond;
    const double sigma_f = p.ice.flexural_strength;
    const double d = rest.distance;
    const thin_ice::LargestVerticalStress top = thin_ice::largestVerticalStress(rest, law);
    const thin_ice::BondVerticalCapacity capacity = thin_ice::bondVerticalCapacity(rest, law);

    std::ostringstream json;
    json << "{\"thickness_m\": "
         << number(p.ice.thickness, "h") << ",\n \"floating_centroid_z_m\": "
         << number(thin_ice::floatingCentroidHeight(p.ice.thickness, p.ice.density, p.water.density), "z at rest")
         << ",\n \"bond\": {\"index\": " << b << ", \"distance_m\": " << number(d, "d")
         << ", \"edge_length_m\": " << number(rest.edge_length, "L_e") << "},\n \"largest_stress_ratio\": "
         << number(top.stress / sigma_f, "the largest sigma_v / sigma_f") << ", \"largest_at_slope\": "
         << number(top.offset / d, "its slope") << ",\n \"breaking_slope\": "
         << (capacity.by_stress ? number(capacity.offset / d, "the breaking slope") : std::string("null"))
         << ",\n \"plate_breaking_curvature_per_m\": "
         << number(sigma_f / plateStressPerCurvature(p.ice.youngs_modulus, p.ice.poisson_ratio,
                                                               p.ice.thickness),
                   "the plate's breaking curvature")
         << ",\n \"slopes\": [";
    for (size_t k = 0; k < slopes.size(); ++k) {
      const thin_ice::BondForce f = thin_ice::bondUnderOffset(rest, law, slopes[k] * d);
      json << (k ? "," : "") << "\n  {\"slope\": " << number(slopes[k], "--slope")
           << ", \"stress_ratio\": " << number(f.sigma_v / sigma_f, "sigma_v / sigma_f at --slope")
           << ", \"breaks\": " << (f.breaks ? "true" : "false") << "}";
    }
    json << "]}\n";
    std::fputs(json.str().c_str(), stdout);  // all of it or, on a refusal above, nothing
  } catch (const std::exception& e) {
    return refuse(e.what());
  }
  return 0;
}
