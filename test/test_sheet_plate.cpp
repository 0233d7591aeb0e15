// Plate bending of the bonded sheet (physics/sheet_plate.hpp, ice.plate_bending): the stiffness,
// the energy of a hexagonal lattice in cylindrical bending worked out by hand, the forces against
// central differences of the energy on a generated Voronoi sheet, and the CPU backend's passes
// against the law.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "cpu_backend.hpp"
#include "thin_ice_sim/ice_sheet.hpp"
#include "thin_ice_sim/incidence.hpp"
#include "thin_ice_sim/model.hpp"
#include "thin_ice_sim/physics/sheet_plate.hpp"
#include "thin_ice_sim/scenario.hpp"
#include "thin_ice_sim/simulation.hpp"

namespace thin_ice {
namespace {

const std::string kQuick = std::string(THIN_ICE_SOURCE_DIR) + "/config/scenarios/quick.yaml";

TEST(SheetPlate, BondStiffnessIsEightThirdsOfThePlatesFlexuralRigidity) {
  // M-2 ice: E = 328 MPa, nu = 0.3, h = 0.051 m: D = 328e6 0.051^3 / (12 0.91) = 3984.389 N m,
  // D' = 8 D / 3 = 10625.04 N m.
  EXPECT_NEAR(plateBondStiffness(328e6, 0.3, 0.051), 10625.04, 0.01);
}

TEST(SheetPlate, ACellWithTwoBondsTenDegreesApartIsFittedAlongALine) {
  // Neighbours at 0.2 m, 10 degrees apart: sum r r^T has trace 0.08 m^2 and det / trace^2 =
  // sin^2(10 deg) / 4 = 0.0075, below the plate's 0.05, so P = I / trace = 12.5 1/m^2; the
  // criterion's fit (1e-9) still solves the 2 x 2 system and gets the plane through the three.
  HeightGradientSums sums = {0.0, 0.0, 0.0, 0.0, 0.0};
  const double angle = 10.0 * M_PI / 180.0;
  addHeightSample(sums, {0.2, 0.0}, 0.002);
  addHeightSample(sums, {0.2 * std::cos(angle), 0.2 * std::sin(angle)}, 0.004);
  const PlateFit fit = plateFit(sums);
  EXPECT_NEAR(fit.inverse.xx, 12.5, 1e-12);
  EXPECT_NEAR(fit.inverse.yy, 12.5, 1e-12);
  EXPECT_EQ(fit.inverse.xy, 0.0);
  EXPECT_NEAR(fit.gradient.x, 12.5 * (0.2 * 0.002 + 0.2 * std::cos(angle) * 0.004), 1e-15);
  EXPECT_NEAR(fit.gradient.y, 12.5 * 0.2 * std::sin(angle) * 0.004, 1e-15);
  const Vec2 plane = heightGradient(sums);
  EXPECT_NEAR(plane.x, 0.01, 1e-12);  // z = 0.01 x + g_y y through both samples
  EXPECT_NEAR(plane.y, (0.004 - 0.01 * 0.2 * std::cos(angle)) / (0.2 * std::sin(angle)), 1e-12);
}

/// Cells, bonds and the pieces the passes read, built by hand or from a generated sheet.
struct Patch {
  std::vector<CellMotion> motion;
  std::vector<int> bond_i, bond_j;
  std::vector<BondRest> rest;
  std::vector<unsigned char> state;
  Incidence incidence;

  Vec2 turn(int k) const { return {std::cos(motion[k].yaw), std::sin(motion[k].yaw)}; }

  std::vector<Vec2> turns() const {
    std::vector<Vec2> t(motion.size());
    for (size_t k = 0; k < motion.size(); ++k) t[k] = turn(static_cast<int>(k));
    return t;
  }

  PlateFit fitOf(int k) const {
    const std::vector<Vec2> t = turns();
    return cellPlateFit(k, incidence.offsets.data(), incidence.entries.data(), state.data(), bond_i.data(),
                        bond_j.data(), rest.data(), t.data(), motion.data());
  }

  std::vector<Vec2> gradients() const {
    std::vector<Vec2> g(motion.size());
    for (size_t k = 0; k < motion.size(); ++k) {
      g[k] = fitOf(static_cast<int>(k)).gradient;
    }
    return g;
  }

