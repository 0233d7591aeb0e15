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
// The plate is Lagrangian: its geometry is the sheet's at rest, turned with the cells. Each intact
// bond b = (i, j) gives the offset o_b = d_b n_b from i's centroid to j's (d_b the rest length,
// n_b the turned normal of Eq. 9), so two cells that have slid over each other in a pile still sit
// d_b apart for the plate (with the cells' current centroids such a pair gave a fit of 3e5 1/m^2
// and a force of 2.7e7 N in the first step of a resumed run).
//   g_k     = P_k sum_j r_kj (z_j - z_k) over k's intact bonds, r_kj = +o_b where k is i, -o_b where
//             k is j; P_k = (sum r r^T)^-1, or 1/trace on a line (heightGradientInverse) [-]
//   kappa_b = (g_j - g_i) . n_b / d_b                                       [1/m]
//   U       = sum_b 1/2 D' A_b kappa_b^2,  A_b = L_b d_b / 2                 [J]
// A_b is the bond's share of the sheet: the diamond of the two centroids and the shared edge (L_b
// long); these tile the sheet. D' = 8 D / 3 with D = E h^3 / (12 (1 - nu^2)): kappa_b is the
// curvature along the bond's direction theta, kappa cos^2(theta) in cylindrical bending, and cos^4
// averages to 3/8 over directions that are spread evenly (a hexagonal lattice's three, or a random
// Voronoi mesh's), so the sum is a plate's D kappa^2 / 2 per unit area. In the twisting term the
// sum acts as a plate of Poisson ratio 1/3, not nu; cylindrical bending, the bend of a sheet
// against a straight structure, is exact.
//
// The force on cell m, -dU/dz_m, with the geometry (the offsets, so the yaws) held over the step:
//   mu_k = dU/dg_k = sum over k's intact bonds of +-q_b (+ where k is j),  q_b = D' L_b kappa_b n_b / 2
//   nu_k = P_k mu_k                                                        [N/m]
//   F_m  = sum over m's intact bonds to k of (nu_k + nu_m) . r_mk           [N]
// The forces of every pair of cells cancel, so the sheet's total vertical force is 0, and heights
// on a plane over the offsets (tilted or not) have kappa = 0 and no force.
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/bond.hpp"
#include "thin_ice_sim/physics/host_device.hpp"
#include "thin_ice_sim/physics/integrate.hpp"
#include "thin_ice_sim/physics/sheet_curvature.hpp"
#include "thin_ice_sim/physics/vec2.hpp"

