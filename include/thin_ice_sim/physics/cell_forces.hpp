// Everything that happens to one cell in one step, after the pair forces are known: the bond
// and contact forces gathered in a fixed order, water (Eq. 16), the rigid planes (pusher, basin walls, false bottom,
// the structure face panel by panel, Eq. 17) and symplectic Euler (Eqs. 14-15). One definition,
// called per cell by the CPU backend's loop and by the CUDA backend's kernel, on the same plain
// arrays, so both do the same arithmetic in the same order.
//
// Multiple time stepping of the structure contact. K_struct of Eq. (17) is two to three orders
// stiffer than any spring of the ice, so with one step for all it alone sets dt. With
// structure_substeps = n > 1 a cell that can reach the face in this step takes n sub-steps of
// dt/n: the face's force is evaluated anew in each, the other forces (bonds, contacts, water,
// pusher, walls, bottom) are held at their value at the start of the step and act through every
// sub-step, as in the multiple-time-step method of Streett, Tildesley and Saville (Mol. Phys. 35,
// 639, 1978). Unlike r-RESPA (Tuckerman, Berne and Martyna 1992), which gives the slow force as two
// half-step kicks and is time-reversible, this is first order, like the symplectic Euler step it
// extends; it was chosen because a kick of a whole step's bond force into the stiff one-sided face
// contact is what the sub-steps are there to avoid. Every other cell takes one step of dt. The
// structure load of the step is the mean of its sub-steps, so the impulse it received is kept.
// A cell that is sub-stepped but does not touch the face moves F dt^2 (n+1)/(2 n m) under the held
// forces instead of F dt^2/m: crossing the margin changes the integrator by O(dt^2), so a borderline
// cell whose margin test rounds differently on the GPU (fused multiply-adds) can part from the CPU
// by that much.
#pragma once

#include <math.h>

#include "thin_ice_sim/physics/bond.hpp"
#include "thin_ice_sim/physics/contact.hpp"
#include "thin_ice_sim/physics/host_device.hpp"
#include "thin_ice_sim/physics/scalar.hpp"
#include "thin_ice_sim/physics/integrate.hpp"
#include "thin_ice_sim/physics/pair_separation.hpp"
#include "thin_ice_sim/physics/plane_contact.hpp"
#include "thin_ice_sim/physics/water.hpp"

