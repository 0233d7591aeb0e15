// CUDA backend: the step of the CPU backend (src/core/cpu_backend.cpp) with every stage on the
// device, calling the same inline laws (include/thin_ice_sim/physics/).
//
// One step, five kernels (one thread per cell, bond or pair):
//   placeCells     world polygons, boxes, (cos, sin) yaw                     placeCell()
//   bondForces     RMIB forces and failure, Eqs. 8-13                        rmibBondForce()
//   contactForces  DEM contacts of the candidate pairs, Eqs. 1-4             demContactForce()
//   stepCells      gather, water, planes, symplectic Euler, structure loads  stepCell()
//   finishStep     pusher, step counters, Algorithm 1's rebuild test
// Steps are launched in batches captured as one CUDA graph (kBatchSteps steps): a 75-cell strip
// would otherwise spend its time launching kernels. A step that finds the stop flag set (a
// rebuild is due, or a cell blew up) does nothing, so the host, which looks at the flags after
// each batch, rebuilds before the next step exactly as the CPU backend does.
//
// The contact rebuild stays on the device (no host round trip but the pair count): cells are
// hashed to bins of the search radius, sorted by bin with cub, each cell counts and then writes
// its neighbours j > i (sorted by j, so the list is sorted by (i, j) as on the CPU), a pair keeps
// the reference overlap S_ref it had in the old list (binary search), and the per-cell incidence
// lists are built and sorted into pair order, so the gather sums in the CPU's order.
//
// Precision: the state is double, as on the CPU; the polygon intersection works on an integer
// grid laid over each pair (polygon_clip.hpp), so it is exact and order-independent on both.
// Loads are summed with atomics over the cells that touch the structure: they do not feed back,
// but their last bits may differ from run to run (the CPU sums in cell order).
#include "cuda_backend.hpp"

#include <cub/cub.cuh>
#include <cuda_runtime.h>

#include <algorithm>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cuda_check.hpp"
#include "device_info.cuh"
#include "thin_ice_sim/backend.hpp"
#include "thin_ice_sim/incidence.hpp"
#include "thin_ice_sim/model.hpp"
#include "thin_ice_sim/physics/cell_forces.hpp"

namespace thin_ice {
namespace cuda {
namespace {

constexpr int kV = kMaxPolygonVertices;
constexpr int kThreads = 128;      ///< threads per block: the polygon kernels keep ~1 kB on the stack
constexpr int kBatchSteps = 32;    ///< steps per captured graph (flags are read after each batch)
constexpr int kStopRebuild = 1;    ///< flag bits
constexpr int kStopBlown = 2;
constexpr int kLoadTotals = 7;     ///< horizontal, lateral, vertical, pusher, torque x y z
constexpr int kLoadPerPanel = 6;   ///< horizontal, lateral, vertical, torque x y z

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
};

template <class T>
class DeviceArray {
 public:
  DeviceArray() = default;
  DeviceArray(const DeviceArray&) = delete;
  DeviceArray& operator=(const DeviceArray&) = delete;
  ~DeviceArray() { if (data_ != nullptr) cudaFree(data_); }
  /// Room for `count` elements; when it must grow, the contents are dropped.
  void resize(size_t count) {
    if (count <= capacity_) { size_ = count; return; }
    if (data_ != nullptr) TIS_CUDA_CHECK(cudaFree(data_));
    data_ = nullptr;
    TIS_CUDA_CHECK(cudaMalloc(&data_, std::max<size_t>(count, 1) * sizeof(T)));
    capacity_ = std::max<size_t>(count, 1);
    size_ = count;
  }
  void upload(const std::vector<T>& host) {
    resize(host.size());
    if (!host.empty()) TIS_CUDA_CHECK(cudaMemcpy(data_, host.data(), host.size() * sizeof(T), cudaMemcpyHostToDevice));
  }
  std::vector<T> download() const {
    std::vector<T> host(size_);
    if (size_ > 0) TIS_CUDA_CHECK(cudaMemcpy(host.data(), data_, size_ * sizeof(T), cudaMemcpyDeviceToHost));
    return host;
  }
  T* get() const { return data_; }
  size_t size() const { return size_; }
  size_t bytes() const { return capacity_ * sizeof(T); }

