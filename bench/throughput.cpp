// Throughput benchmark: cell-steps per second of the whole time step (all forces, contacts,
// integration, loads) for an intact bonded sheet and for a broken field, at several sizes and
// thread counts. Prints a Markdown table on stdout.
//   thin_ice_bench --scenario FILE [--cells N]... [--threads T]... [--sheet intact|broken]...
//                      [--cell-steps S] [--rebuild-each-step] [--backend cpu|cuda]
//   thin_ice_bench --state DIR [--threads T]... [--steps N] [--backend cpu|cuda]
//                      (steps from a saved state, state_bench.hpp)
// Each case: a square-ish sheet of about N cells cut from FILE's ice (structure and walls moved
// out of the way), 20 warm-up steps, then enough steps for about S cell-steps (default 3e7).
// "broken": every bond of the sheet marked broken before the first step (through a checkpoint of
// the new simulation), so that the field is held together by DEM contacts only. (Strengths of 1 Pa
// did this until the scenario keys got physical ranges, which refuse them.)
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "thin_ice_sim/backend.hpp"
#include "thin_ice_sim/built_backends.hpp"
#include "thin_ice_sim/checkpoint.hpp"
#include "thin_ice_sim/openmp_wait_policy.hpp"
#include "thin_ice_sim/scenario.hpp"
#include "thin_ice_sim/simulation.hpp"
#include "state_bench.hpp"

namespace {

/// Peak resident set of this process so far [bytes] (Linux reports kilobytes).
double peakResidentBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return 1024.0 * static_cast<double>(usage.ru_maxrss);
}

struct Case {
  long cells;
  bool broken;
  int threads;
};

