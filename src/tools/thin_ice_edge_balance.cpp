// thin_ice_edge_balance: the vertical force balance of the sheet's front row in a run, snapshot by
// snapshot (thin_ice_sim/front_row_balance.hpp), as a Markdown table beside the structure's
// vertical load on the ice from loads.csv (the mean over that output interval).
//   thin_ice_edge_balance RUN_DIR
// RUN_DIR is a thin_ice_run output with --snapshots; the scenario file and overrides are the ones
// its summary.json names (relative paths from the directory the run was started in, as
// scripts/validate does from the repository root), and its hash must still match.
// Exit status: 0 done; 2 bad arguments, run directory or scenario.
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "thin_ice_sim/front_row_balance.hpp"
#include "thin_ice_sim/scenario.hpp"

namespace {

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) fields.push_back(field);
  return fields;
}

/// Rows of a CSV file as maps from the header's column names.
std::vector<std::map<std::string, std::string>> readCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + " is empty");
  const std::vector<std::string> header = splitCsvLine(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = splitCsvLine(line);
    std::map<std::string, std::string> row;
    for (size_t c = 0; c < header.size() && c < fields.size(); ++c) row[header[c]] = fields[c];
    rows.push_back(row);
  }
  return rows;
}

double number(const std::map<std::string, std::string>& row, const std::string& column, const std::string& path) {
  const auto it = row.find(column);
  if (it == row.end()) throw std::runtime_error(path + ": no column " + column);
  return std::stod(it->second);
}

std::vector<thin_ice::CellPose> readPoses(const std::string& path) {
  std::vector<thin_ice::CellPose> poses;
  for (const auto& row : readCsv(path)) {
    poses.push_back({number(row, "x_m", path), number(row, "y_m", path), number(row, "z_m", path),
                     number(row, "yaw_rad", path)});
  }
  return poses;
}

/// v rounded to `decimals` places, with no "-0" for what rounds to zero.
double shown(double v, int decimals) {
  const double half_unit = 0.5 * std::pow(10.0, -decimals);
  return std::fabs(v) < half_unit ? 0.0 : v;
}

}  // namespace

int main(int argc, char** argv) {
  const char* usage = "usage: thin_ice_edge_balance RUN_DIR\n";
  if (argc == 2 && (std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help")) {
    std::printf("%s", usage);
    return 0;
  }
  if (argc != 2) {
    std::fprintf(stderr, "thin_ice_edge_balance: one run directory is needed\n%s", usage);
    return 2;
  }
  const std::string run = argv[1];
  try {
    if (!std::ifstream(run + "/summary.json")) throw std::runtime_error("no summary.json: not a thin_ice_run output directory");
    if (!std::ifstream(run + "/snapshots/index.csv")) {
      throw std::runtime_error("no snapshots/index.csv: the run needs --snapshots N (N >= 2)");
    }
    const YAML::Node summary = YAML::LoadFile(run + "/summary.json");  // JSON is YAML
    const std::string file = summary["scenario"]["file"].as<std::string>();
    std::vector<std::string> overrides;
    for (const YAML::Node& o : summary["scenario"]["overrides"]) overrides.push_back(o.as<std::string>());
    const thin_ice::Scenario scenario = thin_ice::loadScenario(file, overrides);
    const std::string run_hash = summary["scenario"]["hash"].as<std::string>();
    if (scenario.hash != run_hash) {
      throw std::runtime_error("scenario " + file + " has changed since the run (hash " + scenario.hash +
                               ", the run's " + run_hash + "): its bonds would not be the run's");
    }
    const thin_ice::IceSheet sheet = thin_ice::generateIceSheet(scenario.params.sheet);
    const thin_ice::Model model = thin_ice::buildModel(scenario.params, sheet, file);
    const thin_ice::FrontRow row = thin_ice::frontRow(model, sheet);
    std::printf("front row: %zu cells, %.3f m^2, weight %.0f N; %zu bonds across the cut to %zu cells\n",
                row.cells.size(), row.area, row.weight, row.cut_bonds.size(), row.rear_cells.size());

    const std::string loads_path = run + "/loads.csv", index_path = run + "/snapshots/index.csv";
    const auto loads = readCsv(loads_path);
    const auto index = readCsv(index_path);
    std::printf("| L [m] | structure's vertical load [N] | bonds across the cut [N] | buoyancy lost by the front row [N] "
                "| sum [N] | front row lift [mm] | row behind lift [mm] | broken bonds |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const auto& entry : index) {
      const std::string name = entry.at("file");  // cells_RRRRRR.csv, RRRRRR: the loads.csv row
      const long load_row = std::stol(name.substr(6, 6));
      if (load_row == 0) continue;  // the sheet at rest
      if (load_row > static_cast<long>(loads.size())) throw std::runtime_error(index_path + ": row " + name + " is past " + loads_path);
      const auto& load = loads[load_row - 1];
      const thin_ice::FrontRowBalance b = thin_ice::frontRowBalance(model, row, readPoses(run + "/snapshots/" + name));
      // The structure pushes the ice down: minus its vertical load on the structure.
      const double structure_down = -number(load, "vertical_raw_N", loads_path);
      std::printf("| %.4f | %.0f | %.0f | %.0f | %.0f | %.1f | %.1f | %s |\n", number(load, "pushed_length_m", loads_path),
                  shown(structure_down, 0), shown(b.bond_force, 0), shown(b.lost_buoyancy, 0),
                  shown(b.bond_force + b.lost_buoyancy, 0), shown(1e3 * b.front_lift, 1), shown(1e3 * b.rear_lift, 1),
                  load.at("broken_bonds").c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "thin_ice_edge_balance: %s: %s\n", run.c_str(), e.what());
    return 2;
  }
  return 0;
}
