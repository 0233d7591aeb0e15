#include "thin_ice_sim/study/stall_watch.hpp"

#include <algorithm>
#include <utility>

namespace thin_ice {

StallWatch::StallWatch(double threshold_seconds, std::string phase, Report report)
    : threshold_(threshold_seconds), report_(std::move(report)) {
  last_.phase = std::move(phase);
  since_ = reported_ = Clock::now();
  thread_ = std::thread([this] { watch(); });
}

StallWatch::~StallWatch() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void StallWatch::phase(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  last_.phase = name;
  since_ = reported_ = Clock::now();
}

void StallWatch::moved(double time, double length) {
  std::lock_guard<std::mutex> lock(mutex_);
  last_.moved_before = true;
  last_.last_time = time;
  last_.last_length = length;
  since_ = reported_ = Clock::now();
}

void StallWatch::watch() {
  // Looks four times per threshold (at most once a second), so that a report comes at most a
  // quarter of the threshold late.
  const auto period = std::chrono::duration<double>(std::min(1.0, 0.25 * threshold_));
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    wake_.wait_for(lock, period);
    if (stopping_) break;
    const Clock::time_point now = Clock::now();
    if (std::chrono::duration<double>(now - reported_).count() < threshold_) continue;
    reported_ = now;
    StallReport report = last_;
    report.silent_seconds = std::chrono::duration<double>(now - since_).count();
    lock.unlock();  // the report may take its time (a write to a full pipe): moved() must not wait on it
    report_(report);
    lock.lock();
  }
}

}  // namespace thin_ice
