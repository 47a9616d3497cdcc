// A share of work as a deadline (issue 38, 2: the fit's start choice). `fit --time T` gives the
// choice of its start a quarter of T; on the wall clock alone a machine loaded by others (at a
// load of 15 a fit gets a tenth of each second) ended the choice before it measured the sheets
// that `--evaluations` measures, so the same seed chose another start (saddle_disk `--from
// square`: its grown square unmeasured, 8.28% Hausdorff against 4.38%).
//
// A WorkShare passes once the process has spent `cpuSeconds` of CPU (all its threads, from its
// construction) and `wallSeconds` of the wall clock have gone by, or at `latestSeconds` on the
// wall clock whatever the CPU (so --time still bounds the command), or when `interrupt` is set.
// The Deadline it hands out is cancelled at that moment by a watcher thread that looks every
// 5 ms (Deadline has no clock of its own for CPU: a flag keeps the searches, which only read
// Deadline::passed, as they are). On an idle machine with one busy thread the CPU and the wall
// clock agree and it passes at `wallSeconds`, as before.
//
// Limits: passing is seen up to 5 ms late; it is a cancel, so it suits only searches that read a
// cancel as the clock's end (the choice by the first step toward a saddle, first_step_start.hpp:
// its pleats, tucks and distances read Deadline::passed alone); the tube rings' probe drops the
// rings it grew on a cancel (ring_folds.cpp), so the fit gives it the wall clock's share.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <ctime>
#include <mutex>
#include <thread>

#include "engine/fit/deadline.hpp"

namespace curvefold {

// Seconds of CPU this process has spent, all its threads (std::clock).
inline double processCpuSeconds() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

class WorkShare {
 public:
  WorkShare(double cpuSeconds, double wallSeconds, double latestSeconds,
            const std::atomic<bool>* interrupt = nullptr)
      : cpuAt_(processCpuSeconds() + cpuSeconds),
        at_(later(wallSeconds)),
        latest_(later(latestSeconds)),
        interrupt_(interrupt),
        watcher_([this] { watch(); }) {}
  WorkShare(const WorkShare&) = delete;
  WorkShare& operator=(const WorkShare&) = delete;
  ~WorkShare() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    watcher_.join();
  }

  // The deadline to hand to the searches: passed from the moment the share is spent.
  Deadline deadline() const {
    Deadline d;
    d.cancelled = &passed_;
    return d;
  }
  // Whether the share is spent, now (the deadline's flag follows within 5 ms).
  bool passed() const { return passed_.load(std::memory_order_relaxed) || spent(); }

 private:
  using Clock = std::chrono::steady_clock;
  static Clock::time_point later(double seconds) {
    if (!(seconds < 1e9)) return Clock::time_point::max();
    return Clock::now() + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(std::max(0.0, seconds)));
  }
  bool spent() const {
    if (interrupt_ && interrupt_->load(std::memory_order_relaxed)) return true;
    const Clock::time_point now = Clock::now();
    return now >= latest_ || (now >= at_ && processCpuSeconds() >= cpuAt_);
  }
  void watch() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_) {
      if (spent()) {
        passed_.store(true, std::memory_order_relaxed);
        return;
      }
      wake_.wait_for(lock, std::chrono::milliseconds(5));
    }
  }

  const double cpuAt_;
  const Clock::time_point at_, latest_;
  const std::atomic<bool>* interrupt_;
  std::atomic<bool> passed_{false};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread watcher_;  // last: started once the rest is set
};

}  // namespace curvefold
