// The edge-load check (thin_ice_sim/study/edge_check.hpp) against closed forms worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "thin_ice_sim/study/edge_check.hpp"

namespace {

using thin_ice::BondConstants;
using thin_ice::BondRest;

// A bond across a 0.2 m edge between cells 0.2 m apart, with only its vertical spring set.
BondRest verticalBond(double k_vertical) {
  BondRest b{};
  b.anchor_i = {0.1, 0.0};
  b.anchor_j = {-0.1, 0.0};
  b.normal = {1.0, 0.0};
  b.edge_length = 0.2;
  b.distance = 0.2;
  b.k_normal = 1e7;
  b.k_shear = 1e7;
  b.k_vertical = k_vertical;
  return b;
}

BondConstants constants(double exponent_v, double sigma_f) {
  BondConstants c{};
  c.thickness = 0.05;
  c.exponent_h = exponent_v;
  c.exponent_v = exponent_v;
  c.flexural_strength = sigma_f;
  c.compressive_strength = 1e9;
  c.compression_coupling = 0.4;
  return c;
}

TEST(EdgeCheck, MediumBondTearsThroughAtItsShearPeak) {
  // n = 1: F_v = (1 - dz/h) k_v dz peaks at dz = h/2 at k_v h / 4. k_v = 1e5 N/m, h = 0.05 m:
  // 1250 N. The bending stress there, 3 F_v d / (L_e h^2) = 3 * 1250 * 0.2 / (0.2 * 0.0025) =
  // 1.5e6 Pa, stays below sigma_f = 2e6 Pa, so the bond only goes at |dz| = h.
  const auto cap = thin_ice::bondVerticalCapacity(verticalBond(1e5), constants(1.0, 2e6));
  EXPECT_NEAR(cap.force, 1250.0, 1250.0 * 1e-6);
  EXPECT_FALSE(cap.by_stress);
  EXPECT_DOUBLE_EQ(cap.offset, 0.05);
}

TEST(EdgeCheck, StrongBondBreaksWhenTheBendingStressReachesSigmaF) {
  // n = 1/2, k_v = 1e6 N/m: sigma_v = 3 k_v dz sqrt(1 - dz/h) d / (L_e h^2) reaches
  // sigma_f = 1e6 Pa at dz/h = z with 3 z sqrt(1 - z) * 1e6 * 0.05 * 0.2 / (0.2 * 0.0025) = 1e6,
  // i.e. z sqrt(1 - z) = 1/60: z = 0.0168085 (solved numerically). The force then is sigma_f L_e h^2 / (3 d) =
  // 1e6 * 0.2 * 0.0025 / 0.6 = 833.33 N.
  const auto cap = thin_ice::bondVerticalCapacity(verticalBond(1e6), constants(0.5, 1e6));
  EXPECT_TRUE(cap.by_stress);
  EXPECT_NEAR(cap.force, 833.3333, 1e-3);
  EXPECT_NEAR(cap.offset / 0.05, 0.0168085, 1e-6);
}

TEST(EdgeCheck, TheLargestBendingStressOfAHeightStepIsAtTheTopOfTheSmoothing) {
  // sigma_v = 3 K_v k_v dz d / (L_e h^2) with K_v = (1 - u)^n, dz = u h: for k_v = 1e6 N/m,
  // h = 0.05 m and L_e = d = 0.2 m, sigma_v = 3e6 0.05 / 0.0025 u (1 - u)^n = 6e7 u (1 - u)^n Pa.
  // n = 1/2: the top is at u = 2/3, 6e7 (2/3) sqrt(1/3) = 2.3094011e7 Pa.
  // n = 2: at u = 1/3, 6e7 (1/3) (4/9) = 8.8888889e6 Pa.
  const auto root = thin_ice::largestVerticalStress(verticalBond(1e6), constants(0.5, 1e9));
  EXPECT_NEAR(root.stress, 6e7 * 2.0 / (3.0 * std::sqrt(3.0)), 1.0);
  EXPECT_NEAR(root.offset, 0.05 * 2.0 / 3.0, 1e-8);
  const auto square = thin_ice::largestVerticalStress(verticalBond(1e6), constants(2.0, 1e9));
  EXPECT_NEAR(square.stress, 6e7 * 4.0 / 27.0, 1.0);
  EXPECT_NEAR(square.offset, 0.05 / 3.0, 1e-8);
  // The stress at a step is the law's: u = 0.2 with n = 2 gives 6e7 0.2 0.64 = 7.68e6 Pa.
  EXPECT_NEAR(thin_ice::bondUnderOffset(verticalBond(1e6), constants(2.0, 1e9), 0.01).sigma_v, 7.68e6, 1e-3);
}

TEST(EdgeCheck, TheBondNearestALengthIsTheFirstOfTheNearest) {
  thin_ice::Model model;
  EXPECT_EQ(thin_ice::bondNearestLength(model, 0.2), -1);
  for (double d : {0.3, 0.17, 0.22, 0.22}) {
    model.bond_rest.push_back(verticalBond(1e6));
    model.bond_rest.back().distance = d;
  }
  EXPECT_EQ(thin_ice::bondNearestLength(model, 0.2), 2);  // 0.22 is 0.02 away, 0.17 is 0.03
  EXPECT_EQ(thin_ice::bondNearestLength(model, 0.1), 1);
  EXPECT_EQ(thin_ice::bondNearestLength(model, 1.0), 0);
}

TEST(EdgeCheck, FloatingPlateOfMediumIce) {
  // M-2 ice: E = 328 MPa, h = 0.051 m, nu = 0.3, sigma_f = 108 kPa, rho_w g = 9810 N/m^3.
  // l = (328e6 * 0.051^3 / (12 * 0.91 * 9810))^(1/4) = 0.7983 m;
  // P_crit = sigma_f h^2 / (6 e^(-pi/4) l) = 108e3 * 0.051^2 / (6 * 0.455938 * 0.798313) =
  // 128.627 N/m; the rounded 0.665 * 108e3 * (9810 * 0.051^5 / 328e6)^(1/4) = 128.72 rounds the
  // same (0.6645 for nu = 0.3).
  thin_ice::IceParams ice;
  ice.thickness = 0.051;
  ice.youngs_modulus = 328e6;
  ice.poisson_ratio = 0.3;
  ice.flexural_strength = 108e3;
  thin_ice::WaterParams water;
  water.density = 1000.0;
  water.gravity = 9.81;
  const auto plate = thin_ice::floatingPlateEdge(ice, water);
  EXPECT_NEAR(plate.characteristic_length, 0.79831, 1e-4);
  EXPECT_NEAR(plate.critical_line_load, 128.627, 1e-2);
}

// Cuts behind the front edge of a 1 m x 0.4 m sheet of unjittered 0.2 m squares (two rows of
// five cells, default ice: E = E_v = 328 MPa, h = 0.051 m, sigma_f = 108 kPa): every cut crosses
// the two bonds between neighbouring columns, each with L_e = d = 0.2 m.
std::vector<thin_ice::EdgeCutCapacity> squareGridCuts(int cuts) {
  thin_ice::Params p;
  p.sheet.length = 1.0;
  p.sheet.width = 0.4;
  p.sheet.cell_size = 0.2;
  p.sheet.jitter = 0.0;
  p.sheet.lloyd_iterations = 0;
  p.numerics.time_step = 1e-7;
  const thin_ice::IceSheet sheet = thin_ice::generateIceSheet(p.sheet);
  return thin_ice::edgeCutCapacities(thin_ice::buildModel(p, sheet, "test"), sheet, cuts);
}

TEST(EdgeCheck, ACutThroughASquareGridFailsAtTheSumOfItsBonds) {
  // sigma_v = 3 |F_v| d / (L_e h^2) (E_v = E, so sigma_v reaches sigma_f): each bond fails by Eq. (13) at
  // F_v = sigma_f L_e h^2 / (3 d) = 108e3 * 0.051^2 / 3 = 93.64 N, and the cut carries
  // 2 * 93.636 / 0.4 = 468.18 N per metre of edge.
  const auto cuts = squareGridCuts(2);
  ASSERT_EQ(cuts.size(), 2u);
  for (const auto& cut : cuts) {
    EXPECT_EQ(cut.bonds, 2);
    EXPECT_EQ(cut.failing_by_stress, 2);
    EXPECT_NEAR(cut.line_load, 468.18, 0.01);
    EXPECT_NEAR(cut.sum_of_peaks, 468.18, 0.01);  // equal bonds peak together
  }
  EXPECT_DOUBLE_EQ(cuts[0].distance_from_edge, 0.2);
  EXPECT_DOUBLE_EQ(cuts[1].distance_from_edge, 0.4);
}

}  // namespace
