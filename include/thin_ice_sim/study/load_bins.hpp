// The kept load record of a run: loads.csv's rows gathered into bins of pushed length. A bin
// holds the time-weighted mean of each load over its rows and the least and greatest calibrated
// horizontal load of a row in it, so the record is about 2.5 kB per metre of pushed ice (loads.csv:
// about 190 kB per metre at the 0.01 s rows of the validation runs). It is what a run's load
// statistics are worked out on (analyseLoadBins), and with the checkpoint it is all a resumption
// needs: a run resumed where loads.csv is absent (a fresh clone keeps only load_bins.csv, the
// checkpoint and the summary) ends with the statistics of the run made in one go.
//
// Bin k holds the rows whose pushed length at the row's end lies in (k b, (k + 1) b], b =
// kLoadBinLength; a row at L = 0 (before the pusher moved) belongs to bin 0. A bin is stamped with
// the time and length of its last row, as a row is with the end of its output interval.
#pragma once

#include <vector>

#include "thin_ice_sim/load_sample.hpp"
#include "thin_ice_sim/study/load_statistics.hpp"

namespace thin_ice {

/// [m] Width of a bin: the paper's output step (Section 5.1.1: an output every 0.7 s at the
/// 5 cm/s pushing speed, 35 mm of pushed ice), so that the statistics see the load at the
/// resolution the paper's Table 6 was read from; the greatest row of each bin keeps the peak exact.
inline constexpr double kLoadBinLength = 0.035;

struct LoadBin {
  long index = 0;                    ///< k: the bin covers (k b, (k + 1) b] of pushed length
  double time = 0.0;                 ///< [s] at the end of its last row
  double pushed_length = 0.0;        ///< [m] at the end of its last row
  double duration = 0.0;             ///< [s] of simulated time its rows cover
  long samples = 0;                  ///< rows of loads.csv in it
  double calibrated_mean = 0.0;      ///< [N] F_cal of Eq. (18), time-weighted mean of its rows
  double calibrated_least = 0.0;     ///< [N] least F_cal of a row in it
  double calibrated_greatest = 0.0;  ///< [N] greatest F_cal of a row in it
  double vertical_mean = 0.0;        ///< [N] raw vertical load, +z, time-weighted mean
  double pusher_mean = 0.0;          ///< [N] pusher force, +x, time-weighted mean
  int intact_bonds = 0;              ///< at the end of its last row
  int broken_bonds = 0;              ///< at the end of its last row
};

/// The bin of a row whose interval ends at pushed length `pushed_length` [m] (>= 0).
long loadBinIndex(double pushed_length);

/// Gathers rows into bins as a run writes them; a resumed run goes on from the bins it had, its
/// first rows joining the last bin where they fall into it.
class LoadBinner {
 public:
  LoadBinner() = default;
  /// Goes on from `bins` (in order, as readLoadBins gives them).
  explicit LoadBinner(std::vector<LoadBin> bins) : bins_(std::move(bins)) {}

  /// One row: the loads averaged over an output interval that ends at row.time, and began where
  /// the last row ended (t = 0 for the first).
  void add(const LoadSample& row);

  const std::vector<LoadBin>& bins() const { return bins_; }
  /// Rows added so far, those of the bins it went on from included.
  long samples() const;

 private:
  std::vector<LoadBin> bins_;
};

/// The load statistics of a run (analyseLoadHistory) worked out on its bins: each bin is a sample
/// at its end length with its mean load, and the peak is the greatest row of the record, found at
/// the end length of its bin.
LoadStatistics analyseLoadBins(const std::vector<LoadBin>& bins, const SteadyStateRule& rule,
                               double first_failure_length);

}  // namespace thin_ice