std::vector<std::string> sheetOverrides(const thin_ice::Params& p, long cells, int threads, bool rebuild_each_step) {
  const double area = static_cast<double>(cells) * p.sheet.cell_size * p.sheet.cell_size;
  const double width = std::sqrt(area / 2.0), length = 2.0 * width;  // 2:1 strip
  std::vector<std::string> o = {
      "sheet.length=" + std::to_string(length), "sheet.width=" + std::to_string(width), "sheet.x_min=0",
      "structure.toe_x=" + std::to_string(length + 0.5), "structure.width=" + std::to_string(width),
      "channel.width=" + std::to_string(width), "numerics.threads=" + std::to_string(threads),
      // The critical step depends on the largest cell of each mesh: 4e-6 s is stable for all sizes.
      "numerics.time_step=4e-6", "numerics.critical_step_safety=0.95"};
  // Algorithm 1's rebuild at every step: the difference to the normal run is the rebuild's cost.
  if (rebuild_each_step) o.push_back("numerics.max_steps_between_rebuilds=1");
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  thin_ice::restartWithPassiveOpenMpWaitUnlessSet(argv);
  thin_ice::registerBuiltBackends();
  std::string scenario_path;
  std::vector<long> sizes;
  std::vector<int> threads;
  std::vector<bool> sheets;  // broken?
  bool rebuild_each_step = false;
  std::string backend_name = "cpu";
  double cell_steps = 3e7;
  std::string state_dir;
  long state_steps = 2000;
  for (int k = 1; k < argc; k += 2) {
    const std::string flag = argv[k];
    if (flag == "--rebuild-each-step") {
      rebuild_each_step = true;
      --k;
      continue;
    }
    if (k + 1 >= argc) {
      std::fprintf(stderr, "flag %s needs a value\n", flag.c_str());
      return 2;
    }
    const std::string value = argv[k + 1];
    if (flag == "--scenario") scenario_path = value;
    else if (flag == "--state") state_dir = value;
    else if (flag == "--steps" && std::atol(value.c_str()) > 0) state_steps = std::atol(value.c_str());
    else if (flag == "--cells") sizes.push_back(std::atol(value.c_str()));
    else if (flag == "--threads") threads.push_back(std::atoi(value.c_str()));
    else if (flag == "--cell-steps") cell_steps = std::atof(value.c_str());
    else if (flag == "--backend") backend_name = value;
    else if (flag == "--sheet" && (value == "intact" || value == "broken")) sheets.push_back(value == "broken");
    else {
      std::fprintf(stderr, "unknown flag %s\n", flag.c_str());
      return 2;
    }
  }
  if (!state_dir.empty()) {
    if (threads.empty()) threads = {1};
    int status = 0;
    for (size_t k = 0; k < threads.size() && status == 0; ++k) {
      status = thin_ice_bench::benchState({state_dir, backend_name, threads[k], state_steps}, k == 0);
    }
    return status;
  }
  if (scenario_path.empty()) {
    std::fprintf(stderr,
                 "usage: thin_ice_bench --scenario FILE [--cells N]... [--threads T]... "
                 "[--sheet intact|broken]... [--cell-steps S] [--rebuild-each-step] [--backend cpu|cuda]\n"
                 "       thin_ice_bench --state DIR [--threads T]... [--steps N] [--backend cpu|cuda]\n");
    return 2;
  }
  if (sizes.empty()) sizes = {1000, 10000, 100000};
  if (threads.empty()) threads = {1, 2};
  if (sheets.empty()) sheets = {false, true};
  try {
    const thin_ice::BackendKind backend = thin_ice::parseBackendKind(backend_name, "--backend");
    if (backend == thin_ice::BackendKind::kAuto) throw std::invalid_argument("--backend auto: name cpu or cuda");
    // The thread count means nothing on the GPU: one run per case there.
    if (backend == thin_ice::BackendKind::kCuda) threads = {1};
    const thin_ice::Params base = thin_ice::loadScenario(scenario_path).params;
    const double resident_at_start = peakResidentBytes();
    // The table header waits for the first simulation, so that a backend that cannot start (no
    // GPU) leaves only its error and no half table.
    bool header_printed = false;
    for (long n : sizes) {
      for (bool broken : sheets) {
        for (int t : threads) {
          const thin_ice::Scenario s = thin_ice::loadScenario(scenario_path, sheetOverrides(base, n, t, rebuild_each_step));
          // Device memory: what building and stepping this case adds on the GPU (cudaMemGetInfo).
          const thin_ice::GpuBackendProvider* gpu = thin_ice::gpuBackendProvider();
          const bool on_gpu = backend == thin_ice::BackendKind::kCuda && gpu != nullptr;
          const double device_at_start = on_gpu ? gpu->device_memory_in_use() : 0.0;
          thin_ice::Simulation sim(s, backend);
          if (broken) {  // every bond broken; the first step's rebuild lists the neighbours as contacts
            thin_ice::Checkpoint state = thin_ice::takeCheckpoint(sim);
            for (unsigned char& b : state.state.bond_state) b = thin_ice::kBondBroken;
            thin_ice::restoreCheckpoint(sim, state, true);
          }
          if (!header_printed) {
            std::printf("| cells | sheet | backend | threads | steps | wall [s] | cell-steps/s | ns per cell-step | peak host memory per cell [B] | device memory per cell [B] |\n");
            std::printf("|---:|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
            header_printed = true;
          }
          sim.step(20);
          const long steps = std::max(20L, static_cast<long>(cell_steps / sim.cellCount()));
          const auto t0 = std::chrono::steady_clock::now();
          sim.step(steps);
          const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          const double rate = static_cast<double>(sim.cellCount()) * steps / wall;
          // Growth of the process's peak resident set since start, per cell: an upper bound of what
          // a cell costs (it includes the sheet generation's temporaries).
          const double memory = (peakResidentBytes() - resident_at_start) / sim.cellCount();
          const std::string thread_text = backend == thin_ice::BackendKind::kCuda ? "-" : std::to_string(t);
          char device_text[32] = "-";
          if (on_gpu) std::snprintf(device_text, sizeof device_text, "%.0f", (gpu->device_memory_in_use() - device_at_start) / sim.cellCount());
          std::printf("| %d | %s | %s | %s | %ld | %.2f | %.3g | %.3g | %.0f | %s |\n", sim.cellCount(),
                      broken ? (rebuild_each_step ? "broken field, rebuilt every step" : "broken field")
                             : (rebuild_each_step ? "intact, rebuilt every step" : "intact, bonded"),
                      backend_name.c_str(), thread_text.c_str(), steps, wall, rate, 1e9 / rate, memory, device_text);
          std::fflush(stdout);
          if (!sim.healthy()) std::fprintf(stderr, "warning: %s\n", sim.lastError().c_str());
        }
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "thin_ice_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
