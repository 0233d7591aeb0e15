#include "state_bench.hpp"

#include <yaml-cpp/yaml.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <vector>

#include "thin_ice_sim/checkpoint.hpp"
#include "thin_ice_sim/scenario.hpp"
#include "thin_ice_sim/simulation.hpp"

namespace thin_ice_bench {

int benchState(const StateBenchOptions& o, bool header) {
  try {
    const std::string state_file = o.state_dir + "/state.yaml";
    const YAML::Node state = YAML::LoadFile(state_file);
    std::vector<std::string> overrides;
    for (const YAML::Node& n : state["overrides"]) overrides.push_back(n.as<std::string>());
    const std::string scenario_file = o.state_dir + "/" + state["scenario"].as<std::string>();
    const thin_ice::Checkpoint checkpoint = thin_ice::readCheckpoint(o.state_dir + "/checkpoint.bin");
    // The state's own scenario must be the checkpoint's; the thread count, added after this check,
    // changes how the steps are shared out, not what they compute.
    const std::string hash = thin_ice::loadScenario(scenario_file, overrides).hash;
    if (hash != checkpoint.scenario_hash) {
      throw std::runtime_error(scenario_file + " with the overrides of " + state_file + " has the hash " + hash +
                               ", the checkpoint's scenario " + checkpoint.scenario_hash + ": not the state's scenario");
    }
    overrides.push_back("numerics.threads=" + std::to_string(o.threads));
    const thin_ice::Scenario scenario = thin_ice::loadScenario(scenario_file, overrides);
    const thin_ice::BackendKind backend = thin_ice::parseBackendKind(o.backend, "--backend");
    thin_ice::Simulation sim(scenario, backend);
    thin_ice::restoreCheckpoint(sim, checkpoint, /*accept_changed_scenario=*/true);
    sim.step(20);
    const auto t0 = std::chrono::steady_clock::now();
    sim.step(o.steps);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!sim.healthy()) {
      std::fprintf(stderr, "thin_ice_bench: %s: %s\n", o.state_dir.c_str(), sim.lastError().c_str());
      return 1;
    }
    const double step_time = wall / static_cast<double>(o.steps);                       // [s]
    const double real_time_factor = scenario.params.numerics.time_step / step_time;  // [-]
    if (header) {
      std::printf("| state | backend | threads | cells | contacts | steps | wall [s] | step [us] | real-time factor |\n");
      std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
    }
    std::printf("| %s | %s | %s | %d | %d | %ld | %.2f | %.1f | %.3g |\n", o.state_dir.c_str(), o.backend.c_str(),
                o.backend == "cuda" ? "-" : std::to_string(o.threads).c_str(), sim.cellCount(), sim.loads().contacts,
                o.steps, wall, 1e6 * step_time, real_time_factor);
    std::fflush(stdout);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "thin_ice_bench: --state %s: %s\n", o.state_dir.c_str(), e.what());
    return 1;
  }
}

}  // namespace thin_ice_bench
