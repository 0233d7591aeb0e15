// Multiple time stepping of the structure contact (physics/cell_forces.hpp): one square cell,
// stepped by stepCell as the backends step it, against answers worked out by hand.
//
// The cell: a 0.2 m square of ice, h = 0.05 m, rho_i = 920 kg/m^3 (m = 1.84 kg), floating at its
// draft with no water drag, so that nothing but the structure and the given pair loads act on it.
// The face is vertical (m = (-1, 0, 0)), so an edge flush with it penetrating by d has
// V = 0.2 d h and Eq. (17) is a linear spring k = K_struct 0.2 m = 3.4e10 N/m:
// omega = sqrt(k/m) = 1.359e5 rad/s, a contact lasting pi/omega = 23 us, less than one outer step.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "thin_ice_sim/physics/cell_forces.hpp"

namespace thin_ice {
namespace {

constexpr double kSide = 0.2;          // [m]
constexpr double kH = 0.05;            // [m]
constexpr double kRhoIce = 920.0;      // [kg/m^3]
constexpr double kRhoWater = 1000.0;   // [kg/m^3]
constexpr double kStiffness = 1.7e11;  // K_struct [Pa]
constexpr double kMass = kRhoIce * kSide * kSide * kH;                       // 1.84 kg
constexpr double kInertia = kRhoIce * kH * kSide * kSide * kSide * kSide / 6.0;  // rho h a^4/6 [kg m^2]
constexpr double kOuterStep = 2.4e-5;  // [s]
constexpr double kBeta = 0.5;          // friction_viscous_limit [-]

/// Constants of a cell alone in still water with a vertical face at x = face_x; no bottom, no
/// walls, the pusher far behind.
ModelConstants loneCell(double face_x, double damping_ratio, double dt, int substeps) {
  ModelConstants c{};
  c.contact.thickness = kH;
  c.water = {kRhoWater, 9.81, kH, 0.0, 0.0, 0.0, 0.0};
  c.structure = {kStiffness, kH, 0.1, damping_ratio, 1e-3, kBeta / (dt / substeps)};
  c.pusher = {1e9, kH, 0.0, damping_ratio, 1e-3, kBeta / dt};
  c.structure_face = {-1.0, 0.0, 0.0, -face_x};
  c.structure_top_z = 1.0;
  c.structure_toe_x = face_x;
  c.structure_y_min = -1.0;
  c.panel_width = 2.0;
  c.panels = 1;
  c.calibration_factor = 1.0;
  c.bottom_enabled = false;
  c.walls_enabled = false;
  c.time_step = dt;
  c.structure_substeps = substeps;
  c.rebuild_displacement = 1e3;
  c.rebuild_rotation = 1e3;
  return c;
}

/// One cell and (optionally) one held pair load on it, stepped as a backend steps it.
struct LoneCell {
  double vertex_x[kMaxPolygonVertices] = {-0.5 * kSide, 0.5 * kSide, 0.5 * kSide, -0.5 * kSide};
  double vertex_y[kMaxPolygonVertices] = {-0.5 * kSide, -0.5 * kSide, 0.5 * kSide, 0.5 * kSide};
  double mass = kMass, inertia = kInertia, area = kSide * kSide;
  double inverse_mass = 1.0 / kMass, inverse_inertia = 1.0 / kInertia, polar_moment = kInertia / (kMass / area);
  int vertex_count = 4;
  Vec2 world[kMaxPolygonVertices];
  double box[4];
  int bond_offsets[2] = {0, 0};
  int bond_entries[1] = {1};  // bond 0, the cell is its j
  unsigned char bond_state[1] = {kBondIntact};
  PairLoad bond_load[1] = {};
  int contact_offsets[2] = {0, 0};
  CellMotion motion{};
  CellMotion reference{};
  double structure_impulse_x = 0.0;  ///< [N s] on the structure, summed over the steps
  double last_structure_fx = 0.0;    ///< [N] mean over the last step

