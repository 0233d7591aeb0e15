// Dynamic (DEM) contact between two cells whose polygons overlap, paper Eqs. (1)-(4) read as
// SPEC-NOTES fixes them:
//   F_n = K_n(z) (3E/(1-nu)) Z S/L        Eq. (1) x h^3 with the face height h replaced by the
//                                         vertical overlap Z (= h for level cells): S/L is the mean
//                                         overlap depth, so this is a planar contact of stiffness
//                                         (3E/(1-nu)) Z per metre
//   F_v = K_v(z) Z (3E_v/(1-nu)) S/h       Eq. (3), Z = max(0, h - |z_j - z_i|) (Eq. 2), pushing
//                                         the cells apart vertically (zero when level)
//   both act at the overlap centroid; the yaw moment is (point - centroid) x F (Eq. 4).
// Added, as every DEM needs: normal damping (ratio zeta of critical, never attractive) and
// regularised Coulomb friction against the slip at the contact point.
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/friction.hpp"
#include "thin_ice_sim/physics/host_device.hpp"
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
};

/// Velocity [m/s] of the material point `point` of a body (horizontal part).
TIS_HD Vec2 pointVelocity(const BodyState& b, Vec2 point) {
  return b.velocity + b.wz * perpendicular(point - b.centroid);
}

struct PairForce {
  Vec2 force_on_j;    ///< [N] horizontal force on j; i gets the opposite
  double fz_on_j;     ///< [N] vertical force on j; i gets the opposite
  Vec2 point;         ///< [m] where it acts (for the yaw moments of Eq. 4)
  bool touching;      ///< S > 0
};

/// Force between cells i and j from their polygon overlap (`overlap` = intersection of i's and
/// j's polygons, normal from i to j).
TIS_HD PairForce demContactForce(const PolygonOverlap& overlap, const BodyState& i, const BodyState& j,
                                 const ContactConstants& c) {
  PairForce f;
  f.force_on_j = {0.0, 0.0};
  f.fz_on_j = 0.0;
  f.point = overlap.centroid;
  f.touching = overlap.area > 0.0;
  if (!f.touching) return f;

  const double h = c.thickness;
  const double dz = j.z - i.z;
  const double offset = fabs(dz) / h;
  const double k_h = smoothing(offset, c.exponent_h);
  const double k_v = smoothing(offset, c.exponent_v);
  const double reduced_mass = i.mass * j.mass / (i.mass + j.mass);

  const Vec2 relative = pointVelocity(j, overlap.centroid) - pointVelocity(i, overlap.centroid);
  const Vec2 n = overlap.normal;
  const double approach = dot(relative, n);  // > 0: separating

  // Eq. (1) x h^3 with the contact face h high replaced by the vertical overlap Z of Eq. (2):
  // two slabs at different heights touch over Z, not h (equal at dz = 0). Without it a piece
  // resting on another (|dz| just below h, overlap S the size of a cell) got a horizontal kick of
  // order 1e5 N and blew up (docs/model.md). Damping of stiffness k = K_n E' Z.
  const double overlap_z = fmax(0.0, h - fabs(dz));
  const double stiffness_h = k_h * c.plane_modulus * overlap_z;
  double normal = stiffness_h * overlap.area / overlap.chord_length;
  normal -= 2.0 * c.damping_ratio * sqrt(stiffness_h * reduced_mass) * approach;
  if (normal < 0.0) normal = 0.0;

  // Eqs. (2)-(3), with damping of stiffness K_v E_v' S / h.
  const double stiffness_v = k_v * c.vertical_modulus * overlap.area / h;
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
  const double scale = frictionScale(c.friction, normal + vertical, slip.x, slip.y, side != 0.0 ? 0.0 : slip_z,
                                     c.regularisation_speed);
  f.force_on_j = normal * n - scale * slip;
  f.fz_on_j = side * vertical - (side != 0.0 ? 0.0 : scale * slip_z);
  return f;
}

}  // namespace thin_ice
