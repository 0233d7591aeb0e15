// Checkpoints: a run's state between steps in one binary file, so that a run stopped (by a
// signal, a wall-time budget or the end of a machine's loan) goes on later from where it stopped,
// on either backend, with the same next step it would have taken.
#pragma once

#include <string>

#include "thin_ice_sim/backend.hpp"
#include "thin_ice_sim/simulation.hpp"

namespace thin_ice {

struct Checkpoint {
  std::string scenario_hash;     ///< Scenario::hash of the run's scenario (file text + overrides)
  double pusher_velocity = 0.0;  ///< [m/s] commanded at the time of the checkpoint
  BackendState state;
  /// Read from a file that carries a checksum (format 2); false for format 1 ("TICKPT01", no checksum),
  /// which still resumes, with a warning that damage to it cannot be told.
  bool checksummed = true;
};

Checkpoint takeCheckpoint(const Simulation& sim);

/// Puts `checkpoint` into `sim` (Simulation::restoreState's checks, and a finite pusher velocity);
/// throws std::invalid_argument when its scenario hash is not sim's, naming both, unless
/// accept_changed_scenario (a scenario file whose comments alone changed since the checkpoint, as
/// the caller has been told), and changes nothing then.
void restoreCheckpoint(Simulation& sim, const Checkpoint& checkpoint, bool accept_changed_scenario = false);

/// Native-endian binary, written through a temporary file and a rename (a crash leaves the old
/// file); throws std::runtime_error naming the path when it cannot be written.
void writeCheckpoint(const std::string& path, const Checkpoint& checkpoint);

/// Throws std::runtime_error naming the path and what is wrong: not a checkpoint, another format
/// version or byte order, truncated, bytes left over, or (format 2) a checksum that does not match
/// the contents: the file is damaged. Reads format 1 (no checksum) too, marked checksummed = false.
Checkpoint readCheckpoint(const std::string& path);

}  // namespace thin_ice
