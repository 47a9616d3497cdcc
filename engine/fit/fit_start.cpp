#include "engine/fit/fit_start.hpp"

#include "engine/fit/work_share.hpp"

namespace curvefold {

FitStart chooseFitStart(const FoldFitter& fitter, const std::string& kind,
                        const std::optional<std::string>& symmetry, const FitStartClock& clock) {
  const bool timed = clock.seconds < std::numeric_limits<double>::infinity();
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock.started).count();
  // The choice's share of work, and the wall clock's share for the tube probe (it times its
  // batches by Deadline::at alone, where a share of work sets only the latest moment).
  const Deadline work =
      timed ? workShare(kStartShare * clock.seconds - (processCpuSeconds() - clock.startedCpu),
                        kStartShare * clock.seconds - elapsed,
                        kStartLatest * clock.seconds - elapsed, clock.cancelled)
            : Deadline{};
  const Deadline wall =
      timed ? Deadline{}.notAfter(clock.started +
                                  std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(kStartShare * clock.seconds)))
            : Deadline{};
  FitStart out;
  const bool symmetric = symmetry.has_value();
  out.choice = chooseStart(fitter.measuredTarget(), kind, symmetric ? *symmetry : "", work);
  // Toward a saddle (smooth, no axis) the start is the one whose first step lands nearest: a
  // flat sheet's cross of pleats beats a swept parabola that starts nearer.
  if (!symmetric) out.firstStep = reviseByFirstStep(out.choice, fitter, kind, work);
  // Toward a vase, the cone around its profile where its rings land nearer than the start's
  // (rings only narrow a tube: a belly outside the start is never reached). The probe's rings
  // are handed to the search, which grows them on.
  if (!symmetric && !out.firstStep) {
    auto chains = std::make_shared<TubeChains>();
    out.firstStep = reviseTubeByFirstStep(out.choice, fitter, kind, wall, 2, chains.get());
    if (!chains->chains.empty()) out.tubeChains = std::move(chains);
  }
  // A symmetric design keeps its start (the runners-up seldom have the symmetry).
  if (symmetric) out.choice.runnersUp.clear();
  return out;
}

}  // namespace curvefold
