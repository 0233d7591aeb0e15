#include "thin_ice_sim/study/run_report.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace thin_ice {

const Experiment* experimentFor(const std::string& scenario_name) {
  static const Experiment kTable6[] = {
      {"W", 8600.0, 15790.0, "Table 6 / Fig. 10: W-3 steady state and peak"},
      {"M", 7820.0, 12700.0, "Table 6 / Fig. 11: M-2 steady state and peak"},
      {"S", 13750.0, 20560.0, "Table 6 / Fig. 12: S-2 steady state, S-1 peak"}};
  if (scenario_name.size() < 2 || scenario_name[1] != '-') return nullptr;
  for (const Experiment& e : kTable6) {
    if (std::toupper(static_cast<unsigned char>(scenario_name[0])) == e.series[0]) return &e;
  }
  return nullptr;
}

double experimentWidthScale(double structure_width) {
  constexpr double kExperimentWidth = 10.0;  // [m] Table 4
  return structure_width / kExperimentWidth;
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
