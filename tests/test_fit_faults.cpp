// Faults inside the fold search's refinement (issue 40, 4): NLopt's answer is replaced here (this
// executable defines nlopt_optimize, which the fit's calls bind to before the library's), so each
// outcome can be given on demand. A forced stop (the deadline) and a round-off limit keep the best
// drag seen; out of memory and a failure are not swallowed.
#include <dlfcn.h>

#include <atomic>
#include <new>
#include <optional>
#include <stdexcept>

#include <gtest/gtest.h>
#include <nlopt.h>

#include "engine/fit/fold_fit.hpp"
#include "engine/geometry/triangle_mesh.hpp"
#include "tests/support/random_fold_target.hpp"

namespace {
// NLopt's result for every refinement while set; the real optimizer otherwise.
std::atomic<int> gForced{0};
std::atomic<int> gCalls{0};
}  // namespace

extern "C" nlopt_result nlopt_optimize(nlopt_opt opt, double* x, double* value) {
  ++gCalls;
  if (const int forced = gForced.load(); forced != 0) return static_cast<nlopt_result>(forced);
  using Optimize = nlopt_result (*)(nlopt_opt, double*, double*);
  static const auto real = reinterpret_cast<Optimize>(::dlsym(RTLD_NEXT, "nlopt_optimize"));
  return real(opt, x, value);
}

namespace curvefold {
namespace {

FitSettings searchOnly() {
  FitSettings settings;
  settings.sheetSamples = 500;
  settings.targetSamples = 500;
  settings.denseTargetSamples = 4000;
  settings.proposals = 64;
  settings.useCreases = false;  // drags through crease planes are not refined
  return settings;
}

struct Forced {
  explicit Forced(nlopt_result result) { gForced = result; }
  ~Forced() { gForced = 0; }
};

TEST(FoldFitFaults, RefinementKeepsTheBestDragAtTheDeadlineOrTheRoundOffLimit) {
  const RandomFoldTarget target = makeRandomFoldTarget("rectangle", {{"resolution", 16}}, 1, 1000);
  const FoldFitter fitter(meshOf(target.sheet), searchOnly());
  for (const nlopt_result result : {NLOPT_FORCED_STOP, NLOPT_ROUNDOFF_LIMITED}) {
    FoldSession session(target.initial);
    const Forced forced(result);
    gCalls = 0;
    EXPECT_NO_THROW(fitter.suggest(session, 2)) << result;
    EXPECT_GT(gCalls.load(), 0) << result;
  }
}

// Out of memory in the refinement was swallowed with every other exception (fold_fit.cpp caught
// std::exception), and the search went on with less than it thought it had.
TEST(FoldFitFaults, RunningOutOfMemoryWhileRefiningIsNotSwallowed) {
  const RandomFoldTarget target = makeRandomFoldTarget("rectangle", {{"resolution", 16}}, 1, 1000);
  const FoldFitter fitter(meshOf(target.sheet), searchOnly());
  FoldSession session(target.initial);
  {
    const Forced forced(NLOPT_OUT_OF_MEMORY);
    gCalls = 0;
    EXPECT_THROW(fitter.suggest(session, 2), std::bad_alloc);
    EXPECT_GT(gCalls.load(), 0);
  }
  {
    const Forced forced(NLOPT_FAILURE);
    EXPECT_THROW(fitter.suggest(session, 2), std::runtime_error);
  }
  // And the search works as before once NLopt does.
  FoldSession fresh(target.initial);
  EXPECT_FALSE(fitter.suggest(fresh, 2).empty());
}

}  // namespace
}  // namespace curvefold