namespace thin_ice {

/// A cell may touch at most this many structure panels at once (checked by buildModel).
constexpr int kMaxPanelsPerCell = 4;

/// Constants of every law, precomputed from Params (all SI).
struct ModelConstants {
  ContactConstants contact;
  BondConstants bond;
  WaterConstants water;
  PlaneContactConstants structure;
  PlaneContactConstants pusher;
  PlaneContactConstants bottom;
  PlaneContactConstants wall;
  RigidPlane structure_face;       ///< the inclined face (outward normal towards the ice)
  double structure_top_z;          ///< [m] top of the face
  double structure_toe_x;          ///< [m] origin of the structure frame (the toe on the waterline)
  double structure_y_min;          ///< [m] first panel's left edge
  double panel_width;              ///< [m]
  int panels;
  double calibration_factor;       ///< alpha, Eq. (18)
  bool bottom_enabled;
  double bottom_x_start;           ///< [m] the false bottom covers x >= this
  double bottom_z;                 ///< [m] its height (negative)
  bool walls_enabled;
  double wall_half_width;          ///< [m] walls at y = +-this
  double wall_x_start;             ///< [m] walls from this x on (side panels only: toe - length)
  double time_step;                ///< dt [s]
  int structure_substeps;          ///< n [-]: a cell that can reach the structure takes n steps of dt/n
  double mean_edge_length;         ///< l-bar [m] of Algorithm 1
  double rebuild_displacement;     ///< [m] rebuild when a cell moved farther since the last one
  double rebuild_rotation;         ///< [rad] ... or turned more
  int max_steps_between_rebuilds;  ///< N_iter
  double search_radius;            ///< [m] centroid distance under which a pair may be a candidate
  double search_margin;            ///< [m] a pair is a candidate when |c_i - c_j| <= r_i + r_j + this
  /// [-] a remembered separating edge skips a pair's clip while it keeps the polygons this x
  /// (r_i + r_j) apart (pair_separation.hpp); infinite: never. Never 0, even in a default Model.
  double separation_gap_fraction = kSeparationGapFraction;
};

/// A cell faster than this has blown up [m/s] (the pusher moves at centimetres per second).
constexpr double kRunawaySpeed = 50.0;

/// The structure's share of one cell's plane forces, per panel it touches (on the structure).
struct StructureContact {
  int first_panel;
  int panel_count;
  double fx[kMaxPanelsPerCell], fy[kMaxPanelsPerCell], fz[kMaxPanelsPerCell];  ///< [N]
  double px[kMaxPanelsPerCell], py[kMaxPanelsPerCell], pz[kMaxPanelsPerCell];  ///< where it acts [m]
};

/// Read-only view of the fixed model and the pair data a cell's update needs (device or host
/// pointers; incidence lists: for cell k, entries offsets[k] .. offsets[k+1]-1, each
/// 2 x pair + 1 when the cell is the pair's j).
struct CellStepInputs {
  const double* mass;                 ///< (cells) [kg]
  const double* inertia;              ///< (cells) [kg m^2]
  const double* area;                 ///< (cells) [m^2]
  const double* inverse_mass;         ///< (cells) 1 / mass [1/kg]
  const double* inverse_inertia;      ///< (cells) 1 / inertia [1/(kg m^2)]
  const double* polar_moment;         ///< (cells) inertia / (mass / area) [m^4], for the yaw drag
  const int* vertex_count;            ///< (cells)
  const double* vertex_x;             ///< (cells x kMaxPolygonVertices) body-frame vertices [m]
  const double* vertex_y;
  /// (cells x kMaxPolygonVertices) world vertices [m] at the step's start, or null: the step
  /// places a cell's polygon itself where it needs one (CellPolygon), and the caller hands the
  /// sub-steps theirs (subcycleStructureContact's start_polygon)
  const Vec2* world;
  const double* box;                  ///< (cells x 4) x0 x1 y0 y1 [m]
  const int* bond_offsets;            ///< (cells + 1)
  const int* bond_entries;
  const unsigned char* bond_state;    ///< (bonds) BondState
  const PairLoad* bond_load;          ///< (bonds) valid where the state is not kBondBroken
  const int* contact_offsets;         ///< (cells + 1)
  const int* contact_entries;
  const unsigned char* contact_touching;  ///< (pairs) S > 0 in this step
  const PairLoad* contact_load;       ///< (pairs) valid where touching
};

/// What one cell's update reports.
struct CellStepResult {
  double pusher_fx;  ///< [N] force of the pusher on the cell, +x
  bool blown;        ///< non-finite state or faster than runaway_speed
  bool moved_far;    ///< Algorithm 1, lines 14-16: moved or turned too far since the last rebuild
};

/// A cell's state as the pair laws (bonds, contacts) take it: its motion with its mass and inertia.
TIS_HD BodyState bodyOf(const CellMotion& m, double mass, double inertia) {
  return {{m.x, m.y}, m.z, {m.vx, m.vy}, m.vz, m.wz, mass, inertia};
}

/// Adds a pair's load to one of its cells (end 0: the cell is the pair's i, 1: its j).
/// Branch-free: which end a cell is of its pairs follows no pattern, so a branch on it was
/// mispredicted about once per cell-step on the CPU (callgrind's branch simulation). The sign is
/// exactly +-1, so the sums are those of adding or subtracting, bit for bit.
TIS_HD void addPairLoad(const PairLoad& f, int end, double& fx, double& fy, double& fz, double& tz) {
  const double sign = (double)(2 * end - 1);
  fx += sign * f.force_on_j.x;
  fy += sign * f.force_on_j.y;
  fz += sign * f.fz_on_j;
  tz += f.torque[end];
}

/// Adds the force of a plane on the cell to (fx, fy, fz, tz) and returns it.
TIS_HD PlaneContactForce addPlaneContact(const SlabPenetration& pen, const RigidPlane& plane,
                                         const PlaneContactConstants& law, const CellMotion& m, double mass,
                                         double inertia, double area, double plane_vx, double& fx, double& fy,
                                         double& fz, double& tz) {
  const Vec2 centre = {m.x, m.y};
  const PlaneContactForce f =
      planeContactForce(pen, plane, law, centre, {m.vx, m.vy}, m.vz, m.wz, mass, inertia, area, plane_vx);
  fx += f.fx; fy += f.fy; fz += f.fz;
  tz += cross(f.point - centre, Vec2{f.fx, f.fy});
  return f;
}

/// Whether the slab of a cell (bounding box `box`, bottom at z_low) comes closer than `margin` [m]
/// to the structure's solid. The slab reaches the solid when the least value of m . p over it is
/// below the offset (m_x < 0, m_z > 0: the rightmost x and the lowest z give the least value).
TIS_HD bool reachesStructure(const ModelConstants& c, const double* box, double z_low, double margin) {
  const RigidPlane& face = c.structure_face;
  const double lowest = face.mx * box[1] + face.mz * z_low;
  return lowest < face.offset + margin && z_low < c.structure_top_z + margin;
}

/// The panels [first, last] that the y-range [y0, y1] overlaps; false when it overlaps none.
TIS_HD bool structurePanelRange(const ModelConstants& c, double y0, double y1, int& first, int& last) {
  const double y_end = c.structure_y_min + c.panels * c.panel_width;
  first = (int)maxOf(0.0, floor((y0 - c.structure_y_min) / c.panel_width));
  last = (int)minOf((double)(c.panels - 1), floor((y1 - c.structure_y_min) / c.panel_width));
  return y1 > c.structure_y_min && y0 < y_end && first <= last;
}

/// World position [m] of the body-frame vertex (lx, ly) of a cell at pose `m` whose yaw is
/// turned by (cs, sn) = (cos, sin) yaw. Every placement goes through here, so a polygon placed
/// where it is used is the one a backend's placed array holds, to one rounding: the compilers
/// may fuse its multiply-adds differently where it is inlined.
TIS_HD Vec2 worldVertex(const CellMotion& m, double lx, double ly, double cs, double sn) {
  return Vec2{m.x, m.y} + rotate(Vec2{lx, ly}, cs, sn);
}

/// World vertices of a cell at pose `m` whose (cos, sin) yaw `turn` is known (placeCell's).
TIS_HD void placeVertices(const CellMotion& m, const double* vertex_x, const double* vertex_y, int count, Vec2 turn,
                          Vec2* world) {
  for (int v = 0; v < count; ++v) world[v] = worldVertex(m, vertex_x[v], vertex_y[v], turn.x, turn.y);
}

/// Bounding box (x0 x1 y0 y1) of a cell at pose `m` and, unless `world` is null, its world
/// vertices; returns (cos, sin) yaw.
TIS_HD Vec2 placeCell(const CellMotion& m, const double* vertex_x, const double* vertex_y, int count, Vec2* world,
                      double* box) {
  const double cs = cos(m.yaw), sn = sin(m.yaw);
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (int v = 0; v < count; ++v) {
    const Vec2 w = worldVertex(m, vertex_x[v], vertex_y[v], cs, sn);
    if (world != nullptr) world[v] = w;
    x0 = minOf(x0, w.x); x1 = maxOf(x1, w.x);
    y0 = minOf(y0, w.y); y1 = maxOf(y1, w.y);
  }
  box[0] = x0; box[1] = x1; box[2] = y0; box[3] = y1;
  return {cs, sn};
}

/// A cell's world polygon at the pose `pose` where its step needs one (a rigid plane within its
/// box, the structure face): the backend's placed array when it keeps one (the CPU backend,
/// whose contact pass needs every polygon anyway), or, when CellStepInputs::world is null (the
/// CUDA backend, which keeps none: it saves writing and rereading up to 12 vertices per cell and
/// step), placed here from the body-frame vertices the first time it is asked for. Most cells
/// touch no plane and never ask.
struct CellPolygon {
  const CellMotion& pose;
  const double* vertex_x;  ///< body frame [m]
  const double* vertex_y;
  int count;
  const Vec2* placed;      ///< null until placed, where the backend keeps no world array
  Vec2 own[kMaxPolygonVertices];  ///< read only once placed, so left uninitialised: zeroing it
                                  ///< could cost the GPU 192 B of local stores per cell-step

