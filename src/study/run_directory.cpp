#include "thin_ice_sim/study/run_directory.hpp"

#include "thin_ice_sim/study/run_record.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

namespace thin_ice {
namespace {

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) fields.push_back(field);
  return fields;
}

/// RUN/summary.json as a YAML node (JSON is YAML); throws std::runtime_error naming the file.
YAML::Node loadSummary(const std::string& run_dir) {
  const std::string path = run_dir + "/" + run_record::kSummaryFile;
  if (!std::ifstream(path)) throw std::runtime_error("no " + path + ": not a run directory of `thin_ice run`");
  YAML::Node summary;
  try {
    summary = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  if (!summary.IsMap()) {
    throw std::runtime_error(path + ": not a JSON object; allowed: the summary.json of `thin_ice run`");
  }
  // A record without the field has layout 1 (run_record.hpp); a later layout may mean a field this
  // reader knows by name something else, so it is refused rather than misread.
  const YAML::Node version = summary["schema_version"];
  if (version) {
    int v = 0;
    try {
      // A quoted scalar ("1") is text, not the number the writer writes.
      v = version.Tag() == "!" ? 0 : version.as<int>();
    } catch (const YAML::Exception&) {
      v = 0;
    }
    if (v < 1 || v > run_record::kSummarySchemaVersion) {
      const std::string shown = version.Tag() == "!" ? "\"" + version.Scalar() + "\"" : YAML::Dump(version);
      const bool newer = v > run_record::kSummarySchemaVersion;
      throw std::runtime_error(path + ": \"schema_version\" is " + shown + "; allowed: a whole number from 1 to " +
                               std::to_string(run_record::kSummarySchemaVersion) +
                               (newer ? " (a record of a newer thin_ice is read by that thin_ice)" : ""));
    }
  }
  return summary;
}

/// Appends `item` to `list`, after `separator` when the list is not empty.
void appendItem(std::string& list, const char* separator, const std::string& item) {
  list += (list.empty() ? "" : separator) + item;
}

/// The scenario of a run that recorded its parameters (summary.json "parameters", `recorded`): the
/// file with the run's overrides, and where the file now gives other values, the run's values
/// added to the overrides (unless accept_changed_file), each named in `warning` with both values.
Scenario keepRecordedParameters(const std::string& file, std::vector<std::string> overrides,
                                const YAML::Node& recorded, bool accept_changed_file, std::string& warning) {
  Scenario scenario = loadScenario(file, overrides);
  std::vector<std::string> kept;
  std::string differences, unknown;
  std::set<std::string> given_now;
  for (const ParameterValue& now : scenarioParameters(scenario.params)) {
    given_now.insert(now.key);
    const YAML::Node run_value = recorded[now.key];
    if (!run_value.IsDefined() || !run_value.IsScalar() || run_value.Scalar() == now.value) continue;
    appendItem(differences, ", ", now.key + " " + now.value + " (the run's: " + run_value.Scalar() + ")");
    kept.push_back(now.key + "=" + run_value.Scalar());
  }
  // What the run gave and the file now does not: a rule it used (E_v by its factor, where the file
  // now states a value), after the values in the format's order, so that the rule holds again.
  for (const auto& item : recorded) {
    const std::string key = item.first.as<std::string>();
    if (given_now.count(key) || !item.second.IsScalar()) continue;
    const std::string set = key + "=" + item.second.Scalar();
    try {
      overrideKey(set, file);
    } catch (const ScenarioError&) {
      appendItem(unknown, " ", key);
      continue;
    }
    appendItem(differences, ", ", key + " not given (the run's: " + item.second.Scalar() + ")");
    kept.push_back(set);
  }
  if (!differences.empty()) {
    if (accept_changed_file) {
      warning = "scenario " + file + " now gives " + differences + "; the file's values taken, as asked";
    } else {
      overrides.insert(overrides.end(), kept.begin(), kept.end());
      scenario = loadScenario(file, overrides);
      warning = "scenario " + file + " now gives " + differences + "; the run keeps its own (added to its "
                "overrides; --accept-changed-scenario takes the file's)";
    }
  }
  // Keys the run has no value of: added to the format after it (or a rule the file now uses).
  std::string unrecorded;
  for (const ParameterValue& now : scenarioParameters(scenario.params)) {
    if (!recorded[now.key].IsDefined()) appendItem(unrecorded, " ", now.key);
  }
  if (!unrecorded.empty()) appendItem(warning, "; ", "the run recorded no value of " + unrecorded + ": the file's taken");
  if (!unknown.empty()) {
    appendItem(warning, "; ", "the run recorded " + unknown + ", which the scenario format no longer has: left out");
  }
  return scenario;
}

/// A run recorded before its parameters were: held to the hash of its scenario (file text and
/// overrides). A changed file is refused unless accept_changed_file, which takes it with a warning.
void holdToRunHash(const Scenario& scenario, const std::string& file, const std::string& run_hash,
                   bool accept_changed_file, std::string& warning) {
  if (scenario.hash == run_hash) return;
  const std::string what = "scenario " + file + " has changed since the run (hash " + scenario.hash +
                           ", the run's " + run_hash + ")";
  if (!accept_changed_file) {
    throw std::runtime_error(what + ": its sheet and bonds may not be the run's (--accept-changed-scenario if the "
                             "run's parameters did not change: only comments, or one of its --set values written "
                             "into the file)");
  }
  warning = what + "; taken as the run's, as asked";
}

}  // namespace

