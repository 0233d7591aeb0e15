// The loads a simulation gives out (load_sample.hpp): summed loads become their mean, and alpha of
// Eq. (18) multiplies every component in the one place. Values worked out by hand.
#include <gtest/gtest.h>

#include "thin_ice_sim/load_sample.hpp"

namespace thin_ice {
namespace {

/// Sums of four steps on a structure of two panels.
LoadSample fourStepSums() {
  LoadSample sum;
  sum.horizontal_raw = 10.0;  // [N] summed over 4 steps: mean 2.5 N
  sum.vertical_raw = -6.0;
  sum.lateral_raw = 2.0;
  sum.pusher_force = 12.0;
  sum.torque = {4.0, -8.0, 1.0};
  sum.panel_horizontal = {6.0, 4.0};
  sum.panel_vertical = {-2.0, -4.0};
  sum.panel_lateral = {1.0, 1.0};
  sum.panel_torque = {{2.0, 0.0, -2.0}, {0.0, 4.0, 0.0}};
  return sum;
}

TEST(LoadSample, SummedLoadsBecomeTheirMeanAndFcalIsAlphaTimesTheMeanF) {
  LoadSample l = fourStepSums();
  averageSummedLoads(l, 4, 0.63);
  EXPECT_DOUBLE_EQ(l.horizontal_raw, 2.5);
  EXPECT_DOUBLE_EQ(l.vertical_raw, -1.5);
  EXPECT_DOUBLE_EQ(l.lateral_raw, 0.5);
  EXPECT_DOUBLE_EQ(l.pusher_force, 3.0);
  EXPECT_DOUBLE_EQ(l.torque.y, -2.0);
  EXPECT_DOUBLE_EQ(l.panel_horizontal[0], 1.5);
  EXPECT_DOUBLE_EQ(l.panel_horizontal[1], 1.0);
  EXPECT_DOUBLE_EQ(l.panel_vertical[1], -1.0);
  EXPECT_DOUBLE_EQ(l.panel_lateral[0], 0.25);
  EXPECT_DOUBLE_EQ(l.panel_torque[0].z, -0.5);
  EXPECT_DOUBLE_EQ(l.panel_torque[1].y, 1.0);
  EXPECT_DOUBLE_EQ(l.horizontal_calibrated, 0.63 * 2.5);  // 1.575 N
}

TEST(LoadSample, NoStepTakenGivesZeros) {
  LoadSample l = fourStepSums();
  averageSummedLoads(l, 0, 0.63);
  EXPECT_EQ(l.horizontal_raw, 0.0);
  EXPECT_EQ(l.panel_torque[1].y, 0.0);
  EXPECT_EQ(l.horizontal_calibrated, 0.0);
}

TEST(LoadSample, AlphaMultipliesEveryComponentOfTheTotalAndOfEachPanel) {
  LoadSample l = fourStepSums();
  averageSummedLoads(l, 4, 1.0);
  const CalibratedWrench total = calibratedTotal(l, 0.5);
  EXPECT_DOUBLE_EQ(total.fx, 1.25);   // x: horizontal
  EXPECT_DOUBLE_EQ(total.fy, 0.25);   // y: lateral
  EXPECT_DOUBLE_EQ(total.fz, -0.75);  // z: vertical
  EXPECT_DOUBLE_EQ(total.torque.x, 0.5);
  EXPECT_DOUBLE_EQ(total.torque.y, -1.0);
  EXPECT_DOUBLE_EQ(total.torque.z, 0.125);
  const CalibratedWrench second = calibratedPanel(l, 1, 0.5);
  EXPECT_DOUBLE_EQ(second.fx, 0.5);
  EXPECT_DOUBLE_EQ(second.fy, 0.125);
  EXPECT_DOUBLE_EQ(second.fz, -0.5);
  EXPECT_DOUBLE_EQ(second.torque.y, 0.5);
  EXPECT_DOUBLE_EQ(l.horizontal_calibrated, l.horizontal_raw);  // alpha = 1
}

}  // namespace
}  // namespace thin_ice
