#include "thin_ice_sim/simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cpu_backend.hpp"
#include "thin_ice_sim/backend.hpp"
#include "thin_ice_sim/model.hpp"

namespace thin_ice {

BackendKind parseBackendKind(const std::string& text, const std::string& key) {
  if (text == "cpu") return BackendKind::kCpu;
  if (text == "cuda") return BackendKind::kCuda;
  if (text == "auto") return BackendKind::kAuto;
  throw std::invalid_argument(key + " = '" + text + "': allowed values are 'cpu', 'cuda' and 'auto'");
}

std::vector<int> bondedPieceSizes(int cell_count, const std::vector<int>& bond_i, const std::vector<int>& bond_j,
                                  const std::vector<unsigned char>& bond_broken) {
  // Union-find with path halving; each piece is named by its root cell.
  std::vector<int> parent(cell_count);
  for (int k = 0; k < cell_count; ++k) parent[k] = k;
  auto root = [&parent](int k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  for (size_t b = 0; b < bond_broken.size(); ++b) {
    if (bond_broken[b] != kBondIntact) continue;
    const int a = root(bond_i[b]), c = root(bond_j[b]);
    if (a != c) parent[a < c ? c : a] = a < c ? a : c;
  }
  std::vector<int> size(cell_count, 0);
  for (int k = 0; k < cell_count; ++k) ++size[root(k)];
  std::vector<int> out(cell_count);
  for (int k = 0; k < cell_count; ++k) out[k] = size[root(k)];
  return out;
}

std::vector<CellSnapshot> makeCellSnapshots(const Model& model, const std::vector<CellMotion>& motion,
                                            const std::vector<unsigned char>& bond_broken) {
  const std::vector<int> piece = bondedPieceSizes(model.cell_count, model.bond_i, model.bond_j, bond_broken);
  std::vector<CellSnapshot> out(model.cell_count);
  for (int k = 0; k < model.cell_count; ++k) {
    const CellMotion& m = motion[k];
    out[k] = {m.x, m.y, m.z, m.yaw, m.vx, m.vy, m.vz, m.wz, piece[k] > 1, piece[k]};
  }
  return out;
}

namespace {
const GpuBackendProvider* g_gpu_provider = nullptr;
}  // namespace

void setGpuBackendProvider(const GpuBackendProvider* provider) { g_gpu_provider = provider; }
const GpuBackendProvider* gpuBackendProvider() { return g_gpu_provider; }

Simulation::Simulation(const Scenario& scenario, BackendKind backend) : scenario_(scenario) {
  const Params& p = scenario_.params;
  validateParams(p, scenario_.source.empty() ? scenario_.name : scenario_.source);
  // Which backend, decided before any work so that a refused 'cuda' costs nothing.
  const GpuBackendProvider* gpu = gpuBackendProvider();
  const std::string gpu_missing = gpu == nullptr ? "this build has no CUDA backend (nvcc was not found when it was built)"
                                                 : gpu->unavailable_reason();
  if (backend == BackendKind::kCuda && !gpu_missing.empty()) {
    throw std::runtime_error("backend 'cuda' is not available: " + gpu_missing + "; use 'cpu' or 'auto'");
  }
  const bool use_gpu = backend != BackendKind::kCpu && gpu_missing.empty();
  sheet_ = generateIceSheet(p.sheet);
  model_ = std::make_unique<Model>(buildModel(p, sheet_, scenario_.source.empty() ? scenario_.name : scenario_.source));
  if (use_gpu) {
    backend_ = gpu->make(*model_);
    backend_note_ = "backend " + std::string(backend == BackendKind::kAuto ? "auto: using the GPU, " : "cuda: ") +
                    gpu->device_description();
  } else {
    backend_ = makeCpuBackend(*model_, p.numerics.threads);
    backend_note_ = backend == BackendKind::kAuto ? "backend auto: " + gpu_missing + ", using the CPU" : "backend cpu";
    if (p.numerics.threads > omp_get_num_procs()) {
      backend_note_ += "; numerics.threads = " + std::to_string(p.numerics.threads) + " capped at the " +
                       std::to_string(omp_get_num_procs()) + " cores present";
    }
  }
  pusher_velocity_ = p.pusher.velocity;
}

Simulation::~Simulation() = default;

void Simulation::step(long steps) {
  if (!healthy() || steps <= 0) return;
  // The pusher's travel ends at the structure's toe (pusherTravel): the steps that would carry it
  // past are taken with the plate standing. Before that point nothing here changes the arithmetic.
  const double per_step = pusher_velocity_ * timeStep();  // [m] of travel per step
  const double room = pusherTravel() - pushedLength();      // [m] left
  if (per_step > 0.0 && per_step * static_cast<double>(steps) > room) {
    const long moving = room > 0.0 ? std::min(steps, static_cast<long>(std::floor(room / per_step))) : 0;
    if (moving > 0) backend_->step(moving, pusher_velocity_);
    if (backend_->healthError().empty() && steps > moving) backend_->step(steps - moving, 0.0);
  } else {
    backend_->step(steps, pusher_velocity_);
  }
  last_error_ = backend_->healthError();
}

double Simulation::pusherTravel() const {
  return scenario_.params.structure.toe_x - scenario_.params.sheet.x_min;
}

bool Simulation::pusherAtTravelEnd() const {
  return pushedLength() >= pusherTravel() - std::max(0.0, pusher_velocity_ * timeStep());
}

void Simulation::advance(double span) {
  if (paused_ || !(span > 0.0)) return;
  step(static_cast<long>(std::ceil(span / timeStep() - 1e-9)));
}

void Simulation::setPusherVelocity(double velocity) {
  if (std::isfinite(velocity)) pusher_velocity_ = velocity;
}

double Simulation::pusherVelocity() const { return pusher_velocity_; }

void Simulation::reset() {
  backend_->reset();
  pusher_velocity_ = scenario_.params.pusher.velocity;
  last_error_.clear();
}

BackendState Simulation::saveState() const { return backend_->saveState(); }

void Simulation::restoreState(const BackendState& state) {
  const size_t cells = static_cast<size_t>(model_->cell_count), bonds = model_->bond_rest.size();
  auto refuse = [](const std::string& what) { throw std::invalid_argument("saved state does not fit the model: " + what); };
  if (state.motion.size() != cells) {
    refuse(std::to_string(state.motion.size()) + " cells saved, the model has " + std::to_string(cells));
  }
  if (state.bond_state.size() != bonds) {
    refuse(std::to_string(state.bond_state.size()) + " bonds saved, the model has " + std::to_string(bonds));
  }
  for (size_t b = 0; b < bonds; ++b) {
    if (state.bond_state[b] != kBondIntact && state.bond_state[b] != kBondBroken) {
      refuse("bond " + std::to_string(b) + " has state " + std::to_string(int(state.bond_state[b])) +
             "; allowed: 0 (intact) or 2 (broken)");
    }
  }
  const size_t pairs = state.contact_i.size();
  if (state.contact_j.size() != pairs || state.contact_reference.size() != pairs) {
    refuse("the pair lists differ in length (i: " + std::to_string(pairs) + ", j: " + std::to_string(state.contact_j.size()) +
           ", S_ref: " + std::to_string(state.contact_reference.size()) + ")");
  }
  for (size_t p = 0; p < pairs; ++p) {
    const int i = state.contact_i[p], j = state.contact_j[p];
    if (i < 0 || j <= i || j >= static_cast<int>(cells)) {
      refuse("pair " + std::to_string(p) + " is (" + std::to_string(i) + ", " + std::to_string(j) +
             "); allowed: 0 <= i < j < " + std::to_string(cells));
    }
    if (p > 0 && (state.contact_i[p - 1] > i || (state.contact_i[p - 1] == i && state.contact_j[p - 1] >= j))) {
      refuse("pair " + std::to_string(p) + " (" + std::to_string(i) + ", " + std::to_string(j) + ") does not come after (" +
             std::to_string(state.contact_i[p - 1]) + ", " + std::to_string(state.contact_j[p - 1]) +
             "); allowed: pairs sorted by (i, j), each once");
    }
    const double reference = state.contact_reference[p];
    if (!(reference >= 0.0 || reference == -1.0) || !std::isfinite(reference)) {
      refuse("pair " + std::to_string(p) + " has S_ref " + std::to_string(reference) + " m^2; allowed: -1 or a finite value >= 0");
    }
  }
  for (size_t k = 0; k < cells; ++k) {
    const CellMotion& m = state.motion[k];
    const double values[] = {m.x, m.y, m.z, m.yaw, m.vx, m.vy, m.vz, m.wz};
    const char* names[] = {"x", "y", "z", "yaw", "vx", "vy", "vz", "wz"};
    for (int v = 0; v < 8; ++v) {
      if (!std::isfinite(values[v])) refuse("cell " + std::to_string(k) + " has " + names[v] + " = " + std::to_string(values[v]));
    }
  }
  if (!(state.time >= 0.0) || !std::isfinite(state.time)) {
    refuse("time " + std::to_string(state.time) + " s; allowed: finite and >= 0");
  }
  if (state.steps < 0) refuse("step count " + std::to_string(state.steps) + "; allowed: >= 0");
  if (!std::isfinite(state.pusher_x)) refuse("pusher position " + std::to_string(state.pusher_x) + " m; allowed: finite");
  backend_->restoreState(state);
  last_error_.clear();
}

double Simulation::time() const { return backend_->time(); }
double Simulation::timeStep() const { return model_->constants.time_step; }
double Simulation::criticalTimeStep() const { return model_->critical_time_step; }
int Simulation::structureSubsteps() const { return model_->constants.structure_substeps; }
double Simulation::structureCriticalTimeStep() const { return model_->structure_critical_time_step; }
double Simulation::pushedLength() const { return backend_->pusherPosition() - model_->initial_pusher_x; }
double Simulation::pusherPosition() const { return backend_->pusherPosition(); }
long Simulation::stepCount() const { return backend_->stepCount(); }
LoadSample Simulation::loads() const { return backend_->loads(); }
std::vector<CellSnapshot> Simulation::cells() const { return backend_->cells(); }
int Simulation::cellCount() const { return model_->cell_count; }
const ModelConstants& Simulation::scene() const { return model_->constants; }
std::string Simulation::backendName() const { return backend_->name(); }

const char* Simulation::cpuInstructionSet() { return THIN_ICE_CPU_LEVEL_NAME; }

std::vector<Vec2> Simulation::cellPolygon(int k) const {
  if (k < 0 || k >= model_->cell_count) return {};
  return cellPolygon(k, backend_->cells()[k]);
}

std::vector<Vec2> Simulation::cellPolygon(int k, const CellSnapshot& c) const {
  std::vector<Vec2> polygon;
  if (k < 0 || k >= model_->cell_count) return polygon;
  const double cs = std::cos(c.yaw), sn = std::sin(c.yaw);
  for (int v = 0; v < model_->vertex_count[k]; ++v) {
    const Vec2 offset = {model_->vertex_x[k * kMaxPolygonVertices + v], model_->vertex_y[k * kMaxPolygonVertices + v]};
    polygon.push_back(Vec2{c.x, c.y} + rotate(offset, cs, sn));
  }
  return polygon;
}

}  // namespace thin_ice
