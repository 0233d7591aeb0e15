// The command line shared by the probes that analyse one finished run directory of `thin_ice run`
// (`thin_ice probe edge-balance`, `thin_ice probe profiles`):
//   thin_ice probe PROBE RUN_DIR [--accept-changed-scenario] [--NAME VALUE]...
// and loading that run's scenario with loadRunScenario (thin_ice_sim/study/run_directory.hpp).
// argv[0] is the probe's name; `tool` is what its messages begin with ("thin_ice probe PROBE").
#pragma once

#include <cstdio>
#include <map>
#include <set>
#include <string>

#include "thin_ice_sim/study/run_directory.hpp"

namespace thin_ice_tools {

struct RunToolArgs {
  std::string run;                            ///< the run directory
  bool accept_changed_scenario = false;       ///< --accept-changed-scenario
  std::map<std::string, std::string> values;  ///< --NAME VALUE options, by NAME (with the dashes)
};

/// Parses argv; `valued` lists the --NAME options that take a value. Returns -1 when the tool
/// should go on, else the exit status (0 after --help; 2 after one line naming the bad argument).
inline int parseRunToolArgs(int argc, char** argv, const char* tool, const char* usage,
                            const std::set<std::string>& valued, RunToolArgs& args) {
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "-h" || arg == "--help") {
      std::printf("%s", usage);
      return 0;
    }
    if (arg == "--accept-changed-scenario") {
      args.accept_changed_scenario = true;
    } else if (valued.count(arg) && a + 1 < argc) {
      args.values[arg] = argv[++a];
    } else if (arg.rfind("--", 0) != 0 && args.run.empty()) {
      args.run = arg;
    } else {
      std::fprintf(stderr, "%s: unexpected argument '%s'\n%s", tool, arg.c_str(), usage);
      return 2;
    }
  }
  if (args.run.empty()) {
    std::fprintf(stderr, "%s: a run directory is needed\n%s", tool, usage);
    return 2;
  }
  return -1;
}

/// The run's scenario; a changed scenario file taken as the run's (--accept-changed-scenario) is
/// said on stderr. Throws as loadRunScenario.
inline thin_ice::Scenario loadRunScenario(const RunToolArgs& args, const char* tool) {
  std::string warning;
  thin_ice::Scenario scenario = thin_ice::loadRunScenario(args.run, args.accept_changed_scenario, warning);
  if (!warning.empty()) std::fprintf(stderr, "%s: warning: %s\n", tool, warning.c_str());
  return scenario;
}

}  // namespace thin_ice_tools
