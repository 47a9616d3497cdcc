// Rings about a lobed saddle's axis, folded first (issue 38, 2): a runner-up start toward a saddle
// of k >= 3 lobes (fit_start.hpp), beside the pleats its first step chose.
//
// Why: revolutionAxis (profile_folds.hpp) refuses a saddle's axis where its height swings with
// the turn (saddle25), which took rings from every saddle. On bench/make_polygon_saddles.py's
// four-lobed saddle the rings had come nearer than the pleats that replaced them (`--from square`
// 7.37% / 0.85% Hausdorff / Chamfer of the diagonal against 9.38% / 1.17%).
//
// lobedSaddleAxis: the axis revolutionAxis refuses only for that swing (held by radius within
// `maxSpread`), where one order k >= kLeastLobes of the swing holds kLobedOrderShare of its mean
// square (orders 2 to 6, within the radii covered all around): the saddle repeats every 1/k turn.
// Order 2 (a hypar's) is left out: its rings about the false axis ended far from the pleats
// (saddle_rect_30 and saddle_long from the square, 9.70% and 12.0% Hausdorff against 2.40% and
// 4.23%, saddle25). Defined in profile_folds.cpp, beside the reading it shares.
//
// ringedStart: the flat sheet with rings about that axis folded first, greedily: each step the
// best ring of suggestRings (profile_folds.hpp) and of suggestNestedRings (nested_rings.hpp), each
// measured exactly (kRingedSamples a side) by Chamfer + 0.5 Hausdorff (startByFirstStep's score),
// kept while it lowers that by kRingedLeastGain, up to kRingedSteps rings. The fit folds on from
// it without an axis (its pleats and single folds). None where no ring helps.
// Known limits: the rings are chosen by the fitter's score counting the target in full (the
// saddle's); their planes are made on the sheet once and not refitted after later folds.
#pragma once

#include <optional>
#include <vector>

#include "engine/fit/deadline.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/placed_start.hpp"
#include "engine/fit/profile_folds.hpp"

namespace curvefold {

struct LobedAxis {
  RevolutionAxis axis;
  int order = 0;       // the lobes' order
  double share = 0.0;  // that order's share of the swing's mean square
};
inline constexpr double kLobedOrderShare = 0.6;
inline constexpr int kLeastLobes = 3;

std::optional<LobedAxis> lobedSaddleAxis(const std::vector<SurfaceSample>& samples,
                                         double maxSpread = 0.1);

inline constexpr std::size_t kRingedSteps = 4, kRingedSamples = 1500;
inline constexpr double kRingedLeastGain = 0.02;

std::optional<PlacedStart> ringedStart(const PlacedStart& flat, const FoldFitter& fitter,
                                       const LobedAxis& lobed, const Deadline& deadline);

}  // namespace curvefold
