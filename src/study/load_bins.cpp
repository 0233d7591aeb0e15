#include "thin_ice_sim/study/load_bins.hpp"

#include <algorithm>
#include <cmath>

namespace thin_ice {

long loadBinIndex(double pushed_length) {
  // (k b, (k + 1) b]: a row ending on a boundary closes the bin below it. The pusher's position
  // is summed step by step, so a row meant to end on a boundary ends up to about 1e-9 m off it
  // after 30 m (2.7e-10 m at 7 m, weak ice's 4e-5 s steps), and loads.csv rounds it to nine
  // digits: 1e-6 of a bin (35 nm) takes both to the bin below, and is 1/14000 of a 0.5 mm row.
  const double bins = pushed_length / kLoadBinLength;
  return std::max(0L, static_cast<long>(std::ceil(bins - 1e-6)) - 1);
}

void LoadBinner::add(const LoadSample& row) {
  const double start = bins_.empty() ? 0.0 : bins_.back().time;
  const double duration = std::max(0.0, row.time - start);  // [s] the row's output interval
  const long index = loadBinIndex(row.pushed_length);
  if (bins_.empty() || index != bins_.back().index) {
    LoadBin bin;
    bin.index = index;
    bin.calibrated_least = bin.calibrated_greatest = row.horizontal_calibrated;
    bins_.push_back(bin);
  }
  LoadBin& bin = bins_.back();
  const double before = bin.duration, after = bin.duration + duration;
  // Time-weighted running means; a row of no duration (none is written) would count as a mean of one.
  auto blend = [&](double mean, double value) {
    return after > 0.0 ? (mean * before + value * duration) / after : value;
  };
  bin.calibrated_mean = blend(bin.calibrated_mean, row.horizontal_calibrated);
  bin.vertical_mean = blend(bin.vertical_mean, row.vertical_raw);
  bin.pusher_mean = blend(bin.pusher_mean, row.pusher_force);
  bin.calibrated_least = std::min(bin.calibrated_least, row.horizontal_calibrated);
  bin.calibrated_greatest = std::max(bin.calibrated_greatest, row.horizontal_calibrated);
  bin.duration = after;
  bin.samples += 1;
  bin.time = row.time;
  bin.pushed_length = row.pushed_length;
  bin.intact_bonds = row.intact_bonds;
  bin.broken_bonds = row.broken_bonds;
}

long LoadBinner::samples() const {
  long n = 0;
  for (const LoadBin& bin : bins_) n += bin.samples;
  return n;
}

LoadStatistics analyseLoadBins(const std::vector<LoadBin>& bins, const SteadyStateRule& rule,
                               double first_failure_length) {
  std::vector<double> length, load;
  for (const LoadBin& bin : bins) {
    length.push_back(bin.pushed_length);
    load.push_back(bin.calibrated_mean);
  }
  LoadStatistics s = analyseLoadHistory(length, load, rule, first_failure_length);
  if (s.samples == 0) return s;  // rejected: steady_rule says why
  const auto greatest = std::max_element(bins.begin(), bins.end(), [](const LoadBin& a, const LoadBin& b) {
    return a.calibrated_greatest < b.calibrated_greatest;
  });
  s.peak_load = greatest->calibrated_greatest;
  s.peak_length = greatest->pushed_length;
  return s;
}

}  // namespace thin_ice
