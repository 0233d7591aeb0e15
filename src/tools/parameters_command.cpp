// `thin_ice parameters`: a scenario's whole parameter set as the loader resolves it (its bases
// read, the overrides applied, the derived values worked out), printed as a scenario file that
// stands alone: every key of the format, one value each, with the precision that reads back to
// the same bits. For seeing what a run will use, and for comparing two scenarios with diff.
//   thin_ice parameters --scenario FILE [--set section.key=value ...]
// Exit status: 0 printed; 2 bad arguments or a scenario the loader refuses (its message names the key).
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "thin_ice_sim/scenario.hpp"

int thin_ice::cli::parametersCommand(int argc, char** argv) {
  const std::string usage = "usage: thin_ice parameters --scenario FILE [--set section.key=value ...]\n";
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 1 && (args[0] == "--help" || args[0] == "-h")) {
    std::cout << usage;
    return 0;
  }
  std::string file;
  std::vector<std::string> overrides;
  for (size_t k = 0; k < args.size(); ++k) {
    const bool has_value = k + 1 < args.size();
    if (args[k] == "--scenario" && has_value && file.empty()) {
      file = args[++k];
    } else if (args[k] == "--set" && has_value) {
      overrides.push_back(args[++k]);
    } else {
      std::cerr << "thin_ice parameters: unexpected argument '" << args[k]
                << "'; allowed: --scenario FILE once, then --set section.key=value any number of times\n"
                << usage;
      return 2;
    }
  }
  if (file.empty()) {
    std::cerr << "thin_ice parameters: --scenario FILE is required\n" << usage;
    return 2;
  }
  try {
    const Scenario scenario = loadScenario(file, overrides);
    std::string out = "description: \"the parameters of " + file;
    for (const std::string& o : overrides) out += " --set " + o;
    out += ", as thin_ice resolved them\"\n";
    std::string section;
    for (const ParameterValue& p : scenarioParameters(scenario.params)) {
      const size_t dot = p.key.find('.');
      if (p.key.compare(0, dot, section) != 0 || section.size() != dot) {
        section = p.key.substr(0, dot);
        out += "\n" + section + ":\n";
      }
      out += "  " + p.key.substr(dot + 1) + ": " + p.value + "\n";
    }
    std::cout << out;
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "thin_ice parameters: " << e.what() << "\n";
    return 2;
  }
}