 private:
  T* data_ = nullptr;
  size_t size_ = 0, capacity_ = 0;
};

int blocksFor(long long count) { return static_cast<int>(std::max<long long>(1, (count + kThreads - 1) / kThreads)); }

// --- The step ---------------------------------------------------------------------------------

__global__ void placeCells(int n, const RunScalars* run, const CellMotion* motion, const double* vertex_x,
                           const double* vertex_y, const int* vertex_count, Vec2* world, double* box, Vec2* turn) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= n || run->stop) return;
  turn[k] = placeCell(motion[k], vertex_x + (size_t)k * kV, vertex_y + (size_t)k * kV, vertex_count[k],
                      world + (size_t)k * kV, box + 4 * k);
}

__device__ BodyState bodyOf(const CellMotion& m, double mass, double inertia) {
  return {{m.x, m.y}, m.z, {m.vx, m.vy}, m.vz, m.wz, mass, inertia};
}

__global__ void bondForces(int bonds, RunScalars* run, ModelConstants c, const int* bond_i, const int* bond_j,
                           const BondRest* rest, const CellMotion* motion, const double* mass, const double* inertia,
                           const Vec2* turn, unsigned char* broken, BondForce* force) {
  const int b = blockIdx.x * blockDim.x + threadIdx.x;
  if (b >= bonds || run->stop) return;
  if (broken[b]) {
    force[b].breaks = false;  // it broke in the last step and has applied its last force
    return;
  }
  const int i = bond_i[b], j = bond_j[b];
  const BondForce f = rmibBondForce(rest[b], bodyOf(motion[i], mass[i], inertia[i]), turn[i],
                                    bodyOf(motion[j], mass[j], inertia[j]), turn[j], c.bond);
  force[b] = f;
  if (f.breaks) {
    broken[b] = 1;  // for good; its force of this step still acts
    atomicAdd(&run->newly_broken, 1);
  }
}

__global__ void contactForces(int capacity, RunScalars* run, ModelConstants c, const int* pair_i, const int* pair_j,
                              const CellMotion* motion, const double* mass, const double* inertia, const Vec2* world,
                              const int* vertex_count, const double* box, double* reference, PairForce* force) {
  const int p = blockIdx.x * blockDim.x + threadIdx.x;
  if (p >= capacity || run->stop || p >= run->pair_count) return;
  const int i = pair_i[p], j = pair_j[p];
  const double* bi = box + 4 * i;
  const double* bj = box + 4 * j;
  if (bi[1] <= bj[0] || bj[1] <= bi[0] || bi[3] <= bj[2] || bj[3] <= bi[2]) {
    force[p].touching = false;
    reference[p] = 0.0;
    return;
  }
  const PolygonOverlap overlap = intersectConvexPolygons(world + (size_t)i * kV, vertex_count[i],
                                                         world + (size_t)j * kV, vertex_count[j]);
  const PairForce f = demContactForce(overlap, bodyOf(motion[i], mass[i], inertia[i]),
                                      bodyOf(motion[j], mass[j], inertia[j]), c.contact, reference[p]);
  force[p] = f;
  reference[p] = f.reference_area;
  if (f.touching) atomicAdd(&run->touching, 1);
}

__global__ void stepCells(int n, RunScalars* run, ModelConstants c, CellStepInputs in, const CellMotion* reference,
                          CellMotion* motion, StructureContact* structure, double* totals, double* panels) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= n || run->stop) return;
  const CellStepResult r = stepCell(k, c, in, run->pusher_x, run->pusher_velocity, kRunawaySpeed, reference[k],
                                    motion[k], structure[k]);
  if (r.blown) atomicOr(&run->flags, kStopBlown);
  if (r.moved_far) atomicOr(&run->flags, kStopRebuild);
  if (r.pusher_fx != 0.0) atomicAdd(&totals[3], r.pusher_fx);
  const StructureContact& s = structure[k];
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

