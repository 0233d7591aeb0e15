// `thin_ice analyse`: works out a finished run's load statistics again from its load record, with the
// code `thin_ice run` uses at the end of a run (load_statistics.hpp, run_report.hpp), and prints
// summary.json's "load" and "experiment" objects as one JSON object on stdout, with the alpha of
// Eq. (18) that the run's scenario gives now ("scenario_calibration_factor"; the scenario file is
// taken relative to the current directory, as `thin_ice run` was given it). For runs made before a
// change to the statistics or to alpha; scripts/study reanalyse and scripts/study recalibrate put
// the objects into the run's summary.json.
//   thin_ice analyse RUN_DIR [--write-bins]
// The statistics are worked out on the run's kept record, load_bins.csv (load_bins.hpp), or on
// the bins of its loads.csv where it has none; --write-bins then writes them as its load_bins.csv.
// Exit status: 0 done; 2 bad arguments, or RUN_DIR is not a finished run directory.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "thin_ice_sim/study/load_bins.hpp"
#include "thin_ice_sim/study/load_statistics.hpp"
#include "thin_ice_sim/study/run_record.hpp"
#include "thin_ice_sim/study/run_directory.hpp"
#include "thin_ice_sim/study/run_report.hpp"
#include "thin_ice_sim/sheet_io.hpp"

int thin_ice::cli::analyseCommand(int argc, char** argv) {
  const std::string usage = "usage: thin_ice analyse RUN_DIR [--write-bins]\n";
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 1 && (args[0] == "--help" || args[0] == "-h")) {
    std::cout << usage;
    return 0;
  }
  const bool write_bins = args.size() == 2 && args[1] == "--write-bins";
  if (args.empty() || args.size() > 2 || args[0].rfind("-", 0) == 0 || (args.size() == 2 && !write_bins)) {
    std::cerr << "thin_ice analyse: give one run directory, and --write-bins or nothing after it\n" << usage;
    return 2;
  }
  const std::string dir = args[0];
  try {
    if (std::filesystem::exists(dir + "/" + thin_ice::run_record::kLoadsPartialFile)) {
      throw std::runtime_error(std::string("a run is still writing here (") + thin_ice::run_record::kLoadsPartialFile +
                               ")");
    }
    const thin_ice::RunSummary summary = thin_ice::readRunSummary(dir);
    if (summary.scenario_name.empty() || !(summary.structure_width > 0.0)) {
      throw std::runtime_error("summary.json lacks scenario.name or structure_width_m");
    }
    // The statistics of `thin_ice run`: on the kept record (load_bins.csv, or the bins of loads.csv
    // for a run made before it), the first failure from the rows where loads.csv holds them all.
    const std::vector<thin_ice::LoadBin> bins = thin_ice::readRunLoadBins(dir);
    const std::string bins_path = dir + "/" + thin_ice::run_record::kLoadBinsFile;
    if (write_bins && !std::filesystem::exists(bins_path)) {  // a run made before load_bins.csv
      thin_ice::writeFileAtomically(bins_path, thin_ice::run_record::loadBinsText(bins));
      std::cerr << "thin_ice analyse: wrote " << bins_path << " (" << bins.size() << " bins)\n";
    }
    const std::string loads_path = dir + "/" + thin_ice::run_record::kLoadsFile;
    double first_failure = summary.first_failure_length;
    if (summary.loads_csv_from == 0.0 && std::filesystem::exists(loads_path)) {
      const thin_ice::LoadHistory h = thin_ice::readLoadHistory(loads_path);
      first_failure = thin_ice::firstFailureLength(h.pushed_length, h.broken_bonds);
    }
    const thin_ice::LoadStatistics s = thin_ice::analyseLoadBins(bins, thin_ice::SteadyStateRule(), first_failure);
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
