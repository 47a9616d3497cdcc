// When a search stops: a moment on the steady clock, a flag another thread (or a signal
// handler) sets, and a count of the candidates scored (a budget that does not depend on the
// clock). Shared by the fit (fold_fit.hpp), the unfolding (target_unfolding.hpp) and the studio's
// worker (suggestion_worker.hpp).
#pragma once

#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>

namespace curvefold {

// Seconds of CPU this process has spent so far, all its threads together (the one such clock:
// the fit's share of work, work_share.hpp, and the tests' CPU bounds, tests/cpu_time.hpp).
inline double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The moment a search stops (the default never comes), or earlier when `cancelled` is set from
// another thread, or at `shareAt` once the process has spent `cpuAt` seconds of CPU (a share of
// work, work_share.hpp: the CPU clock is read only past `shareAt`). `evaluations`, when set, counts
// the candidate folds a search scores (a budget that does not depend on the clock: fitFolds checks
// it between steps); `droppedSamples`, when set, counts the sheet samples a search could not place
// on its evaluation copy (FitResult says them).
struct Deadline {
  std::chrono::steady_clock::time_point at = std::chrono::steady_clock::time_point::max();
  const std::atomic<bool>* cancelled = nullptr;
  std::chrono::steady_clock::time_point shareAt = std::chrono::steady_clock::time_point::max();
  double cpuAt = 0.0;  // processCpuSeconds() at which a share past `shareAt` is spent
  std::atomic<std::uint64_t>* evaluations = nullptr;
  std::atomic<std::uint64_t>* droppedSamples = nullptr;
  // When the time passes (a cancel is not this), a search still answers with the best it has
  // scored (the studio's worker, whose time limit must not leave the designer with nothing);
  // otherwise it answers nothing (the fit drops a step the clock cut short whole).
  bool answerLate = false;
  // `seconds` from now (beyond a billion, or NaN: never).
  static Deadline in(double seconds) {
    Deadline deadline;
    if (seconds < 1e9)
      deadline.at = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(std::max(0.0, seconds)));
    return deadline;
  }
  bool isCancelled() const { return cancelled && cancelled->load(std::memory_order_relaxed); }
  bool passed() const {
    if (isCancelled()) return true;
    const auto now = std::chrono::steady_clock::now();
    return now >= at || (now >= shareAt && processCpuSeconds() >= cpuAt);
  }
  // Whether a search past this deadline gives up what it has (see answerLate).
  bool givesUp() const { return isCancelled() || (!answerLate && passed()); }
  // The same deadline, come no later than `latest`.
  Deadline notAfter(std::chrono::steady_clock::time_point latest) const {
    Deadline d = *this;
    d.at = std::min(at, latest);
    return d;
  }
  void countEvaluation() const {
    if (evaluations) evaluations->fetch_add(1, std::memory_order_relaxed);
  }
  void countDroppedSamples(std::uint64_t count) const {
    if (droppedSamples && count > 0) droppedSamples->fetch_add(count, std::memory_order_relaxed);
  }
};

}  // namespace curvefold
