// The runner's progress on stderr: one updating line on a terminal, one plain line per 10 % otherwise,
// and at least one a minute (a heartbeat: a long segment at a low real-time factor can take hours
// per 10 %, and a run that prints nothing cannot be told from a run that hangs).
#pragma once

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "thin_ice_sim/simulation.hpp"

namespace thin_ice_tools {

/// A duration [s] as "1h05m", "3m07s" or "12s"; "?" when unknown (not finite or negative).
inline std::string formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "?";
  const long s = std::lround(seconds);
  char text[32];
  if (s >= 3600) std::snprintf(text, sizeof(text), "%ldh%02ldm", s / 3600, (s / 60) % 60);
  if (s >= 60 && s < 3600) std::snprintf(text, sizeof(text), "%ldm%02lds", s / 60, s % 60);
  if (s < 60) std::snprintf(text, sizeof(text), "%lds", s);
  return text;
}

/// A single updating line on a terminal (every 0.5 s wall); one plain line per 10 % otherwise, or
/// after kHeartbeatSeconds of wall time without one.
class Progress {
 public:
  static constexpr double kHeartbeatSeconds = 60.0;  ///< [s] wall, longest silence off a terminal

  /// start_time [s] and start_fraction: where this segment of the run began (0, 0 unless resumed).
  Progress(double start_time, double start_fraction)
      : tty_(::isatty(STDERR_FILENO) != 0), start_time_(start_time), start_fraction_(start_fraction) {
    while (next_tenth_ - 1e-3 <= start_fraction) next_tenth_ += 0.1;
  }
  void report(double fraction, const thin_ice::LoadSample& s, double wall, bool last) {
    // 1e-3: rows whose time falls a rounding short of a tenth still print it
    const double since_print = wall - (last_print_ < 0.0 ? 0.0 : last_print_);  // [s] wall
    const bool due = last || (tty_ ? wall - last_print_ >= 0.5
                                   : fraction >= next_tenth_ - 1e-3 || since_print >= kHeartbeatSeconds);
    if (!due) return;
    const double rtf = wall > 0.0 ? (s.time - start_time_) / wall : 0.0;
    const double done = fraction - start_fraction_;
    const double eta = done > 0.0 ? wall * (1.0 - fraction) / done : NAN;
    std::fprintf(stderr, "%s%3.0f%%  t %.2f s  L %.3f m  F_cal %.0f N  %.3gx real time  ETA %s%s",
                 tty_ ? "\r" : "", 100.0 * fraction, s.time, s.pushed_length,
                 s.horizontal_calibrated, rtf, formatDuration(eta).c_str(),
                 tty_ ? (last ? "   \n" : "   ") : "\n");
    last_print_ = wall;
    while (next_tenth_ - 1e-3 <= fraction) next_tenth_ += 0.1;
  }

 private:
  bool tty_;
  double start_time_, start_fraction_;
  double last_print_ = -1.0;   // [s] wall
  double next_tenth_ = 0.1;    // fraction at which the next plain line is due
};

}  // namespace thin_ice_tools