__global__ void finishStep(RunScalars* run, double time_step, int max_steps_between_rebuilds) {
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

// --- The contact rebuild ----------------------------------------------------------------------

/// Bin coordinates of a point for bins of side `bin` [m].
__device__ void binOf(const CellMotion& m, double bin, long long& bx, long long& by) {
  bx = (long long)floor(m.x / bin);
  by = (long long)floor(m.y / bin);
}

__device__ unsigned int hashBin(long long bx, long long by, unsigned int table_mask) {
  return (static_cast<unsigned int>(bx * 73856093LL) ^ static_cast<unsigned int>(by * 19349663LL)) & table_mask;
}

__global__ void hashCells(int n, const CellMotion* motion, double bin, unsigned int table_mask, unsigned int* keys,
                          int* cells) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= n) return;
  long long bx, by;
  binOf(motion[k], bin, bx, by);
  keys[k] = hashBin(bx, by, table_mask);
  cells[k] = k;
}

__global__ void binBounds(int n, const unsigned int* sorted_keys, int* bin_start, int* bin_end) {
  const int s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s >= n) return;
  const unsigned int key = sorted_keys[s];
  if (s == 0 || sorted_keys[s - 1] != key) bin_start[key] = s;
  if (s == n - 1 || sorted_keys[s + 1] != key) bin_end[key] = s + 1;
}

struct RebuildView {
  int n;
  const CellMotion* motion;
  const double* radius;
  double search_radius, margin, bin;
  unsigned int table_mask;
  const int* bin_start;
  const int* bin_end;
  const int* sorted_cells;
  const int* bond_offsets;
  const int* bond_entries;
  const int* bond_i;
  const int* bond_j;
  const unsigned char* bond_broken;
};

/// Calls visit(j) for every j > i that is a contact candidate of i: centroids within the search
/// radius and bounding circles (radius + margin) that meet, and no intact bond between them
/// (the CPU's rebuildContacts()). Bins that hash alike are visited once.
template <class Visit>
__device__ void forEachCandidate(const RebuildView& v, int i, Visit visit) {
  const CellMotion& a = v.motion[i];
  long long bx, by;
  binOf(a, v.bin, bx, by);
  unsigned int seen[9];
  int seen_count = 0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const unsigned int key = hashBin(bx + dx, by + dy, v.table_mask);
      bool repeated = false;
      for (int s = 0; s < seen_count; ++s) repeated = repeated || seen[s] == key;
      if (repeated) continue;
      seen[seen_count++] = key;
      const int begin = v.bin_start[key], end = v.bin_end[key];
      for (int s = begin; s < end; ++s) {
        const int j = v.sorted_cells[s];
        if (j <= i) continue;
        const double ex = v.motion[j].x - a.x, ey = v.motion[j].y - a.y;
        const double d2 = ex * ex + ey * ey;
        if (d2 > v.search_radius * v.search_radius) continue;
        const double reach = v.radius[i] + v.radius[j] + v.margin;
        if (d2 > reach * reach) continue;
        bool bonded = false;
        for (int e = v.bond_offsets[i]; e < v.bond_offsets[i + 1] && !bonded; ++e) {
          const int b = v.bond_entries[e] >> 1;
          bonded = !v.bond_broken[b] && (v.bond_i[b] == j || v.bond_j[b] == j);
        }
        if (!bonded) visit(j);
      }
    }
  }
}

__global__ void countCandidates(RebuildView v, int* count) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= v.n) return;
  int c = 0;
  forEachCandidate(v, i, [&](int) { ++c; });
  count[i] = c;
}

__global__ void writeCandidates(RebuildView v, const int* offsets, int* pair_i, int* pair_j) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= v.n) return;
  const int begin = offsets[i];
  int c = 0;
  forEachCandidate(v, i, [&](int j) {
    pair_i[begin + c] = i;
    pair_j[begin + c] = j;
    ++c;
  });
  for (int a = begin + 1; a < begin + c; ++a) {  // insertion sort by j: the list is sorted by (i, j)
    const int key = pair_j[a];
    int b = a - 1;
    while (b >= begin && pair_j[b] > key) {
      pair_j[b + 1] = pair_j[b];
      --b;
    }
    pair_j[b + 1] = key;
  }
}

