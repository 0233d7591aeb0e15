// Peak, phase-1 slope and steady state of a load history; the rule is in load_statistics.hpp.
#include "thin_ice_sim/study/load_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>

namespace thin_ice {
namespace {

std::string format(const char* pattern, ...) {
  char buffer[512];
  va_list args;
  va_start(args, pattern);
  std::vsnprintf(buffer, sizeof(buffer), pattern, args);
  va_end(args);
  return buffer;
}

struct WindowStats {
  double mean = LoadStatistics::kNaN;  // [N]
  double stddev = LoadStatistics::kNaN;  // [N], n - 1 in the denominator
  int count = 0;
};

WindowStats windowStats(const std::vector<double>& load, size_t first, size_t last) {
  WindowStats w;
  w.count = static_cast<int>(last - first);
  if (w.count < 1) return w;
  double sum = 0.0;
  for (size_t i = first; i < last; ++i) sum += load[i];
  w.mean = sum / w.count;
  if (w.count < 2) return w;
  double squares = 0.0;  // two passes: the loads are large and their scatter small
  for (size_t i = first; i < last; ++i) squares += (load[i] - w.mean) * (load[i] - w.mean);
  w.stddev = std::sqrt(squares / (w.count - 1));
  return w;
}

/// Centred moving mean: smoothed[i] = mean of F over the samples with |L_j - L_i| <= half_width.
/// L is non-decreasing, so both window edges only move forward (O(n)).
std::vector<double> movingMean(const std::vector<double>& length, const std::vector<double>& load,
                               double half_width) {
  const size_t n = load.size();
  std::vector<double> prefix(n + 1, 0.0);  // prefix[i] = sum of load[0 .. i)
  for (size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + load[i];
  std::vector<double> smoothed(n);
  size_t lo = 0, hi = 0;  // window [lo, hi)
  for (size_t i = 0; i < n; ++i) {
    while (length[lo] < length[i] - half_width) ++lo;
    if (hi < i + 1) hi = i + 1;
    while (hi < n && length[hi] <= length[i] + half_width) ++hi;
    smoothed[i] = (prefix[hi] - prefix[lo]) / static_cast<double>(hi - lo);
  }
  return smoothed;
}

std::string checkRule(const SteadyStateRule& r) {
  if (!(r.smoothing_length >= 0.0)) return "rule.smoothing_length must be >= 0 m";
  if (!(r.band > 0.0)) return "rule.band must be > 0";
  if (!(r.tail_fraction > 0.0 && r.tail_fraction <= 1.0)) return "rule.tail_fraction must be in (0, 1]";
  if (!(r.min_length >= 0.0)) return "rule.min_length must be >= 0 m";
  if (!(r.max_drift >= 0.0)) return "rule.max_drift must be >= 0";
  if (!(r.onset_fraction >= 0.0)) return "rule.onset_fraction must be >= 0";
  if (!(r.phase1_search_length >= 0.0)) return "rule.phase1_search_length must be >= 0 m";
  return "";
}

}  // namespace

double leastSquaresSlope(const std::vector<double>& x, const std::vector<double>& y, size_t first,
                         size_t last) {
  last = std::min({last, x.size(), y.size()});
  if (last < first + 2) return LoadStatistics::kNaN;
  const double count = static_cast<double>(last - first);
  double mx = 0.0, my = 0.0;
  for (size_t i = first; i < last; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= count;
  my /= count;
  double sxy = 0.0, sxx = 0.0;  // centred sums: no cancellation for x far from 0
  for (size_t i = first; i < last; ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  return sxx > 0.0 ? sxy / sxx : LoadStatistics::kNaN;
}

LoadStatistics analyseLoadHistory(const std::vector<double>& pushed_length,
                                  const std::vector<double>& load, const SteadyStateRule& rule,
                                  double first_failure_length) {
  LoadStatistics s;
  const std::vector<double>& L = pushed_length;
  const std::vector<double>& F = load;
  // --- Reject what cannot be analysed (no statistics at all). ---------------------------------
  if (L.size() != F.size()) {
    s.steady_rule = format("no statistics: %zu pushed lengths but %zu loads", L.size(), F.size());
    return s;
  }
  if (F.empty()) {
    s.steady_rule = "no statistics: empty load history";
    return s;
  }
  const std::string bad_rule = checkRule(rule);
  if (!bad_rule.empty()) {
    s.steady_rule = "no statistics: " + bad_rule;
    return s;
  }
  for (size_t i = 0; i < F.size(); ++i) {
    if (!std::isfinite(L[i]) || !std::isfinite(F[i])) {
      s.steady_rule = format("no statistics: non-finite sample at index %zu (L = %g m, F = %g N)",
                             i, L[i], F[i]);
      return s;
    }
    if (i > 0 && L[i] < L[i - 1]) {
      s.steady_rule = format("no statistics: pushed length decreases at index %zu (%g m -> %g m)",
                             i, L[i - 1], L[i]);
      return s;
    }
  }
  const size_t n = F.size();
  s.samples = static_cast<int>(n);

  // --- Peak. -----------------------------------------------------------------------------------
  const size_t peak = static_cast<size_t>(std::max_element(F.begin(), F.end()) - F.begin());
  s.peak_load = F[peak];
  s.peak_length = L[peak];

  const double span = L.back() - L.front();  // [m]
  if (n < 2 || !(span > 0.0)) {
    s.steady_rule = format("not steady: record too short (%zu samples over %g m of pushed ice)", n,
                           span);
    return s;
  }

  // --- Reference: mean over the last tail_fraction of the pushed length. ----------------------
  const double tail_start = L.back() - rule.tail_fraction * span;
  const size_t tail_first =
      static_cast<size_t>(std::lower_bound(L.begin(), L.end(), tail_start) - L.begin());
  const WindowStats tail = windowStats(F, tail_first, n);
  s.reference_mean = tail.mean;
  const double ref = tail.mean;

  // --- Steady window: F_s stays in the band from L_begin to the end. -------------------------
  std::string why_not;  // empty while the window is acceptable
  size_t begin = n;
  if (!(ref > 0.0)) {
    why_not = format("reference mean %.4g N is not positive", ref);
  } else {
    const std::vector<double> smoothed = movingMean(L, F, 0.5 * rule.smoothing_length);
    size_t after_last_outside = 0;
    for (size_t i = 0; i < n; ++i) {
      if (std::fabs(smoothed[i] - ref) > rule.band * ref) after_last_outside = i + 1;
    }
    begin = after_last_outside;
    if (begin >= n) {
      why_not = "the smoothed load is outside the band at the end of the record";
    } else {
      const double length = L.back() - L[begin];
      const WindowStats w = windowStats(F, begin, n);
      const double slope = leastSquaresSlope(L, F, begin, n);
      const double drift = std::isfinite(slope) ? std::fabs(slope) * length / w.mean : 0.0;
      if (length < rule.min_length) {
        why_not = format("band holds only from L = %.3g m (%.3g m < %.3g m minimum)", L[begin],
                         length, rule.min_length);
      } else if (w.count < rule.min_samples) {
        why_not = format("band holds for %d samples (< %d minimum)", w.count, rule.min_samples);
      } else if (drift > rule.max_drift) {
        why_not = format("load still trends by %.0f%% of its mean over %.3g-%.3g m (> %.0f%%)",
                         100.0 * drift, L[begin], L.back(), 100.0 * rule.max_drift);
      } else {
        s.steady_found = true;
        s.steady_begin = L[begin];
        s.steady_end = L.back();
        s.steady_mean = w.mean;
        s.steady_std = w.stddev;
        s.steady_samples = w.count;
        s.steady_rule = format(
            "steady: %.3g m moving mean stays within +-%.0f%% of the last-%.0f%% mean (%.5g N) from "
            "L = %.4g m to the end (%.3g m >= %.3g m, %d samples, trend %.1f%% <= %.0f%%)",
            rule.smoothing_length, 100.0 * rule.band, 100.0 * rule.tail_fraction, ref, L[begin],
            length, rule.min_length, w.count, 100.0 * drift, 100.0 * rule.max_drift);
      }
    }
  }
  if (!s.steady_found) {
    begin = tail_first;
    s.steady_begin = L[tail_first];
    s.steady_end = L.back();
    s.steady_mean = tail.mean;
    s.steady_std = tail.stddev;
    s.steady_samples = tail.count;
    s.steady_rule = format("not steady: tail mean of the last %.0f%% of L (%.4g-%.4g m); %s",
                           100.0 * rule.tail_fraction, s.steady_begin, s.steady_end,
                           why_not.c_str());
  }

  // --- Phase 1: from the end of the first failure's collapse (or, with none, from the first F
  // above the onset threshold) up to the window start. --------------------------------------------
  size_t onset = 0;
  if (first_failure_length == std::numeric_limits<double>::infinity()) {
    onset = begin;  // the sheet never failed: no pile, no phase 1
  } else if (std::isfinite(first_failure_length)) {
    while (onset < begin && L[onset] < first_failure_length) ++onset;
    size_t lowest = onset;
    for (size_t i = onset; i < begin && L[i] <= first_failure_length + rule.phase1_search_length; ++i) {
      if (F[i] < F[lowest]) lowest = i;
    }
    onset = lowest;
  } else if (ref > 0.0) {
    while (onset < begin && !(F[onset] > rule.onset_fraction * ref)) ++onset;
  }
  if (begin >= onset + 2) {
    s.phase1_slope = leastSquaresSlope(L, F, onset, begin);
    s.phase1_begin = L[onset];
    s.phase1_end = L[begin - 1];
    s.phase1_samples = static_cast<int>(begin - onset);
  }
  return s;
}

double firstFailureLength(const std::vector<double>& pushed_length, const std::vector<int>& broken_bonds) {
  const size_t n = std::min(pushed_length.size(), broken_bonds.size());
  for (size_t i = 0; i < n; ++i) {
    if (broken_bonds[i] > 0) return pushed_length[i];
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace thin_ice