  TIS_HD CellPolygon(const CellMotion& pose_, const double* vertex_x_, const double* vertex_y_, int count_,
                     const Vec2* placed_)
      : pose(pose_), vertex_x(vertex_x_), vertex_y(vertex_y_), count(count_), placed(placed_) {}

  TIS_HD const Vec2* vertices() {
    if (placed == nullptr) {
      double box[4];
      placeCell(pose, vertex_x, vertex_y, count, own, box);
      placed = own;
    }
    return placed;
  }
};

/// Cell k's CellPolygon at `pose` (its pose at the step's start).
TIS_HD CellPolygon cellPolygonOf(const CellStepInputs& in, int k, const CellMotion& pose) {
  const size_t first = (size_t)k * kMaxPolygonVertices;
  return CellPolygon(pose, in.vertex_x + first, in.vertex_y + first, in.vertex_count[k],
                     in.world == nullptr ? nullptr : in.world + first);
}

/// Forces of the structure face's panels first..last (Eq. 17) on a cell (world polygon `poly` of
/// n vertices, pose `m`), added to (fx, fy, fz, tz); slot p - first of `s` gets panel p's force
/// on the structure and where it acts (a panel the cell misses gets a zero slot).
TIS_HD void addStructureForces(const ModelConstants& c, const Vec2* poly, int n, const CellMotion& m, double mass,
                               double inertia, double area, int first, int last, StructureContact& s, double& fx,
                               double& fy, double& fz, double& tz) {
  const double h = c.contact.thickness;
  const double z_low = m.z - 0.5 * h, z_high = m.z + 0.5 * h;
  const RigidPlane& face = c.structure_face;
  s.first_panel = first;
  s.panel_count = 0;
  for (int p = first; p <= last && s.panel_count < kMaxPanelsPerCell; ++p) {
    const double y0 = c.structure_y_min + p * c.panel_width, y1 = y0 + c.panel_width;
    Vec2 strip_a[kMaxSlabVertices], strip[kMaxSlabVertices];  // n + 1, then n + 2 vertices
    const int na = clipPolygonByHalfPlane(poly, n, 0.0, -1.0, -y0, strip_a);
    const int nb = na >= 3 ? clipPolygonByHalfPlane(strip_a, na, 0.0, 1.0, y1, strip) : 0;
    const SlabPenetration pen = slabPenetration(strip, nb, z_low, minOf(z_high, c.structure_top_z), face);
    const PlaneContactForce f = addPlaneContact(pen, face, c.structure, m, mass, inertia, area, 0.0, fx, fy, fz, tz);
    const int slot = s.panel_count++;
    s.fx[slot] = -f.fx; s.fy[slot] = -f.fy; s.fz[slot] = -f.fz;
    s.px[slot] = pen.centroid.x; s.py[slot] = pen.centroid.y; s.pz[slot] = pen.z;
  }
}

/// Forces of the pusher, the basin walls and the false bottom on a cell (its polygon `poly`, placed
/// only if a plane is within the bounding box `box`), added to (fx, fy, fz, tz). Returns the
/// pusher's x force [N].
TIS_HD double addRigidPlaneForces(const ModelConstants& c, CellPolygon& poly, const double* box,
                                  const CellMotion& m, double mass, double inertia, double area,
                                  double pusher_x, double pusher_velocity, double& fx, double& fy, double& fz,
                                  double& tz) {
  const double h = c.contact.thickness;
  const int n = poly.count;
  const double z_low = m.z - 0.5 * h, z_high = m.z + 0.5 * h;
  double pusher_fx = 0.0;
  // Pusher: solid x < pusher_x, outward normal +x.
  if (box[0] < pusher_x) {
    const RigidPlane plate = {1.0, 0.0, 0.0, pusher_x};
    pusher_fx = addPlaneContact(slabPenetration(poly.vertices(), n, z_low, z_high, plate), plate, c.pusher, m, mass,
                                inertia, area, pusher_velocity, fx, fy, fz, tz).fx;
  }
  // Basin walls (or the structure's side panels): solid |y| > half width, for x >= wall_x_start
  // (only the part of the cell beyond that x meets a side panel).
  if (c.walls_enabled && box[1] > c.wall_x_start && (box[3] > c.wall_half_width || box[2] < -c.wall_half_width)) {
    Vec2 part[kMaxPolygonVertices + 1];
    const bool whole = box[0] >= c.wall_x_start;
    const int count = whole ? n : clipPolygonByHalfPlane(poly.vertices(), n, -1.0, 0.0, -c.wall_x_start, part);
    const Vec2* reach = whole ? poly.vertices() : part;
    if (box[3] > c.wall_half_width) {
      const RigidPlane wall = {0.0, -1.0, 0.0, -c.wall_half_width};
      addPlaneContact(slabPenetration(reach, count, z_low, z_high, wall), wall, c.wall, m, mass, inertia, area, 0.0,
                      fx, fy, fz, tz);
    }
    if (box[2] < -c.wall_half_width) {
      const RigidPlane wall = {0.0, 1.0, 0.0, -c.wall_half_width};
      addPlaneContact(slabPenetration(reach, count, z_low, z_high, wall), wall, c.wall, m, mass, inertia, area, 0.0,
                      fx, fy, fz, tz);
    }
  }
  // False bottom: solid z < bottom_z for x >= bottom_x_start.
  if (c.bottom_enabled && z_low < c.bottom_z && box[1] > c.bottom_x_start) {
    Vec2 part[kMaxPolygonVertices + 1];
    const int count = clipPolygonByHalfPlane(poly.vertices(), n, -1.0, 0.0, -c.bottom_x_start, part);
    const RigidPlane floor = {0.0, 0.0, 1.0, c.bottom_z};
    addPlaneContact(slabPenetration(part, count, z_low, z_high, floor), floor, c.bottom, m, mass, inertia, area, 0.0,
                    fx, fy, fz, tz);
  }
  return pusher_fx;
}

/// What the first half of a cell's step hands to its second half when the cell takes the
/// structure sub-steps: the slow forces held through them and the margin of the panel range.
struct HeldForces {
  double fx, fy, fz;  ///< [N] bonds, contacts, water, pusher, walls and bottom at the step's start
  double tz;          ///< [N m] their yaw moment
  double travel;      ///< [m] bound on how far any point of the cell moves in the step
};

/// Inlined like the rest. ptxas -v (nvcc 13, -arch=sm_90, 2026-12-07): the CUDA kernel that runs
/// it (subcycleCells) takes 136 registers and a 1296 B stack frame, and stepCells, which no
/// longer does, 154 and 1376 B (160 and 1296 B when stepCells ran the sub-steps itself).
/// n sub-steps of dt/n of one cell that can reach the structure (see the file comment): the
/// face's force anew in each, the slow forces (fx, fy, fz, tz) held. `start_polygon` is the
/// cell's world polygon at the step's start (the backend's placed one, or placed for it). `s`
/// gets the mean load of each panel slot over the sub-steps and its force-weighted mean point
/// (the cell moves micrometres in one step, so the moment of the mean is the mean moment to that
/// accuracy).
TIS_HD void subcycleStructureContact(int k, const ModelConstants& c, const CellStepInputs& in,
                                     const Vec2* start_polygon, const HeldForces& held, CellMotion& motion,
                                     StructureContact& s) {
  const double margin = held.travel;
  const int n = in.vertex_count[k];
  const double mass = in.mass[k], inertia = in.inertia[k], area = in.area[k];
  const double inverse_mass = in.inverse_mass[k], inverse_inertia = in.inverse_inertia[k];
  const int substeps = c.structure_substeps;
  const double sub_dt = c.time_step / substeps, share = 1.0 / substeps;
  const double* box0 = in.box + 4 * k;
  int first = 0, last = -1;
  // The panels the cell can touch during the step; buildModel leaves room for kMaxPanelsPerCell
  // around the box itself, so where the margin would add one more, the box's own range is used
  // (the cell moves micrometres within the step).
  if (!structurePanelRange(c, box0[2] - margin, box0[3] + margin, first, last) ||
      last - first + 1 > kMaxPanelsPerCell) {
    if (!structurePanelRange(c, box0[2], box0[3], first, last)) last = first - 1;
  }
  s.first_panel = first;
  s.panel_count = 0;
  double weight[kMaxPanelsPerCell];
  for (int slot = 0; slot < kMaxPanelsPerCell; ++slot) {
    s.fx[slot] = s.fy[slot] = s.fz[slot] = 0.0;
    s.px[slot] = s.py[slot] = s.pz[slot] = 0.0;
    weight[slot] = 0.0;
  }
  Vec2 poly[kMaxPolygonVertices];
  double box[4];
  StructureContact now;
  for (int step = 0; step < substeps; ++step) {
    const Vec2* placed = start_polygon;  // the pose at the step's start
    if (step > 0) {
      placeCell(motion, in.vertex_x + (size_t)k * kMaxPolygonVertices, in.vertex_y + (size_t)k * kMaxPolygonVertices,
                n, poly, box);
      placed = poly;
    }
    double sx = held.fx, sy = held.fy, sz = held.fz, stz = held.tz;
    addStructureForces(c, placed, n, motion, mass, inertia, area, first, last, now, sx, sy, sz, stz);
    integrateSymplecticEuler(motion, sx, sy, sz, stz, inverse_mass, inverse_inertia, sub_dt);
    s.panel_count = now.panel_count;
    for (int slot = 0; slot < now.panel_count; ++slot) {
      s.fx[slot] += share * now.fx[slot];
      s.fy[slot] += share * now.fy[slot];
      s.fz[slot] += share * now.fz[slot];
      const double w = sqrt(now.fx[slot] * now.fx[slot] + now.fy[slot] * now.fy[slot] + now.fz[slot] * now.fz[slot]);
      weight[slot] += w;
      s.px[slot] += w * now.px[slot];
      s.py[slot] += w * now.py[slot];
      s.pz[slot] += w * now.pz[slot];
    }
  }
  for (int slot = 0; slot < s.panel_count; ++slot) {
    if (weight[slot] > 0.0) {
      s.px[slot] /= weight[slot]; s.py[slot] /= weight[slot]; s.pz[slot] /= weight[slot];
    } else {
      s.px[slot] = now.px[slot]; s.py[slot] = now.py[slot]; s.pz[slot] = now.pz[slot];
    }
  }
}

/// First half of a step of cell k: gather, water, pusher, walls and bottom. A cell that cannot
/// reach the structure face within the step (every cell when structure_substeps = 1) also takes
/// the face's force and its whole step here and returns false. One that can returns true with
/// `held`, and its step is finished by subcycleStructureContact. The two halves are apart so
/// that the CUDA backend can run the few sub-stepped cells in a pass of their own instead of
/// letting each warp wait on its slowest cell; stepCell runs them back to back. `pusher_fx` gets
/// the pusher's x force on the cell [N].
TIS_HD bool beginCellStep(int k, const ModelConstants& c, const CellStepInputs& in, double pusher_x,
                          double pusher_velocity, CellMotion& motion, StructureContact& structure,
                          double& pusher_fx, HeldForces& held) {
  const CellMotion m = motion;
  double fx = 0.0, fy = 0.0, fz = 0.0, tz = 0.0;
  for (int e = in.bond_offsets[k]; e < in.bond_offsets[k + 1]; ++e) {
    const int b = in.bond_entries[e] >> 1;
    if (in.bond_state[b] == kBondBroken) continue;  // kBondBreaking: its last force still acts
    addPairLoad(in.bond_load[b], in.bond_entries[e] & 1, fx, fy, fz, tz);
  }
  for (int e = in.contact_offsets[k]; e < in.contact_offsets[k + 1]; ++e) {
    const int p = in.contact_entries[e] >> 1;
    if (!in.contact_touching[p]) continue;
    addPairLoad(in.contact_load[p], in.contact_entries[e] & 1, fx, fy, fz, tz);
  }
  const double mass = in.mass[k], inertia = in.inertia[k], area = in.area[k];
  const double inverse_mass = in.inverse_mass[k], inverse_inertia = in.inverse_inertia[k];
  const WaterForce w = waterForce(c.water, mass, area, in.polar_moment[k], m.z, {m.vx, m.vy}, m.vz, m.wz);
  fx += w.horizontal.x; fy += w.horizontal.y; fz += w.vertical; tz += w.torque;
  const int n = in.vertex_count[k];
  CellPolygon poly = cellPolygonOf(in, k, m);
  const double* box = in.box + 4 * k;
  pusher_fx = addRigidPlaneForces(c, poly, box, m, mass, inertia, area, pusher_x, pusher_velocity, fx, fy, fz, tz);
  const double z_low = m.z - 0.5 * c.contact.thickness;
  const double dt = c.time_step;
  // With sub-steps: a bound on how far any point of the cell can travel in this step [m], with
  // the velocity it will have after the forces so far (1-norms bound the 2-norms and need no
  // root; the box's width plus height bounds the vertices' distance from the centroid). A cell
  // that can reach the face before the step ends takes the sub-steps. Not computed with n = 1.
  double travel = 0.0;
  if (c.structure_substeps > 1) {
    const double size = (box[1] - box[0]) + (box[3] - box[2]);
    const double speed = fabs(m.vx) + fabs(m.vy) + fabs(m.vz) + (fabs(fx) + fabs(fy) + fabs(fz)) * inverse_mass * dt;
    const double turn_rate = fabs(m.wz) + fabs(tz) * inverse_inertia * dt;
    travel = (speed + turn_rate * size) * dt;
  }
  if (c.structure_substeps > 1 && reachesStructure(c, box, z_low, travel)) {
    held = {fx, fy, fz, tz, travel};
    return true;
  }
  structure.first_panel = 0;
  structure.panel_count = 0;
  int first, last;
  if (reachesStructure(c, box, z_low, 0.0) && structurePanelRange(c, box[2], box[3], first, last)) {
    addStructureForces(c, poly.vertices(), n, m, mass, inertia, area, first, last, structure, fx, fy, fz, tz);
  }
  integrateSymplecticEuler(motion, fx, fy, fz, tz, inverse_mass, inverse_inertia, dt);
  return false;
}

/// The end of a cell's step: the runaway guard and Algorithm 1's rebuild test (lines 14-16)
/// against `reference`, the cell's state at the last contact rebuild.
TIS_HD void judgeCellStep(const ModelConstants& c, double runaway_speed, const CellMotion& reference,
                          const CellMotion& a, CellStepResult& r) {
  const double speed2 = a.vx * a.vx + a.vy * a.vy + a.vz * a.vz;
  r.blown = !isfinite(a.x + a.y + a.z + a.yaw) || !(speed2 < runaway_speed * runaway_speed);
  const double dx = a.x - reference.x, dy = a.y - reference.y;
  r.moved_far = dx * dx + dy * dy > c.rebuild_displacement * c.rebuild_displacement ||
                fabs(a.yaw - reference.yaw) > c.rebuild_rotation;
}

/// One step of cell k: gather, water, planes, symplectic Euler. `motion` is updated in place;
/// `reference` is its state at the last contact rebuild.
TIS_HD CellStepResult stepCell(int k, const ModelConstants& c, const CellStepInputs& in, double pusher_x,
                               double pusher_velocity, double runaway_speed, const CellMotion& reference,
                               CellMotion& motion, StructureContact& structure) {
  CellStepResult r;
  HeldForces held;
  if (beginCellStep(k, c, in, pusher_x, pusher_velocity, motion, structure, r.pusher_fx, held)) {
    CellPolygon start = cellPolygonOf(in, k, motion);  // the first half left the pose as it was
    subcycleStructureContact(k, c, in, start.vertices(), held, motion, structure);
  }
  judgeCellStep(c, runaway_speed, reference, motion, r);
  return r;
}

/// Load of one structure slot of a cell: the force on the structure [N] and its moments [N m]
/// about the structure frame's origin (toe, 0, 0) and about the panel's centre on the waterline.
struct SlotLoad {
  int panel;
  double fx, fy, fz;
  double tx, ty, tz;
  double panel_tx, panel_ty, panel_tz;
};

TIS_HD SlotLoad structureSlotLoad(const ModelConstants& c, const StructureContact& s, int slot) {
  SlotLoad l;
  l.panel = s.first_panel + slot;
  l.fx = s.fx[slot]; l.fy = s.fy[slot]; l.fz = s.fz[slot];
  const double rx = s.px[slot] - c.structure_toe_x, ry = s.py[slot], rz = s.pz[slot];
  const double ry_panel = ry - (c.structure_y_min + (l.panel + 0.5) * c.panel_width);
  l.tx = ry * l.fz - rz * l.fy;
  l.ty = rz * l.fx - rx * l.fz;
  l.tz = rx * l.fy - ry * l.fx;
  l.panel_tx = ry_panel * l.fz - rz * l.fy;
  l.panel_ty = rz * l.fx - rx * l.fz;
  l.panel_tz = rx * l.fy - ry_panel * l.fx;
  return l;
}

}  // namespace thin_ice
