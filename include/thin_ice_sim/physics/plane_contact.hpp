// Contact of a cell with a rigid plane: the inclined structure face (paper Eq. 17), the pusher
// plate, the false bottom and the basin walls all use this one law.
//
// The cell is a horizontal slab: polygon x [z - h/2, z + h/2]. The solid is the half-space
// {p : m . (p - p0) < 0} with m the unit normal pointing out of the solid. The penetration volume
//   V = integral over the slab's z-range of A_cut(z) dz,
// A_cut(z) = area of the polygon part beyond the line where the plane crosses level z. Between
// the levels where that line passes a vertex, A_cut and its first moments are polynomials of
// degree <= 3 in z, so two-point Gauss-Legendre quadrature per piece is exact.
//   S_pen = V / h       (the thickness-averaged penetrated area: the "penetration area" of Eq. 17)
//   F     = K S_pen m   + damping along m (never attractive) + regularised Coulomb friction
// acting at the centroid of the penetrated volume.
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/friction.hpp"
#include "thin_ice_sim/physics/host_device.hpp"
#include "thin_ice_sim/physics/scalar.hpp"
#include "thin_ice_sim/physics/polygon_clip.hpp"
#include "thin_ice_sim/physics/vec2.hpp"

namespace thin_ice {

/// Largest vertex count of a polygon handed to the slab routines: a cell (kMaxPolygonVertices)
/// cut to a panel's strip by two half-planes gains at most two vertices.
constexpr int kMaxSlabVertices = kMaxPolygonVertices + 2;

/// A rigid plane: solid where m . (p - p0) < 0.
struct RigidPlane {
  double mx, my, mz;  ///< unit outward normal
  double offset;      ///< m . p0 [m]
};

/// Keeps the part of the convex polygon `in` where a x + b y <= c (a, b, c in metres), writing
/// it to `out` (capacity n + 1); returns the new vertex count.
TIS_HD int clipPolygonByHalfPlane(const Vec2* in, int n, double a, double b, double c, Vec2* out) {
  int count = 0;
  for (int k = 0; k < n; ++k) {
    const Vec2 p = in[k], q = in[(k + 1) % n];
    const double sp = a * p.x + b * p.y - c;
    const double sq = a * q.x + b * q.y - c;
    if (sp <= 0.0) out[count++] = p;
    if ((sp < 0.0 && sq > 0.0) || (sp > 0.0 && sq < 0.0)) out[count++] = p + (sp / (sp - sq)) * (q - p);
  }
  return count;
}

/// Area [m^2] and first moments [m^3] of the part of a convex polygon where a x + b y <= c.
TIS_HD void cutAreaAndMoments(const Vec2* poly, int n, double a, double b, double c, double& area,
                              double& moment_x, double& moment_y) {
  area = 0.0;
  moment_x = 0.0;
  moment_y = 0.0;
  Vec2 cut[kMaxSlabVertices + 1];
  if (n > kMaxSlabVertices) return;  // outside the contract: no area rather than an overrun
  const int m = clipPolygonByHalfPlane(poly, n, a, b, c, cut);
  if (m < 3) return;
  const Vec2 v0 = cut[0];
  for (int k = 1; k + 1 < m; ++k) {
    const Vec2 r1 = cut[k] - v0, r2 = cut[k + 1] - v0;
    const double twice = cross(r1, r2);
    area += 0.5 * twice;
    moment_x += twice * (r1.x + r2.x) / 6.0;
    moment_y += twice * (r1.y + r2.y) / 6.0;
  }
  moment_x += area * v0.x;
  moment_y += area * v0.y;
}

struct SlabPenetration {
  double volume;   ///< V [m^3]
  Vec2 centroid;   ///< [m] horizontal centroid of the penetrated volume
  double z;        ///< [m] its height
};

/// Volume of the slab polygon x [z_low, z_high] inside the solid of `plane`, and its centroid.
/// The polygon has at most kMaxSlabVertices vertices (world frame); a larger one gives no volume.
TIS_HD SlabPenetration slabPenetration(const Vec2* poly, int n, double z_low, double z_high,
                                       const RigidPlane& plane) {
  SlabPenetration r;
  r.volume = 0.0;
  r.centroid = {0.0, 0.0};
  r.z = 0.5 * (z_low + z_high);
  if (!(z_high > z_low) || n < 3 || n > kMaxSlabVertices) return r;
  // Solid at level z: m_xy . q < offset - m_z z, i.e. -m_xy . q <= -(offset - m_z z) is outside.
  // Region inside the solid: mx x + my y <= offset - mz z.
  const double horizontal = sqrt(plane.mx * plane.mx + plane.my * plane.my);
  double moment_x = 0.0, moment_y = 0.0, moment_z = 0.0;
  if (horizontal < 1e-12) {
    // Horizontal plane: the whole polygon is inside wherever mz z < offset.
    double area, ax, ay;
    cutAreaAndMoments(poly, n, 0.0, 0.0, 1.0, area, ax, ay);
    double lo = z_low, hi = z_high;
    if (plane.mz > 0.0) hi = minOf(hi, plane.offset / plane.mz);
    else lo = maxOf(lo, plane.offset / plane.mz);
    if (!(hi > lo)) return r;
    r.volume = area * (hi - lo);
    r.centroid = {ax / area, ay / area};
    r.z = 0.5 * (lo + hi);
    return r;
  }
  // Break levels: where the cutting line passes a vertex (only when the plane is inclined).
  double levels[kMaxSlabVertices + 2];
  int count = 0;
  levels[count++] = z_low;
  if (fabs(plane.mz) > 1e-12) {
    for (int k = 0; k < n; ++k) {
      const double zk = (plane.offset - plane.mx * poly[k].x - plane.my * poly[k].y) / plane.mz;
      if (zk > z_low && zk < z_high) levels[count++] = zk;
    }
  }
  levels[count++] = z_high;
  for (int a = 1; a < count; ++a) {  // insertion sort: at most kMaxSlabVertices + 2 levels
    const double v = levels[a];
    int b = a - 1;
    while (b >= 0 && levels[b] > v) {
      levels[b + 1] = levels[b];
      --b;
    }
    levels[b + 1] = v;
  }
  const double gauss = 0.5 / sqrt(3.0);  // two-point Gauss-Legendre abscissae on [-1/2, 1/2]
  for (int s = 0; s + 1 < count; ++s) {
    const double lo = levels[s], hi = levels[s + 1];
    if (!(hi > lo)) continue;
    const double mid = 0.5 * (lo + hi), half_width = hi - lo;
    for (int g = -1; g <= 1; g += 2) {
      const double z = mid + g * gauss * half_width;
      double area, ax, ay;
      cutAreaAndMoments(poly, n, plane.mx, plane.my, plane.offset - plane.mz * z, area, ax, ay);
      const double weight = 0.5 * half_width;
      r.volume += weight * area;
      moment_x += weight * ax;
      moment_y += weight * ay;
      moment_z += weight * area * z;
    }
  }
  if (r.volume > 0.0) {
    r.centroid = {moment_x / r.volume, moment_y / r.volume};
    r.z = moment_z / r.volume;
  }
  return r;
}

struct PlaneContactConstants {
  double stiffness;             ///< K [Pa]: force = K S_pen (Eq. 17)
  double thickness;             ///< h [m]
  double friction;              ///< mu [-]
  double damping_ratio;         ///< zeta [-], of the stiffness K * sqrt(cell area)
  double regularisation_speed;  ///< [m/s]
  double friction_rate_limit;   ///< beta / dt [1/s]: friction scale <= this x m_eff (friction.hpp)
};

struct PlaneContactForce {
  double fx, fy, fz;  ///< [N] force on the cell
  Vec2 point;         ///< [m] where it acts
  bool touching;
};

/// Force of the plane on a cell from its penetration (see the file comment). `centroid`,
/// `velocity`, `vz`, `wz`, `mass`, `inertia` (yaw), `area` describe the cell; `plane_velocity`
/// is the plane's own velocity (the pusher moves; walls do not).
TIS_HD PlaneContactForce planeContactForce(const SlabPenetration& pen, const RigidPlane& plane,
                                           const PlaneContactConstants& c, Vec2 centroid, Vec2 velocity,
                                           double vz, double wz, double mass, double inertia, double area,
                                           double plane_velocity_x) {
  PlaneContactForce f;
  f.fx = f.fy = f.fz = 0.0;
  f.point = pen.centroid;
  f.touching = pen.volume > 0.0;
  if (!f.touching) return f;
  const Vec2 v_point = velocity + wz * perpendicular(pen.centroid - centroid);
  const double rx = v_point.x - plane_velocity_x, ry = v_point.y, rz = vz;
  const double approach = rx * plane.mx + ry * plane.my + rz * plane.mz;  // > 0: leaving the plane
  const double stiffness = c.stiffness * sqrt(area);  // an edge of about one cell width in contact
  double normal = c.stiffness * pen.volume / c.thickness;
  normal -= 2.0 * c.damping_ratio * sqrt(stiffness * mass) * approach;
  if (normal < 0.0) normal = 0.0;
  const double sx = rx - approach * plane.mx, sy = ry - approach * plane.my, sz = rz - approach * plane.mz;
  const Vec2 arm = pen.centroid - centroid;
  const double slip_mass = 1.0 / (1.0 / mass + dot(arm, arm) / inertia);  // as inverseSlipMass
  const double scale = frictionScale(c.friction, normal, sx, sy, sz, c.regularisation_speed,
                                     c.friction_rate_limit * slip_mass);
  f.fx = normal * plane.mx - scale * sx;
  f.fy = normal * plane.my - scale * sy;
  f.fz = normal * plane.mz - scale * sz;
  return f;
}

}  // namespace thin_ice
