// CUDA backend: the step of the CPU backend (src/core/cpu_backend.cpp) with every stage on the
// device, calling the same inline laws (include/thin_ice_sim/physics/).
//
// One step, six kernels (one thread per cell, bond or pair):
//   placeCells      boxes, (cos, sin) yaw (no world polygons, below)         placeCell()
//   bondForces      RMIB forces and failure, Eqs. 8-13                       rmibBondForce()
//   contactForces   DEM contacts of the candidate pairs, Eqs. 1-4            demContactForce()
//   stepCells       gather, water, planes, symplectic Euler, structure loads beginCellStep()
//   subcycleCells   the structure sub-steps of the cells listed by stepCells  subcycleStructureContact()
//   finishStep      pusher, step counters, Algorithm 1's rebuild test
// The few cells that can reach the structure face take n sub-steps (cell_forces.hpp). Run inside
// stepCells, each such cell held its whole warp for the length of its chain and gave the kernel
// the registers and stack of the longest path (M-2 pile, 6000 cells on an H200: stepCells 155 us
// of a 262 us step, in 47 blocks). So stepCells lists them and subcycleCells runs the list in
// warps of its own, in small blocks spread over the multiprocessors.
// Steps are launched in batches captured as one CUDA graph (kBatchSteps steps): a 75-cell strip
// would otherwise spend its time launching kernels. A step that finds the stop flag set (a
// rebuild is due, or a cell blew up) does nothing, so the host, which looks at the flags after
// each batch, rebuilds before the next step exactly as the CPU backend does.
//
// The contact rebuild stays on the device (contact_list.cuh): only the pair count comes back.
//
// Precision: the state is double, as on the CPU; the polygon intersection works on an integer
// grid laid over each pair (polygon_clip.hpp), so it is exact and order-independent on both.
// Loads are summed with atomics over the cells that touch the structure: they do not feed back,
// but their last bits may differ from run to run (the CPU sums in cell order).
#include "cuda_backend.hpp"

#include <cuda_runtime.h>

#include <algorithm>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact_list.cuh"
#include "thin_ice_sim/physics/pair_separation.hpp"
#include "cuda_check.hpp"
#include "device_array.cuh"
#include "device_info.cuh"
#include "thin_ice_sim/backend.hpp"
#include "thin_ice_sim/incidence.hpp"
#include "thin_ice_sim/model.hpp"
#include "thin_ice_sim/physics/cell_forces.hpp"

