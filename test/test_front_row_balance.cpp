// The front row's vertical force balance (thin_ice_sim/study/front_row_balance.hpp) against values
// worked out by hand on a 1 m x 0.6 m sheet of unjittered 0.2 m squares: five columns of three
// cells, the front row the three cells at 0.8 < x < 1.0 m, each bonded to the one behind it
// across an edge L_e = 0.2 m long between centroids d = 0.2 m apart. Default ice: h = 0.051 m,
// rho_i = 920 kg/m^3, E_v = 328 MPa, nu = 0.3, n_v = 1; water rho_w = 1000 kg/m^3, g = 9.81 m/s^2.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "thin_ice_sim/study/front_row_balance.hpp"

namespace {

struct Fixture {
  thin_ice::Params params;
  thin_ice::IceSheet sheet;
  thin_ice::Model model;
};

Fixture squareGrid() {
  Fixture f;
  f.params.sheet.length = 1.0;
  f.params.sheet.width = 0.6;
  f.params.sheet.cell_size = 0.2;
  f.params.sheet.jitter = 0.0;
  f.params.sheet.lloyd_iterations = 0;
  f.params.numerics.time_step = 1e-7;
  // The values the expected numbers below are worked from (set here, not taken from defaults).
  f.params.ice.thickness = 0.051;
  f.params.ice.density = 920.0;
  f.params.ice.vertical_modulus = 328e6;
  f.params.ice.poisson_ratio = 0.3;
  f.params.ice.smoothing_exponent_v = 1.0;
  f.params.water.density = 1000.0;
  f.params.water.gravity = 9.81;
  f.sheet = thin_ice::generateIceSheet(f.params.sheet);
  f.model = thin_ice::buildModel(f.params, f.sheet, "test");
  return f;
}

std::vector<thin_ice::CellPose> atRest(const thin_ice::Model& model) {
  std::vector<thin_ice::CellPose> poses;
  for (const thin_ice::CellMotion& m : model.initial) poses.push_back({m.x, m.y, m.z, 0.0});
  return poses;
}

/// The balance with `lifted` cells raised by dz [m] from rest and the others at rest.
thin_ice::FrontRowBalance liftedBalance(const thin_ice::Model& model, const thin_ice::FrontRow& row,
                                        const std::vector<int>& lifted, double dz) {
  std::vector<thin_ice::CellPose> poses = atRest(model);
  for (int k : lifted) poses[k].z += dz;
  return thin_ice::frontRowBalance(model, row, poses);
}

TEST(FrontRowBalance, FindsTheFrontRowAndItsBonds) {
  const Fixture f = squareGrid();
  ASSERT_EQ(f.model.cell_count, 15);
  const thin_ice::FrontRow row = thin_ice::frontRow(f.model, f.sheet);
  EXPECT_EQ(row.cells.size(), 3u);
  EXPECT_EQ(row.cut_bonds.size(), 3u);
  EXPECT_EQ(row.rear_cells.size(), 3u);
  for (int k : row.cells) EXPECT_NEAR(f.sheet.cells[k].centroid.x, 0.9, 1e-9);
  for (int k : row.rear_cells) EXPECT_NEAR(f.sheet.cells[k].centroid.x, 0.7, 1e-9);
  // 3 x 0.04 m^2; weight rho_i g h A = 920 * 9.81 * 0.051 * 0.12 = 55.234224 N.
  EXPECT_NEAR(row.area, 0.12, 1e-12);
  EXPECT_NEAR(row.weight, 55.234224, 1e-9);
}

TEST(FrontRowBalance, ASheetAtRestIsBalanced) {
  const Fixture f = squareGrid();
  const thin_ice::FrontRowBalance b =
      thin_ice::frontRowBalance(f.model, thin_ice::frontRow(f.model, f.sheet), atRest(f.model));
  EXPECT_EQ(b.bond_force, 0.0);
  EXPECT_EQ(b.lost_buoyancy, 0.0);
  EXPECT_EQ(b.front_lift, 0.0);
}

TEST(FrontRowBalance, ALiftedFrontRowIsPulledDownByItsBondsAndLosesBuoyancy) {
  // Front row lifted by dz = 5 mm. Each cut bond: k_v = G_v h L_e / d with G_v = E_v / (2 (1 + nu))
  // = 328e6 / 2.6 = 1.261538e8 Pa, so k_v = 6.433846e6 N/m; K_v = 1 - dz/h = 46/51;
  // F_v = 46/51 * 6.433846e6 * 0.005 = 29015.38 N, three bonds: 87046.15 N down on the front row.
  // Buoyancy lost (dz is less than the draft rho_i / rho_w h = 0.04692 m): rho_w g A dz =
  // 1000 * 9.81 * 0.12 * 0.005 = 5.886 N.
  const Fixture f = squareGrid();
  const thin_ice::FrontRow row = thin_ice::frontRow(f.model, f.sheet);
  const thin_ice::FrontRowBalance b = liftedBalance(f.model, row, row.cells, 0.005);
  EXPECT_NEAR(b.bond_force, 87046.15, 0.01);
  EXPECT_NEAR(b.lost_buoyancy, 5.886, 1e-9);
  EXPECT_NEAR(b.front_lift, 0.005, 1e-15);
  EXPECT_EQ(b.rear_lift, 0.0);
}

TEST(FrontRowBalance, ARowOutOfTheWaterHasLostItsWeightAndTornBondsCarryNothing) {
  // Lifted by 0.06 m > h: wholly out of the water, so the lost buoyancy is the row's weight
  // (55.234224 N, as its whole buoyancy held it at rest), and K_v(|dz| >= h) = 0.
  const Fixture f = squareGrid();
  const thin_ice::FrontRow row = thin_ice::frontRow(f.model, f.sheet);
  const thin_ice::FrontRowBalance b = liftedBalance(f.model, row, row.cells, 0.06);
  EXPECT_EQ(b.bond_force, 0.0);
  EXPECT_NEAR(b.lost_buoyancy, 55.234224, 1e-9);
}

TEST(FrontRowBalance, ALiftedRowBehindPushesTheFrontRowUp) {
  // The row behind lifted by 5 mm instead: the same bonds, opposite sign.
  const Fixture f = squareGrid();
  const thin_ice::FrontRow row = thin_ice::frontRow(f.model, f.sheet);
  const thin_ice::FrontRowBalance b = liftedBalance(f.model, row, row.rear_cells, 0.005);
  EXPECT_NEAR(b.bond_force, -87046.15, 0.01);
  EXPECT_EQ(b.lost_buoyancy, 0.0);
  EXPECT_NEAR(b.rear_lift, 0.005, 1e-15);
}

TEST(FrontRowBalance, TheSameWhicheverCellOfABondIsI) {
  // Cells are numbered x fastest, so on this grid the front cell of every cut bond is j. Written
  // the other way round (i and j swapped, their anchors swapped, the normal reversed: the same
  // bond), the front cell is i, and the balance must not change.
  const Fixture f = squareGrid();
  thin_ice::Model swapped = f.model;
  for (size_t b = 0; b < swapped.bond_rest.size(); ++b) {
    std::swap(swapped.bond_i[b], swapped.bond_j[b]);
    thin_ice::BondRest& r = swapped.bond_rest[b];
    std::swap(r.anchor_i, r.anchor_j);
    r.normal = -r.normal;
  }
  const thin_ice::FrontRow row = thin_ice::frontRow(swapped, f.sheet);
  ASSERT_EQ(row.cut_bonds.size(), 3u);
  for (int b : row.cut_bonds) EXPECT_NEAR(f.sheet.cells[swapped.bond_i[b]].centroid.x, 0.9, 1e-9);
  EXPECT_NEAR(liftedBalance(swapped, row, row.cells, 0.005).bond_force, 87046.15, 0.01);
}

TEST(FrontRowBalance, RefusesASnapshotOfAnotherSheet) {
  const Fixture f = squareGrid();
  const std::vector<thin_ice::CellPose> too_few(14);
  EXPECT_THROW(thin_ice::frontRowBalance(f.model, thin_ice::frontRow(f.model, f.sheet), too_few),
               std::invalid_argument);
}

}  // namespace