std::vector<CsvRow> readCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + " is empty");
  const std::vector<std::string> header = splitCsvLine(line);
  std::vector<CsvRow> rows;
  for (long number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> fields = splitCsvLine(line);
    if (fields.size() != header.size()) {
      throw std::runtime_error(path + " line " + std::to_string(number) + ": " + std::to_string(fields.size()) +
                               " fields, the header has " + std::to_string(header.size()) + " (a truncated file?)");
    }
    CsvRow row;
    for (size_t c = 0; c < header.size(); ++c) row[header[c]] = fields[c];
    rows.push_back(row);
  }
  return rows;
}

double csvNumber(const CsvRow& row, const std::string& column, const std::string& path) {
  const auto it = row.find(column);
  if (it == row.end()) throw std::runtime_error(path + ": no column " + column);
  try {
    size_t used = 0;
    const double value = std::stod(it->second, &used);
    if (used == it->second.size()) return value;
  } catch (const std::exception&) {
  }
  throw std::runtime_error(path + ": column " + column + " holds '" + it->second + "', not a number");
}

Scenario loadRunScenario(const std::string& run_dir, bool accept_changed_file, std::string& warning,
                         bool* parameters_recorded) {
  const YAML::Node summary = loadSummary(run_dir);
  const std::string file = summary["scenario"]["file"].as<std::string>();
  std::vector<std::string> overrides;
  for (const YAML::Node& o : summary["scenario"]["overrides"]) overrides.push_back(o.as<std::string>());
  // The file is named as the run was started, often relative to the directory it was started from.
  if (std::filesystem::path(file).is_relative() && !std::filesystem::exists(file)) {
    throw std::runtime_error(run_dir + "/summary.json names the scenario " + file +
                             ", relative to the directory the run was started from; there is no such file under the "
                             "working directory " + std::filesystem::current_path().string() +
                             ": resume from that directory (the repository root for the shipped runs)");
  }
  warning.clear();
  const YAML::Node recorded = summary["parameters"];
  if (parameters_recorded) *parameters_recorded = recorded.IsMap();
  if (recorded.IsMap()) return keepRecordedParameters(file, overrides, recorded, accept_changed_file, warning);
  Scenario scenario = loadScenario(file, overrides);
  holdToRunHash(scenario, file, summary["scenario"]["hash"].as<std::string>(), accept_changed_file, warning);
  return scenario;
}