namespace thin_ice {

/// det / trace^2 of a cell's sum r r^T at or below which the plate's fit is solved along a line.
/// The plate's stiffness at a cell grows as P^2, and P as 1 / (det / trace^2): a cell left with two
/// intact bonds a few degrees apart (det / trace^2 = sin^2(angle) / 4 for two) would be stiffer
/// than the time step of the ice can follow. At 0.05 two bonds must be at least 26.6 degrees apart;
/// an intact cell with its neighbours all round has 1/4, a cell on the sheet's edge about 0.2.
constexpr double kPlateFitConditioning = 0.05;

/// D' = 8 D / 3 [N m], D = E h^3 / (12 (1 - nu^2)): the plate stiffness the bond sum needs for
/// cylindrical bending (file comment).
inline double plateBondStiffness(double youngs_modulus, double poisson_ratio, double thickness) {
  const double plate = youngs_modulus * thickness * thickness * thickness / (12.0 * (1.0 - poisson_ratio * poisson_ratio));
  return 8.0 * plate / 3.0;
}

/// o_b = d_b n_b [m]: the plate's offset from bond b's cell i to its cell j (turns: (cos, sin) yaw).
TIS_HD Vec2 plateBondOffset(const BondRest& b, Vec2 turn_i, Vec2 turn_j) {
  return b.distance * turnedBondNormal(b.normal, turn_i, turn_j);
}

/// A bonded neighbour of a cell, as the plate sees it.
struct PlateNeighbour {
  int cell;
  Vec2 offset;  ///< [m] r from the cell to the neighbour: +o_b where the cell is the bond's i, -o_b where j
};

/// The neighbour across incidence entry `entry` (2 x bond + 1 where the cell is the bond's j).
TIS_HD PlateNeighbour plateNeighbour(int entry, const int* bond_i, const int* bond_j, const BondRest* rest,
                                     const Vec2* turn) {
  const int b = entry >> 1, i = bond_i[b], j = bond_j[b];
  const Vec2 offset = plateBondOffset(rest[b], turn[i], turn[j]);
  return (entry & 1) ? PlateNeighbour{i, -offset} : PlateNeighbour{j, offset};
}

/// A cell's height gradient g and its P, fitted over the plate's offsets.
struct PlateFit {
  Vec2 gradient;             ///< [-]
  SymmetricMatrix2 inverse;  ///< P [1/m^2]
};

TIS_HD PlateFit plateFit(const HeightGradientSums& s) {
  return {heightGradient(s, kPlateFitConditioning), heightGradientInverse(s, kPlateFitConditioning)};
}

/// The fit of cell k over its intact bonds (incidence lists of incidence.hpp, taken in their order).
TIS_HD PlateFit cellPlateFit(int k, const int* offsets, const int* entries, const unsigned char* state,
                             const int* bond_i, const int* bond_j, const BondRest* rest, const Vec2* turn,
                             const CellMotion* motion) {
  HeightGradientSums sums = {0.0, 0.0, 0.0, 0.0, 0.0};
  for (int e = offsets[k]; e < offsets[k + 1]; ++e) {
    const int b = entries[e] >> 1;
    if (state[b] != kBondIntact) continue;
    const PlateNeighbour other = plateNeighbour(entries[e], bond_i, bond_j, rest, turn);
    addHeightSample(sums, other.offset, motion[other.cell].z - motion[k].z);
  }
  return plateFit(sums);
}

/// Energy 1/2 D' A_b kappa_b^2 [J] of one bond (for tests and diagnostics; the step uses q_b).
TIS_HD double plateBondEnergy(double stiffness, const BondRest& b, Vec2 turn_i, Vec2 turn_j, Vec2 gradient_i,
                              Vec2 gradient_j) {
  const double kappa =
      curvatureAcrossBond(gradient_i, gradient_j, turnedBondNormal(b.normal, turn_i, turn_j), b.distance);
  return 0.5 * stiffness * 0.5 * b.edge_length * b.distance * kappa * kappa;
}

/// q_b = dU/dg_j = -dU/dg_i = D' L_b kappa_b n_b / 2 [N m] of one bond.
TIS_HD Vec2 bondPlateMoment(double stiffness, const BondRest& b, Vec2 turn_i, Vec2 turn_j, Vec2 gradient_i,
                            Vec2 gradient_j) {
  const Vec2 n = turnedBondNormal(b.normal, turn_i, turn_j);
  const double kappa = curvatureAcrossBond(gradient_i, gradient_j, n, b.distance);
  return (0.5 * stiffness * b.edge_length * kappa) * n;
}

/// nu_k = P_k mu_k [N/m] of cell k from the q_b of its intact bonds and its fit's P_k.
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
                             const int* bond_i, const int* bond_j, const BondRest* rest, const Vec2* turn,
                             const Vec2* moment) {
  double force = 0.0;
  for (int e = offsets[m]; e < offsets[m + 1]; ++e) {
    const int b = entries[e] >> 1;
    if (state[b] != kBondIntact) continue;
    const PlateNeighbour other = plateNeighbour(entries[e], bond_i, bond_j, rest, turn);
    force += dot(moment[other.cell] + moment[m], other.offset);
  }
  return force;
}

}  // namespace thin_ice
