// `thin_ice probe edge-check`: the edge-load check (a free edge against a floating plate's P_crit) for one or more scenarios. Prints, as a
// Markdown table, the vertical line load at which straight cuts near the sheet's front edge fail
// (the bond law swept quasi-statically over a rigid strip, thin_ice_sim/study/edge_check.hpp) beside
// the floating plate's P_crit and characteristic length l, and the sum of the bonds' own peaks.
//   thin_ice probe edge-check --scenario FILE [--scenario FILE]... [--set section.key=value]... [--cuts N]
// Exit status: 0 done; 2 bad arguments or scenario.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "commands.hpp"
#include "thin_ice_sim/study/edge_check.hpp"
#include "thin_ice_sim/scenario.hpp"

int thin_ice::cli::probeEdgeCheck(int argc, char** argv) {
  std::vector<std::string> scenarios, overrides;
  int cuts = 5;
  const char* usage = "usage: thin_ice probe edge-check --scenario FILE [--scenario FILE]... [--set section.key=value]... [--cuts N]\n";
  for (int a = 1; a < argc; ++a) {
    const std::string flag = argv[a];
    if (flag == "-h" || flag == "--help") {
      std::printf("%s", usage);
      return 0;
    }
    if (a + 1 >= argc) {
      std::fprintf(stderr, "thin_ice probe edge-check: %s needs a value\n%s", flag.c_str(), usage);
      return 2;
    }
    const std::string value = argv[++a];
    if (flag == "--scenario") {
      scenarios.push_back(value);
    } else if (flag == "--set") {
      overrides.push_back(value);
    } else if (flag == "--cuts") {
      char* end = nullptr;
      const long n = std::strtol(value.c_str(), &end, 10);
      if (end == value.c_str() || *end != '\0' || n < 1 || n > 100) {
        std::fprintf(stderr, "thin_ice probe edge-check: --cuts %s; allowed: an integer in [1, 100]\n", value.c_str());
        return 2;
      }
      cuts = static_cast<int>(n);
    } else {
      std::fprintf(stderr, "thin_ice probe edge-check: unknown flag %s\n%s", flag.c_str(), usage);
      return 2;
    }
  }
  if (scenarios.empty()) {
    std::fprintf(stderr, "thin_ice probe edge-check: --scenario is required\n%s", usage);
    return 2;
  }
  std::printf("| scenario | l [m] | P_crit [N/m] | cut [m from edge] | bonds | failing by Eq. (13) | line load at failure [N/m] | / P_crit | sum of bond peaks [N/m] |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& path : scenarios) {
    try {
      const thin_ice::Scenario scenario = thin_ice::loadScenario(path, overrides);
      const thin_ice::Params& p = scenario.params;
      const thin_ice::IceSheet sheet = thin_ice::generateIceSheet(p.sheet);
      const thin_ice::Model model = thin_ice::buildModel(p, sheet, path);
      const thin_ice::FloatingPlateEdge plate = thin_ice::floatingPlateEdge(p.ice, p.water);
      for (const thin_ice::EdgeCutCapacity& cut : thin_ice::edgeCutCapacities(model, sheet, cuts)) {
        std::printf("| %s | %.2f | %.0f | %.2f | %d | %d | %.0f | %.2f | %.0f |\n", scenario.name.c_str(),
                    plate.characteristic_length, plate.critical_line_load, cut.distance_from_edge, cut.bonds,
                    cut.failing_by_stress, cut.line_load, cut.line_load / plate.critical_line_load, cut.sum_of_peaks);
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "thin_ice probe edge-check: %s\n", e.what());
      return 2;
    }
  }
  return 0;
}
