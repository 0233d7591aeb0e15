#include "thin_ice_sim/study/run_record.hpp"

#include <algorithm>
#include <cstdio>

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
