// The stall watch (thin_ice_sim/study/stall_watch.hpp): a run that keeps moving is never reported;
// one that stops is reported once per threshold of silence, with its phase and its last row; a run
// that never moved says so. Wall-clock behaviour with wide margins (a busy 2-core machine must not
// make it fail): thresholds of 50 ms against silences of 0.3-0.6 s, and of 0.2 s against gaps of 2 ms.
#include "thin_ice_sim/study/stall_watch.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

namespace thin_ice {
namespace {

using std::chrono::milliseconds;

struct Reports {
  std::mutex mutex;
  std::vector<StallReport> seen;
  StallWatch::Report sink() {
    return [this](const StallReport& r) {
      std::lock_guard<std::mutex> lock(mutex);
      seen.push_back(r);
    };
  }
  std::vector<StallReport> copy() {
    std::lock_guard<std::mutex> lock(mutex);
    return seen;
  }
};

TEST(StallWatch, ARunThatKeepsMovingIsNeverReported) {
  Reports reports;
  {
    StallWatch watch(0.2, "stepping", reports.sink());
    for (int row = 1; row <= 500; ++row) {  // 1 s of rows 2 ms apart: five thresholds in all
      std::this_thread::sleep_for(milliseconds(2));
      watch.moved(0.01 * row, 0.0005 * row);
    }
  }
  EXPECT_TRUE(reports.copy().empty());
}

TEST(StallWatch, ARunThatStopsIsReportedOncePerThresholdWithWhereItWas) {
  Reports reports;
  {
    StallWatch watch(0.05, "setting up", reports.sink());
    watch.phase("stepping");
    watch.moved(12.5, 0.625);
    std::this_thread::sleep_for(milliseconds(600));
  }
  const std::vector<StallReport> seen = reports.copy();
  // 0.6 s of silence at a threshold of 0.05 s: about 12 reports, one each 0.05-0.0625 s; fewer
  // where the machine is busy, never more than one per threshold.
  ASSERT_GE(seen.size(), 2u);
  EXPECT_LE(seen.size(), 12u);
  for (size_t k = 0; k < seen.size(); ++k) {
    EXPECT_EQ(seen[k].phase, "stepping");
    EXPECT_TRUE(seen[k].moved_before);
    EXPECT_EQ(seen[k].last_time, 12.5);
    EXPECT_EQ(seen[k].last_length, 0.625);
    EXPECT_GE(seen[k].silent_seconds, 0.05 * (k + 1)) << "report " << k;
    if (k > 0) EXPECT_GE(seen[k].silent_seconds - seen[k - 1].silent_seconds, 0.05) << "report " << k;
  }
}

TEST(StallWatch, ARunThatNeverMovedSaysSoAndAPhaseChangeRestartsTheCount) {
  Reports reports;
  {
    StallWatch watch(0.05, "setting up", reports.sink());
    std::this_thread::sleep_for(milliseconds(300));
    watch.phase("stepping");
    std::this_thread::sleep_for(milliseconds(300));
  }
  const std::vector<StallReport> seen = reports.copy();
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front().phase, "setting up");
  bool stepping = false;
  for (const StallReport& r : seen) {
    EXPECT_FALSE(r.moved_before);
    if (r.phase == "stepping") {
      stepping = true;
      EXPECT_LT(r.silent_seconds, 0.3 + 0.25) << "counted from the phase change, not from the start";
    }
  }
  EXPECT_TRUE(stepping);
}

}  // namespace
}  // namespace thin_ice
