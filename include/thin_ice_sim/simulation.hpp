// The Simulation API shared by the ROS node and the command-line runner: load a scenario, step,
// command the pusher, pause/reset, read cells, bonds and loads.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "thin_ice_sim/ice_sheet.hpp"
#include "thin_ice_sim/load_sample.hpp"
#include "thin_ice_sim/params.hpp"
#include "thin_ice_sim/scenario.hpp"

namespace thin_ice {

enum class BackendKind { kCpu, kCuda, kAuto };

/// Parses "cpu", "cuda" or "auto"; throws std::invalid_argument naming `key` otherwise.
BackendKind parseBackendKind(const std::string& text, const std::string& key);

class Backend;
struct BackendState;
struct Model;
struct ModelConstants;

class Simulation {
 public:
  /// Builds the sheet, the bonds and the backend. Throws ScenarioError when the time step
  /// exceeds the stable one (the message gives the critical step), std::runtime_error when the
  /// CUDA backend is asked for and unavailable.
  Simulation(const Scenario& scenario, BackendKind backend);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Takes `steps` time steps (also while paused: this is the single-step service).
  void step(long steps);
  /// Advances by `span` seconds of simulated time (rounded to whole steps); nothing when paused.
  void advance(double span);

  void setPusherVelocity(double velocity);  ///< [m/s], applied from the next step
  double pusherVelocity() const;
  void pause() { paused_ = true; }
  void resume() { paused_ = false; }
  bool paused() const { return paused_; }
  /// Back to t = 0 with the same sheet (same seed) and the scenario's pusher velocity.
  void reset();

  double time() const;
  double timeStep() const;
  double criticalTimeStep() const;  ///< [s] of the stiffest spring stepped with dt (for reports)
  int structureSubsteps() const;    ///< n: sub-steps of the structure contact per step
  double structureCriticalTimeStep() const;  ///< [s] with the structure's spring, bounds dt/n
  double pushedLength() const;
  double pusherPosition() const;    ///< [m] x of the plate
  /// [m] the pushed length at which the plate's face reaches the structure's toe (structure.toe_x
  /// - sheet.x_min): the end of the pusher's travel. A pusher moving towards the structure stops
  /// there, within one time step's travel, and pushes no further whatever it is commanded: beyond
  /// it the plate would cut into the structure, and the ice between them would be crushed without
  /// limit (quick.yaml under ASan + UBSan blew up 0.3 m past it, bench/soak).
  double pusherTravel() const;
  bool pusherAtTravelEnd() const;   ///< the plate stands at the end of its travel
  long stepCount() const;

  /// Loads averaged over the steps of the last step()/advance() call (an output interval), so
  /// that a sampled record is not aliased by the contact noise of single steps.
  LoadSample loads() const;
  /// Current cell states (downloads from the device when the backend is on the GPU).
  std::vector<CellSnapshot> cells() const;
  /// World-frame polygon vertices of cell k at its current pose (downloads all cells: to draw
  /// many, take cells() once and use the overload below).
  std::vector<Vec2> cellPolygon(int k) const;
  /// World-frame polygon vertices of cell k at the pose `pose` (an element of cells()).
  std::vector<Vec2> cellPolygon(int k, const CellSnapshot& pose) const;

  int cellCount() const;
  const Params& params() const { return scenario_.params; }
  /// The scene as the laws use it, worked out once from the parameters (physics/cell_forces.hpp):
  /// the structure's face and panels, where the false bottom starts and its height (z, below the
  /// waterline), the walls. Markers and checks read it here rather than work it out again.
  const ModelConstants& scene() const;
  const Scenario& scenario() const { return scenario_; }
  const IceSheet& sheet() const { return sheet_; }
  std::string backendName() const;
  /// One line on how the backend was chosen (e.g. why `auto` fell back to the CPU).
  const std::string& backendNote() const { return backend_note_; }
  /// The host instruction set this build's CPU code was compiled for ("x86-64-v3", "baseline":
  /// CMake's THIN_ICE_CPU_LEVEL); results differ between levels in the last bits.
  static const char* cpuInstructionSet();

  /// The state between steps, for a checkpoint (thin_ice_sim/checkpoint.hpp; the pusher's
  /// velocity is not in it).
  BackendState saveState() const;
  /// Goes on from `state`, saved from this scenario's model on any backend: the next step is the
  /// one that would have followed it. Throws std::invalid_argument, naming what does not fit the
  /// model (cell or bond counts, pair lists of unequal length, a pair out of range or order, a bad
  /// S_ref, a non-finite value), and then changes nothing. Clears a blow-up; the pusher velocity stays as it is.
  void restoreState(const BackendState& state);
  /// False after a numerical blow-up (non-finite state or runaway speed); the simulation then
  /// refuses to step until reset() and lastError() says what happened.
  bool healthy() const { return last_error_.empty(); }
  const std::string& lastError() const { return last_error_; }

 private:
  Scenario scenario_;
  IceSheet sheet_;
  std::unique_ptr<Model> model_;
  std::unique_ptr<Backend> backend_;
  std::string backend_note_;
  double pusher_velocity_ = 0.0;
  bool paused_ = false;
  std::string last_error_;
};

}  // namespace thin_ice
