// The fixture of the tests that run once per backend: the CPU always, the GPU where this build has
// the CUDA backend and a device is present (else the GPU case is skipped, with the reason).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "thin_ice_sim/backend.hpp"
#include "thin_ice_sim/built_backends.hpp"
#include "thin_ice_sim/simulation.hpp"

namespace thin_ice {
namespace test {

inline bool registerBackendsOnce() {
  static const bool registered = (registerBuiltBackends(), true);
  return registered;
}

/// Why the GPU cannot run here ("" when it can).
inline std::string gpuMissing() {
  registerBackendsOnce();
  const GpuBackendProvider* gpu = gpuBackendProvider();
  return gpu == nullptr ? "this build has no CUDA backend" : gpu->unavailable_reason();
}

/// Each TEST_P body runs once per backend; instantiate with THIN_ICE_EVERY_BACKEND() where
/// `using thin_ice::test::EveryBackend;` is in scope (gtest pastes the suite's name into identifiers).
class EveryBackend : public ::testing::TestWithParam<BackendKind> {
 protected:
  void SetUp() override {
    ASSERT_TRUE(registerBackendsOnce());
    if (GetParam() == BackendKind::kCuda && !gpuMissing().empty()) GTEST_SKIP() << "no GPU run: " << gpuMissing();
  }
};

inline std::string backendTestName(const ::testing::TestParamInfo<BackendKind>& info) {
  return info.param == BackendKind::kCpu ? "cpu" : "cuda";
}

}  // namespace test
}  // namespace thin_ice

#define THIN_ICE_EVERY_BACKEND()                                                                      \
  INSTANTIATE_TEST_SUITE_P(Backends, EveryBackend,                                                     \
                           ::testing::Values(::thin_ice::BackendKind::kCpu, ::thin_ice::BackendKind::kCuda), \
                           ::thin_ice::test::backendTestName)
