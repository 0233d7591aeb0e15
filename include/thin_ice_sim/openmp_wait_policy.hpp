// The OpenMP wait policy of the programs (`thin_ice run`, thin_ice_bench, the ROS node): passive,
// unless the caller's environment sets one.
//
// Why: libgomp's default lets a thread that waits at the end of a parallel loop spin for a while
// before it sleeps. On a machine whose cores are busy with other work (two runs on two cores, a
// strip matrix, CI), the spinning threads take the cores from the thread the loop waits for, and
// every step pays for it. Measured on the 2-core build machine with two other runs
// going (thin_ice_bench --state bench/states/m2-pile, 200 steps): one thread 10.2 ms a step, two
// threads 13.1-13.6 ms with the default, 6.5-6.7 ms passive (GOMP_SPINCOUNT=10000: 10.6 ms).
//
// libgomp reads OMP_WAIT_POLICY once, when it is loaded, before main runs: so the program sets it
// and starts itself again (execv of /proc/self/exe with the same arguments, the same process).
// Where that fails, it goes on with the default.
#pragma once

#include <unistd.h>

#include <cstdlib>

namespace thin_ice {

/// Call first thing in main: returns (the default wait policy) only when the environment already
/// names a policy or the restart failed; otherwise the program starts again with a passive one.
inline void restartWithPassiveOpenMpWaitUnlessSet(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  if (setenv("OMP_WAIT_POLICY", "PASSIVE", 1) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("OMP_WAIT_POLICY");  // execv failed: this process keeps libgomp's default
}

}  // namespace thin_ice