RunSummary readRunSummary(const std::string& run_dir) {
  const std::string path = run_dir + "/" + run_record::kSummaryFile;
  const YAML::Node summary = loadSummary(run_dir);
  auto field = [&](const char* key, const char* allowed) {
    const YAML::Node node = summary[key];
    if (!node) throw std::runtime_error(path + ": no \"" + key + "\" (" + allowed + ")");
    return node;
  };
  auto number = [&](const char* key, auto kind, const char* allowed) {
    try {
      return field(key, allowed).template as<decltype(kind)>();
    } catch (const YAML::Exception&) {
      throw std::runtime_error(path + ": \"" + key + "\" is " + YAML::Dump(summary[key]) + "; allowed: " + allowed);
    }
  };
  RunSummary r;
  r.status = number("status", std::string(), "completed, interrupted or unhealthy");
  r.output_interval = number("output_interval_s", 0.0, "a time [s]");
  r.wall_time = number("wall_time_s", 0.0, "a time [s]");
  r.steps = number("steps", 0L, "a whole number of steps");
  // Written since load_bins.csv: where loads.csv begins (0 before: it held the whole run).
  r.loads_csv_from = summary["loads_csv_from_s"] ? number("loads_csv_from_s", 0.0, "a time [s]") : 0.0;
  // null: no bond had broken (jsonNumber writes +infinity as null).
  const YAML::Node failure = summary["load"] ? summary["load"]["first_failure_m"] : YAML::Node();
  if (failure && !failure.IsNull()) {
    try {
      r.first_failure_length = failure.as<double>();
    } catch (const YAML::Exception&) {
      throw std::runtime_error(path + ": \"load\".\"first_failure_m\" is " + YAML::Dump(failure) +
                               "; allowed: a length [m] or null (no bond broken)");
    }
  }
  if (summary["resumed_at_m"]) {
    for (const YAML::Node& l : summary["resumed_at_m"]) r.resumed_at.push_back(l.as<double>());
  }
  if (summary["overrides_from_m"]) {
    for (const YAML::Node& s : summary["overrides_from_m"]) {
      if (!s["set"] || !s["from_m"]) {
        throw std::runtime_error(path + ": an entry of \"overrides_from_m\" is " + YAML::Dump(s) +
                                 "; allowed: {\"set\": \"section.key=value\", \"from_m\": a length [m]}");
      }
      r.switched.push_back({s["set"].as<std::string>(), s["from_m"].as<double>()});
    }
  }
  if (summary["scenario"] && summary["scenario"]["name"]) r.scenario_name = summary["scenario"]["name"].as<std::string>();
  // Not needed to resume, so a missing or null width (jsonNumber's NaN) is NaN here, not an error.
  const YAML::Node width = summary["structure_width_m"];
  r.structure_width = width && !width.IsNull() ? number("structure_width_m", 0.0, "a width [m]")
                                               : std::numeric_limits<double>::quiet_NaN();
  return r;
}

LoadHistory readLoadHistory(const std::string& csv_path) {
  namespace column = run_record::load_column;
  LoadHistory h;
  for (const CsvRow& row : readCsv(csv_path)) {
    h.time.push_back(csvNumber(row, column::kTime, csv_path));
    h.pushed_length.push_back(csvNumber(row, column::kPushedLength, csv_path));
    h.load.push_back(csvNumber(row, column::kHorizontalCalibrated, csv_path));
    h.vertical.push_back(csvNumber(row, column::kVerticalRaw, csv_path));
    h.pusher.push_back(csvNumber(row, column::kPusherForce, csv_path));
    h.intact_bonds.push_back(static_cast<int>(csvNumber(row, column::kIntactBonds, csv_path)));
    h.broken_bonds.push_back(static_cast<int>(csvNumber(row, column::kBrokenBonds, csv_path)));
  }
  return h;
}

std::vector<LoadBin> binLoadHistory(const LoadHistory& h) {
  LoadBinner binner;
  for (std::size_t k = 0; k < h.time.size(); ++k) {
    LoadSample row;
    row.time = h.time[k];
    row.pushed_length = h.pushed_length[k];
    row.horizontal_calibrated = h.load[k];
    row.vertical_raw = h.vertical[k];
    row.pusher_force = h.pusher[k];
    row.intact_bonds = h.intact_bonds[k];
    row.broken_bonds = h.broken_bonds[k];
    binner.add(row);
  }
  return binner.bins();
}

