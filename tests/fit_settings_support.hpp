// The fit's settings and deadlines the fit tests share (test_nested_rings.cpp,
// test_profile_folds.cpp, test_fit.cpp, ...): the sample counts set, everything else the fit's
// defaults.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>

#include "engine/fit/deadline.hpp"
#include "engine/fit/fold_fit.hpp"

namespace curvefold::testing {

// FitSettings with `sheet` and `target` samples for the search's approximate distance and `dense`
// target samples for its closest points; fewer than the defaults keep a step quick.
inline FitSettings sampledSettings(std::size_t sheet, std::size_t target, std::size_t dense) {
  FitSettings settings;
  settings.sheetSamples = sheet;
  settings.targetSamples = target;
  settings.denseTargetSamples = dense;
  return settings;
}

// Small and quick, also under the sanitizers: the fit tests' settings (test_fit.cpp,
// test_pleat_folds.cpp, test_runner_up_fits.cpp).
inline FitSettings quickSettings() {
  FitSettings settings = sampledSettings(700, 700, 8000);
  settings.proposals = 160;
  return settings;
}

// `deadline` counting each candidate it scores into `evaluations` (a step the clock cut makes
// fewer than the whole step).
inline Deadline counting(Deadline deadline, std::atomic<std::uint64_t>& evaluations) {
  deadline.evaluations = &evaluations;
  return deadline;
}

}  // namespace curvefold::testing
