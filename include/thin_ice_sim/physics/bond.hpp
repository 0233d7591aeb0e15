// RMIB static bonds between cells that share a Voronoi edge at t = 0, paper Eqs. (8)-(13), read
// as this project reads them (docs/model.md).
//   anchors   p_i = c_i + R(theta_i) a_i, p_j = c_j + R(theta_j) a_j (the edge midpoint at t = 0)
//   Eq. (8)   du = p_j - p_i (horizontal), dz = z_j - z_i
//   Eq. (9)   u_n = du . n, n = rest normal turned by the mean yaw of the pair
//   Eq. (10)  u_s = du - u_n n
//   Eq. (11-12) F_h = K_n(z) k_n u_n (tension > 0), F_s = k_s u_s, F_v = K_v(z) k_v dz
//             k_n = E h L_e / d, k_s = G h L_e / d, k_v = G_v h L_e / d (bar of section h L_e)
//   Eq. (13)  broken for good when sigma_v > sigma_f - k sigma_c, or sigma_h > sigma_f, or
//             sigma_c > sigma_comp; sigma_h = F_h/(h L_e), sigma_c = max(0, -F_h)/(h L_e), and
//             sigma_v = 6 M/(L_e h^2) with M = |F_v| d/2, the bending stress of a bar clamped
//             between the centroids (docs/model.md: a departure from the paper's |F_v|/(h L_e),
//             chosen by runs)
// Damping (ratio zeta of critical) acts on the anchor velocities; stresses use the elastic forces.
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/contact.hpp"
#include "thin_ice_sim/physics/host_device.hpp"
#include "thin_ice_sim/physics/integrate.hpp"
#include "thin_ice_sim/physics/smoothing.hpp"
#include "thin_ice_sim/physics/vec2.hpp"

