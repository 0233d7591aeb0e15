// The run record, owned here: what a run directory holds and how each file is laid out.
// `thin_ice run` writes it through these names and functions, run_directory.cpp reads it back through
// the same names, and the scripts read it through their mirror, scripts/thin_ice_study/run_record.py
// (test/test_run_record.py holds the mirror to this file).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "thin_ice_sim/load_sample.hpp"
#include "thin_ice_sim/scenario.hpp"
#include "thin_ice_sim/study/load_bins.hpp"

namespace thin_ice::run_record {

/// summary.json's "schema_version": raised when a field changes its meaning or leaves (a field
/// added is not a new version). Records written before the field existed have this layout too.
inline constexpr int kSummarySchemaVersion = 1;

inline constexpr const char* kSummaryFile = "summary.json";
inline constexpr const char* kLoadsFile = "loads.csv";          ///< written through loads.csv.partial
inline constexpr const char* kLoadsPartialFile = "loads.csv.partial";  ///< loads.csv while its segment runs
inline constexpr const char* kLoadBinsFile = "load_bins.csv";  ///< the kept record (load_bins.hpp)
inline constexpr const char* kCheckpointFile = "checkpoint.bin";
inline constexpr const char* kSnapshotDir = "snapshots";
inline constexpr const char* kSnapshotIndexFile = "index.csv";  ///< in kSnapshotDir

/// loads.csv: one row per output interval, the loads averaged over it, stamped at its end.
namespace load_column {
inline constexpr const char* kTime = "time_s";                                ///< [s] simulated
inline constexpr const char* kPushedLength = "pushed_length_m";               ///< [m]
inline constexpr const char* kHorizontalRaw = "horizontal_raw_N";             ///< F of Eq. (17) [N]
inline constexpr const char* kHorizontalCalibrated = "horizontal_calibrated_N";  ///< alpha F, Eq. (18) [N]
inline constexpr const char* kVerticalRaw = "vertical_raw_N";                 ///< [N], +z
inline constexpr const char* kPusherForce = "pusher_force_N";                 ///< [N], +x
inline constexpr const char* kIntactBonds = "intact_bonds";
inline constexpr const char* kBrokenBonds = "broken_bonds";
inline constexpr const char* kContacts = "contacts";
}  // namespace load_column

/// loads.csv's columns before the panels', in order; then panel_1_N ... panel_P_N (each panel's raw
/// horizontal load [N], panelColumn).
inline constexpr const char* kLoadColumns[] = {
    load_column::kTime,        load_column::kPushedLength, load_column::kHorizontalRaw,
    load_column::kHorizontalCalibrated, load_column::kVerticalRaw, load_column::kPusherForce,
    load_column::kIntactBonds, load_column::kBrokenBonds,  load_column::kContacts};

/// load_bins.csv: one row per bin of pushed length (load_bins.hpp), the whole run's record, written
/// at the end of each segment.
namespace bin_column {
inline constexpr const char* kBin = "bin";                                   ///< k: (k b, (k + 1) b]
inline constexpr const char* kTime = "time_s";                               ///< [s] its last row's end
inline constexpr const char* kPushedLength = "pushed_length_m";              ///< [m] its last row's end
inline constexpr const char* kDuration = "duration_s";                       ///< [s] its rows' intervals
inline constexpr const char* kSamples = "samples";                           ///< rows of loads.csv
inline constexpr const char* kCalibratedMean = "horizontal_calibrated_mean_N";        ///< [N]
inline constexpr const char* kCalibratedLeast = "horizontal_calibrated_least_N";      ///< [N]
inline constexpr const char* kCalibratedGreatest = "horizontal_calibrated_greatest_N";  ///< [N]
inline constexpr const char* kVerticalMean = "vertical_raw_mean_N";          ///< [N], +z
inline constexpr const char* kPusherMean = "pusher_force_mean_N";            ///< [N], +x
inline constexpr const char* kIntactBonds = "intact_bonds";
inline constexpr const char* kBrokenBonds = "broken_bonds";
}  // namespace bin_column
inline constexpr const char* kLoadBinColumns[] = {
    bin_column::kBin,           bin_column::kTime,          bin_column::kPushedLength,
    bin_column::kDuration,      bin_column::kSamples,       bin_column::kCalibratedMean,
    bin_column::kCalibratedLeast, bin_column::kCalibratedGreatest, bin_column::kVerticalMean,
    bin_column::kPusherMean,    bin_column::kIntactBonds,   bin_column::kBrokenBonds};

/// load_bins.csv's text: the header and one row per bin (nine significant digits).
std::string loadBinsText(const std::vector<LoadBin>& bins);

/// snapshots/cells_RRRRRR.csv: one row per cell.
namespace snapshot_column {
inline constexpr const char* kCell = "cell";
inline constexpr const char* kX = "x_m";                         ///< [m] centroid
inline constexpr const char* kY = "y_m";                         ///< [m]
inline constexpr const char* kZ = "z_m";                         ///< [m]
inline constexpr const char* kYaw = "yaw_rad";                   ///< [rad]
inline constexpr const char* kInIntactSheet = "in_intact_sheet";  ///< 1 while any of its bonds holds
inline constexpr const char* kPieceCells = "piece_cells";        ///< cells of its bonded piece
inline constexpr const char* kPolygon = "polygon_xy_m";          ///< "x0 y0 x1 y1 ..." [m], one field
}  // namespace snapshot_column
inline constexpr const char* kSnapshotColumns[] = {
    snapshot_column::kCell, snapshot_column::kX,        snapshot_column::kY,
    snapshot_column::kZ,    snapshot_column::kYaw,      snapshot_column::kInIntactSheet,
    snapshot_column::kPieceCells, snapshot_column::kPolygon};

/// A snapshot file's text: the header and one row per cell, `polygons[k]` cell k's world polygon
/// [m] (nine significant digits). Throws std::invalid_argument when the two lists differ in length.
std::string snapshotText(const std::vector<CellSnapshot>& cells, const std::vector<std::vector<Vec2>>& polygons);

/// snapshots/index.csv: one row per snapshot file.
namespace index_column {
inline constexpr const char* kFile = "file";
inline constexpr const char* kTime = "time_s";                   ///< [s] simulated
inline constexpr const char* kPushedLength = "pushed_length_m";  ///< [m]
}  // namespace index_column
inline constexpr const char* kSnapshotIndexColumns[] = {index_column::kFile, index_column::kTime,
                                                        index_column::kPushedLength};

/// One line of snapshots/index.csv: the file, its time [s] and pushed length [m] (six significant
/// digits).
std::string snapshotIndexRow(const std::string& file, double time, double pushed_length);

/// summary.json: what `thin_ice run` records of a run as a whole, written by summaryJson from this
/// and read back by run_directory.cpp (readRunSummary, loadRunScenario). A field that changes its
/// meaning or leaves raises kSummarySchemaVersion.
struct SummaryRecord {
  std::string status;                      ///< completed, interrupted or unhealthy
  std::string error;                       ///< why a run stopped unhealthy ("" writes null)
  std::string scenario_name, scenario_file, scenario_hash;
  std::vector<std::string> overrides;      ///< the run's --set, as given at its start
  std::vector<ParameterValue> parameters;  ///< the whole parameter set in force at the end
  std::string backend, backend_note, cpu_instruction_set;
  int cells = 0;
  double time_step = 0.0, critical_time_step = 0.0;  ///< [s]
  int structure_substeps = 1;
  double structure_critical_time_step = 0.0;          ///< [s]
  double output_interval = 0.0;                       ///< [s] of a row of loads.csv
  double loads_csv_from = 0.0;                        ///< [s] where loads.csv's first row begins
  double load_bin_length = 0.0;                       ///< [m] of a bin of load_bins.csv
  bool target_is_length = false;                      ///< the target: a pushed length, or a time
  double target = 0.0;                                ///< [m] or [s], as target_is_length says
  long steps = 0;
  double simulated_time = 0.0, pushed_length = 0.0;   ///< [s], [m]
  double setup_wall_time = 0.0, wall_time = 0.0;      ///< [s] of wall-clock time, every segment's
  double cell_steps_per_second = 0.0;                 ///< [1/s] cells x steps over wall time
  double real_time_factor = 0.0;                      ///< [-] simulated over wall time
  std::vector<double> resumed_at;                     ///< [m] where each resumption began
  struct Switch {
    std::string set;     ///< "section.key=value" given at a resumption
    double from_length = 0.0;  ///< [m] where it began to apply
  };
  std::vector<Switch> overrides_from;
  int intact_bonds = 0, broken_bonds = 0;
  double calibration_factor = 1.0;                    ///< alpha [-] of Eq. (18)
  std::string load_json;                              ///< the statistics (run_report.hpp, loadJson)
  double structure_width = 0.0;                       ///< [m]
  double toe_x = 0.0, angle_deg = 0.0, structure_height = 0.0;  ///< [m], [deg], [m]
  int panels = 1;
  bool false_bottom = false;
  double bottom_depth = 0.0, bottom_distance_from_structure = 0.0;  ///< [m]
  std::string experiment_json;                        ///< the comparison (run_report.hpp, experimentJson)
};

/// summary.json's text for `r`.
std::string summaryJson(const SummaryRecord& r);

/// "panel_K_N" for panel K (1-based).
std::string panelColumn(int panel);

/// The comma-separated header line of `columns` (with its newline).
template <std::size_t N>
std::string headerLine(const char* const (&columns)[N]) {
  std::string line;
  for (std::size_t k = 0; k < N; ++k) line += std::string(k ? "," : "") + columns[k];
  return line + "\n";
}

/// loads.csv's header for a structure of `panels` panels, and one row of it (nine significant
/// digits; a sample with fewer panel loads than the header writes 0 for the rest).
std::string loadsHeader(int panels);
std::string loadsRow(const LoadSample& s, int panels);

/// The snapshot file of loads.csv's data row `loads_row` (1-based; 0: the sheet at rest):
/// "cells_RRRRRR.csv", six digits. parseSnapshotFileName gives the row back, or false for a
/// name of another form.
std::string snapshotFileName(long loads_row);
bool parseSnapshotFileName(const std::string& name, long& loads_row);

}  // namespace thin_ice::run_record
