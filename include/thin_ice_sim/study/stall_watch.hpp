// A watch on a long run from a thread of its own: when the run has not moved (finished an output
// row) for a while, it says so, with what the run was doing and where it last was. The progress
// line prints only after a row, so a step that never returns (a device call that waits forever,
// a deadlock) would otherwise leave a run silent, and a silent run cannot be told from a slow one.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace thin_ice {

/// What the watch saw when it reports.
struct StallReport {
  double silent_seconds = 0.0;  ///< [s] wall since the run last moved (or since the phase began)
  std::string phase;            ///< what the run was doing: "setting up", "stepping", ...
  bool moved_before = false;    ///< false: no row finished since the watch started
  double last_time = 0.0;       ///< [s] simulated time at the last row (when moved_before)
  double last_length = 0.0;     ///< [m] pushed length at the last row (when moved_before)
};

class StallWatch {
 public:
  using Report = std::function<void(const StallReport&)>;

  /// Starts the watch: `report` is called from the watch's thread after every `threshold_seconds`
  /// [s] of wall time in which the run has not moved, and not otherwise.
  StallWatch(double threshold_seconds, std::string phase, Report report);
  ~StallWatch();  ///< stops the watch's thread and waits for it
  StallWatch(const StallWatch&) = delete;
  StallWatch& operator=(const StallWatch&) = delete;

  /// The run now does `name`; the silence counts from here.
  void phase(const std::string& name);
  /// The run finished a row at simulated time `time` [s] and pushed length `length` [m].
  void moved(double time, double length);

 private:
  using Clock = std::chrono::steady_clock;
  void watch();

  const double threshold_;
  const Report report_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  StallReport last_;           ///< phase and last row, under mutex_
  Clock::time_point since_;    ///< the last move or phase change, under mutex_
  Clock::time_point reported_; ///< the last report (or since_, whichever is later), under mutex_
  std::thread thread_;         ///< started last, once the members above exist
};

}  // namespace thin_ice
