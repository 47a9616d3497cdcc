#include "engine/fit/lobed_saddle.hpp"

#include <cstdio>
#include <random>

#include "engine/fit/nested_rings.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {

std::optional<PlacedStart> ringedStart(const PlacedStart& flat, const FoldFitter& fitter,
                                       const LobedAxis& lobed, const Deadline& deadline) {
  const FitSettings& settings = fitter.settings();
  // The fitter's own samples of the target: the axis was read on them.
  const std::vector<SurfaceSample> samples =
      sampleSurface(fitter.target(), settings.targetSamples, settings.seed + 1);
  auto scoreOf = [&](const Sheet& s) {
    const SurfaceDistance d = surfaceDistance(meshOf(s), fitter.measuredTarget(), kRingedSamples);
    return d.chamfer + 0.5 * d.hausdorff;
  };
  std::mt19937_64 random(settings.seed);
  Sheet sheet = flat.sheet;
  const double start = scoreOf(sheet);
  double best = start;
  std::size_t rings = 0;
  for (; rings < kRingedSteps && !deadline.passed(); ++rings) {
    const FoldSession session(sheet);
    std::vector<FoldSuggestion> steps =
        suggestRings(session, fitter, lobed.axis, samples, 1, settings.rings, deadline, random);
    for (FoldSuggestion& nested :
         suggestNestedRings(session, fitter, lobed.axis, samples, 1, deadline, random))
      steps.push_back(std::move(nested));
    const FoldSuggestion* kept = nullptr;
    double keptScore = (1.0 - kRingedLeastGain) * best;
    for (const FoldSuggestion& step : steps) {
      const double score = scoreOf(step.sheet);
      if (score < keptScore) {
        kept = &step;
        keptScore = score;
      }
    }
    if (!kept) break;
    sheet = kept->sheet;
    best = keptScore;
  }
  if (rings == 0) return std::nullopt;
  PlacedStart out{"ringed_" + flat.surface, flat.parameters, "", sheet};
  char text[200];
  std::snprintf(text, sizeof text,
                "%zu ring%s about its lobes' axis of order %d folded first (score %.4g -> %.4g, "
                "in the target's units); ",
                rings, rings == 1 ? "" : "s", lobed.order, start, best);
  out.placement = text + flat.placement;
  return out;
}

}  // namespace curvefold
