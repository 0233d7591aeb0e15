// Rubble pile profiles (thin_ice_sim/study/rubble_profiles.hpp) of a few hand-placed cells, values worked
// out by hand. Structure: toe at x = 10 m, 60 degrees, 1 m high, 2 m wide; ice h = 0.051 m,
// rho_i = 920, rho_w = 1000 kg/m^3, so a floating cell's centroid is at
// z_float = h/2 - 0.92 h = -0.02142 m and a cell is pile above z_float + h/2 = 0.00408 m.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "thin_ice_sim/study/rubble_profiles.hpp"

namespace {

thin_ice::Params setUp() {
  thin_ice::Params p;
  p.structure.toe_x = 10.0;
  p.structure.angle_deg = 60.0;
  p.structure.height = 1.0;
  p.structure.width = 2.0;
  p.ice.thickness = 0.051;
  p.ice.density = 920.0;
  p.water.density = 1000.0;
  return p;
}

thin_ice::CellSnapshot cellAt(double x, double y, double z) {
  thin_ice::CellSnapshot c{};
  c.x = x;
  c.y = y;
  c.z = z;
  return c;
}

constexpr double kFloat = -0.02142;  // [m]

TEST(RubbleProfiles, BinsSpanFromTheReachToTheTopOfTheFace) {
  // Side: x from 10 - 4 = 6 m to 10 + 1/tan(60 deg) = 10.577 m: ceil(45.77) = 46 bins of 0.1 m.
  // Top: the 2 m width in 20 bins.
  const thin_ice::RubbleProfiles r = thin_ice::computeRubbleProfiles({}, setUp());
  ASSERT_EQ(r.side_x.size(), 46u);
  ASSERT_EQ(r.top_y.size(), 20u);
  EXPECT_NEAR(r.side_x.front(), 6.05, 1e-12);
  EXPECT_NEAR(r.top_y.front(), -0.95, 1e-12);
  for (double v : r.side_height) EXPECT_EQ(v, 0.0);
  for (double v : r.top_extent) EXPECT_EQ(v, 0.0);
}

TEST(RubbleProfiles, LevelIceAndSmallHeaveAreNotPile) {
  // Floating level ice (top h - draft = 4.08 mm above water) and a cell heaved 20 mm (< h/2 = 25.5 mm) are
  // above the waterline but are not pile: neither profile sees them.
  const std::vector<thin_ice::CellSnapshot> cells = {cellAt(9.55, 0.05, kFloat), cellAt(9.25, -0.35, kFloat + 0.02)};
  const thin_ice::RubbleProfiles r = thin_ice::computeRubbleProfiles(cells, setUp());
  for (double v : r.side_height) EXPECT_EQ(v, 0.0);
  for (double v : r.top_extent) EXPECT_EQ(v, 0.0);
}

TEST(RubbleProfiles, PileCellsGiveTheHighestTopAndTheFarthestReach) {
  // B at (9.55, 0.05), lifted 0.1 m: top z + h/2 = 0.07858 + 0.0255 = 0.10408 m, in side bin 35
  // (centre 9.55 m) and top bin 10 (centre 0.05 m), 0.45 m from the toe.
  // E at (9.52, 0.07), z = 0.2 m: the same two bins, higher (0.2255 m) and farther (0.48 m).
  // D at (8.02, -0.95), z = 0.05 m: top 0.0755 m in side bin 20 (centre 8.05 m), top bin 0, 1.98 m out.
  // A cell pushed under water (z = -0.2 m) is not seen from above.
  const std::vector<thin_ice::CellSnapshot> cells = {cellAt(9.55, 0.05, kFloat + 0.1), cellAt(9.52, 0.07, 0.2),
                                                     cellAt(8.02, -0.95, 0.05), cellAt(9.05, 0.55, -0.2)};
  const thin_ice::RubbleProfiles r = thin_ice::computeRubbleProfiles(cells, setUp());
  EXPECT_NEAR(r.side_height[35], 0.2255, 1e-12);
  EXPECT_NEAR(r.side_height[20], 0.0755, 1e-12);
  EXPECT_NEAR(r.top_extent[10], 0.48, 1e-12);
  EXPECT_NEAR(r.top_extent[0], 1.98, 1e-12);
  int side_bins = 0, top_bins = 0;
  for (double v : r.side_height) side_bins += v > 0.0;
  for (double v : r.top_extent) top_bins += v > 0.0;
  EXPECT_EQ(side_bins, 2);
  EXPECT_EQ(top_bins, 2);
}

TEST(RubbleProfiles, CsvListsSideThenTopBins) {
  const thin_ice::RubbleProfiles r = thin_ice::computeRubbleProfiles({cellAt(8.02, -0.95, 0.05)}, setUp());
  const std::string csv = thin_ice::rubbleProfilesCsv(r);
  EXPECT_EQ(csv.rfind("profile,coordinate_m,value_m\nside,6.05,0\n", 0), 0u);
  EXPECT_NE(csv.find("side,8.05,0.0755\n"), std::string::npos);
  EXPECT_NE(csv.find("top,-0.95,1.98\n"), std::string::npos);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 46 + 20);
}

}  // namespace
