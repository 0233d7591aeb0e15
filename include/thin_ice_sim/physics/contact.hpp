// Dynamic (DEM) contact between two cells whose polygons overlap, paper Eqs. (1)-(4) read as
// this project reads them (docs/model.md):
//   F_n = K_n(z) (3E/(1-nu)) Z d          Eq. (1) x h^3 with the face height h replaced by the
//                                         vertical overlap Z (= h for level cells) and the depth
//                                         d = min(S/L, Z): S/L is the mean overlap depth, so this
//                                         is a planar contact of stiffness (3E/(1-nu)) Z per metre
//   F_v = K_v(z) Z (3E_v/(1-nu)) S/h       Eq. (3), Z = max(0, h - |z_j - z_i|) (Eq. 2), pushing
//                                         the cells apart vertically (zero when level)
//   both act at the overlap centroid; the yaw moment is (point - centroid) x F (Eq. 4).
// Added, as every DEM needs: normal damping (ratio zeta of critical, never attractive) and
// regularised Coulomb friction against the slip at the contact point; between cells at
// different heights the edge face that carries F_n also resists the vertical slip along it
// (docs/model.md, "DEM contacts": without it a piece pressed edge-on against another slid up or
// down freely).
// Three departures, each forced by a blow-up traced to it (docs/model.md, "Deviations"):
//  - d = min(S/L, Z): two slabs that overlap by S/L across and by Z up and down are separated
//    along the shallower of the two. A piece resting on another (Z ~ 1 mm, S/L ~ 0.1 m) used to
//    get a horizontal push of 1e4 N.
//  - A reference overlap S_ref: a pair that enters the contact list already overlapping (a bond
//    that broke after its cells had hinged into each other about the bond's anchor) counts only
//    the overlap beyond S_ref, and S_ref shrinks with the overlap. It used to start at 1e6 N.
//  - The viscous part of the regularised friction is bounded by beta m_eff / dt (m_eff: the
//    effective mass of the slip at the contact point, rotation included), the largest that the
//    explicit step integrates without overshoot; above it the friction spun pieces up.
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/friction.hpp"
#include "thin_ice_sim/physics/host_device.hpp"
#include "thin_ice_sim/physics/scalar.hpp"
#include "thin_ice_sim/physics/polygon_clip.hpp"
#include "thin_ice_sim/physics/smoothing.hpp"
#include "thin_ice_sim/physics/vec2.hpp"

