// Reading back what `thin_ice run` wrote (src/tools/run_command.cpp): the scenario of a run, its
// snapshot list and the cells of one snapshot, for tools that analyse a finished run.
#pragma once

#include <limits>
#include <map>
#include <string>
#include <vector>

#include "thin_ice_sim/scenario.hpp"
#include "thin_ice_sim/simulation.hpp"
#include "thin_ice_sim/study/load_bins.hpp"

namespace thin_ice {

/// Rows of a CSV file with a header line, each as column name -> text. Throws std::runtime_error
/// naming the file when it cannot be read.
using CsvRow = std::map<std::string, std::string>;
std::vector<CsvRow> readCsv(const std::string& path);

/// The number in `column` of `row`; throws std::runtime_error naming `path` and the column when it
/// is missing or not a number.
double csvNumber(const CsvRow& row, const std::string& column, const std::string& path);

/// The scenario (file and overrides) named by RUN/summary.json, loaded anew, with the run's own
/// parameters. Relative scenario paths are taken from the current directory, as `thin_ice run` was
/// given them. Throws std::runtime_error when RUN is not a run directory.
/// - A run that recorded its parameters (summary.json "parameters"; older records have none)
///   keeps them: where the file now gives other values, they are added to the overrides, so that
///   the sheet, the bonds and the laws stay the run's whatever became of the file (derived
///   values turned into rules, a base file retouched), and `warning` names each key, the file's
///   value and the run's. With accept_changed_file the file's values are taken instead, and the
///   warning says which change. A key the run did not record (one added to the format after it)
///   takes the file's value, and the warning says so.
/// - An older run (no "parameters") is held to the hash of the file's text and the overrides:
///   a different hash is refused, since its sheet and bonds may not be the run's, unless
///   accept_changed_file (for a file whose comments alone changed, which the caller has checked);
///   `warning` then says so.
/// `parameters_recorded` says which of the two applied.
Scenario loadRunScenario(const std::string& run_dir, bool accept_changed_file, std::string& warning,
                         bool* parameters_recorded = nullptr);

/// An override given when the run was resumed (`thin_ice run --resume DIR --set ...`): it holds
/// from that pushed length on, the run before it went without.
struct SwitchedOverride {
  std::string set;      ///< "section.key=value"
  double from_length;   ///< [m] pushed length at the resumption
};

/// What a resumed run takes over from RUN/summary.json.
struct RunSummary {
  std::string status;              ///< "completed", "interrupted" or "unhealthy"
  double output_interval = 0.0;    ///< [s] between rows of loads.csv
  double loads_csv_from = 0.0;     ///< [s] where loads.csv's first row begins (0: it holds the whole run)
  double first_failure_length = std::numeric_limits<double>::infinity();  ///< [m] load.first_failure_m; +infinity: none broke
  double wall_time = 0.0;          ///< [s] of stepping and output, every segment so far
  long steps = 0;                  ///< time steps taken by the end of the run
  std::vector<double> resumed_at;  ///< [m] pushed lengths at which the run was resumed before
  std::vector<SwitchedOverride> switched;  ///< overrides_from_m: the overrides given at resumptions
  std::string scenario_name;       ///< e.g. "M-2": the Table 6 experiment it is compared with
  double structure_width = 0.0;    ///< [m] structure_width_m (NaN when the summary lacks it)
};
/// Throws std::runtime_error naming the file when it is missing or lacks one of these.
RunSummary readRunSummary(const std::string& run_dir);

/// RUN/loads.csv as the load statistics read it, one entry per row.
struct LoadHistory {
  std::vector<double> time;           ///< [s] at the end of each output interval
  std::vector<double> pushed_length;  ///< [m]
  std::vector<double> load;           ///< [N] horizontal_calibrated_N, F_cal of Eq. (18)
  std::vector<double> vertical;       ///< [N] vertical_raw_N
  std::vector<double> pusher;         ///< [N] pusher_force_N
  std::vector<int> intact_bonds, broken_bonds;
};
/// Throws std::runtime_error naming the file and the column when a row lacks a number.
LoadHistory readLoadHistory(const std::string& csv_path);

/// The bins of a load history read from loads.csv (LoadBinner over its rows): the kept record of
/// a run made before load_bins.csv existed.
std::vector<LoadBin> binLoadHistory(const LoadHistory& history);

/// RUN/load_bins.csv. Throws std::runtime_error naming the file and what is wrong: a missing
/// number, bins out of order, a bin whose time or length runs backwards.
std::vector<LoadBin> readLoadBins(const std::string& csv_path);

/// The run's kept record: load_bins.csv where there is one, otherwise the bins of its loads.csv.
/// Throws std::runtime_error when it has neither.
std::vector<LoadBin> readRunLoadBins(const std::string& run_dir);

/// One entry of RUN/snapshots/index.csv.
struct SnapshotEntry {
  std::string file;   ///< path of the cells CSV
  long loads_row = 0; ///< the loads.csv data row it belongs to (1-based), 0: the sheet at rest
  double time = 0.0;  ///< [s]
  double pushed_length = 0.0;  ///< [m]
};
/// Throws std::runtime_error when the run has no snapshots (it needs --snapshots N).
std::vector<SnapshotEntry> readSnapshotIndex(const std::string& run_dir);

/// The cells of a snapshot: pose and whether each is in the intact sheet (velocities are not
/// written, so they are zero).
std::vector<CellSnapshot> readCellSnapshot(const std::string& path);

}  // namespace thin_ice
