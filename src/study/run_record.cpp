#include "thin_ice_sim/study/run_record.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "thin_ice_sim/study/run_report.hpp"

namespace thin_ice::run_record {

std::string panelColumn(int panel) { return "panel_" + std::to_string(panel) + "_N"; }

std::string loadsHeader(int panels) {
  std::string header = headerLine(kLoadColumns);
  header.pop_back();  // the newline, after the panels
  for (int p = 1; p <= panels; ++p) header += "," + panelColumn(p);
  return header + "\n";
}

std::string loadsRow(const LoadSample& s, int panels) {
  char text[256];
  std::snprintf(text, sizeof(text), "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%d,%d", s.time, s.pushed_length,
                s.horizontal_raw, s.horizontal_calibrated, s.vertical_raw, s.pusher_force, s.intact_bonds,
                s.broken_bonds, s.contacts);
  std::string row = text;
  for (int p = 0; p < panels; ++p) {  // the header's count, whatever the sample holds
    const std::size_t k = static_cast<std::size_t>(p);
    std::snprintf(text, sizeof(text), ",%.9g", k < s.panel_horizontal.size() ? s.panel_horizontal[k] : 0.0);
    row += text;
  }
  return row + "\n";
}

std::string loadBinsText(const std::vector<LoadBin>& bins) {
  std::string text = headerLine(kLoadBinColumns);
  char row[320];
  for (const LoadBin& b : bins) {
    std::snprintf(row, sizeof(row), "%ld,%.9g,%.9g,%.9g,%ld,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%d\n", b.index, b.time,
                  b.pushed_length, b.duration, b.samples, b.calibrated_mean, b.calibrated_least,
                  b.calibrated_greatest, b.vertical_mean, b.pusher_mean, b.intact_bonds, b.broken_bonds);
    text += row;
  }
  return text;
}

std::string snapshotText(const std::vector<CellSnapshot>& cells, const std::vector<std::vector<Vec2>>& polygons) {
  if (polygons.size() != cells.size()) {
    throw std::invalid_argument("snapshotText: " + std::to_string(cells.size()) + " cells and " +
                                std::to_string(polygons.size()) + " polygons");
  }
  std::ostringstream text;
  text.precision(9);
  text << headerLine(kSnapshotColumns);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const CellSnapshot& c = cells[k];
    text << k << ',' << c.x << ',' << c.y << ',' << c.z << ',' << c.yaw << ',' << (c.in_intact_sheet ? 1 : 0) << ','
         << c.piece_cells << ',';
    const std::vector<Vec2>& polygon = polygons[k];
    for (std::size_t v = 0; v < polygon.size(); ++v) text << (v ? " " : "") << polygon[v].x << ' ' << polygon[v].y;
    text << '\n';
  }
  return text.str();
}

std::string snapshotIndexRow(const std::string& file, double time, double pushed_length) {
  std::ostringstream row;  // the stream's default six significant digits
  row << file << ',' << time << ',' << pushed_length << '\n';
  return row.str();
}

