#include "thin_ice_sim/study/run_report.hpp"

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "thin_ice_experiments_yaml.hpp"

namespace thin_ice {
namespace {

/// config/experiments.yaml as built in: the experiments' structure width and one Experiment per
/// ice type. Read once; a file the build embedded cannot be missing, and a malformed one fails the
/// tests that compare with it.
struct ExperimentTable {
  double structure_width;  ///< [m]
  std::vector<Experiment> ice_types;
};

const ExperimentTable& experimentTable() {
  static const ExperimentTable table = [] {
    const YAML::Node root = YAML::Load(kExperimentsYaml);
    ExperimentTable t{root["structure_width"].as<double>(), {}};
    for (const auto& entry : root["ice_types"]) {
      const YAML::Node& e = entry.second;
      t.ice_types.push_back({entry.first.as<std::string>(), e["steady_mean"].as<double>(), e["peak"].as<double>(),
                             e["source"].as<std::string>()});
    }
    return t;
  }();
  return table;
}

}  // namespace

const Experiment* experimentFor(const std::string& scenario_name) {
  if (scenario_name.size() < 2 || scenario_name[1] != '-') return nullptr;
  for (const Experiment& e : experimentTable().ice_types) {
    if (std::toupper(static_cast<unsigned char>(scenario_name[0])) == e.series[0]) return &e;
  }
  return nullptr;
}

double experimentWidthScale(double structure_width) {
  return structure_width / experimentTable().structure_width;
}

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += std::string("\\") + c;
    } else if (static_cast<unsigned char>(c) < 0x20) {  // control characters: \u00XX
      char code[8];
      std::snprintf(code, sizeof(code), "\\u%04x", static_cast<unsigned>(c));
      out += code;
    } else {
      out += c;  // UTF-8 bytes pass through
    }
  }
  return out + "\"";
}

std::string jsonNumber(double value) {
  if (!std::isfinite(value)) return "null";
  char text[32];
  std::snprintf(text, sizeof(text), "%.10g", value);
  return text;
}

std::string loadJson(const LoadStatistics& s, double first_failure_length) {
  auto num = [](double v) { return jsonNumber(v); };
  std::ostringstream j;
  j << "{\n    \"quantity\": \"horizontal_calibrated_N against pushed_length_m\""
    << ",\n    \"samples\": " << s.samples
    << ",\n    \"peak_N\": " << num(s.peak_load) << ", \"peak_at_m\": " << num(s.peak_length)
    << ",\n    \"first_failure_m\": " << num(first_failure_length)
    << ",\n    \"phase1_slope_N_per_m\": " << num(s.phase1_slope)
    << ", \"phase1_range_m\": [" << num(s.phase1_begin) << ", " << num(s.phase1_end) << "]"
    << ",\n    \"steady_found\": " << (s.steady_found ? "true" : "false")
    << ",\n    \"steady_window_m\": [" << num(s.steady_begin) << ", " << num(s.steady_end) << "]"
    << ",\n    \"steady_mean_N\": " << num(s.steady_mean) << ", \"steady_std_N\": " << num(s.steady_std)
    << ", \"steady_samples\": " << s.steady_samples
    << ",\n    \"steady_rule\": " << jsonString(s.steady_rule) << "\n  }";
  return j.str();
}

ExperimentComparison compareWithExperiment(const std::string& scenario_name, double structure_width,
                                           const LoadStatistics& s) {
  ExperimentComparison c;
  c.experiment = experimentFor(scenario_name);
  if (!c.experiment) return c;
  c.width_scale = experimentWidthScale(structure_width);
  c.mean = c.width_scale * c.experiment->mean;
  c.peak = c.width_scale * c.experiment->peak;
  c.mean_error_percent = 100.0 * (s.steady_mean - c.mean) / c.mean;
  c.peak_error_percent = 100.0 * (s.peak_load - c.peak) / c.peak;
  return c;
}

std::string experimentJson(const std::string& scenario_name, double structure_width, const LoadStatistics& s) {
  const ExperimentComparison c = compareWithExperiment(scenario_name, structure_width, s);
  if (!c.experiment) return "null";
  std::ostringstream j;
  j << "{\"series\": " << jsonString(c.experiment->series) << ", \"source\": " << jsonString(c.experiment->source)
    << ", \"width_scale\": " << jsonNumber(c.width_scale) << ", \"steady_mean_N\": " << jsonNumber(c.mean)
    << ", \"peak_N\": " << jsonNumber(c.peak)
    << ",\n    \"steady_mean_error_percent\": " << jsonNumber(c.mean_error_percent)
    << ", \"peak_error_percent\": " << jsonNumber(c.peak_error_percent) << "}";
  return j.str();
}

}  // namespace thin_ice
