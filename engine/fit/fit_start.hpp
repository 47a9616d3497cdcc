// The start a fit folds when none is given whole (issue 38, 2): `fit` without --from, or --from a
// kind without parameters, and Python's curvefold.fit. One home for the command line and the
// module, so both fold the same sheet from the same seed.
//
// chooseFitStart: the rule's sheet (chooseStart, start_surface.hpp) sized to `fitter`'s target,
// revised by its first step toward a saddle (reviseByFirstStep) and, where that does not apply,
// toward a vase (reviseTubeByFirstStep, its probe's rings handed on for the search to grow);
// with a symmetry asked for, neither revision and no runners-up (they seldom have it).
// Limits (FitStartClock): the choice takes kStartShare of the fit's seconds as a share of work
// (work_share.hpp: CPU and wall clock, so a loaded machine measures the sheets --evaluations
// does), ended on the wall clock at kStartLatest; the tube probe times its batches by the wall
// clock's share (timed_batches.hpp). Without seconds (infinity) nothing is timed and nothing
// cancels the choice (it is bounded by the sheets it measures).
// Throws InvalidSymmetry when the symmetry is no symmetry or no candidate sheet has it,
// SurfaceError when the named kind cannot be sized to the target.
#pragma once

#include <atomic>
#include <chrono>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "engine/fit/first_step_start.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/start_surface.hpp"

namespace curvefold {

// The fit's clock as the choice shares it: from `started` (the command's own start: reading the
// target counts), `startedCpu` (processCpuSeconds() then), `seconds` the fit's whole limit
// (infinity: none), `cancelled` (an interrupt) cutting a timed choice.
struct FitStartClock {
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
  double startedCpu = processCpuSeconds();
  double seconds = std::numeric_limits<double>::infinity();
  const std::atomic<bool>* cancelled = nullptr;
};

// The choice's shares of FitStartClock::seconds (docs/performance.md: on a large target each
// sheet measured costs a second or more; the rest is the search's).
inline constexpr double kStartShare = 0.25, kStartLatest = 0.5;

struct FitStart {
  StartChoice choice;  // the sheet to fold (revised), its runners-up (none with a symmetry)
  std::optional<FirstStepStart> firstStep;       // set where a first step chose it
  std::shared_ptr<const TubeChains> tubeChains;  // the probe's rings (FitOptions::tubeChains)
};

// `kind`: a catalogue name or "" (any); `symmetry`: unset where none was asked for (the text as
// parseSymmetry reads it otherwise).
FitStart chooseFitStart(const FoldFitter& fitter, const std::string& kind,
                        const std::optional<std::string>& symmetry, const FitStartClock& clock);

}  // namespace curvefold