  double bondEnergy(int b, double stiffness, const std::vector<Vec2>& g) const {
    const int i = bond_i[b], j = bond_j[b];
    return plateBondEnergy(stiffness, rest[b], turn(i), turn(j), g[i], g[j]);
  }

  double energy(double stiffness) const {
    const std::vector<Vec2> g = gradients();
    double u = 0.0;
    for (size_t b = 0; b < rest.size(); ++b) {
      if (state[b] == kBondIntact) u += bondEnergy(static_cast<int>(b), stiffness, g);
    }
    return u;
  }

  /// The three passes of sheet_plate.hpp, in the order the backends run them.
  std::vector<double> forces(double stiffness) const {
    const int n = static_cast<int>(motion.size());
    const int* offsets = incidence.offsets.data();
    const int* entries = incidence.entries.data();
    std::vector<Vec2> g(n), moment(n), bond_moment(rest.size(), Vec2{0.0, 0.0});
    std::vector<SymmetricMatrix2> inverse(n);
    const std::vector<Vec2> t = turns();
    for (int k = 0; k < n; ++k) {
      const PlateFit fit =
          cellPlateFit(k, offsets, entries, state.data(), bond_i.data(), bond_j.data(), rest.data(), t.data(), motion.data());
      g[k] = fit.gradient;
      inverse[k] = fit.inverse;
    }
    for (size_t b = 0; b < rest.size(); ++b) {
      if (state[b] != kBondIntact) continue;
      bond_moment[b] = bondPlateMoment(stiffness, rest[b], turn(bond_i[b]), turn(bond_j[b]), g[bond_i[b]], g[bond_j[b]]);
    }
    for (int k = 0; k < n; ++k) moment[k] = cellPlateMoment(k, offsets, entries, state.data(), bond_moment.data(), inverse[k]);
    std::vector<double> f(n);
    for (int k = 0; k < n; ++k) {
      f[k] = cellPlateForce(k, offsets, entries, state.data(), bond_i.data(), bond_j.data(), rest.data(), t.data(),
                            moment.data());
    }
    return f;
  }
};

/// A triangular lattice of pitch a (the centroids of hexagonal cells), rows along x, bonds between
/// nearest neighbours: normal along the link, rest length a, edge length a / sqrt(3).
Patch hexagonalLattice(int columns, int rows, double a, std::vector<int>& neighbour_count) {
  Patch p;
  const double row_height = a * std::sqrt(3.0) / 2.0;
  auto index = [&](int i, int j) { return j * columns + i; };
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      CellMotion m{};
      m.x = i * a + (j % 2 ? 0.5 * a : 0.0);
      m.y = j * row_height;
      p.motion.push_back(m);
    }
  }
  auto bond = [&](int i, int j) {
    const Vec2 link = {p.motion[j].x - p.motion[i].x, p.motion[j].y - p.motion[i].y};
    BondRest r{};
    r.normal = (1.0 / norm(link)) * link;
    r.distance = a;
    r.edge_length = a / std::sqrt(3.0);
    p.bond_i.push_back(i);
    p.bond_j.push_back(j);
    p.rest.push_back(r);
  };
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      if (i + 1 < columns) bond(index(i, j), index(i + 1, j));
      if (j + 1 < rows) {
        const int left = j % 2 ? i : i - 1;  // the two cells of the next row that touch (i, j)
        if (left >= 0) bond(index(i, j), index(left, j + 1));
        if (left + 1 < columns) bond(index(i, j), index(left + 1, j + 1));
      }
    }
  }
  p.state.assign(p.rest.size(), kBondIntact);
  p.incidence.build(static_cast<int>(p.motion.size()), p.bond_i, p.bond_j);
  neighbour_count.assign(p.motion.size(), 0);
  for (size_t b = 0; b < p.rest.size(); ++b) {
    ++neighbour_count[p.bond_i[b]];
    ++neighbour_count[p.bond_j[b]];
  }
  return p;
}