/// S_ref of each new pair: the old list's value when the pair was there, else -1 (new).
__global__ void carryReferences(int pairs, const int* pair_i, const int* pair_j, int old_count, const int* old_i,
                                const int* old_j, const double* old_reference, double* reference) {
  const int p = blockIdx.x * blockDim.x + threadIdx.x;
  if (p >= pairs) return;
  const int i = pair_i[p], j = pair_j[p];
  int lo = 0, hi = old_count;  // first old entry not below (i, j)
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (old_i[mid] < i || (old_i[mid] == i && old_j[mid] < j)) lo = mid + 1;
    else hi = mid;
  }
  reference[p] = (lo < old_count && old_i[lo] == i && old_j[lo] == j) ? old_reference[lo] : -1.0;
}

__global__ void countIncidence(int pairs, const int* pair_i, const int* pair_j, int* count) {
  const int p = blockIdx.x * blockDim.x + threadIdx.x;
  if (p >= pairs) return;
  atomicAdd(&count[pair_i[p]], 1);
  atomicAdd(&count[pair_j[p]], 1);
}

__global__ void writeIncidence(int pairs, const int* pair_i, const int* pair_j, const int* offsets, int* cursor,
                               int* entries) {
  const int p = blockIdx.x * blockDim.x + threadIdx.x;
  if (p >= pairs) return;
  const int i = pair_i[p], j = pair_j[p];
  entries[offsets[i] + atomicAdd(&cursor[i], 1)] = 2 * p;
  entries[offsets[j] + atomicAdd(&cursor[j], 1)] = 2 * p + 1;
}

/// Each cell's entries in pair order (the CPU's order): the gather then sums alike on both.
__global__ void sortIncidence(int n, const int* offsets, int* entries) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= n) return;
  for (int a = offsets[k] + 1; a < offsets[k + 1]; ++a) {
    const int key = entries[a];
    int b = a - 1;
    while (b >= offsets[k] && entries[b] > key) {
      entries[b + 1] = entries[b];
      --b;
    }
    entries[b + 1] = key;
  }
}

// --- The backend ------------------------------------------------------------------------------

