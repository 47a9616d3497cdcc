// The start and its runners-up folded side by side, the nearer design kept (issue 38, 2): the
// start's rule (start_surface.hpp) weighs a model of where a fit ends, not the fit, so where its
// runners-up lie close (StartChoice::runnersUp) each is folded too and the fit that ends nearer
// by both measures is kept. One home for every front end (`curvefold fit`, Python's
// curvefold.fit): the engine folds and reports, the front end words it.
//
// fitWithRunnersUp folds `start` (with `symmetry`, "" none: parseSymmetry's text), then each of
// `runnersUp` in order (each its catalogue sheet or placed sheet, no symmetry), each on an equal
// cumulative share of what is left of the limits in `options`: fit i of k ends at (i + 1) / k of
// the time after this call (FitOptions::seconds counts from FitOptions::started, so the last ends
// where a lone fit would), and may score up to (i + 1) / k of maxEvaluations less what the fits
// before it scored. FitOptions::tubeChains is the start's alone; every other option is each
// fit's. A set FitOptions::cancelled stops it between fits (and the fit under way at its next
// check): the starts not folded are left out. Without runners-up it is fitFolds on `start`.
// `prepare`, when set, is called before each fit with its index (0 the start, i runnersUp[i - 1]),
// its session and its options, for a front end's per-fit progress (the command line holds each
// fit's lines back and prints the kept one's).
// Kept: the start, unless a runner-up's fit ended nearer by both exact measures (Hausdorff and
// Chamfer, FitProgress of its last step); of those, the nearest by Chamfer + Hausdorff / 4, as
// the rule weighs a start.
// Throws InvalidTarget where a start's sheet is far from the target or in other units
// (FoldFitter::checkAgainst, before that start is folded), InvalidSymmetry for a bad `symmetry`.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/fit/fold_fit.hpp"
#include "engine/fit/start_surface.hpp"
#include "engine/geometry/fold_session.hpp"

namespace curvefold {

struct StartFit {
  std::unique_ptr<FoldSession> session;  // the start's sheet and the folds kept
  FitResult result;
};

struct RunnerUpFits {
  std::vector<StartFit> fits;  // the start's, then each runner-up's folded (fewer when cancelled)
  std::size_t kept = 0;        // the index of the fit kept (0: the start)
  const StartFit& keptFit() const { return fits[kept]; }
};

using PrepareStartFit = std::function<void(std::size_t, const FoldSession&, FitOptions&)>;

// The sheet a runner-up starts from: placed as it lies, or its kind sized in the catalogue.
Sheet runnerUpSheet(const RunnerUpStart& start);

RunnerUpFits fitWithRunnersUp(const FoldFitter& fitter, const Sheet& start,
                              const std::string& symmetry,
                              const std::vector<RunnerUpStart>& runnersUp,
                              const FitOptions& options, const PrepareStartFit& prepare = {});

// The index of the fit kept of `fits` (the start's first), as above.
std::size_t keptStartFit(const std::vector<StartFit>& fits);

}  // namespace curvefold
