#include "engine/fit/runner_up_fits.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "engine/geometry/symmetry.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {

Sheet runnerUpSheet(const RunnerUpStart& start) {
  return start.placed ? *start.placed : makeSurface(start.surface, start.parameters);
}

std::size_t keptStartFit(const std::vector<StartFit>& fits) {
  std::size_t keep = 0;
  const auto ended = [&](std::size_t i) -> const FitProgress& {
    return fits[i].result.steps.back();
  };
  const auto score = [&](std::size_t j) { return ended(j).chamfer + 0.25 * ended(j).hausdorff; };
  for (std::size_t i = 1; i < fits.size(); ++i) {
    const bool nearer =
        ended(i).hausdorff < ended(0).hausdorff && ended(i).chamfer < ended(0).chamfer;
    if (nearer && (keep == 0 || score(i) < score(keep))) keep = i;
  }
  return keep;
}

RunnerUpFits fitWithRunnersUp(const FoldFitter& fitter, const Sheet& start,
                              const std::string& symmetry,
                              const std::vector<RunnerUpStart>& runnersUp,
                              const FitOptions& options, const PrepareStartFit& prepare) {
  const auto started = options.started.value_or(std::chrono::steady_clock::now());
  const std::size_t starts = 1 + runnersUp.size();
  // The shares count from here: what the start's choice took is gone for every fit.
  const double searchFrom =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const bool timed = options.seconds < std::numeric_limits<double>::infinity();
  std::uint64_t evaluationsUsed = 0;
  RunnerUpFits out;
  for (std::size_t i = 0; i < starts; ++i) {
    if (i > 0 && options.cancelled && options.cancelled->load()) break;
    const Sheet initial = i == 0 ? start : runnerUpSheet(runnersUp[i - 1]);
    StartFit fit;
    fit.session = std::make_unique<FoldSession>(initial);
    if (i == 0 && !symmetry.empty()) fit.session->setSymmetry(parseSymmetry(symmetry, initial));
    fitter.checkAgainst(initial);
    FitOptions share = options;
    const double part = static_cast<double>(i + 1) / static_cast<double>(starts);
    share.seconds = timed ? searchFrom + part * (options.seconds - searchFrom)
                          : std::numeric_limits<double>::infinity();
    share.started = started;
    if (options.maxEvaluations > 0) {
      // What one fit leaves, the next may use.
      const auto upTo =
          static_cast<std::uint64_t>(std::ceil(part * static_cast<double>(options.maxEvaluations)));
      share.maxEvaluations = std::max<std::uint64_t>(1, upTo - std::min(upTo, evaluationsUsed));
    }
    if (i > 0) share.tubeChains = nullptr;  // the start's probe grew them on its sheet
    if (prepare) prepare(i, *fit.session, share);
    fit.result = fitFolds(*fit.session, fitter, share);
    evaluationsUsed += fit.result.evaluations;
    out.fits.push_back(std::move(fit));
  }
  out.kept = keptStartFit(out.fits);
  return out;
}

}  // namespace curvefold