namespace thin_ice {
namespace cuda {
namespace {

constexpr int kV = kMaxPolygonVertices;
constexpr int kBatchSteps = 32;    ///< steps per captured graph (flags are read after each batch)
constexpr int kStopRebuild = 1;    ///< flag bits
constexpr int kStopBlown = 2;
constexpr int kLoadTotals = 7;     ///< horizontal, lateral, vertical, pusher, torque x y z
constexpr int kLoadPerPanel = 6;   ///< horizontal, lateral, vertical, torque x y z
constexpr int kSubcycleThreads = 32;     ///< subcycleCells' block: one warp, so the list spreads over the SMs
constexpr int kSubcycleBlocksPerSm = 4;  ///< its grid's cap: blocks per multiprocessor

/// subcycleCells' grid: enough warps for every cell, at most kSubcycleBlocksPerSm per
/// multiprocessor (the list is the few cells at the face; a larger list loops).
int subcycleBlocks(int cells) {
  int device = 0, multiprocessors = 1;
  TIS_CUDA_CHECK(cudaGetDevice(&device));
  TIS_CUDA_CHECK(cudaDeviceGetAttribute(&multiprocessors, cudaDevAttrMultiProcessorCount, device));
  const int wanted = (cells + kSubcycleThreads - 1) / kSubcycleThreads;
  return std::max(1, std::min(wanted, kSubcycleBlocksPerSm * multiprocessors));
}

/// Device scalars of the run, read back after each batch.
struct RunScalars {
  double pusher_x;          ///< [m]
  double pusher_velocity;   ///< [m/s], set by the host before each call
  int flags;                ///< kStopRebuild | kStopBlown raised in this step
  int stop;                 ///< set at the end of a step with flags: later steps do nothing
  int steps_taken;          ///< in this batch
  int steps_since_rebuild;
  int newly_broken;         ///< bonds broken in this step
  int broken_total;
  int touching;             ///< contacts with S > 0 in this step (accumulating)
  int last_touching;        ///< ... in the last step taken
  int pair_count;           ///< candidate pairs in the list
  int subcycled;            ///< cells stepCells listed for subcycleCells in this step
};

// --- The step ---------------------------------------------------------------------------------

// No world polygons are kept: contactForces places the two polygons of a pair where it clips
// them, a cell's step places its own only where a rigid plane is within its box (CellPolygon),
// and stepCells places those of the few cells it hands to subcycleCells.
// Writing up to 12 vertices per cell here and reading them back in the other kernels was the
// largest share of placeCells' 677 B per cell-step at 10^6 cells (H200, 2026-12-04).
__global__ void placeCells(int n, const RunScalars* run, const CellMotion* motion, const double* vertex_x,
                           const double* vertex_y, const int* vertex_count, double* box, Vec2* turn) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= n || run->stop) return;
  turn[k] = placeCell(motion[k], vertex_x + (size_t)k * kV, vertex_y + (size_t)k * kV, vertex_count[k], nullptr,
                      box + 4 * k);
}

// A bond's springs are made again in every step from its 64 B shape and the two masses it reads
// anyway (bondRestOf: the CPU's records, bit for bit), rather than read from a 112 B record:
// 141 B less per cell-step at 2.94 bonds per cell.
__global__ void bondForces(int bonds, RunScalars* run, ModelConstants c, const int* bond_i, const int* bond_j,
                           const BondShape* shape, const CellMotion* motion, const double* mass, const double* inertia,
                           const Vec2* turn, unsigned char* state, PairLoad* load) {
  const int b = blockIdx.x * blockDim.x + threadIdx.x;
  if (b >= bonds || run->stop) return;
  const unsigned char was = state[b];
  if (was == kBondBreaking) state[b] = kBondBroken;  // it applied its last force in the last step
  if (was != kBondIntact) return;
  const int i = bond_i[b], j = bond_j[b];
  const double mass_i = mass[i], mass_j = mass[j];
  const BondForce f = rmibBondForce(bondRestOf(shape[b], mass_i, mass_j, c.bond), bodyOf(motion[i], mass_i, inertia[i]),
                                    turn[i], bodyOf(motion[j], mass_j, inertia[j]), turn[j], c.bond);
  load[b] = bondLoad(f);
  if (f.breaks) {
    state[b] = kBondBreaking;  // for good; its force of this step still acts
    atomicAdd(&run->newly_broken, 1);
  }
}

__global__ void contactForces(int capacity, RunScalars* run, ModelConstants c, const int* pair_i, const int* pair_j,
                              const CellMotion* motion, const double* mass, const double* inertia,
                              const double* vertex_x, const double* vertex_y, const Vec2* turn,
                              const int* vertex_count, const double* radius, const double* box, double* reference,
                              int* separating_edge, unsigned char* touching, PairLoad* load) {
  const int p = blockIdx.x * blockDim.x + threadIdx.x;
  if (p >= capacity || run->stop || p >= run->pair_count) return;
  const int i = pair_i[p], j = pair_j[p];
  const double* bi = box + 4 * i;
  const double* bj = box + 4 * j;
  if (bi[1] <= bj[0] || bj[1] <= bi[0] || bi[3] <= bj[2] || bj[3] <= bi[2]) {
    touching[p] = 0;
    reference[p] = 0.0;
    return;
  }
  // One slab above the other, with no reference overlap to follow: no force, whatever the clip
  // would give (contact.hpp; the CPU backend does the same).
  if (contactSkipsClip(motion[i].z, motion[j].z, c.contact.thickness, reference[p])) {
    touching[p] = 0;
    return;
  }
  // Apart by more than the clip's rounding along the edge that kept them apart last time: the
  // clip would give no overlap (pair_separation.hpp; the CPU backend does the same).
  const int ni = vertex_count[i], nj = vertex_count[j];
  Vec2 wi[kV], wj[kV];
  placeVertices(motion[i], vertex_x + (size_t)i * kV, vertex_y + (size_t)i * kV, ni, turn[i], wi);
  placeVertices(motion[j], vertex_x + (size_t)j * kV, vertex_y + (size_t)j * kV, nj, turn[j], wj);
  const double gap = c.separation_gap_fraction * (radius[i] + radius[j]);
  PolygonOverlap overlap;
  if (!clipUnlessApart(wi, ni, wj, nj, gap, separating_edge[p], overlap)) {
    touching[p] = 0;
    reference[p] = 0.0;
    return;
  }
  const BodyState body_i = bodyOf(motion[i], mass[i], inertia[i]), body_j = bodyOf(motion[j], mass[j], inertia[j]);
  const PairForce f = demContactForce(overlap, body_i, body_j, c.contact, reference[p]);
  load[p] = contactLoad(f, body_i.centroid, body_j.centroid);
  touching[p] = f.touching ? 1 : 0;
  reference[p] = f.reference_area;
  if (f.touching) atomicAdd(&run->touching, 1);
}

/// Adds cell k's structure load (its slots in `s`) to the step's totals and its panels.
__device__ void addStructureLoads(const ModelConstants& c, const StructureContact& s, double* totals, double* panels) {
  for (int slot = 0; slot < s.panel_count; ++slot) {
    const SlotLoad l = structureSlotLoad(c, s, slot);
    atomicAdd(&totals[0], l.fx);
    atomicAdd(&totals[1], l.fy);
    atomicAdd(&totals[2], l.fz);
    atomicAdd(&totals[4], l.tx);
    atomicAdd(&totals[5], l.ty);
    atomicAdd(&totals[6], l.tz);
    double* panel = panels + kLoadPerPanel * l.panel;
    atomicAdd(&panel[0], l.fx);
    atomicAdd(&panel[1], l.fy);
    atomicAdd(&panel[2], l.fz);
    atomicAdd(&panel[3], l.panel_tx);
    atomicAdd(&panel[4], l.panel_ty);
    atomicAdd(&panel[5], l.panel_tz);
  }
}

/// The runaway guard and the rebuild test of a cell whose step is done, raised as run flags.
__device__ void raiseCellFlags(RunScalars* run, const ModelConstants& c, const CellMotion& reference,
                               const CellMotion& motion) {
  CellStepResult r;
  judgeCellStep(c, kRunawaySpeed, reference, motion, r);
  if (r.blown) atomicOr(&run->flags, kStopBlown);
  if (r.moved_far) atomicOr(&run->flags, kStopRebuild);
}

__global__ void stepCells(int n, RunScalars* run, ModelConstants c, CellStepInputs in, const CellMotion* reference,
                          CellMotion* motion, StructureContact* structure, int* subcycled_cells,
                          HeldForces* held, Vec2* start_polygons, double* totals, double* panels) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= n || run->stop) return;
  double pusher_fx = 0.0;
  HeldForces h;
  const bool subcycled =
      beginCellStep(k, c, in, run->pusher_x, run->pusher_velocity, motion[k], structure[k], pusher_fx, h);
  if (pusher_fx != 0.0) atomicAdd(&totals[3], pusher_fx);
  if (subcycled) {  // its step ends in subcycleCells, from its polygon at the step's start
    const int slot = atomicAdd(&run->subcycled, 1);
    subcycled_cells[slot] = k;
    held[slot] = h;
    double box[4];  // placeCell computes it too; placeCells has already written the same box
    placeCell(motion[k], in.vertex_x + (size_t)k * kV, in.vertex_y + (size_t)k * kV, in.vertex_count[k],
              start_polygons + (size_t)slot * kV, box);
    return;
  }
  raiseCellFlags(run, c, reference[k], motion[k]);
  addStructureLoads(c, structure[k], totals, panels);
}