  LoneCell(double x, double vx) {
    motion.x = x;
    motion.z = 0.5 * kH - kRhoIce / kRhoWater * kH;  // floating at the draft
    motion.vx = vx;
    reference = motion;
  }

  /// Holds the horizontal force `fx` [N] on the cell, as a bond's load would be held.
  void holdForce(double fx) {
    bond_offsets[1] = 1;
    bond_load[0].force_on_j = {fx, 0.0};
  }

  /// The step's inputs, with the cell placed at its current pose: its world polygon too, as the
  /// CPU backend places it, unless `keep_world` is false (the CUDA backend keeps none).
  CellStepInputs place(bool keep_world = true) {
    placeCell(motion, vertex_x, vertex_y, vertex_count, keep_world ? world : nullptr, box);
    return {&mass,           &inertia,        &area,         &inverse_mass,
            &inverse_inertia, &polar_moment,   &vertex_count, vertex_x,
            vertex_y,        keep_world ? world : nullptr,    box,           bond_offsets,
            bond_entries,    bond_state,      bond_load,     contact_offsets,
            nullptr,         nullptr,         nullptr};
  }

  void step(const ModelConstants& c, bool keep_world = true, double pusher_x = -100.0, double pusher_velocity = 0.0) {
    const CellStepInputs in = place(keep_world);
    StructureContact s;
    const CellStepResult r = stepCell(0, c, in, pusher_x, pusher_velocity, kRunawaySpeed, reference, motion, s);
    ASSERT_FALSE(r.blown);
    last_structure_fx = 0.0;
    for (int slot = 0; slot < s.panel_count; ++slot) last_structure_fx += s.fx[slot];
    structure_impulse_x += last_structure_fx * c.time_step;
    pusher_impulse_x += r.pusher_fx * c.time_step;
  }

