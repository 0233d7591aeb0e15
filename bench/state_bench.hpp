// thin_ice_bench --state DIR: time steps from a saved state (bench/states/NAME: state.yaml, a
// frozen scenario.yaml and checkpoint.bin), on either backend. The grown rubble pile of a long run
// is where the time of a validation run goes, and an intact or broken sheet cut to size does not
// reproduce its contact graph.
#pragma once

#include <string>

namespace thin_ice_bench {

struct StateBenchOptions {
  std::string state_dir;
  std::string backend = "cpu";  ///< cpu | cuda
  int threads = 1;              ///< CPU threads (ignored on the GPU)
  long steps = 2000;            ///< timed steps, after 20 warm-up steps
};

/// Prints one Markdown table row (and the header before it when `header`); returns 0, or prints
/// the error naming the file and returns 1.
int benchState(const StateBenchOptions& options, bool header);

}  // namespace thin_ice_bench