TEST(SheetPlate, TwoBondedCellsSlidOverEachOtherKeepTheirRestOffset) {
  // In a rubble pile two cells can still be bonded after one slid onto the other: here their
  // centroids coincide in plan, 0.02 m apart in height. The plate measures them over the bond's rest
  // offset, d = 0.2 m along x: one sample on a line, so P = I / d^2 = 25 1/m^2 and g_i =
  // (0.02 / 0.2, 0); seen from j the offset is -d along x and the step -0.02 m, so g_j is the same,
  // the pair has no curvature and no force (where the cells' own centroids gave P = 1 / 0 here).
  Patch p;
  CellMotion below{}, above{};
  above.z = 0.02;
  p.motion = {below, above};
  BondRest r{};
  r.normal = {1.0, 0.0};
  r.distance = 0.2;
  r.edge_length = 0.1;
  p.bond_i = {0};
  p.bond_j = {1};
  p.rest = {r};
  p.state = {kBondIntact};
  p.incidence.build(2, p.bond_i, p.bond_j);
  for (int k = 0; k < 2; ++k) {
    const PlateFit fit = p.fitOf(k);
    EXPECT_NEAR(fit.inverse.xx, 25.0, 1e-12) << "cell " << k;
    EXPECT_NEAR(fit.inverse.yy, 25.0, 1e-12) << "cell " << k;
    EXPECT_NEAR(fit.gradient.x, 0.1, 1e-15) << "cell " << k;
    EXPECT_EQ(fit.gradient.y, 0.0) << "cell " << k;
  }
  for (double f : p.forces(plateBondStiffness(328e6, 0.3, 0.051))) EXPECT_NEAR(f, 0.0, 1e-9);
}

TEST(SheetPlate, HexagonalLatticeInCylindricalBendingHasAPlatesEnergy) {
  // z = kappa x^2 / 2 with kappa = 0.05 1/m, pitch a = 0.2 m, D' = 10625.04 N m (M-2). A cell with
  // all six neighbours sees them symmetrically, so its gradient is exactly (kappa x, 0), and a bond
  // at angle theta to x has kappa_b = kappa cos^2 theta: A_b = a^2 / (2 sqrt 3) = 0.0115470 m^2, so
  // a bond along x holds D' A_b kappa^2 / 2 = 0.153359 J, a bond at 60 or 120 degrees 1/16 of it,
  // and the three bonds of one cell hold 9/8 of it, 0.172529 J: the plate's D kappa^2 / 2 over the
  // cell's area sqrt(3) a^2 / 2 (D = 3984.389 N m).
  const double a = 0.2, kappa = 0.05, stiffness = plateBondStiffness(328e6, 0.3, 0.051);
  std::vector<int> neighbours;
  Patch p = hexagonalLattice(9, 9, a, neighbours);
  for (CellMotion& m : p.motion) m.z = 0.5 * kappa * m.x * m.x;
  const std::vector<Vec2> g = p.gradients();
  double along_x = -1.0, oblique = -1.0;
  int checked = 0;
  for (size_t b = 0; b < p.rest.size(); ++b) {
    if (neighbours[p.bond_i[b]] != 6 || neighbours[p.bond_j[b]] != 6) continue;
    const double u = p.bondEnergy(static_cast<int>(b), stiffness, g);
    const bool is_along_x = std::fabs(p.rest[b].normal.y) < 1e-12;
    EXPECT_NEAR(u, is_along_x ? 0.153359 : 0.153359 / 16.0, 1e-6) << "bond " << b;
    (is_along_x ? along_x : oblique) = u;
    ++checked;
  }
  ASSERT_GT(checked, 50);
  EXPECT_NEAR(along_x + 2.0 * oblique, 0.172529, 1e-6);
  const double plate_per_cell = 0.5 * 3984.389 * kappa * kappa * std::sqrt(3.0) / 2.0 * a * a;
  EXPECT_NEAR(along_x + 2.0 * oblique, plate_per_cell, 1e-6);
}

TEST(SheetPlate, TiltedPlaneCarriesNoEnergyAndNoForce) {
  std::vector<int> neighbours;
  Patch p = hexagonalLattice(6, 5, 0.2, neighbours);
  for (CellMotion& m : p.motion) m.z = 0.03 * m.x - 0.02 * m.y + 0.01;
  const double stiffness = plateBondStiffness(328e6, 0.3, 0.051);
  EXPECT_NEAR(p.energy(stiffness), 0.0, 1e-20);
  for (double f : p.forces(stiffness)) EXPECT_NEAR(f, 0.0, 1e-9);
}