/// The cells stepCells listed, a grid-stride loop over them: the list's length is known only on
/// the device, and the launch is part of a captured graph.
__global__ void subcycleCells(RunScalars* run, ModelConstants c, CellStepInputs in, const CellMotion* reference,
                              CellMotion* motion, StructureContact* structure, const int* subcycled_cells,
                              const HeldForces* held, const Vec2* start_polygons, double* totals, double* panels) {
  if (run->stop) return;
  const int count = run->subcycled;
  for (int slot = blockIdx.x * blockDim.x + threadIdx.x; slot < count; slot += gridDim.x * blockDim.x) {
    const int k = subcycled_cells[slot];
    subcycleStructureContact(k, c, in, start_polygons + (size_t)slot * kV, held[slot], motion[k], structure[k]);
    raiseCellFlags(run, c, reference[k], motion[k]);
    addStructureLoads(c, structure[k], totals, panels);
  }
}

/// The run's scalars after a contact rebuild: the new pair count, no flags, counting anew.
__global__ void startAfterRebuild(RunScalars* run, int pair_count) {
  run->pair_count = pair_count;
  run->flags = 0;
  run->stop = 0;
  run->steps_since_rebuild = 0;
  run->subcycled = 0;
}

__global__ void finishStep(RunScalars* run, double time_step, int max_steps_between_rebuilds) {
  run->subcycled = 0;  // the list is this step's
  if (run->stop) return;
  run->pusher_x += run->pusher_velocity * time_step;
  run->steps_taken += 1;
  run->steps_since_rebuild += 1;
  run->last_touching = run->touching;
  run->touching = 0;
  if (run->newly_broken > 0) {  // the pair now needs a DEM contact
    run->broken_total += run->newly_broken;
    run->newly_broken = 0;
    run->flags |= kStopRebuild;
  }
  if (run->steps_since_rebuild >= max_steps_between_rebuilds) run->flags |= kStopRebuild;
  if (run->flags != 0) run->stop = 1;
}

