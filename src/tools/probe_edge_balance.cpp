// `thin_ice probe edge-balance`: the vertical force balance of the sheet's front row in a run,
// snapshot by snapshot (thin_ice_sim/study/front_row_balance.hpp), as a Markdown table beside the
// structure's vertical load on the ice from loads.csv (the mean over that output interval).
//   thin_ice probe edge-balance RUN_DIR [--accept-changed-scenario]
// RUN_DIR is the output of a `thin_ice run` with --snapshots; its scenario is the one summary.json names
// (thin_ice_sim/study/run_directory.hpp: run from the directory the run was started in).
// Exit status: 0 done; 2 bad arguments, run directory or scenario.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "thin_ice_sim/study/front_row_balance.hpp"
#include "thin_ice_sim/study/run_directory.hpp"
#include "thin_ice_sim/study/run_record.hpp"
#include "run_tool_args.hpp"

namespace {

/// v rounded to `decimals` places, with no "-0" for what rounds to zero.
double shown(double v, int decimals) {
  const double half_unit = 0.5 * std::pow(10.0, -decimals);
  return std::fabs(v) < half_unit ? 0.0 : v;
}

constexpr const char* kTool = "thin_ice probe edge-balance";

}  // namespace

int thin_ice::cli::probeEdgeBalance(int argc, char** argv) {
  const char* usage = "usage: thin_ice probe edge-balance RUN_DIR [--accept-changed-scenario]\n";
  thin_ice_tools::RunToolArgs args;
  const int status = thin_ice_tools::parseRunToolArgs(argc, argv, kTool, usage, {}, args);
  if (status >= 0) return status;
  const std::string& run = args.run;
  try {
    const thin_ice::Scenario scenario = thin_ice_tools::loadRunScenario(args, kTool);
    const std::vector<thin_ice::SnapshotEntry> index = thin_ice::readSnapshotIndex(run);
    const thin_ice::IceSheet sheet = thin_ice::generateIceSheet(scenario.params.sheet);
    const thin_ice::Model model = thin_ice::buildModel(scenario.params, sheet, scenario.source);
    const thin_ice::FrontRow row = thin_ice::frontRow(model, sheet);
    // The whole table is made before any of it is printed, so a bad snapshot leaves no half table.
    std::string table;
    char line[512];
    std::snprintf(line, sizeof(line), "front row: %zu cells, %.3f m^2, weight %.0f N; %zu bonds across the cut to %zu cells\n",
                  row.cells.size(), row.area, row.weight, row.cut_bonds.size(), row.rear_cells.size());
    table += line;

    // Each snapshot's row of loads.csv, found by its time: a loads.csv begun at a resumption (a
    // run carried on from its kept record, summary.json's loads_csv_from_s > 0) does not start at
    // row 1, and a short row at an earlier target shifts the numbering against t / interval.
    const std::string loads_path = run + "/" + thin_ice::run_record::kLoadsFile;
    const auto loads = thin_ice::readCsv(loads_path);
    namespace column = thin_ice::run_record::load_column;
    std::vector<double> row_time;
    for (const auto& r : loads) row_time.push_back(thin_ice::csvNumber(r, column::kTime, loads_path));
    table += "| L [m] | structure's vertical load [N] | bonds across the cut [N] | buoyancy lost by the front row [N] "
             "| sum [N] | front row lift [mm] | row behind lift [mm] | broken bonds |\n";
    table += "|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const thin_ice::SnapshotEntry& entry : index) {
      if (entry.loads_row == 0) continue;  // the sheet at rest
      // snapshots/index.csv gives the time to six significant digits: the row nearest to it.
      const double tolerance = 1e-5 * std::max(1.0, entry.time);  // [s]
      auto at = std::lower_bound(row_time.begin(), row_time.end(), entry.time - tolerance);
      if (at != row_time.end() && at + 1 != row_time.end() && std::fabs(at[1] - entry.time) < std::fabs(*at - entry.time)) ++at;
      if (at == row_time.end() || std::fabs(*at - entry.time) > tolerance) {
        throw std::runtime_error(entry.file + " is at t = " + std::to_string(entry.time) + " s, which no row of " + loads_path +
                                 " ends at (its rows run from t = " + (row_time.empty() ? std::string("-") : std::to_string(row_time.front())) +
                                 " s)");
      }
      const auto& load = loads[static_cast<std::size_t>(at - row_time.begin())];
      std::vector<thin_ice::CellPose> poses;
      for (const thin_ice::CellSnapshot& c : thin_ice::readCellSnapshot(entry.file)) poses.push_back({c.x, c.y, c.z, c.yaw});
      const thin_ice::FrontRowBalance b = thin_ice::frontRowBalance(model, row, poses);
      // The structure pushes the ice down: minus its vertical load on the structure.
      const double structure_down = -thin_ice::csvNumber(load, column::kVerticalRaw, loads_path);
      std::snprintf(line, sizeof(line), "| %.4f | %.0f | %.0f | %.0f | %.0f | %.1f | %.1f | %.0f |\n",
                    thin_ice::csvNumber(load, column::kPushedLength, loads_path), shown(structure_down, 0),
                    shown(b.bond_force, 0), shown(b.lost_buoyancy, 0), shown(b.bond_force + b.lost_buoyancy, 0),
                    shown(1e3 * b.front_lift, 1), shown(1e3 * b.rear_lift, 1),
                    thin_ice::csvNumber(load, column::kBrokenBonds, loads_path));
      table += line;
    }
    std::fputs(table.c_str(), stdout);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s: %s\n", kTool, run.c_str(), e.what());
    return 2;
  }
  return 0;
}
