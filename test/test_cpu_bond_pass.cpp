// The CPU backend's vectorised bond pass (src/core/cpu_bond_pass.cpp) against the law it
// compiles, rmibBondForce and bondLoad of physics/bond.hpp called bond by bond here: on a sheet
// of 3 m x 1 m in 0.2 m cells (more than two blocks of 64 bonds, the last one partial) with every
// cell moved, turned, lifted and set moving by a fixed pseudo-random amount, five cells lifted by
// more than h (their bonds must break, Eq. 13's |dz| >= h) and a whole block broken beforehand.
// For each smoothing exponent of Table 1, one that is not (1.5), unequal exponents, and each
// reading of sigma_v.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "cpu_bond_pass.hpp"
#include "thin_ice_sim/ice_sheet.hpp"

namespace thin_ice {
namespace {

struct Case {
  double exponent_h, exponent_v;
  bool vectorised;  ///< whether the pass should have a vectorised instance for it
};

struct Scene {
  Model model;
  std::vector<CellMotion> motion;
  std::vector<Vec2> turn;
};

Scene perturbedScene(const Case& k) {
  Params p;
  p.sheet.length = 3.0;
  p.sheet.width = 1.0;
  p.sheet.cell_size = 0.2;
  p.numerics.time_step = 1e-7;
  p.ice.smoothing_exponent_h = k.exponent_h;
  p.ice.smoothing_exponent_v = k.exponent_v;
  Scene s;
  s.model = buildModel(p, generateIceSheet(p.sheet), "test");
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double h = p.ice.thickness;
  s.motion = s.model.initial;
  for (size_t c = 0; c < s.motion.size(); ++c) {
    CellMotion& m = s.motion[c];
    // Micrometres: stresses around sigma_f, so that some bonds fail by Eq. (13)'s stresses too.
    m.x += 1e-5 * unit(random);
    m.y += 1e-5 * unit(random);
    m.z += (c % 11 == 3 ? 1.2 * h : 1e-5 * unit(random));  // every 11th cell: lifted through
    m.yaw = 0.03 * unit(random);
    m.vx = 0.1 * unit(random);
    m.vy = 0.1 * unit(random);
    m.vz = 0.1 * unit(random);
    m.wz = 0.5 * unit(random);
    s.turn.push_back({std::cos(m.yaw), std::sin(m.yaw)});
  }
  return s;
}

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  auto exponent = [](double n) { return n == 0.5 ? std::string("half") : std::to_string(static_cast<int>(n * 10)); };
  return "n" + exponent(info.param.exponent_h) + "_nv" + exponent(info.param.exponent_v);
}

class CpuBondPassTest : public ::testing::TestWithParam<Case> {};

TEST_P(CpuBondPassTest, GivesTheLawsLoadsAndFailuresBondByBond) {
  const Case k = GetParam();
  const Scene s = perturbedScene(k);
  const Model& model = s.model;
  const int bonds = static_cast<int>(model.bond_rest.size());
  ASSERT_GT(bonds, 2 * kBondBlock);
  ASSERT_NE(bonds % kBondBlock, 0) << "the last block should be partial";

  std::vector<unsigned char> state(bonds);
  for (int b = 0; b < bonds; ++b) state[b] = b / kBondBlock == 1 ? kBondBroken : kBondIntact;  // a whole block
  std::vector<PairLoad> load(bonds, PairLoad{{NAN, NAN}, NAN, NAN, NAN});
  const CpuBondPass pass(model);
  EXPECT_EQ(pass.vectorised(), k.vectorised);
  const int broken = pass.run(s.motion.data(), s.turn.data(), state.data(), load.data(), 1, false);

  int expected_broken = 0;
  for (int b = 0; b < bonds; ++b) {
    if (b >= kBondBlock && b < 2 * kBondBlock) {
      EXPECT_EQ(state[b], kBondBroken) << "bond " << b;  // a broken bond stays broken
      continue;
    }
    const int i = model.bond_i[b], j = model.bond_j[b];
    auto body = [&](int c) { return bodyOf(s.motion[c], model.mass[c], model.inertia[c]); };
    const BondForce f =
        rmibBondForce(model.bond_rest[b], body(i), s.turn[i], body(j), s.turn[j], model.constants.bond);
    const PairLoad want = bondLoad(f);
    // The vectorised arithmetic may place its fused multiply-adds elsewhere: the last bits only.
    const double scale = std::fabs(want.force_on_j.x) + std::fabs(want.force_on_j.y) + std::fabs(want.fz_on_j) + 1e-30;
    const double torque_scale = std::fabs(want.torque[0]) + std::fabs(want.torque[1]) + 1e-30;
    EXPECT_NEAR(load[b].force_on_j.x, want.force_on_j.x, 1e-12 * scale) << "bond " << b;
    EXPECT_NEAR(load[b].force_on_j.y, want.force_on_j.y, 1e-12 * scale) << "bond " << b;
    EXPECT_NEAR(load[b].fz_on_j, want.fz_on_j, 1e-12 * scale) << "bond " << b;
    EXPECT_NEAR(load[b].torque[0], want.torque[0], 1e-12 * torque_scale) << "bond " << b;
    EXPECT_NEAR(load[b].torque[1], want.torque[1], 1e-12 * torque_scale) << "bond " << b;
    EXPECT_EQ(state[b], f.breaks ? kBondBreaking : kBondIntact) << "bond " << b;
    expected_broken += f.breaks ? 1 : 0;
  }
  EXPECT_EQ(broken, expected_broken);
  EXPECT_GE(expected_broken, 5) << "the lifted cells' bonds should break";
  EXPECT_LT(expected_broken, bonds - kBondBlock) << "and not every bond";
}

TEST_P(CpuBondPassTest, IsBitIdenticalOnOneAndTwoThreads) {
  const Scene s = perturbedScene(GetParam());
  const int bonds = static_cast<int>(s.model.bond_rest.size());
  const CpuBondPass pass(s.model);
  std::vector<unsigned char> state_one(bonds, kBondIntact), state_two(bonds, kBondIntact);
  std::vector<PairLoad> load_one(bonds), load_two(bonds);
  const int one = pass.run(s.motion.data(), s.turn.data(), state_one.data(), load_one.data(), 1, false);
  const int two = pass.run(s.motion.data(), s.turn.data(), state_two.data(), load_two.data(), 2, true);
  EXPECT_EQ(one, two);
  EXPECT_EQ(state_one, state_two);
  EXPECT_EQ(std::memcmp(load_one.data(), load_two.data(), sizeof(PairLoad) * bonds), 0);
}

INSTANTIATE_TEST_SUITE_P(
    Exponents, CpuBondPassTest,
    ::testing::Values(Case{1.0, 1.0, true}, Case{2.0, 2.0, true}, Case{0.5, 0.5, true}, Case{1.5, 1.5, false},
                      Case{2.0, 1.0, false}),
    caseName);

}  // namespace
}  // namespace thin_ice