namespace thin_ice {

/// A bond's own geometry, fixed at t = 0.
struct BondShape {
  Vec2 anchor_i;        ///< [m] edge midpoint relative to i's centroid, body frame of i
  Vec2 anchor_j;        ///< [m] edge midpoint relative to j's centroid, body frame of j
  Vec2 normal;          ///< unit, from i towards j, world frame at t = 0 (yaw 0)
  double edge_length;   ///< L_e [m]
  double distance;      ///< d_ij [m], centroid to centroid at t = 0
};

/// What a bond remembers from t = 0: its shape (64 B) and the springs that follow from it (48 B
/// more; bondRestOf).
struct BondRest : BondShape {
  double k_normal;      ///< k_n [N/m]
  double k_shear;       ///< k_s [N/m]
  double k_vertical;    ///< k_v [N/m]
  // Damping coefficients 2 zeta sqrt(k m_red) of the three springs at K = 1 [N s/m], precomputed
  // (m_red = m_i m_j / (m_i + m_j)); the smoothing factor K scales them by sqrt(K).
  double damping_normal;
  double damping_shear;
  double damping_vertical;
};

/// Characteristic length l = [E h^3 / (12 (1 - nu^2) rho_w g)]^(1/4) [m] of a floating plate.
inline double floatingPlateLength(double youngs_modulus, double poisson_ratio, double thickness,
                                  double water_density, double gravity) {
  return pow(youngs_modulus * thickness * thickness * thickness /
                 (12.0 * (1.0 - poisson_ratio * poisson_ratio) * water_density * gravity),
             0.25);
}

/// The vertical modulus E_v [Pa] whose sheet of vertical shear springs, G_v h per unit of area
/// with G_v = E_v / (2 (1 + nu)), has the floating plate's length l: G_v = rho_w g l^2 / h. The
/// scenarios take E_v as a multiple of it (docs/model.md, "The choice of E_v").
inline double floatingPlateVerticalModulus(double youngs_modulus, double poisson_ratio, double thickness,
                                           double water_density, double gravity) {
  const double l = floatingPlateLength(youngs_modulus, poisson_ratio, thickness, water_density, gravity);
  return 2.0 * (1.0 + poisson_ratio) * water_density * gravity * l * l / thickness;
}

/// Arm [m] of the floating plate's largest moment under an edge line load P: M_max = e^(-pi/4) P l,
/// 1.11 l from the edge (semi-infinite beam on an elastic foundation). The edge check's
/// P_crit = sigma_f h^2 / (6 arm) takes it from here.
inline double floatingPlateMomentArm(double youngs_modulus, double poisson_ratio, double thickness,
                                     double water_density, double gravity) {
  const double e_minus_pi_over_4 = 0.45593812776599624;  // exp(-pi/4)
  return e_minus_pi_over_4 * floatingPlateLength(youngs_modulus, poisson_ratio, thickness, water_density, gravity);
}

struct BondConstants {
  double thickness;             ///< h [m]
  double exponent_h;            ///< n of K_n [-]
  double exponent_v;            ///< n of K_v [-]
  double flexural_strength;     ///< sigma_f [Pa]
  double compressive_strength;  ///< sigma_comp [Pa]
  double compression_coupling;  ///< k of Eq. (13) [-]
  // What the springs of Eqs. (11)-(12) are made of (bondRestOf).
  double youngs_modulus;          ///< E [Pa], of k_n
  double shear_modulus;           ///< G = E / (2 (1 + nu)) [Pa], of k_s
  double vertical_shear_modulus;  ///< G_v = E_v / (2 (1 + nu)) [Pa], of k_v
  double damping_ratio;           ///< zeta [-] of the three springs
};

/// A bond's rest record from its shape and the masses of its two cells [kg]: the springs of
/// Eqs. (11)-(12), k = modulus x h L_e / d (a bar of section h L_e and length d), and their
/// damping 2 zeta sqrt(k m_red), m_red = m_i m_j / (m_i + m_j). The model's records are made
/// here. The CUDA backend makes each again in every step from the 64 B shape rather than read
/// the 112 B record: the same operations (products, quotients, square roots, no sums of
/// products for a compiler to fuse), so the same bits.
TIS_HD BondRest bondRestOf(const BondShape& s, double mass_i, double mass_j, const BondConstants& c) {
  BondRest b;
  static_cast<BondShape&>(b) = s;
  const double bar = c.thickness * s.edge_length / s.distance;  // section over length [m]
  b.k_normal = c.youngs_modulus * bar;
  b.k_shear = c.shear_modulus * bar;
  b.k_vertical = c.vertical_shear_modulus * bar;
  const double reduced_mass = mass_i * mass_j / (mass_i + mass_j);
  const double two_zeta = 2.0 * c.damping_ratio;
  b.damping_normal = two_zeta * sqrt(b.k_normal * reduced_mass);
  b.damping_shear = two_zeta * sqrt(b.k_shear * reduced_mass);
  b.damping_vertical = two_zeta * sqrt(b.k_vertical * reduced_mass);
  return b;
}


struct BondForce {
  Vec2 force_on_j;     ///< [N]; i gets the opposite
  double fz_on_j;      ///< [N]
  Vec2 arm_i;          ///< [m] anchor of i relative to i's centroid, world frame (moment arm)
  Vec2 arm_j;          ///< [m]
  double sigma_h;      ///< [Pa] horizontal (tensile > 0) stress
  double sigma_v;      ///< [Pa] vertical stress
  double sigma_c;      ///< [Pa] current compressive stress
  bool breaks;         ///< Eq. (13) met in this step
};

/// Life of a bond, one byte per bond. A bond that breaks still applies the force of the step in
/// which it broke (kBondBreaking); from the next step on it is gone for good (kBondBroken).
/// Any state other than kBondIntact counts as broken for contacts and for output.
enum BondState : unsigned char { kBondIntact = 0, kBondBreaking = 1, kBondBroken = 2 };

/// The rest normal n of Eq. (9) turned by the pair's mean yaw: the bisector of its two turned
/// copies (exact for |yaw_i - yaw_j| < pi, and one square root instead of a sine and a cosine).
TIS_HD Vec2 turnedBondNormal(Vec2 rest_normal, Vec2 turn_i, Vec2 turn_j) {
  const Vec2 sum = rotate(rest_normal, turn_i.x, turn_i.y) + rotate(rest_normal, turn_j.x, turn_j.y);
  return (1.0 / norm(sum)) * sum;
}

/// The load of a bond force on its two cells: the moments act through the anchors.
TIS_HD PairLoad bondLoad(const BondForce& f) {
  return {f.force_on_j, f.fz_on_j, {cross(f.arm_i, -f.force_on_j), cross(f.arm_j, f.force_on_j)}};
}

/// sigma_v of Eq. (13) [Pa]: 6 M / (L_e h^2) with M = |F_v| d / 2, the surface stress of a bar of
/// section L_e x h clamped at both centroids and offset by F_v. The paper's words give |F_v| / (h L_e);
/// on weak-ice strips that reading carried the same load but let the sheet slide to the toe instead
/// of failing in front of its rubble (docs/model.md, "Readings tried and rejected").
TIS_HD double verticalBondStress(double vertical_force, const BondRest& b, const BondConstants& c) {
  const double h = c.thickness;
  return 3.0 * fabs(vertical_force) * b.distance / (b.edge_length * h * h);
}

/// Eq. (13) with the pure-compression limit (docs/model.md), and torn through when the cells are
/// offset vertically by the whole thickness (|dz| >= h: no face left in common; K_n = K_v = 0
/// there, so Eq. (13) alone would keep such a bond, carrying shear, for ever).
/// sigma_comp of Eq. (13)'s vertical threshold is the bond's present compression sigma_c (docs/model.md:
/// with k ~ sigma_f / sigma_comp, the paper's reading of k, a constant compressive strength there
/// would leave a threshold of zero for every bond).
TIS_HD bool bondFails(double sigma_h, double sigma_v, double sigma_c, double vertical_offset,
                      const BondConstants& c) {
  // | rather than ||: all four are cheap and have no side effect, and without short-circuit jumps
  // the CPU's bond pass vectorises (src/core/cpu_bond_pass.cpp).
  return (fabs(vertical_offset) >= c.thickness) | (sigma_h > c.flexural_strength) |
         (sigma_v > c.flexural_strength - c.compression_coupling * sigma_c) |
         (sigma_c > c.compressive_strength);
}

/// Force of bond b between cells i and j; turn_i = (cos yaw_i, sin yaw_i), likewise turn_j
/// (computed once per cell and step by the caller).
TIS_HD BondForce rmibBondForce(const BondRest& b, const BodyState& i, Vec2 turn_i, const BodyState& j,
                               Vec2 turn_j, const BondConstants& c) {
  BondForce f;
  f.arm_i = rotate(b.anchor_i, turn_i.x, turn_i.y);
  f.arm_j = rotate(b.anchor_j, turn_j.x, turn_j.y);
  const Vec2 n = turnedBondNormal(b.normal, turn_i, turn_j);

  const Vec2 du = (j.centroid + f.arm_j) - (i.centroid + f.arm_i);            // Eq. (8)
  const double dz = j.z - i.z;
  const double u_n = dot(du, n);                                              // Eq. (9)
  const Vec2 u_s = du - u_n * n;                                              // Eq. (10)

  const double offset = fabs(dz) / c.thickness;
  // Every ice type of Table 1 has one exponent for both: K_v and its root are then K_n's (hot loop).
  const bool same_exponent = c.exponent_v == c.exponent_h;
  const double k_h = smoothing(offset, c.exponent_h);
  const double k_v = same_exponent ? k_h : smoothing(offset, c.exponent_v);
  // K scales the bond's springs, as Eqs. (1) and (3) write it into the forces (docs/model.md).
  const double root_k_h = k_h == 1.0 ? 1.0 : sqrt(k_h);  // the damping scales with sqrt(K)
  const double root_k_v = same_exponent ? root_k_h : (k_v == 1.0 ? 1.0 : sqrt(k_v));
  const double elastic_h = k_h * b.k_normal * u_n;                            // Eqs. (11)-(12)
  const Vec2 elastic_s = b.k_shear * u_s;
  const double elastic_v = k_v * b.k_vertical * dz;

  // Damping on the anchor velocities.
  const Vec2 w = (j.velocity + j.wz * perpendicular(f.arm_j)) - (i.velocity + i.wz * perpendicular(f.arm_i));
  const double w_n = dot(w, n);
  const Vec2 w_s = w - w_n * n;
  const double damping_h = root_k_h * b.damping_normal * w_n;
  const Vec2 damping_s = b.damping_shear * w_s;
  const double damping_v = root_k_v * b.damping_vertical * (j.vz - i.vz);

  // The bond pulls j back towards i: force on j opposes the displacement.
  f.force_on_j = -((elastic_h + damping_h) * n + elastic_s + damping_s);
  f.fz_on_j = -(elastic_v + damping_v);

  const double section = c.thickness * b.edge_length;                        // Eq. (13)
  f.sigma_h = elastic_h / section;
  f.sigma_c = elastic_h < 0.0 ? -f.sigma_h : 0.0;  // the same quotient, negated exactly
  f.sigma_v = verticalBondStress(elastic_v, b, c);
  f.breaks = bondFails(f.sigma_h, f.sigma_v, f.sigma_c, dz, c);
  return f;
}

}  // namespace thin_ice
