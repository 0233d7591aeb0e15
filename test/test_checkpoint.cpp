// Checkpoints: a run split at a checkpoint written to a file and read back goes on bit for bit
// as the run that was never stopped (on each backend), and bad files or states that do not fit
// are refused with the reason, changing nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "thin_ice_sim/backend.hpp"
#include "thin_ice_sim/built_backends.hpp"
#include "thin_ice_sim/checkpoint.hpp"
#include "thin_ice_sim/scenario.hpp"
#include "thin_ice_sim/simulation.hpp"
#include "every_backend.hpp"

namespace thin_ice {
namespace {

using test::EveryBackend;
using test::gpuMissing;

const std::string kQuick = std::string(THIN_ICE_SOURCE_DIR) + "/config/scenarios/quick.yaml";

/// quick.yaml cut to a 1 m strip 0.1 m from the structure: it meets the face after ~0.27 s.
Scenario strip(const std::string& length = "1.0") {
  return loadScenario(kQuick, {"sheet.length=" + length, "structure.toe_x=1.1", "bottom.distance_from_structure=0.5"});
}

std::string temporaryPath(const std::string& name) {
  return ::testing::TempDir() + "/thin_ice_checkpoint_" + name;
}

std::string fileBytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

THIN_ICE_EVERY_BACKEND();

/// The cells bit for bit; the loads too on the CPU. The GPU sums the loads with atomics, whose
/// order (and so their last bits) varies from run to run (cuda_backend.cu); they feed nothing back.
void expectSameRun(const Simulation& a, const Simulation& b, BackendKind backend) {
  ASSERT_EQ(a.stepCount(), b.stepCount());
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(a.pusherPosition(), b.pusherPosition());
  const LoadSample la = a.loads(), lb = b.loads();
  const double sum_order = backend == BackendKind::kCpu ? 0.0 : 1e-12;  // relative
  EXPECT_NEAR(la.horizontal_raw, lb.horizontal_raw, sum_order * std::fabs(la.horizontal_raw));
  EXPECT_NEAR(la.vertical_raw, lb.vertical_raw, sum_order * std::fabs(la.vertical_raw));
  EXPECT_NEAR(la.pusher_force, lb.pusher_force, sum_order * std::fabs(la.pusher_force));
  EXPECT_EQ(la.broken_bonds, lb.broken_bonds);
  EXPECT_EQ(la.contacts, lb.contacts);
  const std::vector<CellSnapshot> ca = a.cells(), cb = b.cells();
  ASSERT_EQ(ca.size(), cb.size());
  for (size_t k = 0; k < ca.size(); ++k) {
    ASSERT_EQ(ca[k].x, cb[k].x) << "cell " << k;
    ASSERT_EQ(ca[k].y, cb[k].y) << "cell " << k;
    ASSERT_EQ(ca[k].z, cb[k].z) << "cell " << k;
    ASSERT_EQ(ca[k].yaw, cb[k].yaw) << "cell " << k;
    ASSERT_EQ(ca[k].vx, cb[k].vx) << "cell " << k;
    ASSERT_EQ(ca[k].vz, cb[k].vz) << "cell " << k;
    ASSERT_EQ(ca[k].wz, cb[k].wz) << "cell " << k;
  }
}

TEST_P(EveryBackend, ARunSplitAtACheckpointFileGoesOnBitForBit) {
  // Stopped at 0.45 s, with the sheet against the face, 9 bonds broken and pairs in contact, so
  // that S_ref, the bond states and the pusher all have to come back; gone on to 1.3 s, past the
  // next failure (between 1.1 and 1.2 s, 13 bonds: quick.yaml as shipped, `thin_ice run`).
  Simulation straight(strip(), GetParam());
  Simulation first_half(strip(), GetParam());
  straight.advance(0.45);
  first_half.advance(0.45);
  ASSERT_TRUE(first_half.healthy()) << first_half.lastError();
  ASSERT_GT(first_half.loads().broken_bonds, 0);
  ASSERT_GT(first_half.loads().contacts, 0);
  ASSERT_GT(first_half.loads().horizontal_raw, 0.0);
  const std::string path = temporaryPath("split.bin");
  writeCheckpoint(path, takeCheckpoint(first_half));

  Simulation second_half(strip(), GetParam());
  restoreCheckpoint(second_half, readCheckpoint(path));
  EXPECT_EQ(second_half.time(), first_half.time());
  EXPECT_EQ(second_half.pushedLength(), first_half.pushedLength());
  straight.advance(0.85);
  second_half.advance(0.85);
  ASSERT_TRUE(second_half.healthy()) << second_half.lastError();
  EXPECT_GT(second_half.loads().broken_bonds, first_half.loads().broken_bonds);  // 13 against 9
  expectSameRun(straight, second_half, GetParam());
  std::remove(path.c_str());
}

/// The strip run on the CPU to 0.45 s, a state worth handing on (contacts, broken bonds, a load on
/// the structure), its checkpoint restored into a simulation on `kind`, and both stepped 50 steps
/// on: the restored one stays healthy, at the same step, with every cell within `tolerance` [m] of
/// the CPU's.
void expectACpuCheckpointGoesOn(BackendKind kind, double tolerance) {
  Simulation cpu(strip(), BackendKind::kCpu);
  cpu.advance(0.45);
  ASSERT_TRUE(cpu.healthy()) << cpu.lastError();
  EXPECT_GT(cpu.loads().contacts, 0);
  EXPECT_GT(cpu.loads().broken_bonds, 0);
  EXPECT_GT(cpu.loads().horizontal_raw, 0.0);
  Simulation restored(strip(), kind);
  restoreCheckpoint(restored, takeCheckpoint(cpu));
  cpu.step(50);
  restored.step(50);
  ASSERT_TRUE(restored.healthy()) << restored.lastError();
  EXPECT_EQ(restored.stepCount(), cpu.stepCount());
  const std::vector<CellSnapshot> a = cpu.cells(), b = restored.cells();
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) {
    ASSERT_NEAR(a[k].x, b[k].x, tolerance) << "cell " << k;
    ASSERT_NEAR(a[k].y, b[k].y, tolerance) << "cell " << k;
    ASSERT_NEAR(a[k].z, b[k].z, tolerance) << "cell " << k;
  }
}

TEST(Checkpoint, ACpuCheckpointGoesOnOnTheGpu) {
  if (!gpuMissing().empty()) GTEST_SKIP() << "no GPU run: " << gpuMissing();
  // The backends agree to rounding, not bit for bit (fused multiply-adds): 50 steps on, every
  // cell is where the CPU has it to 1e-9 m, as test_cuda_backend asks of a run from rest.
  expectACpuCheckpointGoesOn(BackendKind::kCuda, 1e-9);
}

// The CPU half of ACpuCheckpointGoesOnOnTheGpu, which is skipped without a GPU: the state it hands
// on is a meaningful one, and restored on the CPU it goes on bit for bit as the run it was taken of.
TEST(Checkpoint, ACpuCheckpointGoesOnOnTheGpuHasAHealthyCpuHalf) {
  expectACpuCheckpointGoesOn(BackendKind::kCpu, 0.0);
}

TEST(Checkpoint, TheFileHoldsEveryFieldAsItWas) {
  Checkpoint c;
  c.scenario_hash = "0123456789abcdef";
  c.pusher_velocity = 0.05;
  c.state.time = 1.25;
  c.state.steps = 50000;
  c.state.pusher_x = 2.0625;
  c.state.motion = {{1.0, 2.0, -0.02, 0.1, 0.5, -0.25, 0.125, 3.0}, {4.0, 5.0, 0.0, -0.1, 0.0, 0.0, 0.0, 0.0}};
  c.state.bond_state = {kBondIntact, kBondBroken, kBondIntact};
  c.state.contact_i = {0};
  c.state.contact_j = {1};
  c.state.contact_reference = {-1.0};
  const std::string path = temporaryPath("fields.bin");
  writeCheckpoint(path, c);
  const Checkpoint r = readCheckpoint(path);
  EXPECT_EQ(r.scenario_hash, c.scenario_hash);
  EXPECT_EQ(r.pusher_velocity, 0.05);
  EXPECT_EQ(r.state.time, 1.25);
  EXPECT_EQ(r.state.steps, 50000);
  EXPECT_EQ(r.state.pusher_x, 2.0625);
  ASSERT_EQ(r.state.motion.size(), 2u);
  EXPECT_EQ(r.state.motion[0].z, -0.02);
  EXPECT_EQ(r.state.motion[0].wz, 3.0);
  EXPECT_EQ(r.state.motion[1].yaw, -0.1);
  EXPECT_EQ(r.state.bond_state, c.state.bond_state);
  EXPECT_EQ(r.state.contact_i, c.state.contact_i);
  EXPECT_EQ(r.state.contact_j, c.state.contact_j);
  EXPECT_EQ(r.state.contact_reference, c.state.contact_reference);
  EXPECT_TRUE(r.checksummed);
  // magic 8, mark 4, hash 4 + 16, four scalars 4 x 8, cells 8 + 2 x 64, bonds 8 + 3,
  // one pair 8 + 4 + 4 + 8, checksum 8, end 8 bytes
  EXPECT_EQ(fileBytes(path).size(), 8u + 4 + 20 + 32 + 136 + 11 + 24 + 8 + 8);
  std::remove(path.c_str());
}

/// readCheckpoint(path of `bytes`) must throw a runtime_error whose message holds `part`.
void expectUnreadable(const std::string& bytes, const std::string& part) {
  const std::string path = temporaryPath("bad.bin");
  writeBytes(path, bytes);
  try {
    readCheckpoint(path);
    ADD_FAILURE() << "read a bad file; expected: " << part;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

TEST(Checkpoint, BadFilesAreRefusedWithTheReason) {
  Simulation sim(strip(), BackendKind::kCpu);
  sim.advance(0.01);
  const std::string path = temporaryPath("good.bin");
  writeCheckpoint(path, takeCheckpoint(sim));
  const std::string good = fileBytes(path);
  std::remove(path.c_str());
  expectUnreadable("", "truncated");
  expectUnreadable("cell,x_m,y_m\n0,1,2\n", "header");
  expectUnreadable(good.substr(0, good.size() / 2), "truncated");
  expectUnreadable(good.substr(0, good.size() - 3), "truncated");
  expectUnreadable(good + "x", "1 bytes after the end mark");
  std::string swapped = good;
  std::reverse(swapped.begin() + 8, swapped.begin() + 12);  // the byte-order mark as the other order writes it
  expectUnreadable(swapped, "byte order");
  std::string huge = good;
  // The cell count sits after magic, mark, hash (4 + 16), velocity, time, steps and pusher x.
  const size_t cell_count_at = 8 + 4 + 4 + sim.scenario().hash.size() + 4 * 8;
  huge[cell_count_at + 6] = 0x7f;  // ~3.6e16 cells: refused before any allocation
  expectUnreadable(huge, "truncated in cells");
  expectUnreadable(std::string(8, 'x') + good.substr(8), "header");
  // One flipped bit anywhere in the contents, here in the first cell's x (the outside tester's
  // case: it resumed silently before format 2), and a flipped exponent byte of the same number
  // (a cell 5.6e306 m away): the checksum refuses both.
  const size_t first_cell_x = cell_count_at + 8;
  std::string flipped = good;
  flipped[first_cell_x] ^= 0x01;
  expectUnreadable(flipped, "checksum does not match");
  std::string far = good;
  far[first_cell_x + 7] ^= 0x40;
  expectUnreadable(far, "checksum does not match");
}

TEST(Checkpoint, AFileOfFormat1WithoutAChecksumIsStillRead) {
  // Format 1: format 2 less its checksum, under the header TICKPT01 (the committed long runs'
  // checkpoints and bench/states/ are of it). It reads as it was written, marked unchecksummed.
  Simulation sim(strip(), BackendKind::kCpu);
  sim.advance(0.01);
  const std::string path = temporaryPath("format1.bin");
  writeCheckpoint(path, takeCheckpoint(sim));
  std::string bytes = fileBytes(path);
  bytes[7] = '1';
  bytes.erase(bytes.size() - 16, 8);  // the checksum, before the end mark
  writeBytes(path, bytes);
  const Checkpoint old = readCheckpoint(path);
  EXPECT_FALSE(old.checksummed);
  EXPECT_EQ(old.state.steps, sim.stepCount());
  EXPECT_EQ(old.state.motion.size(), static_cast<size_t>(sim.cellCount()));
  EXPECT_EQ(old.state.motion.back().x, sim.saveState().motion.back().x);
  std::remove(path.c_str());
}

TEST(Checkpoint, AStateThatDoesNotFitTheModelIsRefusedAndChangesNothing) {
  Simulation small(strip("1.0"), BackendKind::kCpu), other(strip("0.9"), BackendKind::kCpu);
  small.advance(0.02);
  other.advance(0.01);
  const double before = other.time();
  try {
    restoreCheckpoint(other, takeCheckpoint(small));
    ADD_FAILURE() << "restored another scenario's checkpoint";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("scenario hash"), std::string::npos) << e.what();
  }
  EXPECT_EQ(other.time(), before);

  const double small_time = small.time();
  BackendState state = small.saveState();
  state.motion.pop_back();
  try {
    small.restoreState(state);
    ADD_FAILURE() << "restored a state with another cell count";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cells saved"), std::string::npos) << e.what();
  }
  state = small.saveState();
  ASSERT_GE(state.contact_i.size(), 2u);
  std::swap(state.contact_i[0], state.contact_i[1]);
  std::swap(state.contact_j[0], state.contact_j[1]);
  EXPECT_THROW(small.restoreState(state), std::invalid_argument);
  state = small.saveState();
  state.bond_state[0] = 7;
  EXPECT_THROW(small.restoreState(state), std::invalid_argument);
  state = small.saveState();
  state.motion[3].vz = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(small.restoreState(state), std::invalid_argument);
  EXPECT_EQ(small.time(), small_time);  // every refusal left the run where it was
}

}  // namespace
}  // namespace thin_ice
