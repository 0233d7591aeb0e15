// RMIB static bonds between cells that share a Voronoi edge at t = 0, paper Eqs. (8)-(13), read
// as SPEC-NOTES fixes them.
//   anchors   p_i = c_i + R(theta_i) a_i, p_j = c_j + R(theta_j) a_j (the edge midpoint at t = 0)
//   Eq. (8)   du = p_j - p_i (horizontal), dz = z_j - z_i
//   Eq. (9)   u_n = du . n, n = rest normal turned by the mean yaw of the pair
//   Eq. (10)  u_s = du - u_n n
//   Eq. (11-12) F_h = K_n(z) k_n u_n (tension > 0), F_s = k_s u_s, F_v = K_v(z) k_v dz
//             k_n = E h L_e / d, k_s = G h L_e / d, k_v = G_v h L_e / d (bar of section h L_e)
//   Eq. (13)  broken for good when sigma_v > sigma_f - k sigma_c, or sigma_h > sigma_f, or
//             sigma_c > sigma_comp; sigma_h = F_h/(h L_e), sigma_c = max(0, -F_h)/(h L_e), sigma_v
//             from F_v by the chosen model (shear: |F_v|/(h L_e); bending: 6 M/(L_e h^2), M = |F_v| d/2)
// Damping (ratio zeta of critical) acts on the anchor velocities; stresses use the elastic forces.
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/contact.hpp"
#include "thin_ice_sim/physics/host_device.hpp"
#include "thin_ice_sim/physics/smoothing.hpp"
#include "thin_ice_sim/physics/vec2.hpp"

namespace thin_ice {

/// What a bond remembers from t = 0.
struct BondRest {
  Vec2 anchor_i;        ///< [m] edge midpoint relative to i's centroid, body frame of i
  Vec2 anchor_j;        ///< [m] edge midpoint relative to j's centroid, body frame of j
  Vec2 normal;          ///< unit, from i towards j, world frame at t = 0 (yaw 0)
  double edge_length;   ///< L_e [m]
  double distance;      ///< d_ij [m], centroid to centroid at t = 0
  double k_normal;      ///< k_n [N/m]
  double k_shear;       ///< k_s [N/m]
  double k_vertical;    ///< k_v [N/m]
};

struct BondConstants {
  double thickness;             ///< h [m]
  double exponent_h;            ///< n of K_n [-]
  double exponent_v;            ///< n of K_v [-]
  double flexural_strength;     ///< sigma_f [Pa]
  double compressive_strength;  ///< sigma_comp [Pa]
  double compression_coupling;  ///< k of Eq. (13) [-]
  bool bending_stress;          ///< sigma_v from the clamped-beam moment (true) or F_v/(h L_e)
  double damping_ratio;         ///< zeta [-]
};

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

/// Bending or shear reading of sigma_v (SPEC-NOTES, "RMIB bonds").
TIS_HD double verticalBondStress(double vertical_force, const BondRest& b, const BondConstants& c) {
  const double h = c.thickness;
  if (c.bending_stress) return 3.0 * fabs(vertical_force) * b.distance / (b.edge_length * h * h);
  return fabs(vertical_force) / (h * b.edge_length);
}

/// Eq. (13) with the pure-compression limit of SPEC-NOTES.
TIS_HD bool bondFails(double sigma_h, double sigma_v, double sigma_c, const BondConstants& c) {
  return sigma_h > c.flexural_strength ||
         sigma_v > c.flexural_strength - c.compression_coupling * sigma_c ||
         sigma_c > c.compressive_strength;
}

TIS_HD BondForce rmibBondForce(const BondRest& b, const BodyState& i, double yaw_i, const BodyState& j,
                               double yaw_j, const BondConstants& c) {
  BondForce f;
  f.arm_i = rotate(b.anchor_i, cos(yaw_i), sin(yaw_i));
  f.arm_j = rotate(b.anchor_j, cos(yaw_j), sin(yaw_j));
  const double mean_yaw = 0.5 * (yaw_i + yaw_j);
  const Vec2 n = rotate(b.normal, cos(mean_yaw), sin(mean_yaw));

  const Vec2 du = (j.centroid + f.arm_j) - (i.centroid + f.arm_i);            // Eq. (8)
  const double dz = j.z - i.z;
  const double u_n = dot(du, n);                                              // Eq. (9)
  const Vec2 u_s = du - u_n * n;                                              // Eq. (10)

  const double offset = fabs(dz) / c.thickness;
  const double k_h = smoothing(offset, c.exponent_h);
  const double k_v = smoothing(offset, c.exponent_v);
  const double elastic_h = k_h * b.k_normal * u_n;                            // Eqs. (11)-(12)
  const Vec2 elastic_s = b.k_shear * u_s;
  const double elastic_v = k_v * b.k_vertical * dz;

  // Damping on the anchor velocities.
  const double reduced_mass = i.mass * j.mass / (i.mass + j.mass);
  const Vec2 w = (j.velocity + j.wz * perpendicular(f.arm_j)) - (i.velocity + i.wz * perpendicular(f.arm_i));
  const double w_n = dot(w, n);
  const Vec2 w_s = w - w_n * n;
  const double two_zeta = 2.0 * c.damping_ratio;
  const double damping_h = two_zeta * sqrt(k_h * b.k_normal * reduced_mass) * w_n;
  const Vec2 damping_s = (two_zeta * sqrt(b.k_shear * reduced_mass)) * w_s;
  const double damping_v = two_zeta * sqrt(k_v * b.k_vertical * reduced_mass) * (j.vz - i.vz);

  // The bond pulls j back towards i: force on j opposes the displacement.
  f.force_on_j = -((elastic_h + damping_h) * n + elastic_s + damping_s);
  f.fz_on_j = -(elastic_v + damping_v);

  const double section = c.thickness * b.edge_length;                        // Eq. (13)
  f.sigma_h = elastic_h / section;
  f.sigma_c = elastic_h < 0.0 ? -elastic_h / section : 0.0;
  f.sigma_v = verticalBondStress(elastic_v, b, c);
  f.breaks = bondFails(f.sigma_h, f.sigma_v, f.sigma_c, c);
  return f;
}

}  // namespace thin_ice