std::vector<LoadBin> readLoadBins(const std::string& csv_path) {
  namespace column = run_record::bin_column;
  std::vector<LoadBin> bins;
  long line = 1;
  for (const CsvRow& row : readCsv(csv_path)) {
    ++line;
    LoadBin b;
    auto count = [&](const char* name) {
      const double value = csvNumber(row, name, csv_path);
      if (!(value >= 0.0) || value != std::floor(value)) {
        throw std::runtime_error(csv_path + " data row " + std::to_string(line - 1) + ": " + name + " " + row.at(name) +
                                 "; allowed: a whole number >= 0");
      }
      return static_cast<long>(value);
    };
    b.index = count(column::kBin);
    b.time = csvNumber(row, column::kTime, csv_path);
    b.pushed_length = csvNumber(row, column::kPushedLength, csv_path);
    b.duration = csvNumber(row, column::kDuration, csv_path);
    b.samples = count(column::kSamples);
    b.calibrated_mean = csvNumber(row, column::kCalibratedMean, csv_path);
    b.calibrated_least = csvNumber(row, column::kCalibratedLeast, csv_path);
    b.calibrated_greatest = csvNumber(row, column::kCalibratedGreatest, csv_path);
    b.vertical_mean = csvNumber(row, column::kVerticalMean, csv_path);
    b.pusher_mean = csvNumber(row, column::kPusherMean, csv_path);
    b.intact_bonds = static_cast<int>(count(column::kIntactBonds));
    b.broken_bonds = static_cast<int>(count(column::kBrokenBonds));
    if (!bins.empty() && !(b.index > bins.back().index && b.time > bins.back().time &&
                           b.pushed_length >= bins.back().pushed_length)) {
      throw std::runtime_error(csv_path + " data row " + std::to_string(line - 1) + ": bin " + std::to_string(b.index) +
                               " at t = " + row.at(column::kTime) + " s does not follow bin " +
                               std::to_string(bins.back().index) + "; allowed: bins, times and lengths in increasing order "
                               "(the record is damaged)");
    }
    if (b.samples == 0 || !(b.duration > 0.0)) {
      throw std::runtime_error(csv_path + " data row " + std::to_string(line - 1) + ": a bin of " + std::to_string(b.samples) +
                               " rows over " + row.at(column::kDuration) + " s; allowed: at least one row, over more than 0 s");
    }
    bins.push_back(b);
  }
  return bins;
}

std::vector<LoadBin> readRunLoadBins(const std::string& run_dir) {
  const std::string bins_path = run_dir + "/" + run_record::kLoadBinsFile;
  if (std::filesystem::exists(bins_path)) return readLoadBins(bins_path);
  const std::string loads_path = run_dir + "/" + run_record::kLoadsFile;
  if (std::filesystem::exists(loads_path)) {
    // Only a loads.csv of the whole run stands for its record: one begun at a resumption holds
    // the rows after it alone.
    const YAML::Node from = loadSummary(run_dir)["loads_csv_from_s"];
    if (from && !from.IsNull() && from.as<double>() > 0.0) {
      throw std::runtime_error("no " + bins_path + ", and " + loads_path + " holds the rows from t = " +
                               from.as<std::string>() + " s on only: the run's kept record is missing");
    }
    return binLoadHistory(readLoadHistory(loads_path));
  }
  throw std::runtime_error("no " + bins_path + " nor " + loads_path + ": not a run directory of `thin_ice run`");
}

std::vector<SnapshotEntry> readSnapshotIndex(const std::string& run_dir) {
  const std::string index_path =
      run_dir + "/" + run_record::kSnapshotDir + "/" + run_record::kSnapshotIndexFile;
  if (!std::ifstream(index_path)) throw std::runtime_error("no snapshots/index.csv: the run needs --snapshots N");
  std::vector<SnapshotEntry> entries;
  for (const CsvRow& row : readCsv(index_path)) {
    SnapshotEntry e;
    namespace column = run_record::index_column;
    const std::string name = row.count(column::kFile) ? row.at(column::kFile) : "";
    if (!run_record::parseSnapshotFileName(name, e.loads_row)) {
      throw std::runtime_error(index_path + ": file '" + name + "' is not a cells_RRRRRR.csv name (six digits)");
    }
    e.file = run_dir + "/" + run_record::kSnapshotDir + "/" + name;
    e.time = csvNumber(row, column::kTime, index_path);
    e.pushed_length = csvNumber(row, column::kPushedLength, index_path);
    entries.push_back(e);
  }
  return entries;
}

std::vector<CellSnapshot> readCellSnapshot(const std::string& path) {
  std::vector<CellSnapshot> cells;
  for (const CsvRow& row : readCsv(path)) {
    namespace column = run_record::snapshot_column;
    CellSnapshot c{};
    c.x = csvNumber(row, column::kX, path);
    c.y = csvNumber(row, column::kY, path);
    c.z = csvNumber(row, column::kZ, path);
    c.yaw = csvNumber(row, column::kYaw, path);
    c.in_intact_sheet = csvNumber(row, column::kInIntactSheet, path) != 0.0;
    // Older snapshots have no piece_cells column: 0 there means "not recorded".
    c.piece_cells = row.count(column::kPieceCells) ? static_cast<int>(csvNumber(row, column::kPieceCells, path)) : 0;
    cells.push_back(c);
  }
  return cells;
}

}  // namespace thin_ice
