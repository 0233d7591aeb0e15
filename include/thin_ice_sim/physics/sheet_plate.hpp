// Plate bending of the bonded sheet: the optional key `ice.plate_bending` (beyond the paper and
// SPEC-NOTES; docs/model.md, "Plate bending").
//
// Why: cells have no pitch or roll and their vertical bonds are shear springs (Eqs. 11-12), so the
// intact sheet carries no bending moment. On water it obeys G_v h lap(w) = rho_w g w where nothing
// presses on it, its curvature is w / l^2, and it bends sharply at every free edge, where a real
// plate carries no moment at all (docs/validation/calibration.md, 2026-12-03). This term adds the
// moment of a Kirchhoff plate, with the cells' heights as its only unknowns, so the model keeps its
// four degrees of freedom per cell.
//
// The energy, from the curvature of sheet_curvature.hpp across each intact bond b = (i, j):
//   U = sum_b 1/2 D' A_b kappa_b^2,   kappa_b = (g_j - g_i) . n_b / d_b,   A_b = L_b d_b / 2
// with g the cells' least-squares height gradients, n_b the bond's turned normal, d_b its rest
// length, L_b its edge length (A_b is the bond's share of the sheet: the Voronoi diamond of the two
// centroids and the edge, which tile the sheet). D' = 8 D / 3 with D = E h^3 / (12 (1 - nu^2)):
// kappa_b is the curvature along the bond's direction theta, kappa_b = kappa cos^2(theta) in
// cylindrical bending, and cos^4 averages to 3/8 over directions that are spread evenly (a
// hexagonal lattice's three, or a random Voronoi mesh's), so that the sum gives a plate's
// D kappa^2 / 2 per unit area. In the twisting term the sum acts as a plate of Poisson ratio 1/3,
// not nu; cylindrical bending, the bend of a sheet against a straight structure, is exact.
//
// The force on cell m, -dU/dz_m, with the horizontal geometry held (small slopes; the cells move
// millimetres in a step): g_k = P_k sum_j r_kj (z_j - z_k) over k's intact bonds, r_kj = c_j - c_k
// (P_k = (sum r r^T)^-1, or 1/trace on a line, heightGradientFit), so
//   mu_k = dU/dg_k = sum over k's intact bonds of +-q_b (+ where k is j),  q_b = D' L_b kappa_b n_b / 2
//   nu_k = P_k mu_k                                                        [N/m]
//   F_m  = sum over m's intact bonds to k of (nu_k + nu_m) . (c_k - c_m)   [N]
// The forces of every pair of cells cancel, so the sheet's total vertical force is 0, and a plane
// (tilted or not) has kappa = 0 and no force.
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/bond.hpp"
#include "thin_ice_sim/physics/host_device.hpp"
#include "thin_ice_sim/physics/integrate.hpp"
#include "thin_ice_sim/physics/sheet_curvature.hpp"
#include "thin_ice_sim/physics/vec2.hpp"

namespace thin_ice {

/// D' = 8 D / 3 [N m], D = E h^3 / (12 (1 - nu^2)): the plate stiffness the bond sum needs for
/// cylindrical bending (file comment).
inline double plateBondStiffness(double youngs_modulus, double poisson_ratio, double thickness) {
  const double plate = youngs_modulus * thickness * thickness * thickness / (12.0 * (1.0 - poisson_ratio * poisson_ratio));
  return 8.0 * plate / 3.0;
}

/// Energy 1/2 D' A_b kappa_b^2 [J] of one bond (for tests and diagnostics; the step uses q_b).
TIS_HD double plateBondEnergy(double stiffness, Vec2 gradient_i, Vec2 gradient_j, Vec2 n, double distance,
                              double edge_length) {
  const double kappa = curvatureAcrossBond(gradient_i, gradient_j, n, distance);
  return 0.5 * stiffness * 0.5 * edge_length * distance * kappa * kappa;
}

/// q_b = dU/dg_j = -dU/dg_i = D' L_b kappa_b n_b / 2 [N m] of one bond.
TIS_HD Vec2 plateBondMoment(double stiffness, Vec2 gradient_i, Vec2 gradient_j, Vec2 n, double distance,
                            double edge_length) {
  const double kappa = curvatureAcrossBond(gradient_i, gradient_j, n, distance);
  return (0.5 * stiffness * edge_length * kappa) * n;
}

/// q_b of bond b from its rest data, its cells' turns (cos yaw, sin yaw) and height gradients.
TIS_HD Vec2 bondPlateMoment(double stiffness, const BondRest& b, Vec2 turn_i, Vec2 turn_j, Vec2 gradient_i,
                            Vec2 gradient_j) {
  return plateBondMoment(stiffness, gradient_i, gradient_j, turnedBondNormal(b.normal, turn_i, turn_j), b.distance,
                         b.edge_length);
}

/// nu_k = P_k mu_k [N/m] of cell k from the q_b of its intact bonds (incidence lists of
/// incidence.hpp, taken in their order) and its fit's P_k.
TIS_HD Vec2 cellPlateMoment(int k, const int* offsets, const int* entries, const unsigned char* state,
                            const Vec2* bond_moment, const SymmetricMatrix2& inverse) {
  Vec2 mu = {0.0, 0.0};
  for (int e = offsets[k]; e < offsets[k + 1]; ++e) {
    const int b = entries[e] >> 1;
    if (state[b] != kBondIntact) continue;
    const double sign = (double)(2 * (entries[e] & 1) - 1);
    mu = mu + sign * bond_moment[b];
  }
  return inverse * mu;
}

/// F_m [N], upward, on cell m from its and its bonded neighbours' nu (cellPlateMoment).
TIS_HD double cellPlateForce(int m, const int* offsets, const int* entries, const unsigned char* state,
                             const int* bond_i, const int* bond_j, const CellMotion* motion, const Vec2* moment) {
  double force = 0.0;
  const CellMotion& self = motion[m];
  for (int e = offsets[m]; e < offsets[m + 1]; ++e) {
    const int b = entries[e] >> 1;
    if (state[b] != kBondIntact) continue;
    const int k = (entries[e] & 1) ? bond_i[b] : bond_j[b];
    const CellMotion& other = motion[k];
    force += dot(moment[k] + moment[m], Vec2{other.x - self.x, other.y - self.y});
  }
  return force;
}

}  // namespace thin_ice
