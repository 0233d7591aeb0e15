// What `thin_ice run` writes about a run's loads in summary.json, shared with `thin_ice analyse` so
// that a finished run's statistics can be worked out again with the same code: the experiment of
// Table 6 that a series is compared with, and the "load" and "experiment" objects.
#pragma once

#include <string>

#include "thin_ice_sim/study/load_statistics.hpp"

namespace thin_ice {

/// A Table 6 experiment (Lemstrom et al.): ice type letter, steady-state mean F_avg [N] and peak
/// F_p [N] on the experiments' structure, and where the numbers come from. The figures are those
/// of config/experiments.yaml, embedded when the library is built.
struct Experiment {
  std::string series;
  double mean, peak;
  std::string source;
};

/// The experiment a scenario named "W-3", "M-1", ... is compared with; nullptr for other names.
const Experiment* experimentFor(const std::string& scenario_name);

/// Table 6 loads are for the structure of Table 4 (10 m wide): a narrower slice of the same set-up
/// is compared with them scaled by its width (load per metre of structure) [-].
double experimentWidthScale(double structure_width);

/// A run's load statistics beside the experiment of its series (experiment nullptr: none).
struct ExperimentComparison {
  const Experiment* experiment = nullptr;
  double width_scale = 1.0;         ///< [-] the run's structure width / 10 m
  double mean = 0.0, peak = 0.0;    ///< [N] the experiment's steady mean and peak, scaled by width
  double mean_error_percent = 0.0;  ///< 100 (model - experiment) / experiment, steady mean
  double peak_error_percent = 0.0;  ///< the same for the peak
};
ExperimentComparison compareWithExperiment(const std::string& scenario_name, double structure_width,
                                           const LoadStatistics& s);

/// A JSON string literal (quotes, backslashes and control characters escaped).
std::string jsonString(const std::string& text);
/// A JSON number with ten significant digits; NaN and infinity (which JSON lacks) become null.
std::string jsonNumber(double value);

/// summary.json's "load" object (no trailing newline), indented as `thin_ice run` writes it:
/// the statistics of F_cal against L and the first failure that starts phase 1 [m].
std::string loadJson(const LoadStatistics& s, double first_failure_length);

/// summary.json's "experiment" object for `scenario_name` on a structure `structure_width` [m]
/// wide, with the errors of `s` against it; "null" when the scenario has no experiment.
std::string experimentJson(const std::string& scenario_name, double structure_width, const LoadStatistics& s);

}  // namespace thin_ice
