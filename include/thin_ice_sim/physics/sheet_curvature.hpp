// The curvature of the bonded sheet across a bond, and the plate stress it stands for: the
// optional failure criterion `ice.curvature_failure` (beyond the paper and SPEC-NOTES;
// docs/model.md, "Curvature failure"; docs/validation/calibration.md, 2026-12-03).
//
// Why: cells have no pitch or roll and their vertical bonds are shear springs, so Eq. (13) reads
// sigma_v from the height step between two neighbours, that is from the sheet's slope. A floating
// plate fails on its bending moment, which follows its curvature; a sheet pressed down under a
// rubble pile can be bent several times past a plate's breaking curvature while its slope stays
// below the bond law's breaking slope (calibration.md), so it never fails there.
//
// The estimate, from the cells' heights alone:
//   height gradient of cell i   g_i = argmin_g sum_j (z_j - z_i - g . r_ij)^2 over its intact bonds,
//                                     r_ij = c_j - c_i (centroids, horizontal) [-]
//   curvature across bond ij    kappa_ij = (g_j - g_i) . n / d_ij [1/m]
//                                     (n the bond's unit normal from i to j, d_ij its rest length)
//   plate stress                sigma = 6 M / h^2 with M = D kappa, D = E h^3 / (12 (1 - nu^2)):
//                               sigma = E h |kappa| / (2 (1 - nu^2)) [Pa] (Kirchhoff plate, unit width)
// A plane gives g_i = g_j and kappa = 0 whatever its slope; a parabola z = kappa x^2 / 2 sampled
// symmetrically about each cell gives g_i = kappa x_i, hence kappa_ij = kappa exactly. A cell
// whose intact bonds all lie on one line (one bond, or a row) gets the slope along that line.
//
// Scope (ice.curvature_failure_scope): `all` checks every intact bond; `sheet` only the bonds
// between two cells of the intact sheet, the largest piece held together by intact bonds
// (largestPieceCells, backend.hpp, refreshed at every contact rebuild, so at the latest one step
// after a bond broke). A floe that broke off still bends and carries the plate term, but fails by
// Eq. (13) alone: the test of whether the finer rubble the criterion makes in the pile is what
// raises the load (docs/validation/calibration.md, 2026-12-03).
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/host_device.hpp"
#include "thin_ice_sim/physics/vec2.hpp"

namespace thin_ice {

/// Sums of the least-squares fit of a cell's height gradient: sum r r^T and sum r dz.
struct HeightGradientSums {
  double xx, xy, yy;  ///< [m^2]
  double xz, yz;      ///< [m^2]
};

/// Adds one neighbour at horizontal offset r [m] and height difference dz [m].
TIS_HD void addHeightSample(HeightGradientSums& s, Vec2 r, double dz) {
  s.xx += r.x * r.x;
  s.xy += r.x * r.y;
  s.yy += r.y * r.y;
  s.xz += r.x * dz;
  s.yz += r.y * dz;
}

/// det / trace^2 of sum r r^T (at most 1/4) at or below which the curvature criterion's fit is
/// solved along a line: the samples span no area worth solving on.
constexpr double kGradientFitConditioning = 1e-9;

/// The least-squares gradient (dz/dx, dz/dy) [-] of the sums; along the line where the samples
/// all lie on one (the 2 x 2 system is then singular, or as good as singular: det <= conditioning
/// trace^2); zero without samples.
TIS_HD Vec2 heightGradient(const HeightGradientSums& s, double conditioning = kGradientFitConditioning) {
  const double trace = s.xx + s.yy;
  const double det = s.xx * s.yy - s.xy * s.xy;
  if (det > conditioning * trace * trace) {
    return {(s.yy * s.xz - s.xy * s.yz) / det, (s.xx * s.yz - s.xy * s.xz) / det};
  }
  // Collinear samples r_k = t_k u: sum r r^T = (sum t^2) u u^T, trace = sum t^2, so this is
  // u (sum t dz) / (sum t^2), the least-squares slope along u.
  if (trace > 0.0) return {s.xz / trace, s.yz / trace};
  return {0.0, 0.0};
}

/// A symmetric 2 x 2 matrix [1/m^2 here]: (xx xy; xy yy).
struct SymmetricMatrix2 {
  double xx, xy, yy;
};

TIS_HD Vec2 operator*(const SymmetricMatrix2& a, Vec2 v) { return {a.xx * v.x + a.xy * v.y, a.xy * v.x + a.yy * v.y}; }

/// The matrix P [1/m^2] of the fit above (same conditioning), g = P sum r dz, in each of its three cases:
/// (sum r r^T)^-1; 1/trace times the identity on a line (P r_k = t_k u / sum t^2 for samples
/// along u, which is what heightGradient gives there); 0 without samples. The plate term
/// (sheet_plate.hpp) needs it for dg/dz; heightGradient keeps its own quotients, so the curvature
/// criterion's results do not depend on it.
TIS_HD SymmetricMatrix2 heightGradientInverse(const HeightGradientSums& s, double conditioning) {
  const double trace = s.xx + s.yy;
  const double det = s.xx * s.yy - s.xy * s.xy;
  if (det > conditioning * trace * trace) return {s.yy / det, -s.xy / det, s.xx / det};
  if (trace > 0.0) return {1.0 / trace, 0.0, 1.0 / trace};
  return {0.0, 0.0, 0.0};
}

/// kappa_ij [1/m] across a bond of unit normal n (i to j) and length d [m] from the gradients of
/// its two cells.
TIS_HD double curvatureAcrossBond(Vec2 gradient_i, Vec2 gradient_j, Vec2 n, double distance) {
  return dot(gradient_j - gradient_i, n) / distance;
}

/// Whether the curvature criterion checks the bond between cells i and j: sheet holds one byte per
/// cell, nonzero for a cell of the intact sheet, or is null when every bond is checked.
TIS_HD bool curvatureChecked(const unsigned char* sheet, int i, int j) {
  return sheet == nullptr || (sheet[i] & sheet[j]) != 0;
}

/// E h / (2 (1 - nu^2)) [Pa m]: the plate stress per unit curvature at the surface.
inline double plateStressPerCurvature(double youngs_modulus, double poisson_ratio, double thickness) {
  return youngs_modulus * thickness / (2.0 * (1.0 - poisson_ratio * poisson_ratio));
}

}  // namespace thin_ice
