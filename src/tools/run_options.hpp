// The command line of `thin_ice run`: its usage text, the options it takes and their parsing. A bad
// command line is a UsageError (exit status 2, with the usage); the checks that need the built
// model (--until-length end, the pusher's travel, step counts) are run_command.cpp's. argv[0] is
// the subcommand's name; `thin_ice resume DIR ...` reaches here as `run --resume DIR ...`.
#pragma once

#include <cmath>
#include <cstdlib>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "thin_ice_sim/simulation.hpp"

namespace thin_ice_tools {

inline const char* kUsage =
    "usage: thin_ice run --scenario FILE [--set section.key=value]... "
    "(--until-length L|end | --until-time T)\n"
    "                    [--backend cpu|cuda|auto] [--output-interval S] [--snapshots N] [--profiles]\n"
    "                    [--stall-report S] --out DIR\n"
    "       thin_ice run --resume DIR [--accept-changed-scenario] [--set section.key=value]...\n"
    "                    (--until-length L|end | --until-time T)\n"
    "                    [--backend cpu|cuda|auto] [--snapshots N] [--profiles] [--stall-report S]\n"
    "       thin_ice resume DIR ...  (the same as thin_ice run --resume DIR ...)\n"
    "  --stall-report S  a run that has finished no output row for S seconds of wall time says so on\n"
    "                    stderr, every S seconds, with what it was doing (default 120)\n";

struct UsageError : std::runtime_error {  // bad command line: exit status 2 with the usage
  using std::runtime_error::runtime_error;
};

struct Options {
  std::string scenario, out;
  std::string resume;                  // the run directory to go on with (then also `out`)
  bool accept_changed_scenario = false;  // --resume taking the scenario file's values where they differ from the run's
  std::vector<std::string> overrides;  // "section.key=value", applied in order
  double until_length = 0.0;           // [m] pushed length to reach (0: not given)
  bool until_travel_end = false;       // --until-length end: the pusher's whole travel, known once the model is built
  double until_time = 0.0;             // [s] simulated time to reach (0: not given)
  thin_ice::BackendKind backend = thin_ice::BackendKind::kAuto;
  double output_interval = 0.0;        // [s] simulated time between rows of loads.csv (0: not given)
  int snapshots = 0;                   // cell snapshots, evenly spaced in progress
  bool profiles = false;               // write the rubble pile's side and top profiles at the end
  // [s] wall: a run that finishes no output row for this long says so (a row takes seconds at the
  // slowest real-time factors seen, 0.0024x with 0.01 s rows, and setting up a validation
  // scenario seconds: two minutes is no slow run's silence)
  double stall_seconds = 120.0;
  bool help = false;
};

inline double parseNumber(const std::string& flag, const std::string& text, const char* allowed) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value) || !(value > 0.0)) {
    throw UsageError(flag + " '" + text + "' is invalid; allowed: " + allowed);
  }
  return value;
}

inline thin_ice::BackendKind parseBackend(const std::string& text) {
  try {
    return thin_ice::parseBackendKind(text, "--backend");
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

inline Options parseOptions(int argc, char** argv) {
  Options o;
  for (int k = 1; k < argc; ++k) {
    const std::string flag = argv[k];
    if (flag == "--help" || flag == "-h") {
      o.help = true;
      return o;
    }
    if (flag == "--profiles") {
      o.profiles = true;
      continue;
    }
    if (flag == "--accept-changed-scenario") {
      o.accept_changed_scenario = true;
      continue;
    }
    static const std::set<std::string> kFlags = {"--scenario", "--set", "--until-length",
        "--until-time", "--backend", "--out", "--output-interval", "--snapshots", "--resume", "--stall-report"};
    if (!kFlags.count(flag)) {
      throw UsageError("unknown argument '" + flag + "'; allowed: --scenario --set --until-length "
                       "--until-time --backend --output-interval --snapshots --profiles --out --resume "
                       "--accept-changed-scenario --stall-report");
    }
    if (k + 1 >= argc) throw UsageError(flag + " needs a value");
    const std::string value = argv[++k];
    if (flag == "--scenario") o.scenario = value;
    if (flag == "--resume") o.resume = value;
    if (flag == "--out") o.out = value;
    if (flag == "--until-length" && value == "end") {
      o.until_travel_end = true;
      o.until_length = std::numeric_limits<double>::infinity();  // set to the travel in resolveTravelEnd
    } else if (flag == "--until-length") {
      o.until_length = parseNumber(flag, value, "a length > 0 [m], or 'end' (the pusher's whole travel)");
    }
    if (flag == "--until-time") o.until_time = parseNumber(flag, value, "a time > 0 [s]");
    if (flag == "--backend") o.backend = parseBackend(value);
    if (flag == "--output-interval") o.output_interval = parseNumber(flag, value, "a time > 0 [s]");
    if (flag == "--stall-report") o.stall_seconds = parseNumber(flag, value, "a wall time > 0 [s]");
    if (flag == "--set" && value.find('=') == std::string::npos) {
      throw UsageError("--set '" + value + "' is invalid; allowed: section.key=value");
    }
    if (flag == "--set") o.overrides.push_back(value);
    if (flag == "--snapshots") {
      char* end = nullptr;
      const long count = std::strtol(value.c_str(), &end, 10);
      if (value.empty() || *end != '\0' || count < 0 || count > 100000) {
        throw UsageError("--snapshots '" + value + "' is invalid; allowed: an integer 0..100000");
      }
      o.snapshots = static_cast<int>(count);
    }
  }
  if (!o.resume.empty()) {
    // The run directory holds the scenario, its overrides and the output interval.
    if (!o.scenario.empty() || !o.out.empty() || o.output_interval > 0.0) {
      throw UsageError("--resume DIR takes the scenario, --output-interval and --out of the run in DIR; "
                       "give none of them");
    }
    o.out = o.resume;
  } else {
    if (o.accept_changed_scenario) throw UsageError("--accept-changed-scenario goes with --resume DIR only");
    if (o.scenario.empty()) throw UsageError("--scenario FILE is required");
    if (o.out.empty()) throw UsageError("--out DIR is required");
    if (!(o.output_interval > 0.0)) o.output_interval = 0.01;
  }
  if ((o.until_length > 0.0) == (o.until_time > 0.0)) {
    throw UsageError("give exactly one of --until-length L [m] or --until-time T [s]");
  }
  return o;
}

}  // namespace thin_ice_tools