/// The cells (at their initial state) and intact bonds of a model.
Patch patchOf(const Model& model) {
  Patch p;
  p.motion = model.initial;
  p.bond_i = model.bond_i;
  p.bond_j = model.bond_j;
  p.rest = model.bond_rest;
  p.state.assign(p.rest.size(), kBondIntact);
  p.incidence.build(model.cell_count, p.bond_i, p.bond_j);
  return p;
}

/// The quick strip, 1 m long, with the given overrides.
Model stripModel(const std::string& more_override) {
  std::vector<std::string> overrides = {"sheet.length=1.0", "structure.toe_x=1.1", "bottom.distance_from_structure=0.5"};
  if (!more_override.empty()) overrides.push_back(more_override);
  const Scenario s = loadScenario(kQuick, overrides);
  return buildModel(s.params, generateIceSheet(s.params.sheet), s.source);
}

/// The cells and bonds of a generated Voronoi sheet (the quick strip, 1 m), with random heights,
/// yaws and three bonds broken.
Patch voronoiPatch() {
  Patch p = patchOf(stripModel(""));
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (CellMotion& m : p.motion) {
    m.z += 0.005 * unit(random);
    m.yaw += 0.01 * unit(random);
  }
  for (size_t b = 0; b < p.rest.size(); b += p.rest.size() / 3) p.state[b] = kBondBroken;
  return p;
}

TEST(SheetPlate, ForcesAreMinusTheEnergysGradientOnAVoronoiSheet) {
  // U is quadratic in the heights (the horizontal geometry held), so a central difference is exact
  // but for rounding: dU/dz_m = (U(z + e) - U(z - e)) / 2e.
  Patch p = voronoiPatch();
  ASSERT_GT(p.motion.size(), 20u);
  const double stiffness = plateBondStiffness(328e6, 0.3, 0.051);
  const std::vector<double> f = p.forces(stiffness);
  double scale = 0.0, total = 0.0;
  for (double v : f) {
    scale = std::max(scale, std::fabs(v));
    total += v;
  }
  ASSERT_GT(scale, 1.0) << "the random heights should bend the sheet";
  EXPECT_NEAR(total, 0.0, 1e-9 * scale * f.size()) << "the forces of every pair cancel";
  const double step = 1e-6;
  for (size_t m = 0; m < p.motion.size(); ++m) {
    const double z = p.motion[m].z;
    p.motion[m].z = z + step;
    const double up = p.energy(stiffness);
    p.motion[m].z = z - step;
    const double down = p.energy(stiffness);
    p.motion[m].z = z;
    EXPECT_NEAR(f[m], -(up - down) / (2.0 * step), 1e-6 * scale) << "cell " << m;
  }
}

TEST(SheetPlate, TheCpuBackendAddsThePlatesForceToEachCell) {
  // One step of the strip bent as z = kappa x^2 / 2 plus noise, with and without the term: the
  // cells' vertical velocities differ by F dt / m, F from the law on the initial state.
  Model on = stripModel("ice.plate_bending=true");
  ASSERT_GT(on.constants.plate_bond_stiffness, 0.0);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double x0 = on.initial.front().x;
  for (CellMotion& m : on.initial) m.z += 0.5 * 0.05 * (m.x - x0) * (m.x - x0) + 0.002 * unit(random);
  Model off = on;
  off.constants.plate_bond_stiffness = 0.0;

  const std::vector<double> f = patchOf(on).forces(on.constants.plate_bond_stiffness);

  std::unique_ptr<Backend> with = makeCpuBackend(on, 1), without = makeCpuBackend(off, 1);
  with->step(1, on.initial_pusher_velocity);
  without->step(1, off.initial_pusher_velocity);
  const std::vector<CellSnapshot> a = with->cells(), b = without->cells();
  const double dt = on.constants.time_step;
  double largest = 0.0;
  for (int k = 0; k < on.cell_count; ++k) largest = std::max(largest, std::fabs(f[k]));
  ASSERT_GT(largest, 1.0);
  for (int k = 0; k < on.cell_count; ++k) {
    const double expected = f[k] * dt / on.mass[k];
    const double weight = on.mass[k] * on.constants.water.gravity + largest;  // the sizes of the other forces
    EXPECT_NEAR(a[k].vz - b[k].vz, expected, 1e-12 * weight * dt / on.mass[k]) << "cell " << k;
  }
}

}  // namespace
}  // namespace thin_ice
