// `thin_ice analyse`: works out a finished run's load statistics again from its loads.csv, with the
// code `thin_ice run` uses at the end of a run (load_statistics.hpp, run_report.hpp), and prints
// summary.json's "load" and "experiment" objects as one JSON object on stdout, with the alpha of
// Eq. (18) that the run's scenario gives now ("scenario_calibration_factor"; the scenario file is
// taken relative to the current directory, as `thin_ice run` was given it). For runs made before a
// change to the statistics or to alpha; scripts/study reanalyse and scripts/study recalibrate put
// the objects into the run's summary.json.
//   thin_ice analyse RUN_DIR
// Exit status: 0 done; 2 bad arguments, or RUN_DIR is not a finished run directory.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

#include "commands.hpp"
#include "thin_ice_sim/study/load_statistics.hpp"
#include "thin_ice_sim/study/run_directory.hpp"
#include "thin_ice_sim/study/run_report.hpp"

int thin_ice::cli::analyseCommand(int argc, char** argv) {
  const std::string usage = "usage: thin_ice analyse RUN_DIR\n";
  const std::string first = argc > 1 ? argv[1] : "";
  if (argc == 2 && (first == "--help" || first == "-h")) {
    std::cout << usage;
    return 0;
  }
  if (argc != 2 || first.rfind("-", 0) == 0) {
    std::cerr << "thin_ice analyse: give one run directory\n" << usage;
    return 2;
  }
  const std::string dir = argv[1];
  try {
    if (std::filesystem::exists(dir + "/loads.csv.partial")) {
      throw std::runtime_error("a run is still writing here (loads.csv.partial)");
    }
    const thin_ice::RunSummary summary = thin_ice::readRunSummary(dir);
    if (summary.scenario_name.empty() || !(summary.structure_width > 0.0)) {
      throw std::runtime_error("summary.json lacks scenario.name or structure_width_m");
    }
    const thin_ice::LoadHistory h = thin_ice::readLoadHistory(dir + "/loads.csv");
    const double first_failure = thin_ice::firstFailureLength(h.pushed_length, h.broken_bonds);
    const thin_ice::LoadStatistics s =
        thin_ice::analyseLoadHistory(h.pushed_length, h.load, thin_ice::SteadyStateRule(), first_failure);
    // alpha of Eq. (18) that the run's scenario (file as it stands now, with the run's overrides)
    // gives, for scripts/study recalibrate; null, with the reason, when the scenario cannot be loaded.
    std::string alpha = "null", scenario_error = "null";
    try {
      std::string changed;  // a changed file is what is asked for here: its alpha now
      alpha = thin_ice::jsonNumber(
          thin_ice::loadRunScenario(dir, true, changed).params.structure.calibration_factor);
    } catch (const std::exception& e) {
      scenario_error = thin_ice::jsonString(e.what());
    }
    std::cout << "{\n  \"load\": " << thin_ice::loadJson(s, first_failure) << ",\n  \"experiment\": "
              << thin_ice::experimentJson(summary.scenario_name, summary.structure_width, s)
              << ",\n  \"scenario_calibration_factor\": " << alpha << ", \"scenario_error\": " << scenario_error
              << "\n}\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "thin_ice analyse: " << dir << ": " << e.what() << "\n";
    return 2;
  }
}
