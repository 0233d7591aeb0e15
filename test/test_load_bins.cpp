// The kept load record (load_bins.hpp, run_record.hpp): which bin a row falls into, the
// time-weighted means and the least and greatest row of a bin, worked out by hand; a record cut at
// any row, written, read back and continued, against the record made in one go; the statistics'
// peak from the greatest row; and damaged files refused with what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "thin_ice_sim/study/load_bins.hpp"
#include "thin_ice_sim/study/run_directory.hpp"
#include "thin_ice_sim/study/run_record.hpp"

namespace thin_ice {
namespace {

LoadSample row(double time, double length, double load, int broken = 0) {
  LoadSample s;
  s.time = time;
  s.pushed_length = length;
  s.horizontal_calibrated = load;
  s.vertical_raw = -load / 2.0;
  s.pusher_force = 2.0 * load;
  s.intact_bonds = 100 - broken;
  s.broken_bonds = broken;
  return s;
}

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(LoadBins, RowsFallIntoHalfOpenBinsOfThirtyFiveMillimetres) {
  EXPECT_EQ(loadBinIndex(0.0), 0);     // before the pusher moved
  EXPECT_EQ(loadBinIndex(0.001), 0);
  EXPECT_EQ(loadBinIndex(0.035), 0);   // a row ending on the boundary closes the bin below
  EXPECT_EQ(loadBinIndex(0.0351), 1);
  EXPECT_EQ(loadBinIndex(0.07), 1);
  EXPECT_EQ(loadBinIndex(3 * 0.035), 2);  // 0.105 is not a binary fraction: still bin 2
  EXPECT_EQ(loadBinIndex(0.1051), 3);
  // The pusher's summed position drifts by about 1e-9 m over a run: a row meant to end on a
  // boundary stays in the bin below; half a millimetre on (the next 0.01 s row) is the next bin.
  EXPECT_EQ(loadBinIndex(7.035 + 2e-9), 200);
  EXPECT_EQ(loadBinIndex(7.035 - 2e-9), 200);
  EXPECT_EQ(loadBinIndex(7.0355), 201);
}

TEST(LoadBins, MeansAreWeightedByEachRowsIntervalAndKeepTheLeastAndGreatestRow) {
  // Rows every 0.01 s at 1 m/s, the last one short (0.005 s, a target between rows). Bin 0:
  // L = 0.01, 0.02, 0.03 with F = 10, 40, 10 -> mean 20, least 10, greatest 40. Bin 1: L = 0.04
  // (0.01 s, F = 30) and 0.045 (0.005 s, F = 60): mean (30 * 0.01 + 60 * 0.005) / 0.015 = 40.
  LoadBinner binner;
  for (const LoadSample& s : {row(0.01, 0.01, 10), row(0.02, 0.02, 40), row(0.03, 0.03, 10, 3),
                              row(0.04, 0.04, 30, 5), row(0.045, 0.045, 60, 6)}) {
    binner.add(s);
  }
  const std::vector<LoadBin>& bins = binner.bins();
  ASSERT_EQ(bins.size(), 2u);
  EXPECT_EQ(bins[0].index, 0);
  EXPECT_EQ(bins[0].samples, 3);
  EXPECT_NEAR(bins[0].duration, 0.03, 1e-15);
  EXPECT_NEAR(bins[0].calibrated_mean, 20.0, 1e-12);
  EXPECT_EQ(bins[0].calibrated_least, 10.0);
  EXPECT_EQ(bins[0].calibrated_greatest, 40.0);
  EXPECT_NEAR(bins[0].vertical_mean, -10.0, 1e-12);
  EXPECT_NEAR(bins[0].pusher_mean, 40.0, 1e-12);
  EXPECT_EQ(bins[0].broken_bonds, 3);  // at the bin's end
  EXPECT_DOUBLE_EQ(bins[0].time, 0.03);
  EXPECT_EQ(bins[1].index, 1);
  EXPECT_EQ(bins[1].samples, 2);
  EXPECT_NEAR(bins[1].duration, 0.015, 1e-15);
  EXPECT_NEAR(bins[1].calibrated_mean, 40.0, 1e-12);
  EXPECT_EQ(bins[1].calibrated_greatest, 60.0);
  EXPECT_EQ(bins[1].broken_bonds, 6);
  EXPECT_DOUBLE_EQ(bins[1].pushed_length, 0.045);
  EXPECT_EQ(binner.samples(), 5);
}

TEST(LoadBins, ARecordCutAtAnyRowWrittenReadBackAndContinuedIsTheRecordMadeInOneGo) {
  std::vector<LoadSample> rows;
  for (int k = 1; k <= 40; ++k) {  // 0.5 mm per row, F rising and wobbling
    const double t = 0.01 * k;
    rows.push_back(row(t, 0.05 * t, 100.0 + 7.0 * k + ((k * 37) % 11), k / 10));
    if (k == 15) rows.push_back(row(0.154, 0.05 * 0.154, 400.0, 1));  // a short row: a target between rows
  }
  for (std::size_t k = 1; k < rows.size(); ++k) {  // the short row's successor covers 0.154-0.16 s
    ASSERT_GT(rows[k].time, rows[k - 1].time);
  }
  LoadBinner whole;
  for (const LoadSample& s : rows) whole.add(s);
  for (std::size_t cut = 1; cut < rows.size(); ++cut) {
    LoadBinner first;
    for (std::size_t k = 0; k < cut; ++k) first.add(rows[k]);
    const std::string path = writeTemp("thin_ice_test_bins.csv", run_record::loadBinsText(first.bins()));
    LoadBinner resumed(readLoadBins(path));
    for (std::size_t k = cut; k < rows.size(); ++k) resumed.add(rows[k]);
    ASSERT_EQ(resumed.bins().size(), whole.bins().size()) << "cut after row " << cut;
    for (std::size_t b = 0; b < whole.bins().size(); ++b) {
      const LoadBin &x = resumed.bins()[b], &y = whole.bins()[b];
      EXPECT_EQ(x.index, y.index);
      EXPECT_EQ(x.samples, y.samples);
      EXPECT_NEAR(x.calibrated_mean, y.calibrated_mean, 1e-8 * y.calibrated_mean) << "cut " << cut << ", bin " << b;
      EXPECT_EQ(x.calibrated_greatest, y.calibrated_greatest);
      EXPECT_EQ(x.calibrated_least, y.calibrated_least);
      EXPECT_NEAR(x.vertical_mean, y.vertical_mean, 1e-8 * std::fabs(y.vertical_mean));
      EXPECT_NEAR(x.pusher_mean, y.pusher_mean, 1e-8 * y.pusher_mean);
      EXPECT_NEAR(x.duration, y.duration, 1e-12);
      EXPECT_DOUBLE_EQ(x.time, y.time);
      EXPECT_DOUBLE_EQ(x.pushed_length, y.pushed_length);
      EXPECT_EQ(x.broken_bonds, y.broken_bonds);
      EXPECT_EQ(x.intact_bonds, y.intact_bonds);
    }
    std::remove(path.c_str());
  }
}

TEST(LoadBins, StatisticsTakeTheMeansAsSamplesAndThePeakFromTheGreatestRow) {
  LoadBinner binner;
  for (int k = 1; k <= 2000; ++k) {  // 1 m at 0.5 mm per row; one spike of one row at L = 0.5 m
    binner.add(row(0.01 * k, 0.0005 * k, k == 1000 ? 900.0 : 100.0));
  }
  const LoadStatistics s = analyseLoadBins(binner.bins(), SteadyStateRule(), LoadStatistics::kNaN);
  EXPECT_EQ(s.samples, static_cast<int>(binner.bins().size()));
  EXPECT_EQ(s.samples, 29);  // ceil(1 / 0.035)
  EXPECT_EQ(s.peak_load, 900.0);
  // The spike's bin is (14 b, 15 b] = (0.49, 0.525] m, stamped at its last row's length.
  EXPECT_NEAR(s.peak_length, 0.525, 1e-9);
  // The spike adds 800 N x 0.01 s to its bin of 70 rows: mean 100 + 800 / 70 there, 100 elsewhere.
  EXPECT_NEAR(binner.bins()[14].calibrated_mean, 100.0 + 800.0 / 70.0, 1e-9);
}

/// readLoadBins refuses the file written from `rows`, with a message holding `needle`.
void expectRefused(const std::string& name, const std::string& rows, const std::string& needle) {
  const std::string path = writeTemp(name, run_record::headerLine(run_record::kLoadBinColumns) + rows);
  try {
    readLoadBins(path);
    ADD_FAILURE() << name << " was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

TEST(LoadBins, DamagedRecordsAreRefusedSayingWhatIsWrong) {
  expectRefused("thin_ice_test_bins_order.csv",
                "1,0.7,0.07,0.7,70,10,9,11,0,0,5,0\n0,1.4,0.035,0.7,70,10,9,11,0,0,5,0\n", "does not follow bin 1");
  expectRefused("thin_ice_test_bins_empty.csv", "0,0.7,0.035,0.7,0,10,9,11,0,0,5,0\n", "a bin of 0 rows");
  expectRefused("thin_ice_test_bins_frac.csv", "0.5,0.7,0.035,0.7,70,10,9,11,0,0,5,0\n",
                "bin 0.5; allowed: a whole number");
}

}  // namespace
}  // namespace thin_ice