  double pusher_impulse_x = 0.0;  ///< [N s] of the pusher on the cell, summed over the steps
};

TEST(StructureSubsteps, ElasticImpactOnAVerticalFaceReboundsAtTheSpeedItCameIn) {
  // Undamped, the cell leaves at -v0 and gives the face the impulse 2 m v0. Symplectic Euler's
  // energy error over one oscillation is within a factor (1 +- omega dt/2) of its energy, so the
  // exit speed is within omega dt/2 = 1.7 % for 96 sub-steps of 0.25 us (omega dt = 0.034).
  const double v0 = 0.1, face_x = 0.5 * kSide + 1e-6;
  const int substeps = 96;
  const double omega = std::sqrt(kStiffness * kSide / kMass);
  const double bound = 0.5 * omega * kOuterStep / substeps;
  const ModelConstants c = loneCell(face_x, 0.0, kOuterStep, substeps);
  LoneCell cell(0.0, v0);
  for (int s = 0; s < 20; ++s) cell.step(c);  // 480 us: in, bounce, out
  EXPECT_NEAR(cell.motion.vx, -v0, bound * v0);
  EXPECT_NEAR(cell.structure_impulse_x, 2.0 * kMass * v0, bound * 2.0 * kMass * v0);
  EXPECT_LT(cell.motion.x, 0.0);  // on its way back

  // The same outer step without sub-steps cannot resolve the contact (omega dt = 3.3 > 2): one
  // step's penetration v0 dt throws the cell back at about ten times the speed it came in.
  const ModelConstants single = loneCell(face_x, 0.0, kOuterStep, 1);
  LoneCell coarse(0.0, v0);
  for (int s = 0; s < 20; ++s) coarse.step(single);
  EXPECT_LT(coarse.motion.vx, -3.0 * v0);
}

TEST(StructureSubsteps, WithNoOtherForceTheSubstepsAreTheFineSingleRateStep) {
  // Nothing is held (no pair load, no drag, buoyancy balancing weight), so n sub-steps of dt/n
  // must be n single-rate steps of dt/n, up to the rounding of the placement.
  const double v0 = 0.1, face_x = 0.5 * kSide + 1e-6;
  const int substeps = 48;
  LoneCell multi(0.0, v0), fine(0.0, v0);
  const ModelConstants c_multi = loneCell(face_x, 0.2, kOuterStep, substeps);
  const ModelConstants c_fine = loneCell(face_x, 0.2, kOuterStep / substeps, 1);
  for (int s = 0; s < 20; ++s) multi.step(c_multi);
  for (int s = 0; s < 20 * substeps; ++s) fine.step(c_fine);
  EXPECT_NEAR(multi.motion.vx, fine.motion.vx, 1e-9 * v0);
  EXPECT_NEAR(multi.motion.x, fine.motion.x, 1e-12);
  EXPECT_NEAR(multi.structure_impulse_x, fine.structure_impulse_x, 1e-9 * kMass * v0);
  // Damped (zeta = 0.2), it comes back slower than it went in.
  EXPECT_LT(multi.motion.vx, 0.0);
  EXPECT_GT(multi.motion.vx, -v0);
}

TEST(StructureSubsteps, AHeldPushIsCarriedByTheFaceAtItsFullValue) {
  // A held force of 1000 N presses the cell against the face (damped, zeta = 0.2). At rest the
  // face carries exactly 1000 N at a penetration d = F/k = 2.9e-8 m: had the held force been
  // applied per sub-step instead of spread over the step, the face would carry n times it.
  const double push = 1000.0, face_x = 0.5 * kSide;
  for (int substeps : {1, 8}) {
    const double dt = substeps == 1 ? kOuterStep / 8 : kOuterStep;
    const ModelConstants c = loneCell(face_x, 0.2, dt, substeps);
    LoneCell cell(0.0, 0.0);
    cell.holdForce(push);
    for (int s = 0; s < 2000; ++s) cell.step(c);
    EXPECT_NEAR(cell.last_structure_fx, push, 1e-6 * push) << substeps << " sub-steps";
    EXPECT_NEAR(cell.motion.x + 0.5 * kSide - face_x, push / (kStiffness * kSide), 1e-3 * push / (kStiffness * kSide))
        << substeps << " sub-steps";
    EXPECT_NEAR(cell.motion.vx, 0.0, 1e-9) << substeps << " sub-steps";
  }
}

TEST(StructureSubsteps, FarFromTheFaceTheSubstepCountChangesNothing) {
  // A cell 5 m from the face takes one step of dt whatever n is: bit-identical motion.
  ModelConstants c1 = loneCell(5.0, 0.2, kOuterStep, 1), c8 = loneCell(5.0, 0.2, kOuterStep, 8);
  c1.water.linear_drag = c8.water.linear_drag = 20.0;  // a force that changes with the state
  LoneCell one(0.0, 0.3), eight(0.0, 0.3);
  one.holdForce(5.0);
  eight.holdForce(5.0);
  for (int s = 0; s < 500; ++s) {
    one.step(c1);
    eight.step(c8);
  }
  EXPECT_EQ(one.motion.x, eight.motion.x);
  EXPECT_EQ(one.motion.vx, eight.motion.vx);
  EXPECT_EQ(eight.structure_impulse_x, 0.0);
}

TEST(StructureSubsteps, TheFirstHalfHandsOnExactlyTheCellsThatCanReachTheFaceWithinTheStep) {
  // The CUDA backend runs a step in two passes (beginCellStep for every cell, then the sub-steps
  // of the cells it handed on); the CPU backend does the same. A cell at 0.5 m/s with a held
  // 5 N and no drag, buoyancy balancing its weight: it can travel v dt = 1.2e-5 m in a step of
  // 24 us (the held force adds F dt^2/m = 1.6e-9 m), so it is handed on when its front edge is
  // 1.0e-5 m from the face and not when it is 1.4e-5 m away.
  const double v0 = 0.5, push = 5.0;
  const double travel = (v0 + push / kMass * kOuterStep) * kOuterStep;
  for (double gap : {1.0e-5, 1.4e-5}) {
    const ModelConstants c = loneCell(0.5 * kSide + gap, 0.0, kOuterStep, 8);
    LoneCell cell(0.0, v0);
    cell.holdForce(push);
    const CellStepInputs in = cell.place();
    StructureContact s;
    HeldForces held{};
    double pusher_fx = -1.0;
    const bool handed_on = beginCellStep(0, c, in, -100.0, 0.0, cell.motion, s, pusher_fx, held);
    EXPECT_EQ(pusher_fx, 0.0);
    if (gap < travel) {
      ASSERT_TRUE(handed_on) << "gap " << gap;
      EXPECT_EQ(cell.motion.x, 0.0);  // not moved yet: its step is the second half's
      EXPECT_EQ(held.fx, push);
      EXPECT_EQ(held.fy, 0.0);
      EXPECT_NEAR(held.fz, 0.0, 1e-12 * kMass * 9.81);
      EXPECT_NEAR(held.travel, travel, 1e-9 * travel);
      // The second half finishes the step as stepCell does in one call, bit for bit.
      LoneCell whole(0.0, v0);
      whole.holdForce(push);
      const CellStepInputs whole_in = whole.place();
      StructureContact whole_s;
      stepCell(0, c, whole_in, -100.0, 0.0, kRunawaySpeed, whole.reference, whole.motion, whole_s);
      subcycleStructureContact(0, c, in, in.world, held, cell.motion, s);
      EXPECT_EQ(cell.motion.x, whole.motion.x);
      EXPECT_EQ(cell.motion.vx, whole.motion.vx);
      EXPECT_EQ(s.panel_count, whole_s.panel_count);
    } else {
      EXPECT_FALSE(handed_on) << "gap " << gap;
      EXPECT_GT(cell.motion.x, 0.0);  // the whole step is taken in the first half
      EXPECT_EQ(s.panel_count, 0);
    }
  }
  // With one sub-step no cell is handed on, even one pressed into the face.
  const ModelConstants single = loneCell(0.5 * kSide - 1e-6, 0.0, kOuterStep, 1);
  LoneCell pressed(0.0, v0);
  const CellStepInputs in = pressed.place();
  StructureContact s;
  HeldForces held{};
  double pusher_fx = 0.0;
  EXPECT_FALSE(beginCellStep(0, single, in, -100.0, 0.0, pressed.motion, s, pusher_fx, held));
  EXPECT_EQ(s.panel_count, 1);
  EXPECT_GT(s.fx[0], 0.0);  // the ice pushes the structure in +x
}

TEST(StructureSubsteps, ACellStepThatPlacesItsOwnPolygonMovesAsOneGivenThePlacedPolygon) {
  // The CUDA backend keeps no world polygons (CellStepInputs::world null): a cell's step places
  // its own where a plane is within its box (CellPolygon). A turned, irregular pentagon pressed
  // at once by the pusher, a side wall, the false bottom and the structure face (handed on to the
  // sub-steps) must move as it does with the polygon placed beforehand, as the CPU backend
  // places it, to the rounding of the placement (below).
  auto pentagon = [](double y) {
    LoneCell cell(0.0, 0.02);  // at the pusher's speed
    const double px[] = {-0.09, 0.07, 0.1, 0.02, -0.1}, py[] = {-0.1, -0.08, 0.03, 0.1, 0.04};
    for (int v = 0; v < 5; ++v) {
      cell.vertex_x[v] = px[v];
      cell.vertex_y[v] = py[v];
    }
    cell.vertex_count = 5;
    cell.motion.y = y;
    cell.motion.yaw = 0.4;
    cell.motion.vy = 0.05;
    cell.reference = cell.motion;
    return cell;
  };
  double box[4];
  const LoneCell start = pentagon(0.02);
  placeCell(start.motion, start.vertex_x, start.vertex_y, start.vertex_count, nullptr, box);
  ModelConstants c = loneCell(box[1] - 1e-6, 0.2, kOuterStep, 8);  // its front 1 um into the face
  const PlaneContactConstants plane = {1e9, kH, 0.3, 0.2, 1e-3, kBeta / kOuterStep};
  c.pusher = plane;
  c.walls_enabled = true;
  c.wall = plane;
  c.wall_half_width = 0.1;  // the cell, centred at y = 0.02, reaches past it
  c.wall_x_start = 0.0;     // from the cell's middle: only its front part meets the wall
  c.bottom_enabled = true;
  c.bottom = plane;
  c.bottom_x_start = -1.0;
  const double z_low = pentagon(0.0).motion.z - 0.5 * kH;
  c.bottom_z = z_low + 1e-3;  // the bottom 1 mm into the slab
  for (const bool walls_and_bottom : {false, true}) {
    ModelConstants k = c;
    k.walls_enabled = k.bottom_enabled = walls_and_bottom;
    LoneCell placed = pentagon(0.02), own = pentagon(0.02);
    const double pusher_x = box[0] + 2e-4;  // 0.2 mm into the cell's back
    {  // The first step hands the cell on to the sub-steps, which start from the placed polygon.
      LoneCell probe = pentagon(0.02);
      StructureContact s;
      HeldForces held{};
      double pusher_fx = 0.0;
      ASSERT_TRUE(beginCellStep(0, k, probe.place(false), pusher_x, 0.02, probe.motion, s, pusher_fx, held));
    }
    for (int s = 0; s < 40; ++s) {
      placed.step(k, true, pusher_x + 0.02 * s * kOuterStep, 0.02);
      own.step(k, false, pusher_x + 0.02 * s * kOuterStep, 0.02);
    }
    EXPECT_GT(own.pusher_impulse_x, 0.0);
    EXPECT_GT(own.structure_impulse_x, 0.0);
    // Not bit for bit: the compilers fuse multiply-adds (x86-64-v3 here, nvcc on the GPU) where
    // the inlined placement lands, so a vertex placed here and one placed by the backend can
    // differ by one rounding, 1e-17 m. A contact's force goes with its penetration (1 um here), so
    // it can move by 1e-17 / 1e-6 = 1e-11 of itself; the pose by far less. Seen: the motion equal,
    // the structure's impulse one unit in the last place apart. Tried: placing the polygon 0.5 um
    // off the pose moved x by 8e-9 m and the yaw by 9e-8 rad; not placing it at all, by 5e-6 m.
    EXPECT_NEAR(own.motion.x, placed.motion.x, 1e-12);  // [m]
    EXPECT_NEAR(own.motion.y, placed.motion.y, 1e-12);
    EXPECT_NEAR(own.motion.z, placed.motion.z, 1e-12);
    EXPECT_NEAR(own.motion.yaw, placed.motion.yaw, 1e-12);  // [rad]
    EXPECT_NEAR(own.motion.vx, placed.motion.vx, 1e-12);    // [m/s]
    EXPECT_NEAR(own.motion.vy, placed.motion.vy, 1e-12);
    EXPECT_NEAR(own.motion.vz, placed.motion.vz, 1e-12);
    EXPECT_NEAR(own.motion.wz, placed.motion.wz, 1e-12);  // [rad/s]
    EXPECT_NEAR(own.pusher_impulse_x, placed.pusher_impulse_x, 1e-10 * placed.pusher_impulse_x);  // [N s]
    EXPECT_NEAR(own.structure_impulse_x, placed.structure_impulse_x, 1e-10 * placed.structure_impulse_x);
    if (walls_and_bottom) {
      // The wall and the bottom acted: without them the cell moves otherwise.
      LoneCell free = pentagon(0.02);
      ModelConstants none = c;
      none.walls_enabled = none.bottom_enabled = false;
      for (int s = 0; s < 40; ++s) free.step(none, false, pusher_x + 0.02 * s * kOuterStep, 0.02);
      EXPECT_NE(free.motion.vy, own.motion.vy);
      EXPECT_NE(free.motion.vz, own.motion.vz);
    }
  }
}

}  // namespace
}  // namespace thin_ice
