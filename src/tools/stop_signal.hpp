// How `thin_ice run` stops on SIGINT or SIGTERM: the handler only records the request; the stepping
// loop looks at it after each output interval, finishes that interval and writes everything. A
// second request ends the process at once, but a repeat within 1 s of the first is the same
// request delivered twice (GNU timeout signals the command and then its own process group).
#pragma once

#include <time.h>

#include <atomic>
#include <csignal>

namespace thin_ice_tools {
namespace stop_detail {

/// The signal that asked the run to stop (0: none). The handler only records it; the stepping
/// loop looks at it after each output interval. Any thread (OpenMP's included) may take the
/// signal, so it is a lock-free atomic rather than a volatile sig_atomic_t.
inline std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free atomic");

/// [ns] CLOCK_MONOTONIC at the first stop signal.
inline std::atomic<long long> g_first_stop_ns{0};
static_assert(std::atomic<long long>::is_always_lock_free, "the signal handler needs a lock-free atomic");

/// A repeat within this time [ns] of the first signal is the same request delivered twice: GNU
/// timeout (a wall budget) sends its signal to the command and then to its own process group, which
/// holds the command too. Seen on a GPU machine: 6 of 14 strip runs under `timeout -s TERM` died at
/// the second delivery and left only loads.csv.partial.
constexpr long long kRepeatedDeliveryNs = 1000000000LL;

extern "C" inline void requestStop(int signal_number) {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
  const long long now_ns = static_cast<long long>(now.tv_sec) * 1000000000LL + now.tv_nsec;
  int none = 0;
  if (g_stop_signal.compare_exchange_strong(none, signal_number)) {
    g_first_stop_ns.store(now_ns);
    return;
  }
  if (now_ns - g_first_stop_ns.load() < kRepeatedDeliveryNs) return;
  std::signal(signal_number, SIG_DFL);  // a second request ends the process at once
  std::raise(signal_number);
}

}  // namespace stop_detail

/// The signal that asked the run to stop, 0 if none.
inline int stopSignal() { return stop_detail::g_stop_signal.load(); }

/// Installs the handler for SIGINT and SIGTERM.
inline void stopOnSigintAndSigterm() {
  std::signal(SIGINT, stop_detail::requestStop);
  std::signal(SIGTERM, stop_detail::requestStop);
}

}  // namespace thin_ice_tools
