// The laws of include/thin_ice_sim/physics/, one at a time, against answers worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "thin_ice_sim/incidence.hpp"
#include "thin_ice_sim/physics/bond.hpp"
#include "thin_ice_sim/physics/contact.hpp"
#include "thin_ice_sim/physics/integrate.hpp"
#include "thin_ice_sim/physics/plane_contact.hpp"
#include "thin_ice_sim/physics/smoothing.hpp"
#include "thin_ice_sim/physics/water.hpp"

namespace thin_ice {
namespace {

constexpr double kTolTable = 6e-4;  // Table 2 prints three decimals, 0.0625 rounded up to 0.063
constexpr double kTolExact = 1e-12;    // closed-form arithmetic, relative

TEST(Smoothing, ReproducesTable2) {
  const double z[] = {0.0, 0.25, 0.5, 0.75, 1.0};
  const double strong[] = {1.000, 0.866, 0.707, 0.500, 0.0};
  const double medium[] = {1.000, 0.750, 0.500, 0.250, 0.0};
  const double weak[] = {1.000, 0.563, 0.250, 0.063, 0.0};
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(smoothing(z[k], 0.5), strong[k], kTolTable) << "z = " << z[k];
    EXPECT_NEAR(smoothing(z[k], 1.0), medium[k], kTolTable) << "z = " << z[k];
    EXPECT_NEAR(smoothing(z[k], 2.0), weak[k], kTolTable) << "z = " << z[k];
  }
  EXPECT_EQ(smoothing(1.5, 1.0), 0.0);  // K(z > 1) = 0, Eq. (5)
  EXPECT_NEAR(smoothing(0.3, 1.5), std::pow(0.7, 1.5), kTolExact);
}

TEST(Water, FloatingCellSettlesAtTheDraft) {
  // A 0.2 m square, h = 0.05 m, rho_i = 920: draft = 0.92 h, centroid at h/2 - 0.92 h.
  const WaterConstants w = {1000.0, 9.81, 0.05, 20.0, 0.5, 200.0, 1.0};
  const double area = 0.04, mass = 920.0 * area * 0.05, j = 0.04 * 0.04 / 6.0;
  const double z_draft = 0.5 * 0.05 - 0.92 * 0.05;
  EXPECT_NEAR(waterForce(w, mass, area, j, z_draft, {0, 0}, 0.0, 0.0).vertical, 0.0, 1e-12);
  // Displaced by 1 mm down: restoring force rho_w g A 1e-3 upwards.
  EXPECT_NEAR(waterForce(w, mass, area, j, z_draft - 1e-3, {0, 0}, 0.0, 0.0).vertical, 1000 * 9.81 * area * 1e-3,
              1e-9);
  // Dropped at the waterline, it comes to rest at the draft.
  CellMotion c = {0, 0, 0.0, 0, 0, 0, 0, 0};
  const double dt = 1e-4;
  for (int step = 0; step < 100000; ++step) {
    const WaterForce f = waterForce(w, mass, area, j, c.z, {c.vx, c.vy}, c.vz, c.wz);
    integrateSymplecticEuler(c, f.horizontal.x, f.horizontal.y, f.vertical, f.torque, 1.0 / mass, 1.0, dt);
  }
  EXPECT_NEAR(c.z, z_draft, 1e-6);
  EXPECT_NEAR(c.vz, 0.0, 1e-6);
}

std::vector<Vec2> square(Vec2 centre, double side) {
  const double a = 0.5 * side;
  return {centre + Vec2{-a, -a}, centre + Vec2{a, -a}, centre + Vec2{a, a}, centre + Vec2{-a, a}};
}

/// Yaw inertia of a 0.2 m square of 1.84 kg: m a^2 / 6 [kg m^2].
constexpr double kSquareInertia = 1.84 * 0.04 / 6.0;

/// Eqs. (1)-(3) alone: no crushing limit (1e12 Pa), friction bound of dt = 1e-6 s.
ContactConstants iceContact() {
  return {0.05, 3.0 * 300e6 / 0.7, 3.0 * 300e6 / 0.7, 1.0, 1.0, 0.3, 0.5 / 1e-6, 1e12, 0.2, 1e-3};
}

/// An existing pair that had no overlap before this step (a new pair would pass -1).
constexpr double kNoReference = 0.0;

/// The force on two 0.2 m squares at rest, j 1 mm into i along x (S = 0.2e-3 m^2, L = 0.2 m) and
/// `lift` [m] higher.
PairForce squaresOneMillimetreIn(double lift, const ContactConstants& c) {
  const auto a = square({0.0, 0.0}, 0.2), b = square({0.199, 0.0}, 0.2);
  const PolygonOverlap o = intersectConvexPolygons(a.data(), 4, b.data(), 4);
  const BodyState i = {{0.0, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  const BodyState j = {{0.199, 0.0}, lift, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  return demContactForce(o, i, j, c, kNoReference);
}

TEST(Contact, HorizontalForceIsEquation1TimesHCubedForLevelCells) {
  // Squares 0.2 m, overlapping by 1 mm along x, level: S = 0.2e-3 m^2, L = 0.2 m,
  // F = (3E/(1-nu)) h S/L = (9e8/0.7) 0.05 1e-3 = 64285.7 N along +x on j. No vertical force.
  const PairForce f = squaresOneMillimetreIn(0.0, iceContact());
  EXPECT_NEAR(f.force_on_j.x, 9e8 / 0.7 * 0.05 * 1e-3, 1e-6 * 64285.7);
  EXPECT_NEAR(f.force_on_j.y, 0.0, 1e-9);
  EXPECT_EQ(f.fz_on_j, 0.0);
}

TEST(Contact, VerticalForceIsEquation3) {
  // Same overlap, j 0.02 m higher: z = 0.4, K = 0.6 (n = 1), Z = 0.03 m,
  // F_v = 0.6 * 0.03 * (9e8/0.7) * 2e-4 / 0.05 = 92571.4 N upwards on j, and the horizontal
  // force over the 0.03 m face: F_n = 0.6 (9e8/0.7) 0.03 1e-3 = 23142.9 N.
  const PairForce f = squaresOneMillimetreIn(0.02, iceContact());
  EXPECT_NEAR(f.fz_on_j, 0.6 * 0.03 * 9e8 / 0.7 * 2e-4 / 0.05, 1e-6 * 92571.4);
  EXPECT_NEAR(f.force_on_j.x, 0.6 * 9e8 / 0.7 * 0.03 * 1e-3, 1e-6 * 23142.9);
}

TEST(Contact, HorizontalAndVerticalExponentsActApart) {
  // As above with n = 2 for K_n and n = 1 for K_v: K_n = 0.6^2 = 0.36, K_v = 0.6, so
  // F_n = 0.36 (9e8/0.7) 0.03 1e-3 = 13885.7 N and F_v = 92571.4 N as before.
  ContactConstants c = iceContact();
  c.exponent_h = 2.0;
  const PairForce f = squaresOneMillimetreIn(0.02, c);
  EXPECT_NEAR(f.fz_on_j, 0.6 * 0.03 * 9e8 / 0.7 * 2e-4 / 0.05, 1e-6 * 92571.4);
  EXPECT_NEAR(f.force_on_j.x, 0.36 * 9e8 / 0.7 * 0.03 * 1e-3, 1e-6 * 13885.7);
}

TEST(Contact, EqualAndOppositeWhicheverOrder) {
  const auto a = square({0.0, 0.0}, 0.2), b = square({0.15, 0.05}, 0.2);
  const BodyState i = {{0.0, 0.0}, 0.001, {0.1, 0.02}, 0.0, 0.3, 1.84, kSquareInertia};
  const BodyState j = {{0.15, 0.05}, 0.0, {-0.05, 0.0}, 0.01, -0.2, 1.5, 1.5 * 0.04 / 6.0};
  const PairForce ij = demContactForce(intersectConvexPolygons(a.data(), 4, b.data(), 4), i, j, iceContact(), kNoReference);
  const PairForce ji = demContactForce(intersectConvexPolygons(b.data(), 4, a.data(), 4), j, i, iceContact(), kNoReference);
  // The force on j computed as (i, j) is minus the force on j computed as (j, i) (there: on "i").
  EXPECT_NEAR(ij.force_on_j.x, -ji.force_on_j.x, 1e-9 * std::fabs(ij.force_on_j.x));
  EXPECT_NEAR(ij.force_on_j.y, -ji.force_on_j.y, 1e-9 * std::fabs(ij.force_on_j.x));
  EXPECT_NEAR(ij.fz_on_j, -ji.fz_on_j, 1e-9 * std::fabs(ij.fz_on_j) + 1e-12);
}

TEST(Contact, CollisionConservesMomentumAndGainsNoEnergy) {
  // Two free squares (no water) collide head-on and slightly off-centre.
  const double h = 0.05, side = 0.2, mass_a = 1.84, mass_b = 1.2;
  const double inertia_a = mass_a * side * side / 6.0, inertia_b = mass_b * side * side / 6.0;
  CellMotion a = {0.0, 0.0, 0.0, 0.0, 0.3, 0.0, 0.0, 0.0};
  CellMotion b = {0.21, 0.03, 0.0, 0.0, -0.2, 0.0, 0.0, 0.0};
  auto energy = [&] {
    return 0.5 * mass_a * (a.vx * a.vx + a.vy * a.vy) + 0.5 * mass_b * (b.vx * b.vx + b.vy * b.vy) +
           0.5 * inertia_a * a.wz * a.wz + 0.5 * inertia_b * b.wz * b.wz;
  };
  const double px0 = mass_a * a.vx + mass_b * b.vx, py0 = mass_a * a.vy + mass_b * b.vy;
  const double e0 = energy();
  ContactConstants c = iceContact();
  c.thickness = h;
  bool touched = false;
  double reference = -1.0;  // new pair, apart: no reference overlap
  for (int step = 0; step < 40000; ++step) {
    const auto pa = square({0, 0}, side), pb = square({0, 0}, side);
    std::vector<Vec2> wa, wb;
    for (const Vec2& v : pa) wa.push_back(Vec2{a.x, a.y} + rotate(v, std::cos(a.yaw), std::sin(a.yaw)));
    for (const Vec2& v : pb) wb.push_back(Vec2{b.x, b.y} + rotate(v, std::cos(b.yaw), std::sin(b.yaw)));
    const BodyState ia = {{a.x, a.y}, a.z, {a.vx, a.vy}, a.vz, a.wz, mass_a, inertia_a};
    const BodyState ib = {{b.x, b.y}, b.z, {b.vx, b.vy}, b.vz, b.wz, mass_b, inertia_b};
    const PairForce f = demContactForce(intersectConvexPolygons(wa.data(), 4, wb.data(), 4), ia, ib, c, reference);
    reference = f.reference_area;
    touched = touched || f.touching;
    const double ta = cross(f.point - Vec2{a.x, a.y}, -f.force_on_j);
    const double tb = cross(f.point - Vec2{b.x, b.y}, f.force_on_j);
    integrateSymplecticEuler(a, -f.force_on_j.x, -f.force_on_j.y, -f.fz_on_j, ta, 1 / mass_a, 1 / inertia_a, 1e-6);
    integrateSymplecticEuler(b, f.force_on_j.x, f.force_on_j.y, f.fz_on_j, tb, 1 / mass_b, 1 / inertia_b, 1e-6);
  }
  ASSERT_TRUE(touched);
  EXPECT_LT(b.vx - a.vx, 0.5);  // they bounced: no longer closing at 0.5 m/s
  EXPECT_GT(b.vx - a.vx, 0.0);
  EXPECT_NEAR(mass_a * a.vx + mass_b * b.vx, px0, 1e-9);
  EXPECT_NEAR(mass_a * a.vy + mass_b * b.vy, py0, 1e-9);
  EXPECT_LE(energy(), e0 * (1.0 + 1e-6));
}

TEST(Contact, CrushingLimitsTheNormalForceToSigmaCTimesTheFace) {
  // The 1 mm overlap of the Eq. (1) test would push with 64285.7 N; with sigma_c = 1 MPa the face
  // Z x L = 0.05 x 0.2 m crushes at 1e6 * 0.01 = 10000 N.
  ContactConstants c = iceContact();
  c.crushing_strength = 1e6;
  EXPECT_NEAR(squaresOneMillimetreIn(0.0, c).force_on_j.x, 10000.0, 1e-9 * 10000.0);
  c.crushing_strength = 1e8;  // 1e6 N: above the elastic force, which then holds
  EXPECT_NEAR(squaresOneMillimetreIn(0.0, c).force_on_j.x, 9e8 / 0.7 * 0.05 * 1e-3, 1e-6 * 64285.7);
}

TEST(Contact, PieceRestingOnAnotherIsPushedOverItsVerticalOverlapOnly) {
  // j 0.049 m above i: Z = 1 mm, K_n = 1 - 0.98 = 0.02. Shifted by 0.05 m along x the squares
  // overlap by S = 0.15 x 0.2 m, S/L = 0.15 m, but the slabs are 1 mm apart vertically: the depth
  // is Z, F_n = 0.02 (9e8/0.7) 1e-3 1e-3 = 25.714 N (it was 3857 N with S/L).
  const auto a = square({0.0, 0.0}, 0.2), b = square({0.05, 0.0}, 0.2);
  const PolygonOverlap o = intersectConvexPolygons(a.data(), 4, b.data(), 4);
  ASSERT_NEAR(o.area / o.chord_length, 0.15, 1e-9);
  const BodyState i = {{0.0, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  const BodyState j = {{0.05, 0.0}, 0.049, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  const PairForce f = demContactForce(o, i, j, iceContact(), kNoReference);
  const double k_n = 1.0 - 0.049 / 0.05;
  EXPECT_NEAR(f.force_on_j.x, k_n * 9e8 / 0.7 * 1e-3 * 1e-3, 1e-6 * 25.714);
  // Eq. (3) carries the piece: F_v = K_v Z (3E_v/(1-nu)) S / h, upwards on j.
  EXPECT_NEAR(f.fz_on_j, k_n * 1e-3 * 9e8 / 0.7 * 0.03 / 0.05, 1e-6 * f.fz_on_j);
}

/// The squares of squaresOneMillimetreIn, j `lift` higher and moving at (vy, vz) [m/s].
PairForce squaresSlipping(double lift, double vy, double vz, const ContactConstants& c) {
  const auto a = square({0.0, 0.0}, 0.2), b = square({0.199, 0.0}, 0.2);
  const PolygonOverlap o = intersectConvexPolygons(a.data(), 4, b.data(), 4);
  const BodyState i = {{0.0, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  const BodyState j = {{0.199, 0.0}, lift, {0.0, vy}, vz, 0.0, 1.84, kSquareInertia};
  return demContactForce(o, i, j, c, kNoReference);
}

TEST(Contact, EdgeFaceFrictionResistsTheVerticalSlipOfOffsetCells) {
  // j 0.02 m higher, sliding down at 0.1 m/s against i's edge: F_n = 23142.9 N on the 0.03 m
  // face (VerticalForceIsEquation3), F_v = k_v 0.03 with its damping (closing: it adds). The
  // edge face resists the vertical slip with mu F_n = 0.3 x 23142.9 = 6942.9 N upwards on j (0.1 m/s
  // is above v_reg = 1 mm/s; the bound beta m_eff/dt = 1.85e5 N s/m is above mu F_n / 0.1 = 69429).
  const PairForce held = squaresSlipping(0.02, 0.0, -0.1, iceContact());
  const double f_n = 0.6 * 9e8 / 0.7 * 0.03 * 1e-3;
  const double k_v = 0.6 * 9e8 / 0.7 * 2e-4 / 0.05;                              // [N/m]
  const double f_v = k_v * 0.03 + 2.0 * 0.2 * std::sqrt(k_v * 0.5 * 1.84) * 0.1;  // closing: damping adds
  EXPECT_NEAR(held.fz_on_j, f_v + 0.3 * f_n, 1e-6 * f_v);
  // No horizontal slip: the horizontal force is F_n alone.
  EXPECT_NEAR(held.force_on_j.x, f_n, 1e-6 * f_n);
  EXPECT_EQ(held.force_on_j.y, 0.0);
}

TEST(Contact, EdgeFaceFrictionKeepsTheHorizontalBoundAndLevelCells) {
  ContactConstants edge = iceContact();
  // Horizontal slip along the edge (j at 0.1 m/s in y), no bound: the edge face and the top faces
  // together resist it with mu (F_n + F_v) = 0.3 (23142.9 + 92571.4) = 34714.3 N.
  edge.friction_rate_limit = 1e300;
  const double f_n = 0.6 * 9e8 / 0.7 * 0.03 * 1e-3, f_v = 0.6 * 0.03 * 9e8 / 0.7 * 2e-4 / 0.05;
  EXPECT_NEAR(squaresSlipping(0.02, 0.1, 0.0, edge).force_on_j.y, -0.3 * (f_n + f_v), 1e-6 * f_v);
  // Level cells (F_v = 0, K = 1): F_n = 9e8/0.7 x 0.05 x 1e-3 = 64285.7 N, and one bound mu F_n on
  // the slip (0, 0.05, -0.1) of speed 0.111803 m/s: -0.3 F_n (0, 0.05, -0.1) / 0.111803 on j, that
  // is y -8624.7 N and z +17249.4 N (mu F_n / speed = 172498 N s/m, under the bound 1.85e5).
  const PairForce level = squaresSlipping(0.0, 0.05, -0.1, iceContact());
  const double f_level = 9e8 / 0.7 * 0.05 * 1e-3, speed = std::sqrt(0.05 * 0.05 + 0.1 * 0.1);
  EXPECT_NEAR(level.force_on_j.x, f_level, 1e-6 * f_level);
  EXPECT_NEAR(level.force_on_j.y, -0.3 * f_level * 0.05 / speed, 1e-6 * f_level);
  EXPECT_NEAR(level.fz_on_j, 0.3 * f_level * 0.1 / speed, 1e-6 * f_level);
  // With the bound of dt = 1e-6 s and a slow slip (1 cm/s in y and down), mu F_n / |slip| is far
  // above beta m_eff / dt: the edge face takes all of it and the top faces add nothing. m_eff from
  // the overlap's centroid (0.0995, 0), 0.0995 m from both centroids: 1/m_eff = 2 (1/m + r^2/I).
  const double m_eff = 1.0 / (2.0 * (1.0 / 1.84 + 0.0995 * 0.0995 / kSquareInertia));
  const double limit = 0.5 / 1e-6 * m_eff;  // [N s/m]
  const PairForce slow = squaresSlipping(0.02, 0.01, -0.01, iceContact());
  EXPECT_NEAR(slow.force_on_j.y, -limit * 0.01, 1e-6 * limit * 0.01);
  const double damped_f_v = f_v + 2.0 * 0.2 * std::sqrt(0.6 * 9e8 / 0.7 * 2e-4 / 0.05 * 0.92) * 0.01;
  EXPECT_NEAR(slow.fz_on_j, damped_f_v + limit * 0.01, 1e-6 * damped_f_v);
}

TEST(Contact, ANewPairCountsOnlyTheOverlapBeyondItsFirst) {
  // A pair that enters the list overlapping by S0 (a bond broke) pushes with nothing at first,
  // then with the overlap beyond S0; when the overlap shrinks, S_ref shrinks with it.
  const BodyState i = {{0.0, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  const BodyState j = {{0.19, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  const auto a = square({0.0, 0.0}, 0.2);
  const auto deep = square({0.19, 0.0}, 0.2), deeper = square({0.189, 0.0}, 0.2), shallow = square({0.195, 0.0}, 0.2);
  const PairForce first = demContactForce(intersectConvexPolygons(a.data(), 4, deep.data(), 4), i, j, iceContact(), -1.0);
  EXPECT_TRUE(first.touching);
  EXPECT_EQ(norm(first.force_on_j), 0.0);
  const double grid_bound = 2e-9;  // [m^2] perimeters x grid step of the integer clip (polygon_clip.hpp)
  EXPECT_NEAR(first.reference_area, 0.2 * 0.01, grid_bound);
  // 1 mm deeper: F = (9e8/0.7) 0.05 1e-3 = 64285.7 N, as for a fresh 1 mm overlap.
  const PairForce second =
      demContactForce(intersectConvexPolygons(a.data(), 4, deeper.data(), 4), i, j, iceContact(), first.reference_area);
  EXPECT_NEAR(second.force_on_j.x, 9e8 / 0.7 * 0.05 * 1e-3, 1e-5 * 64285.7);
  const PairForce third =
      demContactForce(intersectConvexPolygons(a.data(), 4, shallow.data(), 4), i, j, iceContact(), second.reference_area);
  EXPECT_NEAR(third.reference_area, 0.2 * 0.005, grid_bound);
  EXPECT_EQ(norm(third.force_on_j), 0.0);
}

TEST(Contact, SlabsOneAboveTheOtherDoNotTouchButKeepTheirReferenceOverlap) {
  // j 0.06 m above i (h = 0.05 m): Z = 0, so Eqs. (1) and (3), which both carry Z, give nothing,
  // though the squares overlap by S = 0.15 x 0.2 = 0.03 m^2 in plan. Not touching, no force.
  const auto a = square({0.0, 0.0}, 0.2), b = square({0.05, 0.0}, 0.2);
  const PolygonOverlap o = intersectConvexPolygons(a.data(), 4, b.data(), 4);
  ASSERT_NEAR(o.area, 0.03, 1e-9);
  const BodyState i = {{0.0, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  const BodyState j = {{0.05, 0.0}, 0.06, {0.02, -0.01}, -0.1, 0.3, 1.84, kSquareInertia};
  const PairForce apart = demContactForce(o, i, j, iceContact(), kNoReference);
  EXPECT_FALSE(apart.touching);
  EXPECT_EQ(apart.force_on_j.x, 0.0);
  EXPECT_EQ(apart.force_on_j.y, 0.0);
  EXPECT_EQ(apart.fz_on_j, 0.0);
  EXPECT_EQ(apart.reference_area, 0.0);  // none before, none after: the next touch counts all of S
  // A reference overlap follows S while one slab passes over the other, as for a touching pair:
  // 0.05 m^2 shrinks to S; a new pair (-1) takes S.
  EXPECT_EQ(demContactForce(o, i, j, iceContact(), 0.05).reference_area, o.area);
  EXPECT_EQ(demContactForce(o, i, j, iceContact(), 0.01).reference_area, 0.01);
  EXPECT_EQ(demContactForce(o, i, j, iceContact(), -1.0).reference_area, o.area);
  // Exactly one thickness apart is still apart (Z = 0); a micrometre less touches.
  EXPECT_FALSE(demContactForce(o, i, {j.centroid, 0.05, j.velocity, j.vz, j.wz, j.mass, j.inertia}, iceContact(),
                               kNoReference).touching);
  EXPECT_TRUE(demContactForce(o, i, {j.centroid, 0.05 - 1e-6, j.velocity, j.vz, j.wz, j.mass, j.inertia},
                              iceContact(), kNoReference).touching);
}

TEST(Contact, APairSkipsItsClipOnlyWhenTheClipCouldChangeNothing) {
  // contactSkipsClip lets the contact loops write "apart" without clipping: that must be what the
  // clip and the law would give. Random pairs of squares, overlapping or not, one slab at least a
  // thickness above the other, no reference overlap: the law gives not touching and S_ref = 0.
  const double h = iceContact().thickness;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> shift(-0.25, 0.25), turn(0.0, 1.5), rise(h, 3.0 * h);
  int overlapping = 0;
  for (int k = 0; k < 500; ++k) {
    std::vector<Vec2> a = square({0.0, 0.0}, 0.2), b = square({shift(random), shift(random)}, 0.2);
    const double yaw = turn(random), c = std::cos(yaw), s = std::sin(yaw);
    const Vec2 centre_b = 0.25 * (b[0] + b[1] + b[2] + b[3]);
    for (Vec2& v : b) v = centre_b + Vec2{c * (v.x - centre_b.x) - s * (v.y - centre_b.y), s * (v.x - centre_b.x) + c * (v.y - centre_b.y)};
    const double dz = (k % 2 == 0 ? 1.0 : -1.0) * rise(random);
    ASSERT_TRUE(contactSkipsClip(0.0, dz, h, 0.0));
    const PolygonOverlap o = intersectConvexPolygons(a.data(), 4, b.data(), 4);
    overlapping += o.area > 0.0 ? 1 : 0;
    const BodyState i = {{0.0, 0.0}, 0.0, {0.01, 0}, 0.02, 0.1, 1.84, kSquareInertia};
    const BodyState j = {centre_b, dz, {-0.03, 0.01}, -0.05, -0.2, 1.84, kSquareInertia};
    const PairForce f = demContactForce(o, i, j, iceContact(), 0.0);
    EXPECT_FALSE(f.touching) << "pair " << k;
    EXPECT_EQ(f.reference_area, 0.0) << "pair " << k;
  }
  EXPECT_GT(overlapping, 100) << "too few overlapping pairs: nothing was tested";
  // Not skipped: a vertical overlap (Z > 0), or a reference overlap to follow (new pair, S_ref > 0).
  EXPECT_FALSE(contactSkipsClip(0.0, 0.99 * h, h, 0.0));
  EXPECT_FALSE(contactSkipsClip(0.0, 2.0 * h, h, -1.0));
  EXPECT_FALSE(contactSkipsClip(0.0, 2.0 * h, h, 1e-4));
  EXPECT_TRUE(contactSkipsClip(0.3, 0.3 - 1.5 * h, h, 0.0));  // j below i
}

TEST(Friction, ViscousBranchIsBoundedSoThatAnExplicitStepCannotReverseTheSlip) {
  // mu N / v_reg = 0.3 * 1e4 / 1e-3 = 3e6 N s/m; with m_eff = 0.5 kg and dt = 5e-6 s an explicit
  // step multiplies the slip by 1 - 3e6 * 5e-6 / 0.5 = -29: it grows. Bounded by beta m / dt:
  const double mu = 0.3, normal = 1e4, v_reg = 1e-3, mass = 0.5, dt = 5e-6, beta = 0.5;
  EXPECT_NEAR(frictionScale(mu, normal, 1e-4, 0.0, 0.0, v_reg, 1e300), 3e6, 1e-6);
  EXPECT_NEAR(frictionScale(mu, normal, 1e-4, 0.0, 0.0, v_reg, beta * mass / dt), beta * mass / dt, 1e-9);
  // Above v_reg the Coulomb branch is untouched while below the bound: 0.3 * 1e4 / 10 = 300.
  EXPECT_NEAR(frictionScale(mu, normal, 10.0, 0.0, 0.0, v_reg, beta * mass / dt), 300.0, 1e-9);
  // A body sliding on a plane at 1 mm/s: unbounded, the first step throws the slip to -29 mm/s
  // and from then on it flips sign every step at mu N dt / m = 30 mm/s (a chatter that feeds
  // the yaw of a piece in a pile); bounded, it decays without changing sign.
  double unbounded = 1e-3, bounded = 1e-3, largest_unbounded = 0.0;
  int sign_flips = 0;
  for (int step = 0; step < 20; ++step) {
    const double next_unbounded =
        unbounded - frictionScale(mu, normal, unbounded, 0.0, 0.0, v_reg, 1e300) * unbounded * dt / mass;
    sign_flips += (next_unbounded < 0.0) != (unbounded < 0.0) ? 1 : 0;
    unbounded = next_unbounded;
    largest_unbounded = std::max(largest_unbounded, std::fabs(unbounded));
    const double next = bounded - frictionScale(mu, normal, bounded, 0.0, 0.0, v_reg, beta * mass / dt) * bounded * dt / mass;
    EXPECT_GE(next, 0.0);
    EXPECT_LT(next, bounded);
    bounded = next;
  }
  EXPECT_EQ(sign_flips, 20);
  EXPECT_GT(largest_unbounded, 20.0 * 1e-3);
  EXPECT_LT(bounded, 1e-3 * std::pow(0.5, 19));  // each step keeps at most 1 - beta of the slip
}

constexpr Vec2 kNoTurn = {1.0, 0.0};  // (cos 0, sin 0)

BondRest unitBond() {
  // Two 0.2 m cells side by side along x sharing an edge of 0.2 m; centroids 0.2 m apart.
  BondRest b;
  b.anchor_i = {0.1, 0.0};
  b.anchor_j = {-0.1, 0.0};
  b.normal = {1.0, 0.0};
  b.edge_length = 0.2;
  b.distance = 0.2;
  b.k_normal = 300e6 * 0.05 * 0.2 / 0.2;  // E h L_e / d
  b.k_shear = 0.4 * b.k_normal;
  b.k_vertical = 1e4;
  b.damping_normal = b.damping_shear = b.damping_vertical = 0.0;
  return b;
}

BondConstants bondLaw(double coupling) { return {0.05, 1.0, 1.0, 100e3, 130e3, coupling}; }

TEST(Bond, ItsSpringsFollowFromItsShapeAndTheMassesOfItsCells) {
  // Eqs. (11)-(12): k = modulus h L_e / d. h = 0.05 m, L_e = 0.2 m, d = 0.25 m: h L_e / d = 0.04 m.
  // E = 5e8 Pa, nu = 0.3: G = E / 2.6 = 1.9231e8 Pa; E_v = 1e8 Pa: G_v = 3.8462e7 Pa. So
  // k_n = 2e7, k_s = 7.6923e6 and k_v = 1.5385e6 N/m. Masses 2 and 3 kg: m_red = 1.2 kg; zeta = 0.1:
  // c = 0.2 sqrt(1.2 k) = 979.796, 607.644 and 271.746 N s/m.
  BondConstants c = bondLaw(0.0);
  c.youngs_modulus = 5e8;
  c.shear_modulus = 5e8 / 2.6;
  c.vertical_shear_modulus = 1e8 / 2.6;
  c.damping_ratio = 0.1;
  const BondShape shape = {{0.12, 0.01}, {-0.13, -0.02}, {0.6, 0.8}, 0.2, 0.25};
  const BondRest b = bondRestOf(shape, 2.0, 3.0, c);
  EXPECT_NEAR(b.k_normal, 2e7, 1e-12 * 2e7);
  EXPECT_NEAR(b.k_shear, 7.692307692307692e6, 1e-12 * 7.7e6);
  EXPECT_NEAR(b.k_vertical, 1.538461538461538e6, 1e-12 * 1.5e6);
  EXPECT_NEAR(b.damping_normal, 979.7958971132712, 1e-12 * 980.0);
  EXPECT_NEAR(b.damping_shear, 607.6436202502, 1e-12 * 608.0);
  EXPECT_NEAR(b.damping_vertical, 271.7464881947030, 1e-12 * 272.0);
  // Bit for bit what the model build computed inline before bondRestOf existed, in that order:
  // the CUDA backend makes the springs anew in every step and must get the CPU's records.
  const double bar = 0.05 * 0.2 / 0.25;
  const double k_normal = 5e8 * bar, k_shear = (5e8 / 2.6) * bar, k_vertical = (1e8 / 2.6) * bar;
  const double reduced_mass = 2.0 * 3.0 / (2.0 + 3.0), two_zeta = 2.0 * 0.1;
  EXPECT_EQ(b.k_normal, k_normal);
  EXPECT_EQ(b.k_shear, k_shear);
  EXPECT_EQ(b.k_vertical, k_vertical);
  EXPECT_EQ(b.damping_normal, two_zeta * std::sqrt(k_normal * reduced_mass));
  EXPECT_EQ(b.damping_shear, two_zeta * std::sqrt(k_shear * reduced_mass));
  EXPECT_EQ(b.damping_vertical, two_zeta * std::sqrt(k_vertical * reduced_mass));
  // The shape passes through unchanged.
  const BondShape& back = b;
  EXPECT_EQ(back.anchor_i.x, 0.12);
  EXPECT_EQ(back.anchor_j.y, -0.02);
  EXPECT_EQ(back.normal.y, 0.8);
  EXPECT_EQ(back.edge_length, 0.2);
  EXPECT_EQ(back.distance, 0.25);
}

TEST(Bond, PulledApartItBreaksAtTheFlexuralStrength) {
  // sigma_h = k_n u / (h L_e) = sigma_f at u = sigma_f h L_e / k_n = 1e5 * 0.01 / 1.5e7 = 6.667e-5 m.
  const BondRest b = unitBond();
  const double u_fail = 100e3 * 0.05 * 0.2 / b.k_normal;
  for (const double factor : {0.99, 1.01}) {
    const BodyState i = {{0.0, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
    const BodyState j = {{0.2 + factor * u_fail, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
    const BondForce f = rmibBondForce(b, i, kNoTurn, j, kNoTurn, bondLaw(0.0));
    EXPECT_NEAR(f.sigma_h, factor * 100e3, 1e-6 * 100e3);
    EXPECT_NEAR(f.force_on_j.x, -b.k_normal * factor * u_fail, 1e-6);  // pulls j back
    EXPECT_EQ(f.breaks, factor > 1.0);
  }
}

TEST(Bond, VerticalOffsetBreaksAtEquation13WithAndWithoutCompression) {
  // Bending reading: sigma_v = 3 |F_v| d / (L_e h^2), F_v = K_v k_v dz.
  const BondRest b = unitBond();
  const double h = 0.05;
  auto sigmaV = [&](double dz) { return 3.0 * (1.0 - dz / h) * b.k_vertical * dz * b.distance / (b.edge_length * h * h); };
  // Find dz with sigma_v = target by bisection on the closed form.
  auto offsetFor = [&](double target) {
    double lo = 0.0, hi = 0.5 * h;
    for (int k = 0; k < 200; ++k) ((sigmaV(0.5 * (lo + hi)) < target) ? lo : hi) = 0.5 * (lo + hi);
    return lo;
  };
  // No compression: threshold sigma_f.
  for (const double factor : {0.99, 1.01}) {
    const double dz = offsetFor(factor * 100e3);
    const BodyState i = {{0.0, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
    const BodyState j = {{0.2, 0.0}, dz, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
    EXPECT_EQ(rmibBondForce(b, i, kNoTurn, j, kNoTurn, bondLaw(0.5)).breaks, factor > 1.0);
  }
  // Compressed to sigma_c = 40 kPa with k = 0.5: threshold 100 - 20 = 80 kPa.
  const double squeeze = 40e3 * h * b.edge_length / b.k_normal;
  for (const double factor : {0.99, 1.01}) {
    const BodyState i = {{0.0, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
    // K_n also falls with the offset: compress a little more so that sigma_c is 40 kPa.
    const double dz = offsetFor(factor * 80e3);
    const BodyState j = {{0.2 - squeeze / (1.0 - dz / h), 0.0}, dz, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
    const BondForce f = rmibBondForce(b, i, kNoTurn, j, kNoTurn, bondLaw(0.5));
    EXPECT_NEAR(f.sigma_c, 40e3, 1e-6 * 40e3);
    EXPECT_EQ(f.breaks, factor > 1.0) << "factor " << factor;
  }
}

TEST(Bond, SpringsAndDampingFollowTheirOwnSmoothingExponents) {
  // j 0.02 m higher (z = 0.4 of h = 0.05 m), pulled 1e-5 m along x, moving at 0.01 m/s along x
  // and 0.02 m/s up; damping D = 100 N s/m on each spring. K_2(0.4) = 0.36, K_1(0.4) = 0.6;
  // the elastic force scales with K, the damping with sqrt(K):
  //   F_x on j = -(K_n k_n 1e-5 + sqrt(K_n) D 0.01),  F_z on j = -(K_v k_v 0.02 + sqrt(K_v) D 0.02).
  BondRest b = unitBond();
  b.damping_normal = b.damping_vertical = 100.0;
  const BodyState i = {{0.0, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  const BodyState j = {{0.2 + 1e-5, 0.0}, 0.02, {0.01, 0}, 0.02, 0.0, 1.84, kSquareInertia};
  struct Case { double n_h, n_v, k_n, k_v; };
  for (const Case& e : {Case{2.0, 1.0, 0.36, 0.6}, Case{1.0, 2.0, 0.6, 0.36}, Case{2.0, 2.0, 0.36, 0.36}}) {
    BondConstants law = bondLaw(0.0);
    law.exponent_h = e.n_h;
    law.exponent_v = e.n_v;
    const BondForce f = rmibBondForce(b, i, kNoTurn, j, kNoTurn, law);
    const double fx = -(e.k_n * b.k_normal * 1e-5 + std::sqrt(e.k_n) * 100.0 * 0.01);
    const double fz = -(e.k_v * b.k_vertical * 0.02 + std::sqrt(e.k_v) * 100.0 * 0.02);
    EXPECT_NEAR(f.force_on_j.x, fx, 1e-9 * std::fabs(fx)) << "n_h " << e.n_h << ", n_v " << e.n_v;
    EXPECT_NEAR(f.fz_on_j, fz, 1e-9 * std::fabs(fz)) << "n_h " << e.n_h << ", n_v " << e.n_v;
  }
}

TEST(Bond, TornThroughWhenTheCellsAreOffsetByTheWholeThickness) {
  // With |dz| >= h, K_n = K_v = 0: no stress of Eq. (13) is left to break it, but the cells share
  // no face any more; the bond breaks. Just below h, unstressed otherwise, it holds.
  const BondRest b = unitBond();
  const BodyState i = {{0.0, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  BondConstants law = bondLaw(0.0);
  law.flexural_strength = 1e12;  // only the offset can break it here
  const BodyState level_with_h = {{0.2, 0.0}, 0.05, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  const BodyState below_h = {{0.2, 0.0}, 0.0499, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  EXPECT_TRUE(rmibBondForce(b, i, kNoTurn, level_with_h, kNoTurn, law).breaks);
  EXPECT_FALSE(rmibBondForce(b, i, kNoTurn, below_h, kNoTurn, law).breaks);
}

TEST(Bond, TheVerticalStressIsTheBendingStressOfTheBar) {
  // F_v = 100 N on the unit bond (h = 0.05 m, L_e = 0.2 m, d = 0.2 m): M = 100 x d/2 = 10 N m,
  // sigma_v = 6 M / (L_e h^2) = 60 / (0.2 x 0.0025) = 1.2e5 Pa, whatever the sign of F_v.
  const BondRest b = unitBond();
  const BondConstants law = bondLaw(0.0);
  EXPECT_NEAR(verticalBondStress(-100.0, b, law), 1.2e5, 1e-5);
  EXPECT_NEAR(verticalBondStress(100.0, b, law), 1.2e5, 1e-5);
}

TEST(Bond, RigidTurnOfThePairGivesNoForce) {
  // Both cells turned by 0.3 rad about the bond's anchor point (the edge midpoint at x = 0.1):
  // nothing is stretched, so the force is zero (objectivity of du, n and the shear part).
  const BondRest b = unitBond();
  const double a = 0.3;
  const Vec2 turn = {std::cos(a), std::sin(a)};
  const Vec2 anchor = {0.1, 0.0};
  const Vec2 ci = anchor + rotate(Vec2{-0.1, 0.0}, turn.x, turn.y);
  const Vec2 cj = anchor + rotate(Vec2{0.1, 0.0}, turn.x, turn.y);
  const BodyState i = {ci, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  const BodyState j = {cj, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  const BondForce f = rmibBondForce(b, i, turn, j, turn, bondLaw(0.0));
  EXPECT_NEAR(norm(f.force_on_j), 0.0, 1e-9);
  // A relative turn of j alone by 0.01 rad about its centroid shears the bond: force along y.
  const Vec2 small = {std::cos(0.01), std::sin(0.01)};
  const BodyState j0 = {{0.2, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  const BodyState i0 = {{0.0, 0.0}, 0.0, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia};
  const BondForce g = rmibBondForce(b, i0, kNoTurn, j0, small, bondLaw(0.0));
  // The anchor of j moves by -0.1 * (cos 0.01 - 1, sin 0.01) ~ (5e-6, -1e-3): shear pulls j up.
  EXPECT_GT(g.force_on_j.y, 0.9 * b.k_shear * 0.1 * std::sin(0.01));
}

TEST(PlaneContact, VerticalPlaneVolumeByHand) {
  // Square 0.2 m slab, h = 0.05, 1 mm beyond the plane x = 0.099 (solid x > 0.099):
  // V = 0.2 * 0.001 * 0.05 = 1e-5 m^3, centroid x = 0.0995.
  const auto poly = square({0.0, 0.0}, 0.2);
  const RigidPlane plane = {-1.0, 0.0, 0.0, -0.099};
  const SlabPenetration p = slabPenetration(poly.data(), 4, -0.025, 0.025, plane);
  EXPECT_NEAR(p.volume, 1e-5, 1e-15);
  EXPECT_NEAR(p.centroid.x, 0.0995, 1e-12);
  EXPECT_NEAR(p.centroid.y, 0.0, 1e-12);
}

TEST(PlaneContact, TwelveGonCutToAPanelStripStillIntegratesAndOversizeInputIsRefused) {
  // A regular 12-gon of circumradius 0.1 cut to the strip |y| <= 0.05 has 14 vertices at most;
  // behind the vertical plane x = 0 (solid x > 0) half of the strip's area lies in the solid.
  std::vector<Vec2> dodecagon;
  for (int k = 0; k < 12; ++k) dodecagon.push_back({0.1 * std::cos(k * M_PI / 6 + 0.1), 0.1 * std::sin(k * M_PI / 6 + 0.1)});
  Vec2 half[kMaxSlabVertices], strip[kMaxSlabVertices];
  const int na = clipPolygonByHalfPlane(dodecagon.data(), 12, 0.0, 1.0, 0.05, half);
  const int nb = clipPolygonByHalfPlane(half, na, 0.0, -1.0, 0.05, strip);
  ASSERT_LE(nb, kMaxSlabVertices);
  const double strip_area = polygonArea(strip, nb);
  const RigidPlane plane = {-1.0, 0.0, 0.0, 0.0};
  const SlabPenetration p = slabPenetration(strip, nb, -0.025, 0.025, plane);
  // The strip is symmetric about x = 0 only approximately (the 12-gon is turned by 0.1 rad):
  // compare with the area of the part x > 0 computed by one more clip.
  Vec2 right[kMaxSlabVertices + 1];
  const int nr = clipPolygonByHalfPlane(strip, nb, -1.0, 0.0, 0.0, right);
  EXPECT_NEAR(p.volume, polygonArea(right, nr) * 0.05, 1e-15);
  EXPECT_GT(p.volume, 0.3 * strip_area * 0.05);
  std::vector<Vec2> too_many(kMaxSlabVertices + 1, Vec2{0.0, 0.0});
  for (int k = 0; k <= kMaxSlabVertices; ++k) too_many[k] = {std::cos(k * 0.4), std::sin(k * 0.4)};
  EXPECT_EQ(slabPenetration(too_many.data(), kMaxSlabVertices + 1, -0.025, 0.025, plane).volume, 0.0);
}

TEST(PlaneContact, InclinedFaceVolumeByHandAndForceNormalToIt) {
  // Face at 60 deg through x = 0.1 at z = 0, solid towards +x: m = (-sin 60, 0, cos 60).
  // A square slab [-0.1, 0.1]^2 x [-0.025, 0.025]: at level z the face is at x = 0.1 + z cot 60,
  // so the cut area is 0.2 * max(0, -z cot 60) for z < 0: V = 0.2 cot60 * 0.025^2 / 2.
  const double a = M_PI / 3.0;
  const RigidPlane face = {-std::sin(a), 0.0, std::cos(a), -std::sin(a) * 0.1};
  const auto poly = square({0.0, 0.0}, 0.2);
  const SlabPenetration p = slabPenetration(poly.data(), 4, -0.025, 0.025, face);
  const double expected = 0.2 / std::tan(a) * 0.025 * 0.025 / 2.0;
  EXPECT_NEAR(p.volume, expected, 1e-12 * expected + 1e-18);
  // At rest, the force is K V / h along m: normal to the face, pushing the ice back and up.
  const PlaneContactConstants law = {1.7e11, 0.05, 0.1, 0.2, 1e-3, 0.5 / 4e-6};
  const PlaneContactForce f = planeContactForce(p, face, law, {0, 0}, {0, 0}, 0.0, 0.0, 1.84, kSquareInertia, 0.04, 0.0);
  const double magnitude = 1.7e11 * expected / 0.05;
  EXPECT_NEAR(f.fx, magnitude * face.mx, 1e-9 * magnitude);
  EXPECT_NEAR(f.fy, 0.0, 1e-9 * magnitude);
  EXPECT_NEAR(f.fz, magnitude * face.mz, 1e-9 * magnitude);
  EXPECT_LT(f.fx, 0.0);
  EXPECT_GT(f.fz, 0.0);
}

}  // namespace
}  // namespace thin_ice
