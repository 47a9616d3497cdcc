// A share of work as a deadline (issue 38, 2: the fit's start choice). `fit --time T` gives the
// choice of its start a quarter of T; on the wall clock alone a machine loaded by others (at a
// load of 15 a fit gets a tenth of each second) ended the choice before it measured the sheets
// that `--evaluations` measures, so the same seed chose another start (saddle_disk `--from
// square`: its grown square unmeasured, 8.28% Hausdorff against 4.38%).
//
// workShare: a Deadline that passes once the process has spent `cpuSeconds` of CPU (all its
// threads, from the call) and `wallSeconds` of the wall clock have gone by, or at `latestSeconds`
// on the wall clock whatever the CPU (so --time still bounds the command), or when `interrupt` is
// set. The searches read it as any deadline (Deadline::passed reads the CPU clock there, once the
// wall share is past); its passing is the clock's, not a cancel. On an idle machine with one busy
// thread the CPU and the wall clock agree and it passes at `wallSeconds`.
//
// Limits: a search that times its batches by Deadline::at (timed_batches.hpp: the nested and
// tube rings) sees only `latestSeconds` there; the fit gives the tube rings' probe the wall
// clock's share instead (fit_start.cpp).
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>

#include "engine/fit/deadline.hpp"

namespace curvefold {

inline Deadline workShare(double cpuSeconds, double wallSeconds, double latestSeconds,
                          const std::atomic<bool>* interrupt = nullptr) {
  using Clock = std::chrono::steady_clock;
  const auto later = [now = Clock::now()](double seconds) {  // beyond a billion, or NaN: never
    if (!(seconds < 1e9)) return Clock::time_point::max();
    return now + std::chrono::duration_cast<Clock::duration>(
                     std::chrono::duration<double>(std::max(0.0, seconds)));
  };
  Deadline d;
  d.cancelled = interrupt;
  d.cpuAt = processCpuSeconds() + cpuSeconds;
  d.shareAt = later(wallSeconds);
  d.at = later(latestSeconds);
  return d;
}

}  // namespace curvefold