namespace thin_ice {

struct ContactConstants {
  double thickness;             ///< h [m]
  double plane_modulus;         ///< 3E/(1-nu) [Pa], Eq. (1)
  double vertical_modulus;      ///< 3E_v/(1-nu) [Pa], Eq. (3)
  double exponent_h;            ///< n of K_n [-]
  double exponent_v;            ///< n of K_v [-]
  double friction;              ///< mu ice-ice [-]
  double friction_rate_limit;   ///< beta / dt [1/s]: friction scale <= this x m_eff
  double crushing_strength;     ///< sigma_c [Pa]: F_n <= sigma_c Z L
  double damping_ratio;         ///< zeta [-]
  double regularisation_speed;  ///< [m/s]
};

/// What a contact law needs of one body.
struct BodyState {
  Vec2 centroid;   ///< [m]
  double z;        ///< [m]
  Vec2 velocity;   ///< [m/s]
  double vz;       ///< [m/s]
  double wz;       ///< [rad/s]
  double mass;     ///< [kg]
  double inertia;  ///< yaw moment of inertia [kg m^2]
};

/// Velocity [m/s] of the material point `point` of a body (horizontal part).
TIS_HD Vec2 pointVelocity(const BodyState& b, Vec2 point) {
  return b.velocity + b.wz * perpendicular(point - b.centroid);
}

struct PairForce {
  Vec2 force_on_j;    ///< [N] horizontal force on j; i gets the opposite
  double fz_on_j;     ///< [N] vertical force on j; i gets the opposite
  Vec2 point;         ///< [m] where it acts (for the yaw moments of Eq. 4)
  double reference_area;  ///< S_ref [m^2] after this step, carried to the next
  bool touching;      ///< the slabs touch: S > 0 and Z > 0 (a force may act)
};

/// What the per-cell gather needs of one pair's force, a contact's or a bond's, stored per pair
/// and step (40 bytes, where the full force records are 56 and 88: the gather is memory-bound).
struct PairLoad {
  Vec2 force_on_j;     ///< [N] horizontal force on j; i gets the opposite
  double fz_on_j;      ///< [N] vertical force on j; i gets the opposite
  /// [N m] yaw moments: [0] of -force_on_j about i's centroid, [1] of force_on_j about j's.
  /// Indexed by the end (0: i, 1: j), so a cell's gather picks its own without a branch.
  double torque[2];
};

/// The load of a contact force on cells centred at centre_i and centre_j (the moments of Eq. 4).
TIS_HD PairLoad contactLoad(const PairForce& f, Vec2 centre_i, Vec2 centre_j) {
  return {f.force_on_j, f.fz_on_j, {cross(f.point - centre_i, -f.force_on_j), cross(f.point - centre_j, f.force_on_j)}};
}

/// Inverse effective mass [1/kg] of a slip at `point` of body b: 1/m + |r|^2/I (an upper bound
/// of the exact 1/m + (r x t)^2/I for any slip direction t).
TIS_HD double inverseSlipMass(const BodyState& b, Vec2 point) {
  const Vec2 r = point - b.centroid;
  return 1.0 / b.mass + dot(r, r) / b.inertia;
}

/// Vertical overlap Z [m] of two slabs h thick whose mid-planes are at z_i and z_j, Eq. (2):
/// max(0, h - |z_j - z_i|).
TIS_HD double verticalOverlap(double z_i, double z_j, double h) { return maxOf(0.0, h - fabs(z_j - z_i)); }

/// Whether a listed pair may go without its polygon clip this step: nothing the clip could give
/// would change what the pair does or carries forward. Its slabs do not overlap vertically
/// (Z = 0, Eq. 2), so Eqs. (1) and (3), which both carry Z, give no force and demContactForce
/// returns "not touching" whatever S is; and it holds no reference overlap (S_ref = 0), which only
/// the clip's S could change. A pair that holds one (new to the list, or S_ref > 0) still clips,
/// so that S_ref follows S while one slab passes over the other. In a grown pile most pairs whose
/// polygons overlap are pieces stacked one above the other (docs/performance.md).
TIS_HD bool contactSkipsClip(double z_i, double z_j, double h, double reference_area) {
  return reference_area == 0.0 && !(verticalOverlap(z_i, z_j, h) > 0.0);
}

/// Force between cells i and j from their polygon overlap (`overlap` = intersection of i's and
/// j's polygons, normal from i to j). `reference_area` is the pair's S_ref from the previous step,
/// or negative for a pair new to the contact list (its present overlap becomes S_ref).
TIS_HD PairForce demContactForce(const PolygonOverlap& overlap, const BodyState& i, const BodyState& j,
                                 const ContactConstants& c, double reference_area) {
  PairForce f;
  f.force_on_j = {0.0, 0.0};
  f.fz_on_j = 0.0;
  f.point = overlap.centroid;
  f.touching = false;
  f.reference_area = 0.0;  // apart: the next touch starts from no overlap
  if (!(overlap.area > 0.0)) return f;
  f.reference_area = reference_area < 0.0 ? overlap.area : minOf(reference_area, overlap.area);
  const double h = c.thickness;
  // One slab wholly above the other: no face touches (Eqs. 1 and 3 both carry Z), but S_ref
  // follows the overlap as for a touching pair, so that it is the same when they meet.
  const double overlap_z = verticalOverlap(i.z, j.z, h);
  if (!(overlap_z > 0.0)) return f;
  f.touching = true;
  const double area = overlap.area - f.reference_area;  // S - S_ref >= 0 [m^2]

  const double dz = j.z - i.z;
  const double offset = fabs(dz) / h;
  const double k_h = smoothing(offset, c.exponent_h);
  const double k_v = c.exponent_v == c.exponent_h ? k_h : smoothing(offset, c.exponent_v);
  const double reduced_mass = i.mass * j.mass / (i.mass + j.mass);

  const Vec2 relative = pointVelocity(j, overlap.centroid) - pointVelocity(i, overlap.centroid);
  const Vec2 n = overlap.normal;
  const double approach = dot(relative, n);  // > 0: separating

  // Eq. (1) x h^3 with the contact face h high replaced by the vertical overlap Z of Eq. (2):
  // two slabs at different heights touch over Z, not h (equal at dz = 0); the depth is the
  // shallower of S/L and Z. Damping of stiffness k = K_n E' Z. (The face h and depth S/L as
  // printed shattered the sheet: docs/model.md, "Readings tried and rejected".)
  const double stiffness_h = k_h * c.plane_modulus * overlap_z;
  const double depth = minOf(area / overlap.chord_length, overlap_z);
  double normal = stiffness_h * depth;
  normal -= 2.0 * c.damping_ratio * sqrt(stiffness_h * reduced_mass) * approach;
  normal = minOf(maxOf(normal, 0.0), c.crushing_strength * overlap_z * overlap.chord_length);

  // Eqs. (2)-(3), with damping of stiffness K_v E_v' S / h.
  const double stiffness_v = k_v * c.vertical_modulus * area / h;
  const double side = dz > 0.0 ? 1.0 : (dz < 0.0 ? -1.0 : 0.0);
  double vertical = stiffness_v * overlap_z;
  if (side != 0.0) {
    vertical -= 2.0 * c.damping_ratio * sqrt(stiffness_v * reduced_mass) * side * (j.vz - i.vz);
    if (vertical < 0.0) vertical = 0.0;
  } else {
    vertical = 0.0;
  }

  // Friction against the slip: relative velocity less its component along n.
  const Vec2 slip = relative - approach * n;
  const double slip_z = j.vz - i.vz;
  const double slip_mass = 1.0 / (inverseSlipMass(i, overlap.centroid) + inverseSlipMass(j, overlap.centroid));
  const double scale_limit = c.friction_rate_limit * slip_mass;
  if (side != 0.0) {
    // Cells at different heights touch over a vertical edge face Z high that carries F_n, and
    // over their top and bottom faces, which carry F_v. The edge face resists the slip along it
    // in 3-D; the top and bottom faces the horizontal slip. Their sum on the horizontal slip stays
    // within the explicit step's bound (friction.hpp); the vertical slip's effective mass,
    // m_i m_j / (m_i + m_j), is at least slip_mass, so the edge face's share is stable there too.
    const double edge = frictionScale(c.friction, normal, slip.x, slip.y, slip_z, c.regularisation_speed, scale_limit);
    const double faces =
        frictionScale(c.friction, vertical, slip.x, slip.y, 0.0, c.regularisation_speed, scale_limit - edge);
    f.force_on_j = normal * n - (edge + faces) * slip;
    f.fz_on_j = side * vertical - edge * slip_z;
    return f;
  }
  // Level cells: F_v = 0, one bound mu F_n on the slip in every direction.
  const double scale = frictionScale(c.friction, normal, slip.x, slip.y, slip_z, c.regularisation_speed, scale_limit);
  f.force_on_j = normal * n - scale * slip;
  f.fz_on_j = -(scale * slip_z);
  return f;
}

}  // namespace thin_ice