std::string summaryJson(const SummaryRecord& r) {
  std::ostringstream j;
  auto num = [](double v) { return jsonNumber(v); };
  j << "{\n  \"schema_version\": " << kSummarySchemaVersion << ",\n  \"status\": " << jsonString(r.status)
    << ",\n  \"error\": " << (r.error.empty() ? "null" : jsonString(r.error))
    << ",\n  \"scenario\": {\"name\": " << jsonString(r.scenario_name) << ", \"file\": " << jsonString(r.scenario_file)
    << ", \"hash\": " << jsonString(r.scenario_hash) << ", \"overrides\": [";
  for (std::size_t k = 0; k < r.overrides.size(); ++k) j << (k ? ", " : "") << jsonString(r.overrides[k]);
  // The whole parameter set in force at the end, so that a resumption keeps the run's own values
  // whatever the scenario file says by then (thin_ice_sim/study/run_directory.hpp).
  j << "]},\n  \"parameters\": {";
  for (std::size_t k = 0; k < r.parameters.size(); ++k) {
    j << (k ? ", " : "") << jsonString(r.parameters[k].key) << ": " << jsonString(r.parameters[k].value);
  }
  j << "},\n  \"backend\": " << jsonString(r.backend) << ", \"backend_note\": " << jsonString(r.backend_note)
    << ", \"cpu_instruction_set\": " << jsonString(r.cpu_instruction_set) << ",\n  \"cells\": " << r.cells
    << ", \"time_step_s\": " << num(r.time_step) << ", \"critical_time_step_s\": " << num(r.critical_time_step)
    << ", \"structure_substeps\": " << r.structure_substeps
    << ", \"structure_critical_time_step_s\": " << num(r.structure_critical_time_step)
    << ",\n  \"output_interval_s\": " << num(r.output_interval) << ", \"loads_csv_from_s\": " << num(r.loads_csv_from)
    << ", \"load_bin_length_m\": " << num(r.load_bin_length) << ",\n  \"target\": {\""
    << (r.target_is_length ? "pushed_length_m" : "time_s") << "\": " << num(r.target) << "}"
    << ",\n  \"steps\": " << r.steps << ", \"simulated_time_s\": " << num(r.simulated_time)
    << ", \"pushed_length_m\": " << num(r.pushed_length) << ",\n  \"setup_wall_time_s\": " << num(r.setup_wall_time)
    << ", \"wall_time_s\": " << num(r.wall_time) << ",\n  \"cell_steps_per_second\": " << num(r.cell_steps_per_second)
    << ", \"real_time_factor\": " << num(r.real_time_factor);
  j << ",\n  \"resumed_at_m\": [";
  for (std::size_t k = 0; k < r.resumed_at.size(); ++k) j << (k ? ", " : "") << num(r.resumed_at[k]);
  j << "],\n  \"overrides_from_m\": [";
  for (std::size_t k = 0; k < r.overrides_from.size(); ++k) {
    j << (k ? ", " : "") << "{\"set\": " << jsonString(r.overrides_from[k].set)
      << ", \"from_m\": " << num(r.overrides_from[k].from_length) << "}";
  }
  j << "]" << ",\n  \"intact_bonds\": " << r.intact_bonds << ", \"broken_bonds\": " << r.broken_bonds
    << ",\n  \"calibration_factor\": " << num(r.calibration_factor) << ",\n  \"load\": " << r.load_json;
  j << ",\n  \"structure_width_m\": " << num(r.structure_width);
  // The geometry the run used, overrides applied, so that a reader (the validation report's
  // profile plots) draws the face without re-reading the scenario file.
  j << ",\n  \"structure\": {\"toe_x_m\": " << num(r.toe_x) << ", \"angle_deg\": " << num(r.angle_deg)
    << ", \"width_m\": " << num(r.structure_width) << ", \"height_m\": " << num(r.structure_height)
    << ", \"panels\": " << r.panels << "}";
  j << ",\n  \"false_bottom\": " << (r.false_bottom ? "" : "null");
  if (r.false_bottom) {
    j << "{\"depth_m\": " << num(r.bottom_depth)
      << ", \"distance_from_structure_m\": " << num(r.bottom_distance_from_structure) << "}";
  }
  j << ",\n  \"experiment\": " << r.experiment_json;
  j << "\n}\n";
  return j.str();
}

std::string snapshotFileName(long loads_row) {
  char name[32];
  std::snprintf(name, sizeof(name), "cells_%06ld.csv", loads_row);
  return name;
}

bool parseSnapshotFileName(const std::string& name, long& loads_row) {
  if (name.size() != 16 || name.compare(0, 6, "cells_") != 0 || name.compare(12, 4, ".csv") != 0) return false;
  if (!std::all_of(name.begin() + 6, name.begin() + 12, [](char c) { return c >= '0' && c <= '9'; })) return false;
  loads_row = std::stol(name.substr(6, 6));
  return true;
}

}  // namespace thin_ice::run_record