// --- The backend ------------------------------------------------------------------------------

static_assert(sizeof(BondShape) == 64, "bondForces reads 64 B per bond (docs/performance.md)");

/// The bonds' shapes, from which bondForces makes their springs in every step. The device never
/// sees the model's springs, so a model whose springs are not those of bondRestOf (edited after
/// the build) is refused here rather than stepped otherwise than on the CPU.
std::vector<BondShape> bondShapes(const Model& model) {
  std::vector<BondShape> shapes;
  shapes.reserve(model.bond_rest.size());
  for (size_t b = 0; b < model.bond_rest.size(); ++b) {
    const BondRest& rest = model.bond_rest[b];
    const BondRest made = bondRestOf(rest, model.mass[model.bond_i[b]], model.mass[model.bond_j[b]],
                                     model.constants.bond);
    if (made.k_normal != rest.k_normal || made.k_shear != rest.k_shear || made.k_vertical != rest.k_vertical ||
        made.damping_normal != rest.damping_normal || made.damping_shear != rest.damping_shear ||
        made.damping_vertical != rest.damping_vertical) {
      std::ostringstream msg;
      msg << "CUDA backend: bond " << b << "'s springs are not those its shape, its cells' masses and the ice "
          << "constants give (bondRestOf); the GPU makes them from those, so it would step another model";
      throw std::invalid_argument(msg.str());
    }
    shapes.push_back(rest);  // the shape part
  }
  return shapes;
}

