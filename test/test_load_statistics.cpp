// Load-history statistics (load_statistics.hpp) on synthetic records with known answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "thin_ice_sim/study/load_statistics.hpp"

namespace thin_ice {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSlopeTolerance = 0.05;      // [-] the phase-1 fit sees the ripple
constexpr double kMeanTolerance = 0.02;       // [-] window mean vs. 3000 N (ripple, knee)
constexpr double kStartTolerance = 0.5;       // [m] smoothing moves the detected start
constexpr double kSampleSpacing = 0.005;      // [m] pushed length between samples (0.1 s at 5 cm/s)

struct Record {
  std::vector<double> length;  // [m]
  std::vector<double> load;    // [N]
};

/// Phase 1: F = 1500 N/m L up to L = 2 m, then phase 2: F = 3000 N, both with a +-10 % sine
/// ripple of 0.3 m wavelength; 0 <= L <= length_end.
Record rampThenPlateau(double length_end) {
  Record r;
  const int count = static_cast<int>(std::lround(length_end / kSampleSpacing)) + 1;
  for (int i = 0; i < count; ++i) {
    const double l = i * kSampleSpacing;
    const double base = l < 2.0 ? 1500.0 * l : 3000.0;
    r.length.push_back(l);
    r.load.push_back(base * (1.0 + 0.1 * std::sin(2.0 * kPi * l / 0.3)));
  }
  return r;
}

TEST(LoadStatistics, RampThenPlateau) {
  const Record r = rampThenPlateau(6.0);
  const LoadStatistics s = analyseLoadHistory(r.length, r.load);

  double peak = -1.0, peak_at = -1.0;  // by hand
  for (size_t i = 0; i < r.load.size(); ++i) {
    if (r.load[i] > peak) {
      peak = r.load[i];
      peak_at = r.length[i];
    }
  }
  EXPECT_EQ(s.samples, static_cast<int>(r.load.size()));
  EXPECT_DOUBLE_EQ(s.peak_load, peak);
  EXPECT_DOUBLE_EQ(s.peak_length, peak_at);

  ASSERT_TRUE(s.steady_found) << s.steady_rule;
  EXPECT_NEAR(s.steady_begin, 2.0, kStartTolerance) << s.steady_rule;
  EXPECT_DOUBLE_EQ(s.steady_end, 6.0);
  EXPECT_NEAR(s.steady_mean, 3000.0, kMeanTolerance * 3000.0);
  // A +-10 % sine has a standard deviation of 10 % / sqrt(2) of the mean.
  EXPECT_NEAR(s.steady_std, 300.0 / std::sqrt(2.0), 0.25 * 300.0 / std::sqrt(2.0));
  EXPECT_GT(s.steady_samples, 600);  // at least 3 m of samples
  EXPECT_NEAR(s.reference_mean, 3000.0, kMeanTolerance * 3000.0);
  EXPECT_EQ(s.steady_rule.rfind("steady:", 0), 0u) << s.steady_rule;

  EXPECT_NEAR(s.phase1_slope, 1500.0, kSlopeTolerance * 1500.0)
      << "fit over " << s.phase1_begin << "-" << s.phase1_end << " m";
  EXPECT_LT(s.phase1_begin, 0.3);  // first F above 5 % of 3000 N
  EXPECT_NEAR(s.phase1_end, s.steady_begin, 2.0 * kSampleSpacing);
  EXPECT_GT(s.phase1_samples, 100);
}

/// The ramp of rampThenPlateau with the intact sheet's first failure in front of it: F climbs
/// linearly to 10 kN at L = 0.08 m, where the first bond breaks, and collapses onto the ramp by
/// L = 0.09 m, as a row of bonds gives way over a few output intervals.
TEST(LoadStatistics, PhaseOneStartsWhereTheFirstFailureEnds) {
  Record r = rampThenPlateau(6.0);
  constexpr double kFailure = 0.08, kCollapsed = 0.09;  // [m]
  std::vector<int> broken(r.length.size(), 0);
  for (size_t i = 0; i < r.length.size(); ++i) {
    const double l = r.length[i];
    if (l < kFailure) r.load[i] = 10000.0 * l / kFailure;
    if (l >= kFailure && l < kCollapsed - 1e-9) {
      r.load[i] = 10000.0 + (r.load[i] - 10000.0) * (l - kFailure) / (kCollapsed - kFailure);
    }
    broken[i] = l >= kFailure ? 5 : 0;
  }
  const double failure = firstFailureLength(r.length, broken);
  EXPECT_DOUBLE_EQ(failure, r.length[16]);  // 16 samples of 5 mm below 0.08 m
  const double never = firstFailureLength(r.length, std::vector<int>(r.length.size(), 0));
  EXPECT_TRUE(std::isinf(never) && never > 0.0);
  // A sheet that never broke has no phase 1, whatever its load did.
  const LoadStatistics unbroken = analyseLoadHistory(r.length, r.load, SteadyStateRule(), never);
  EXPECT_TRUE(std::isnan(unbroken.phase1_slope));
  EXPECT_EQ(unbroken.phase1_samples, 0);

  // The fit starts at the bottom of the collapse, 0.09 m (the ramp's 135 N; the ripple is rising
  // there, so no later sample within 0.1 m is lower), and sees the ramp alone.
  const LoadStatistics s = analyseLoadHistory(r.length, r.load, SteadyStateRule(), failure);
  EXPECT_NEAR(s.phase1_begin, kCollapsed, 1e-9);
  EXPECT_NEAR(s.phase1_slope, 1500.0, kSlopeTolerance * 1500.0);
  // Starting on the spike, the same fit is pulled far below the ramp; nothing else changes.
  const LoadStatistics from_contact = analyseLoadHistory(r.length, r.load);
  EXPECT_LT(from_contact.phase1_slope, 0.8 * 1500.0);
  EXPECT_LT(from_contact.phase1_begin, kFailure);
  EXPECT_EQ(from_contact.steady_begin, s.steady_begin);
  EXPECT_EQ(from_contact.steady_mean, s.steady_mean);
  EXPECT_EQ(from_contact.peak_load, s.peak_load);
}

TEST(LoadStatistics, KeepsRisingIsNotSteady) {
  Record r;
  for (int i = 0; i <= 1200; ++i) {
    r.length.push_back(i * kSampleSpacing);
    r.load.push_back(1500.0 * r.length.back());
  }
  const LoadStatistics s = analyseLoadHistory(r.length, r.load);
  EXPECT_FALSE(s.steady_found);
  EXPECT_EQ(s.steady_rule.rfind("not steady: tail mean", 0), 0u) << s.steady_rule;
  // Reported window: the last 25 % of the record, 4.5-6 m, mean 1500 N/m x 5.25 m.
  EXPECT_NEAR(s.steady_begin, 4.5, 1e-9);
  EXPECT_DOUBLE_EQ(s.steady_end, 6.0);
  EXPECT_NEAR(s.steady_mean, 1500.0 * 5.25, 1e-6);
  EXPECT_DOUBLE_EQ(s.peak_load, 9000.0);
  EXPECT_NEAR(s.phase1_slope, 1500.0, 1e-6);  // an exact line
}

TEST(LoadStatistics, ShortPlateauAfterLongRiseIsNotSteady) {
  // Like strong ice in Fig. 12: still rising until 0.5 m before the end.
  Record r;
  for (int i = 0; i <= 1200; ++i) {
    const double l = i * kSampleSpacing;
    r.length.push_back(l);
    r.load.push_back(1500.0 * std::min(l, 5.5));
  }
  const LoadStatistics s = analyseLoadHistory(r.length, r.load);
  EXPECT_FALSE(s.steady_found) << s.steady_rule;
}

TEST(LoadStatistics, FlatRecordIsSteadyFromTheStart) {
  const std::vector<double> length = {0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0};
  const std::vector<double> load(length.size(), 5000.0);
  const LoadStatistics s = analyseLoadHistory(length, load);
  ASSERT_TRUE(s.steady_found) << s.steady_rule;
  EXPECT_DOUBLE_EQ(s.steady_begin, 0.0);
  EXPECT_DOUBLE_EQ(s.steady_mean, 5000.0);
  EXPECT_DOUBLE_EQ(s.steady_std, 0.0);
  EXPECT_EQ(s.steady_samples, 11);
  EXPECT_TRUE(std::isnan(s.phase1_slope));  // nothing before the window
  EXPECT_EQ(s.phase1_samples, 0);
}

TEST(LoadStatistics, EmptyInput) {
  const LoadStatistics s = analyseLoadHistory({}, {});
  EXPECT_FALSE(s.steady_found);
  EXPECT_EQ(s.samples, 0);
  EXPECT_TRUE(std::isnan(s.peak_load));
  EXPECT_TRUE(std::isnan(s.steady_mean));
  EXPECT_NE(s.steady_rule.find("empty"), std::string::npos) << s.steady_rule;
}

TEST(LoadStatistics, NonFiniteInput) {
  Record r = rampThenPlateau(6.0);
  r.load[700] = std::numeric_limits<double>::quiet_NaN();
  LoadStatistics s = analyseLoadHistory(r.length, r.load);
  EXPECT_FALSE(s.steady_found);
  EXPECT_EQ(s.samples, 0);
  EXPECT_TRUE(std::isnan(s.peak_load));
  EXPECT_NE(s.steady_rule.find("non-finite sample at index 700"), std::string::npos)
      << s.steady_rule;

  r = rampThenPlateau(6.0);
  r.length[3] = std::numeric_limits<double>::infinity();
  s = analyseLoadHistory(r.length, r.load);
  EXPECT_FALSE(s.steady_found);
  EXPECT_NE(s.steady_rule.find("non-finite"), std::string::npos) << s.steady_rule;
}

TEST(LoadStatistics, MalformedInput) {
  LoadStatistics s = analyseLoadHistory({0.0, 1.0}, {1.0});
  EXPECT_FALSE(s.steady_found);
  EXPECT_NE(s.steady_rule.find("2 pushed lengths but 1 loads"), std::string::npos);

  s = analyseLoadHistory({0.0, 2.0, 1.0}, {1.0, 2.0, 3.0});
  EXPECT_FALSE(s.steady_found);
  EXPECT_NE(s.steady_rule.find("decreases at index 2"), std::string::npos) << s.steady_rule;

  s = analyseLoadHistory({0.0}, {42.0});  // one sample: a peak, nothing else
  EXPECT_FALSE(s.steady_found);
  EXPECT_DOUBLE_EQ(s.peak_load, 42.0);
  EXPECT_NE(s.steady_rule.find("too short"), std::string::npos) << s.steady_rule;

  SteadyStateRule rule;
  rule.tail_fraction = 0.0;
  s = analyseLoadHistory({0.0, 1.0}, {1.0, 2.0}, rule);
  EXPECT_FALSE(s.steady_found);
  EXPECT_NE(s.steady_rule.find("tail_fraction"), std::string::npos) << s.steady_rule;
}

TEST(LoadStatistics, LeastSquaresSlopeByHand) {
  const std::vector<double> x = {0.0, 1.0, 2.0, 3.0};
  const std::vector<double> y = {1.0, 3.0, 4.0, 8.0};
  // x-bar = 1.5, y-bar = 4; Sxy = 1.5*3 + 0.5*1 + 0.5*0 + 1.5*4 = 11; Sxx = 5.
  EXPECT_DOUBLE_EQ(leastSquaresSlope(x, y, 0, 4), 11.0 / 5.0);
  EXPECT_DOUBLE_EQ(leastSquaresSlope(x, y, 1, 3), 1.0);
  EXPECT_TRUE(std::isnan(leastSquaresSlope(x, y, 2, 3)));   // one point
  EXPECT_TRUE(std::isnan(leastSquaresSlope({1.0, 1.0}, {0.0, 5.0}, 0, 2)));  // no spread in x
}

/// The rule has no load scale of its own (bands, drift and onset are fractions of a mean), so
/// scaling F by a factor scales every load statistic by it and moves no window: a change of the
/// structural factor alpha of Eq. (18), which multiplies the output only, changes no verdict.
TEST(LoadStatistics, ScalingTheLoadScalesTheStatisticsAndKeepsTheWindows) {
  Record saw_tooth;  // teeth of 4 kN every 0.19 m over a trough rising 1.2 kN per metre, then flat
  for (int i = 0; i <= 1000; ++i) {
    const double l = i * kSampleSpacing;
    const double trough = 500.0 + 1200.0 * std::min(l, 2.5);
    const double phase = std::fmod(l, 0.19) / 0.19;
    saw_tooth.length.push_back(l);
    saw_tooth.load.push_back(trough + 4000.0 * phase * phase);
  }
  for (const Record& r : {rampThenPlateau(6.0), saw_tooth}) {
    const LoadStatistics base = analyseLoadHistory(r.length, r.load);
    for (double factor : {1.0 / 0.63, 0.63, 1.7}) {
      std::vector<double> scaled = r.load;
      for (double& f : scaled) f *= factor;
      const LoadStatistics s = analyseLoadHistory(r.length, scaled);
      SCOPED_TRACE(factor);
      EXPECT_EQ(s.steady_found, base.steady_found);
      EXPECT_EQ(s.steady_begin, base.steady_begin);
      EXPECT_EQ(s.steady_samples, base.steady_samples);
      EXPECT_EQ(s.phase1_begin, base.phase1_begin);
      EXPECT_EQ(s.phase1_samples, base.phase1_samples);
      EXPECT_EQ(s.peak_length, base.peak_length);
      EXPECT_NEAR(s.peak_load, factor * base.peak_load, 1e-12 * factor * base.peak_load);
      EXPECT_NEAR(s.steady_mean, factor * base.steady_mean, 1e-12 * factor * base.steady_mean);
      EXPECT_NEAR(s.steady_std, factor * base.steady_std, 1e-9 * factor * base.steady_std);
      EXPECT_NEAR(s.phase1_slope, factor * base.phase1_slope, 1e-9 * std::fabs(factor * base.phase1_slope));
    }
  }
}

}  // namespace
}  // namespace thin_ice
