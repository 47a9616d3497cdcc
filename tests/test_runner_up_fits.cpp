// The start and its runners-up folded side by side (runner_up_fits.hpp): the fit kept, the
// shares of the count, and a cancel between fits.
#include <atomic>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "engine/fit/fold_fit.hpp"
#include "engine/fit/runner_up_fits.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "fit_settings_support.hpp"
#include "sheet_fixtures.hpp"
#include "tests/support/random_fold_target.hpp"

namespace curvefold {
namespace {

using testing::quickSettings;

FitOptions quickOptions(std::uint64_t evaluations) {
  FitOptions options;
  options.maxFolds = 2;
  options.distanceSamples = 4000;
  options.seconds = std::numeric_limits<double>::infinity();
  options.maxEvaluations = evaluations;
  return options;
}

// A cylinder folded once: its own sheet folds back onto it (the unfolding reads the fold), a flat
// square only comes nearer.
struct TwoStarts {
  RandomFoldTarget target = makeRandomFoldTarget("cylinder", {{"resolution", 20}}, 1, 2002);
  RunnerUpStart cylinder{"cylinder", {{"resolution", 20}}, std::nullopt, "", ""};
  RunnerUpStart square{"square", {{"resolution", 12}}, std::nullopt, "", ""};
};

const FitProgress& ended(const StartFit& fit) {
  return fit.result.steps.back();
}

TEST(RunnerUpFits, KeepsARunnerUpNearerByBothMeasuresAndNotOneFarther) {
  const TwoStarts starts;
  const FoldFitter fitter(meshOf(starts.target.sheet), quickSettings());
  // The square is the rule's choice, the cylinder its runner-up: the cylinder's fit is kept.
  std::vector<std::size_t> prepared;
  const RunnerUpFits cylinderWins = fitWithRunnersUp(
      fitter, runnerUpSheet(starts.square), "", {starts.cylinder}, quickOptions(400),
      [&](std::size_t index, const FoldSession& session, FitOptions& options) {
        prepared.push_back(index);
        EXPECT_EQ(session.foldCount(), 0u);
        // Each an equal cumulative share of the count: half, then what the first left.
        if (index == 0) {
          EXPECT_EQ(options.maxEvaluations, 200u);
        } else {
          EXPECT_GE(options.maxEvaluations, 1u);
        }
      });
  EXPECT_EQ(prepared, (std::vector<std::size_t>{0, 1}));
  ASSERT_EQ(cylinderWins.fits.size(), 2u);
  const FitProgress& fromSquare = ended(cylinderWins.fits[0]);
  const FitProgress& fromCylinder = ended(cylinderWins.fits[1]);
  ASSERT_LT(fromCylinder.hausdorff, fromSquare.hausdorff);
  ASSERT_LT(fromCylinder.chamfer, fromSquare.chamfer);
  EXPECT_EQ(cylinderWins.kept, 1u);
  EXPECT_TRUE(identical(cylinderWins.keptFit().session->initial(),
                        makeSurface("cylinder", {{"resolution", 20}})));
  testing::expectInvariants(cylinderWins.keptFit().session->fixed(),
                            cylinderWins.keptFit().session->initial());

  // The other way round: the square, farther, is not kept over the cylinder.
  const RunnerUpFits cylinderKept = fitWithRunnersUp(fitter, runnerUpSheet(starts.cylinder), "",
                                                     {starts.square}, quickOptions(400));
  ASSERT_EQ(cylinderKept.fits.size(), 2u);
  EXPECT_GT(ended(cylinderKept.fits[1]).chamfer, ended(cylinderKept.fits[0]).chamfer);
  EXPECT_EQ(cylinderKept.kept, 0u);
}

// Results that ended as given (Hausdorff, Chamfer), the start's first.
std::vector<StartFit> endedAt(const std::vector<std::pair<double, double>>& ends) {
  std::vector<StartFit> fits;
  for (const auto& [hausdorff, chamfer] : ends) {
    StartFit fit;
    FitProgress step;
    step.hausdorff = hausdorff;
    step.chamfer = chamfer;
    fit.result.steps.push_back(step);
    fits.push_back(std::move(fit));
  }
  return fits;
}

TEST(RunnerUpFits, KeepsOnlyARunnerUpNearerByBothAndOfThoseTheNearestByTheRulesWeight) {
  // Nearer by Chamfer alone, or by Hausdorff alone: the start.
  EXPECT_EQ(keptStartFit(endedAt({{10, 2}, {12, 1}})), 0u);
  EXPECT_EQ(keptStartFit(endedAt({{10, 2}, {8, 3}})), 0u);
  EXPECT_EQ(keptStartFit(endedAt({{10, 2}, {10, 1}})), 0u);  // as near is not nearer
  // Nearer by both: the runner-up; of two, the least Chamfer + Hausdorff / 4 (9 / 4 + 1.5 = 3.75
  // against 6 / 4 + 1.9 = 3.4).
  EXPECT_EQ(keptStartFit(endedAt({{10, 2}, {9, 1.5}})), 1u);
  EXPECT_EQ(keptStartFit(endedAt({{10, 2}, {9, 1.5}, {6, 1.9}, {12, 0.5}})), 2u);
  EXPECT_EQ(keptStartFit(endedAt({{10, 2}})), 0u);
}

TEST(RunnerUpFits, ACancelStopsItBetweenFits) {
  const TwoStarts starts;
  const FoldFitter fitter(meshOf(starts.target.sheet), quickSettings());
  std::atomic<bool> cancel{false};
  FitOptions options = quickOptions(400);
  options.cancelled = &cancel;
  const RunnerUpFits fits =
      fitWithRunnersUp(fitter, runnerUpSheet(starts.square), "", {starts.cylinder}, options,
                       [&](std::size_t, const FoldSession&, FitOptions&) { cancel = true; });
  ASSERT_EQ(fits.fits.size(), 1u);  // the runner-up not folded
  EXPECT_EQ(fits.kept, 0u);
  EXPECT_TRUE(fits.fits[0].result.cancelled);
}

}  // namespace
}  // namespace curvefold