class CudaBackend final : public Backend {
 public:
  explicit CudaBackend(const Model& model)
      : model_(model), n_(model.cell_count), bonds_(static_cast<int>(model.bond_rest.size())), contacts_(n_) {
    TIS_CUDA_CHECK(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking));
    vertex_x_.upload(model.vertex_x);
    vertex_y_.upload(model.vertex_y);
    vertex_count_.upload(model.vertex_count);
    mass_.upload(model.mass);
    inertia_.upload(model.inertia);
    area_.upload(model.area);
    inverse_mass_.upload(model.inverse_mass);
    inverse_inertia_.upload(model.inverse_inertia);
    polar_moment_.upload(model.polar_moment);
    radius_.upload(model.radius);
    bond_i_.upload(model.bond_i);
    bond_j_.upload(model.bond_j);
    bond_shape_.upload(bondShapes(model));
    Incidence bonds;
    bonds.build(n_, model.bond_i, model.bond_j);
    bond_offsets_.upload(bonds.offsets);
    bond_entries_.upload(bonds.entries);
    bond_load_.resize(bonds_);
    bond_state_.resize(bonds_);
    motion_.resize(n_);
    reference_.resize(n_);
    box_.resize(static_cast<size_t>(n_) * 4);
    turn_.resize(n_);
    structure_.resize(n_);
    subcycled_cells_.resize(n_);
    held_.resize(n_);
    start_polygons_.resize(static_cast<size_t>(n_) * kV);
    subcycle_blocks_ = subcycleBlocks(n_);
    totals_.resize(kLoadTotals);
    panels_.resize(static_cast<size_t>(kLoadPerPanel) * model.constants.panels);
    run_.resize(1);
    TIS_CUDA_CHECK(cudaMallocHost(&run_host_, sizeof(RunScalars)));
    reset();
  }

  ~CudaBackend() override {
    if (graph_exec_ != nullptr) cudaGraphExecDestroy(graph_exec_);
    if (run_host_ != nullptr) cudaFreeHost(run_host_);
    if (stream_ != nullptr) cudaStreamDestroy(stream_);
  }

  std::string name() const override { return "cuda"; }

  void reset() override {
    motion_.upload(model_.initial);
    TIS_CUDA_CHECK(cudaMemset(bond_state_.get(), 0, bonds_ * sizeof(unsigned char)));
    TIS_CUDA_CHECK(cudaMemset(bond_load_.get(), 0, bonds_ * sizeof(PairLoad)));
    RunScalars r{};
    r.pusher_x = model_.initial_pusher_x;
    *run_host_ = r;
    TIS_CUDA_CHECK(cudaMemcpy(run_.get(), &r, sizeof(RunScalars), cudaMemcpyHostToDevice));
    contacts_.clear();
    time_ = 0.0;
    steps_ = 0;
    pusher_x_ = model_.initial_pusher_x;
    broken_count_ = 0;
    last_contacts_ = 0;
    health_error_.clear();
    loads_ = LoadSample{};
    rebuild_requested_ = true;
    TIS_CUDA_CHECK(cudaDeviceSynchronize());  // the uploads ran on the legacy stream, the step runs on stream_
  }

  void step(long steps, double pusher_velocity) override {
    const ModelConstants& c = model_.constants;
    TIS_CUDA_CHECK(cudaMemcpyAsync(&run_.get()->pusher_velocity, &pusher_velocity, sizeof(double),
                                   cudaMemcpyHostToDevice, stream_));
    TIS_CUDA_CHECK(cudaMemsetAsync(totals_.get(), 0, totals_.bytes(), stream_));
    TIS_CUDA_CHECK(cudaMemsetAsync(panels_.get(), 0, panels_.bytes(), stream_));
    long taken = 0;
    while (taken < steps && health_error_.empty()) {
      if (rebuild_requested_) rebuildContacts();
      const int batch = static_cast<int>(std::min<long>(steps - taken, kBatchSteps));
      TIS_CUDA_CHECK(cudaMemsetAsync(&run_.get()->steps_taken, 0, sizeof(int), stream_));
      if (batch == kBatchSteps) {
        launchGraph();
      } else {
        for (int s = 0; s < batch; ++s) launchStep();
      }
      TIS_CUDA_CHECK(cudaGetLastError());
      TIS_CUDA_CHECK(cudaMemcpyAsync(run_host_, run_.get(), sizeof(RunScalars), cudaMemcpyDeviceToHost, stream_));
      TIS_CUDA_CHECK(cudaStreamSynchronize(stream_));
      const RunScalars& r = *run_host_;
      if (r.steps_taken == 0) {
        health_error_ = "CUDA backend: a batch took no step (stop flag left set)";
        break;
      }
      for (int s = 0; s < r.steps_taken; ++s) time_ += c.time_step;  // as the CPU adds it
      steps_ += r.steps_taken;
      taken += r.steps_taken;
      pusher_x_ = r.pusher_x;
      broken_count_ = r.broken_total;
      last_contacts_ = r.last_touching;
      if (r.flags & kStopBlown) {
        std::ostringstream msg;
        msg << "numerical blow-up at t = " << time_ << " s: a cell state became non-finite or faster than "
            << kRunawaySpeed << " m/s (time step " << c.time_step << " s)";
        health_error_ = msg.str();
      } else if (r.flags & kStopRebuild) {
        rebuild_requested_ = true;
      }
    }
    loads_ = downloadLoads(taken);
  }

  double time() const override { return time_; }
  long stepCount() const override { return steps_; }
  double pusherPosition() const override { return pusher_x_; }
  LoadSample loads() const override { return loads_; }
  std::string healthError() const override { return health_error_; }

  std::vector<CellSnapshot> cells() const override {
    return makeCellSnapshots(model_, motion_.download(), bond_state_.download());
  }

  long pairsKeptApart() const override {
    TIS_CUDA_CHECK(cudaStreamSynchronize(stream_));
    return contacts_.pairsKeptApart();
  }

  BackendState saveState() const override {
    TIS_CUDA_CHECK(cudaStreamSynchronize(stream_));
    BackendState s;
    s.time = time_;
    s.steps = steps_;
    s.pusher_x = pusher_x_;
    s.motion = motion_.download();
    s.bond_state = bond_state_.download();
    // A bond that broke in the last step taken has applied its last force; the next bondForces
    // launch would retire it. The state says so now, as the CPU's does.
    for (unsigned char& b : s.bond_state) {
      if (b == kBondBreaking) b = kBondBroken;
    }
    contacts_.download(s.contact_i, s.contact_j, s.contact_reference);
    return s;
  }

  void restoreState(const BackendState& s) override {
    reset();
    motion_.upload(s.motion);
    bond_state_.upload(s.bond_state);
    time_ = s.time;
    steps_ = s.steps;
    pusher_x_ = s.pusher_x;
    broken_count_ = countBrokenBonds(s.bond_state);
    RunScalars r{};
    r.pusher_x = pusher_x_;
    r.broken_total = broken_count_;
    *run_host_ = r;
    TIS_CUDA_CHECK(cudaMemcpy(run_.get(), &r, sizeof(RunScalars), cudaMemcpyHostToDevice));
    // The saved pairs are what the first rebuild (rebuild_requested_ is set) carries S_ref from.
    if (contacts_.seed(s.contact_i, s.contact_j, s.contact_reference) && graph_exec_ != nullptr) {
      TIS_CUDA_CHECK(cudaGraphExecDestroy(graph_exec_));
      graph_exec_ = nullptr;
    }
    TIS_CUDA_CHECK(cudaDeviceSynchronize());  // the uploads ran on the legacy stream, the step runs on stream_
  }

 private:
  /// The kernels of one step on stream_ (also what the graph captures).
  void launchStep() {
    const ModelConstants& c = model_.constants;
    RunScalars* run = run_.get();
    placeCells<<<blocksFor(n_), kThreads, 0, stream_>>>(n_, run, motion_.get(), vertex_x_.get(), vertex_y_.get(),
                                                         vertex_count_.get(), box_.get(), turn_.get());
    if (bonds_ > 0) {
      bondForces<<<blocksFor(bonds_), kThreads, 0, stream_>>>(bonds_, run, c, bond_i_.get(), bond_j_.get(),
                                                               bond_shape_.get(), motion_.get(), mass_.get(),
                                                               inertia_.get(), turn_.get(), bond_state_.get(),
                                                               bond_load_.get());
    }
    const int capacity = contacts_.capacity();
    contactForces<<<blocksFor(capacity), kThreads, 0, stream_>>>(
        capacity, run, c, contacts_.pairI(), contacts_.pairJ(), motion_.get(), mass_.get(), inertia_.get(),
        vertex_x_.get(), vertex_y_.get(), turn_.get(), vertex_count_.get(), radius_.get(), box_.get(),
        contacts_.referenceArea(),
        contacts_.separatingEdge(), contacts_.touching(),
        contacts_.load());
    const CellStepInputs in = {mass_.get(),
                               inertia_.get(),
                               area_.get(),
                               inverse_mass_.get(),
                               inverse_inertia_.get(),
                               polar_moment_.get(),
                               vertex_count_.get(),
                               vertex_x_.get(),
                               vertex_y_.get(),
                               nullptr,  // no world polygons: placed where needed
                               box_.get(),
                               bond_offsets_.get(),
                               bond_entries_.get(),
                               bond_state_.get(),
                               bond_load_.get(),
                               contacts_.incidenceOffsets(),
                               contacts_.incidenceEntries(),
                               contacts_.touching(),
                               contacts_.load()};
    stepCells<<<blocksFor(n_), kThreads, 0, stream_>>>(n_, run, c, in, reference_.get(), motion_.get(),
                                                        structure_.get(), subcycled_cells_.get(), held_.get(),
                                                        start_polygons_.get(), totals_.get(), panels_.get());
    if (c.structure_substeps > 1) {
      subcycleCells<<<subcycle_blocks_, kSubcycleThreads, 0, stream_>>>(
          run, c, in, reference_.get(), motion_.get(), structure_.get(), subcycled_cells_.get(), held_.get(),
          start_polygons_.get(), totals_.get(), panels_.get());
    }
    finishStep<<<1, 1, 0, stream_>>>(run, c.time_step, c.max_steps_between_rebuilds);
  }

  /// kBatchSteps steps as one graph launch; captured again whenever the pair buffers moved.
  void launchGraph() {
    if (graph_exec_ == nullptr) {
      cudaGraph_t graph;
      TIS_CUDA_CHECK(cudaStreamBeginCapture(stream_, cudaStreamCaptureModeThreadLocal));
      for (int s = 0; s < kBatchSteps; ++s) launchStep();
      TIS_CUDA_CHECK(cudaStreamEndCapture(stream_, &graph));
      TIS_CUDA_CHECK(cudaGraphInstantiate(&graph_exec_, graph, 0));
      TIS_CUDA_CHECK(cudaGraphDestroy(graph));
    }
    TIS_CUDA_CHECK(cudaGraphLaunch(graph_exec_, stream_));
  }

  void rebuildContacts() {
    const ModelConstants& c = model_.constants;
    const CandidateInputs in = {n_,          motion_.get(),       radius_.get(),      c.search_radius,
                                c.search_margin, bond_offsets_.get(), bond_entries_.get(), bond_i_.get(),
                                bond_j_.get(), bond_state_.get()};
    if (contacts_.rebuild(in, stream_) && graph_exec_ != nullptr) {  // it holds the old pointers and sizes
      TIS_CUDA_CHECK(cudaGraphExecDestroy(graph_exec_));
      graph_exec_ = nullptr;
    }
    // Algorithm 1: the state at this rebuild is the reference of the next test; clear the flags.
    TIS_CUDA_CHECK(cudaMemcpyAsync(reference_.get(), motion_.get(), n_ * sizeof(CellMotion), cudaMemcpyDeviceToDevice,
                                   stream_));
    startAfterRebuild<<<1, 1, 0, stream_>>>(run_.get(), contacts_.count());
    TIS_CUDA_CHECK(cudaGetLastError());
    rebuild_requested_ = false;
  }

  LoadSample downloadLoads(long taken) const {
    const ModelConstants& c = model_.constants;
    const std::vector<double> totals = totals_.download();
    const std::vector<double> panels = panels_.download();
    LoadSample sum;
    sum.panel_horizontal.assign(c.panels, 0.0);
    sum.panel_lateral.assign(c.panels, 0.0);
    sum.panel_vertical.assign(c.panels, 0.0);
    sum.panel_torque.assign(c.panels, Torque3{});
    // The device's sums over the steps taken; averageSummedLoads makes them the sample's means.
    sum.horizontal_raw = totals[0];
    sum.lateral_raw = totals[1];
    sum.vertical_raw = totals[2];
    sum.pusher_force = totals[3];
    sum.torque = {totals[4], totals[5], totals[6]};
    for (int p = 0; p < c.panels; ++p) {
      const double* q = &panels[static_cast<size_t>(kLoadPerPanel) * p];
      sum.panel_horizontal[p] = q[0];
      sum.panel_lateral[p] = q[1];
      sum.panel_vertical[p] = q[2];
      sum.panel_torque[p] = {q[3], q[4], q[5]};
    }
    averageSummedLoads(sum, taken, c.calibration_factor);
    sum.time = time_;
    sum.pushed_length = pusher_x_ - model_.initial_pusher_x;
    sum.broken_bonds = broken_count_;
    sum.intact_bonds = bonds_ - broken_count_;
    sum.contacts = last_contacts_;
    return sum;
  }

  const Model& model_;
  const int n_, bonds_;
  cudaStream_t stream_ = nullptr;
  cudaGraphExec_t graph_exec_ = nullptr;
  RunScalars* run_host_ = nullptr;  ///< pinned
  // Fixed model.
  DeviceArray<double> vertex_x_, vertex_y_, mass_, inertia_, area_, radius_;
  DeviceArray<double> inverse_mass_, inverse_inertia_, polar_moment_;
  DeviceArray<int> vertex_count_, bond_i_, bond_j_, bond_offsets_, bond_entries_;
  DeviceArray<BondShape> bond_shape_;  ///< (bonds) the springs follow from it (bondRestOf)
  // State.
  DeviceArray<CellMotion> motion_, reference_;
  DeviceArray<unsigned char> bond_state_;  ///< (bonds) BondState
  DeviceArray<PairLoad> bond_load_;  ///< (bonds)
  DeviceArray<Vec2> turn_;
  DeviceArray<double> box_;
  DeviceArray<StructureContact> structure_;
  DeviceArray<int> subcycled_cells_;  ///< (cells) the cells listed for subcycleCells, run->subcycled of them
  DeviceArray<HeldForces> held_;      ///< (cells) what their sub-steps hold, by list slot
  DeviceArray<Vec2> start_polygons_;  ///< (cells x kV) their polygons at the step's start, by list slot
  int subcycle_blocks_ = 1;           ///< subcycleCells' grid
  DeviceArray<double> totals_, panels_;
  DeviceArray<RunScalars> run_;
  DeviceContactList contacts_;
  bool rebuild_requested_ = true;
  double time_ = 0.0;
  long steps_ = 0;
  double pusher_x_ = 0.0;
  int broken_count_ = 0;
  int last_contacts_ = 0;
  LoadSample loads_;
  std::string health_error_;
};

std::string unavailableReason() {
  try {
    return deviceCount() > 0 ? std::string() : std::string("no CUDA device is present");
  } catch (const std::exception& e) {
    return std::string("the CUDA runtime failed: ") + e.what();
  }
}

std::unique_ptr<Backend> makeBackend(const Model& model) { return std::make_unique<CudaBackend>(model); }

const GpuBackendProvider kProvider = {unavailableReason, deviceDescription, makeBackend, deviceMemoryInUse};

}  // namespace

void registerCudaBackend() { setGpuBackendProvider(&kProvider); }

}  // namespace cuda
}  // namespace thin_ice