class CudaBackend final : public Backend {
 public:
  explicit CudaBackend(const Model& model) : model_(model), n_(model.cell_count),
                                             bonds_(static_cast<int>(model.bond_rest.size())) {
    TIS_CUDA_CHECK(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking));
    vertex_x_.upload(model.vertex_x);
    vertex_y_.upload(model.vertex_y);
    vertex_count_.upload(model.vertex_count);
    mass_.upload(model.mass);
    inertia_.upload(model.inertia);
    area_.upload(model.area);
    radius_.upload(model.radius);
    bond_i_.upload(model.bond_i);
    bond_j_.upload(model.bond_j);
    bond_rest_.upload(model.bond_rest);
    Incidence bonds;
    bonds.build(n_, model.bond_i, model.bond_j);
    bond_offsets_.upload(bonds.offsets);
    bond_entries_.upload(bonds.entries);
    bond_force_.resize(bonds_);
    bond_broken_.resize(bonds_);
    motion_.resize(n_);
    reference_.resize(n_);
    world_.resize(static_cast<size_t>(n_) * kV);
    box_.resize(static_cast<size_t>(n_) * 4);
    turn_.resize(n_);
    structure_.resize(n_);
    totals_.resize(kLoadTotals);
    panels_.resize(static_cast<size_t>(kLoadPerPanel) * model.constants.panels);
    contact_offsets_.resize(n_ + 1);
    cursor_.resize(n_ + 1);
    candidate_count_.resize(n_ + 1);
    candidate_offsets_.resize(n_ + 1);
    keys_.resize(n_);
    sorted_keys_.resize(n_);
    cells_.resize(n_);
    sorted_cells_.resize(n_);
    table_size_ = 1;
    while (table_size_ < 2u * static_cast<unsigned int>(std::max(n_, 1))) table_size_ <<= 1;
    bin_start_.resize(table_size_);
    bin_end_.resize(table_size_);
    run_.resize(1);
    TIS_CUDA_CHECK(cudaMallocHost(&run_host_, sizeof(RunScalars)));
    ensurePairCapacity(static_cast<size_t>(8) * std::max(n_, 1));
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
    TIS_CUDA_CHECK(cudaMemset(bond_broken_.get(), 0, bonds_ * sizeof(unsigned char)));
    TIS_CUDA_CHECK(cudaMemset(bond_force_.get(), 0, bonds_ * sizeof(BondForce)));
    RunScalars r{};
    r.pusher_x = model_.initial_pusher_x;
    *run_host_ = r;
    TIS_CUDA_CHECK(cudaMemcpy(run_.get(), &r, sizeof(RunScalars), cudaMemcpyHostToDevice));
    pair_count_ = 0;
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
    return makeCellSnapshots(model_, motion_.download(), bond_broken_.download());
  }

 private:
  /// The kernels of one step on stream_ (also what the graph captures).
  void launchStep() {
    const ModelConstants& c = model_.constants;
    RunScalars* run = run_.get();
    placeCells<<<blocksFor(n_), kThreads, 0, stream_>>>(n_, run, motion_.get(), vertex_x_.get(), vertex_y_.get(),
                                                         vertex_count_.get(), world_.get(), box_.get(), turn_.get());
    if (bonds_ > 0) {
      bondForces<<<blocksFor(bonds_), kThreads, 0, stream_>>>(bonds_, run, c, bond_i_.get(), bond_j_.get(),
                                                               bond_rest_.get(), motion_.get(), mass_.get(),
                                                               inertia_.get(), turn_.get(), bond_broken_.get(),
                                                               bond_force_.get());
    }
    const int capacity = static_cast<int>(pair_i_.size());
    contactForces<<<blocksFor(capacity), kThreads, 0, stream_>>>(
        capacity, run, c, pair_i_.get(), pair_j_.get(), motion_.get(), mass_.get(), inertia_.get(), world_.get(),
        vertex_count_.get(), box_.get(), reference_area_.get(), contact_force_.get());
    const CellStepInputs in = {mass_.get(),          inertia_.get(),        area_.get(),
                               vertex_count_.get(),  world_.get(),          box_.get(),
                               bond_offsets_.get(),  bond_entries_.get(),   bond_broken_.get(),
                               bond_force_.get(),    contact_offsets_.get(), contact_entries_.get(),
                               contact_force_.get()};
    stepCells<<<blocksFor(n_), kThreads, 0, stream_>>>(n_, run, c, in, reference_.get(), motion_.get(),
                                                        structure_.get(), totals_.get(), panels_.get());
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

  void ensurePairCapacity(size_t pairs) {
    if (pairs <= pair_i_.size() && pair_i_.size() > 0) return;
    const size_t capacity = std::max(pairs + pairs / 2, static_cast<size_t>(1024));
    // Keep the current list (its S_ref) across the move.
    std::vector<int> keep_i, keep_j;
    std::vector<double> keep_ref;
    if (pair_count_ > 0) {
      keep_i = pair_i_.download(); keep_i.resize(pair_count_);
      keep_j = pair_j_.download(); keep_j.resize(pair_count_);
      keep_ref = reference_area_.download(); keep_ref.resize(pair_count_);
    }
    for (DeviceArray<int>* a : {&pair_i_, &pair_j_, &new_i_, &new_j_}) a->resize(capacity);  // contents dropped
    reference_area_.resize(capacity);
    new_reference_.resize(capacity);
    contact_force_.resize(capacity);
    contact_entries_.resize(2 * capacity);
    if (pair_count_ > 0) {
      TIS_CUDA_CHECK(cudaMemcpy(pair_i_.get(), keep_i.data(), pair_count_ * sizeof(int), cudaMemcpyHostToDevice));
      TIS_CUDA_CHECK(cudaMemcpy(pair_j_.get(), keep_j.data(), pair_count_ * sizeof(int), cudaMemcpyHostToDevice));
      TIS_CUDA_CHECK(cudaMemcpy(reference_area_.get(), keep_ref.data(), pair_count_ * sizeof(double),
                                cudaMemcpyHostToDevice));
    }
    TIS_CUDA_CHECK(cudaDeviceSynchronize());  // the copies above ran on the legacy stream
    if (graph_exec_ != nullptr) {  // it holds the old pointers and sizes
      TIS_CUDA_CHECK(cudaGraphExecDestroy(graph_exec_));
      graph_exec_ = nullptr;
    }
  }

  void rebuildContacts() {
    const ModelConstants& c = model_.constants;
    const int grid = blocksFor(n_);
    // Bins of the search radius, hashed; cells sorted by bin.
    hashCells<<<grid, kThreads, 0, stream_>>>(n_, motion_.get(), c.search_radius, table_size_ - 1, keys_.get(),
                                               cells_.get());
    size_t temp_bytes = 0;
    int end_bit = 0;
    while ((1u << end_bit) < table_size_) ++end_bit;
    TIS_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(nullptr, temp_bytes, keys_.get(), sorted_keys_.get(), cells_.get(),
                                                   sorted_cells_.get(), n_, 0, end_bit, stream_));
    temp_.resize(temp_bytes);
    TIS_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(temp_.get(), temp_bytes, keys_.get(), sorted_keys_.get(),
                                                   cells_.get(), sorted_cells_.get(), n_, 0, end_bit, stream_));
    TIS_CUDA_CHECK(cudaMemsetAsync(bin_start_.get(), 0, bin_start_.bytes(), stream_));
    TIS_CUDA_CHECK(cudaMemsetAsync(bin_end_.get(), 0, bin_end_.bytes(), stream_));
    binBounds<<<grid, kThreads, 0, stream_>>>(n_, sorted_keys_.get(), bin_start_.get(), bin_end_.get());

    const RebuildView view = {n_,
                              motion_.get(),
                              radius_.get(),
                              c.search_radius,
                              c.search_margin,
                              c.search_radius,
                              table_size_ - 1,
                              bin_start_.get(),
                              bin_end_.get(),
                              sorted_cells_.get(),
                              bond_offsets_.get(),
                              bond_entries_.get(),
                              bond_i_.get(),
                              bond_j_.get(),
                              bond_broken_.get()};
    // Count, scan, and (after making room) write the candidate pairs, sorted by (i, j).
    TIS_CUDA_CHECK(cudaMemsetAsync(candidate_count_.get(), 0, candidate_count_.bytes(), stream_));
    countCandidates<<<grid, kThreads, 0, stream_>>>(view, candidate_count_.get());
    TIS_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(nullptr, temp_bytes, candidate_count_.get(),
                                                 candidate_offsets_.get(), n_ + 1, stream_));
    temp_.resize(temp_bytes);
    TIS_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(temp_.get(), temp_bytes, candidate_count_.get(),
                                                 candidate_offsets_.get(), n_ + 1, stream_));
    int total = 0;
    TIS_CUDA_CHECK(cudaMemcpyAsync(&total, candidate_offsets_.get() + n_, sizeof(int), cudaMemcpyDeviceToHost, stream_));
    TIS_CUDA_CHECK(cudaStreamSynchronize(stream_));
    ensurePairCapacity(static_cast<size_t>(total));
    writeCandidates<<<grid, kThreads, 0, stream_>>>(view, candidate_offsets_.get(), new_i_.get(), new_j_.get());
    carryReferences<<<blocksFor(total), kThreads, 0, stream_>>>(total, new_i_.get(), new_j_.get(), pair_count_,
                                                                 pair_i_.get(), pair_j_.get(), reference_area_.get(),
                                                                 new_reference_.get());
    // The new list replaces the old one in place (the captured graph keeps its pointers).
    if (total > 0) {
      TIS_CUDA_CHECK(cudaMemcpyAsync(pair_i_.get(), new_i_.get(), total * sizeof(int), cudaMemcpyDeviceToDevice, stream_));
      TIS_CUDA_CHECK(cudaMemcpyAsync(pair_j_.get(), new_j_.get(), total * sizeof(int), cudaMemcpyDeviceToDevice, stream_));
      TIS_CUDA_CHECK(cudaMemcpyAsync(reference_area_.get(), new_reference_.get(), total * sizeof(double),
                                     cudaMemcpyDeviceToDevice, stream_));
    }
    pair_count_ = total;

    // Per-cell incidence lists in pair order.
    TIS_CUDA_CHECK(cudaMemsetAsync(candidate_count_.get(), 0, candidate_count_.bytes(), stream_));
    countIncidence<<<blocksFor(total), kThreads, 0, stream_>>>(total, pair_i_.get(), pair_j_.get(),
                                                                candidate_count_.get());
    TIS_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(temp_.get(), temp_bytes, candidate_count_.get(),
                                                 contact_offsets_.get(), n_ + 1, stream_));
    TIS_CUDA_CHECK(cudaMemsetAsync(cursor_.get(), 0, cursor_.bytes(), stream_));
    writeIncidence<<<blocksFor(total), kThreads, 0, stream_>>>(total, pair_i_.get(), pair_j_.get(),
                                                                contact_offsets_.get(), cursor_.get(),
                                                                contact_entries_.get());
    sortIncidence<<<grid, kThreads, 0, stream_>>>(n_, contact_offsets_.get(), contact_entries_.get());

    // Algorithm 1: the state at this rebuild is the reference of the next test; clear the flags.
    TIS_CUDA_CHECK(cudaMemcpyAsync(reference_.get(), motion_.get(), n_ * sizeof(CellMotion), cudaMemcpyDeviceToDevice,
                                   stream_));
    RunScalars* run = run_.get();
    const int zero = 0;
    TIS_CUDA_CHECK(cudaMemcpyAsync(&run->pair_count, &total, sizeof(int), cudaMemcpyHostToDevice, stream_));
    TIS_CUDA_CHECK(cudaMemcpyAsync(&run->flags, &zero, sizeof(int), cudaMemcpyHostToDevice, stream_));
    TIS_CUDA_CHECK(cudaMemcpyAsync(&run->stop, &zero, sizeof(int), cudaMemcpyHostToDevice, stream_));
    TIS_CUDA_CHECK(cudaMemcpyAsync(&run->steps_since_rebuild, &zero, sizeof(int), cudaMemcpyHostToDevice, stream_));
    TIS_CUDA_CHECK(cudaGetLastError());
    TIS_CUDA_CHECK(cudaStreamSynchronize(stream_));  // `total` and `zero` live on this stack frame
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
    const double inv = taken > 0 ? 1.0 / static_cast<double>(taken) : 0.0;
    sum.horizontal_raw = totals[0] * inv;
    sum.lateral_raw = totals[1] * inv;
    sum.vertical_raw = totals[2] * inv;
    sum.pusher_force = totals[3] * inv;
    sum.torque = {totals[4] * inv, totals[5] * inv, totals[6] * inv};
    for (int p = 0; p < c.panels; ++p) {
      const double* q = &panels[static_cast<size_t>(kLoadPerPanel) * p];
      sum.panel_horizontal[p] = q[0] * inv;
      sum.panel_lateral[p] = q[1] * inv;
      sum.panel_vertical[p] = q[2] * inv;
      sum.panel_torque[p] = {q[3] * inv, q[4] * inv, q[5] * inv};
    }
    sum.horizontal_calibrated = c.calibration_factor * sum.horizontal_raw;
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
  DeviceArray<int> vertex_count_, bond_i_, bond_j_, bond_offsets_, bond_entries_;
  DeviceArray<BondRest> bond_rest_;
  // State.
  DeviceArray<CellMotion> motion_, reference_;
  DeviceArray<unsigned char> bond_broken_;
  DeviceArray<BondForce> bond_force_;
  DeviceArray<Vec2> world_, turn_;
  DeviceArray<double> box_;
  DeviceArray<StructureContact> structure_;
  DeviceArray<double> totals_, panels_;
  DeviceArray<RunScalars> run_;
  // Contacts (capacity-sized) and the rebuild's scratch.
  DeviceArray<int> pair_i_, pair_j_, new_i_, new_j_, contact_offsets_, contact_entries_, cursor_;
  DeviceArray<double> reference_area_, new_reference_;
  DeviceArray<PairForce> contact_force_;
  DeviceArray<int> candidate_count_, candidate_offsets_, cells_, sorted_cells_, bin_start_, bin_end_;
  DeviceArray<unsigned int> keys_, sorted_keys_;
  DeviceArray<unsigned char> temp_;
  unsigned int table_size_ = 1;
  int pair_count_ = 0;
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

const GpuBackendProvider kProvider = {unavailableReason, deviceDescription, makeBackend};

}  // namespace

void registerCudaBackend() { setGpuBackendProvider(&kProvider); }

}  // namespace cuda
}  // namespace thin_ice
