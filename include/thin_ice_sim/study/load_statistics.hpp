// Statistics of a load history F(L) (horizontal load against pushed ice length), as the paper
// reads Figures 9-12 (Section 5.1): peak load, the phase-1 slope (linear rise while the rubble
// pile grows, about 1500 N/m in the experiments) and the phase-2 steady state (F about constant),
// its window, mean and scatter. Pure functions: no I/O, no simulation.
//
// The steady state is found by a fixed rule written in code (SteadyStateRule), never by eye:
//   reference = mean of raw F over the last tail_fraction of the pushed length
//   F_s(L)    = moving mean of F over the samples with |L_i - L| <= smoothing_length / 2
//   L_begin   = the first sample after the last one whose F_s lies outside
//               reference * (1 +- band); L_end = the last sample
//   found     = L_end - L_begin >= min_length, >= min_samples samples in the window, and the
//               least-squares trend over the window, |slope| (L_end - L_begin), is at most
//               max_drift * (window mean)  (a record that keeps rising is not steady)
// Otherwise the last tail_fraction of the record is reported as a "not steady: tail mean" window
// with found = false.
//
// Phase 1: least-squares slope of F against L over [L_onset, L_stop), where L_stop is the start
// of the steady window (or of the tail window when no steady state was found). Phase 1 is the
// rise of the load while the rubble pile grows, and the pile begins with the sheet's first
// failure, so with a first failure (first_failure_length, the caller's: the first broken bond)
// L_onset is where that failure's collapse ends: the lowest F within phase1_search_length after
// it. The intact sheet's elastic loading before it, and the collapse itself, are one event, and a
// fit that starts on them is governed by them (M-2-long to 2.15 m: 232 N/m from first contact,
// 1452 N/m from the first broken bond's row, 1397 N/m from the end of the collapse; the end found
// is the same for search lengths of 0.05, 0.1 and 0.2 m in six runs). A sheet that never failed
// (first_failure_length = +infinity) has no pile and no phase 1. Where the first failure is not
// known (NaN), L_onset is the first L at which F exceeds onset_fraction * reference.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace thin_ice {

/// The numbers of the steady-state rule. Defaults suit the paper's records: 2-6 m of pushed
/// ice, loads of 5-20 kN with failure events every few decimetres.
struct SteadyStateRule {
  double smoothing_length = 0.5;  ///< [m] width of the centred moving mean of F (10 s at 5 cm/s)
  double band = 0.15;             ///< [-] F_s must stay within reference * (1 +- band)
  double tail_fraction = 0.25;    ///< [-] last fraction of the pushed length giving the reference
  double min_length = 1.0;        ///< [m] shortest steady window accepted
  int min_samples = 10;           ///< [-] fewest samples in the steady window accepted
  double max_drift = 0.10;        ///< [-] largest |trend| over the window, relative to its mean
  double onset_fraction = 0.05;   ///< [-] without a failure, phase 1 starts where F first exceeds this x reference
  double phase1_search_length = 0.1;  ///< [m] after the first failure, phase 1 starts at the lowest F within this
};

struct LoadStatistics {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  int samples = 0;               ///< samples analysed (0 when the input was rejected)
  double peak_load = kNaN;       ///< [N] largest F in the record
  double peak_length = kNaN;     ///< [m] L at the (first) peak

  double phase1_slope = kNaN;    ///< [N/m] least-squares dF/dL over the phase-1 range
  double phase1_begin = kNaN;    ///< [m] first L of the phase-1 fit
  double phase1_end = kNaN;      ///< [m] last L of the phase-1 fit
  int phase1_samples = 0;        ///< samples in the phase-1 fit

  bool steady_found = false;     ///< true when the rule above found a steady state
  double steady_begin = kNaN;    ///< [m] window start (tail window when not found)
  double steady_end = kNaN;      ///< [m] window end
  double steady_mean = kNaN;     ///< [N] mean of raw F over the window
  double steady_std = kNaN;      ///< [N] sample standard deviation (n - 1) of F over the window
  int steady_samples = 0;        ///< samples in the window
  double reference_mean = kNaN;  ///< [N] mean of F over the last tail_fraction of L
  std::string steady_rule;       ///< one line: how the window was chosen, or why nothing was
};

/// Analyses a load history. `pushed_length` [m] must be non-decreasing and as long as `load`
/// [N]; `first_failure_length` [m] is L at the sheet's first broken bond, after which phase 1
/// begins (+infinity: no bond broke, so no phase 1; NaN: not known). Never throws on bad data: empty, mismatched, too short, non-finite or
/// decreasing input gives steady_found = false and steady_rule says what was wrong.
LoadStatistics analyseLoadHistory(const std::vector<double>& pushed_length,
                                  const std::vector<double>& load,
                                  const SteadyStateRule& rule = SteadyStateRule(),
                                  double first_failure_length = LoadStatistics::kNaN);

/// L [m] of the first sample with a broken bond, +infinity when none broke; `broken_bonds` is the
/// count per sample, as long as `pushed_length`.
double firstFailureLength(const std::vector<double>& pushed_length, const std::vector<int>& broken_bonds);

/// Least-squares slope dy/dx over samples [first, last) [units of y per unit of x]; NaN when
/// fewer than two samples or all x are equal.
double leastSquaresSlope(const std::vector<double>& x, const std::vector<double>& y, size_t first,
                         size_t last);

}  // namespace thin_ice
