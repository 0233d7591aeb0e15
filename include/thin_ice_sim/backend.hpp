// The interface every backend (CPU with OpenMP, CUDA) implements behind Simulation:
// upload the model, step(n), download cells, read loads.
#pragma once

#include <string>
#include <vector>

#include "thin_ice_sim/model.hpp"
#include "thin_ice_sim/simulation.hpp"

namespace thin_ice {

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string name() const = 0;
  /// Back to the model's initial state, t = 0.
  virtual void reset() = 0;
  /// Takes `steps` time steps with the pusher at `pusher_velocity` [m/s]. Loads are averaged
  /// over these steps. Stops early and sets healthError() on a numerical blow-up.
  virtual void step(long steps, double pusher_velocity) = 0;
  virtual double time() const = 0;
  virtual long stepCount() const = 0;
  virtual double pusherPosition() const = 0;
  virtual LoadSample loads() const = 0;
  virtual std::vector<CellSnapshot> cells() const = 0;
  /// Empty while healthy; else what went wrong (non-finite state, runaway speed).
  virtual std::string healthError() const = 0;
};

}  // namespace thin_ice
