// A lobed saddle's axis (issue 38, 2): the axis of a saddle of k >= 3 lobes, about which rings
// once folded it (saddle25).
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
// Tried, not kept (docs/performance.md, saddle26): the rule's sheet with up to 4 rings about this
// axis folded first (suggestRings and suggestNestedRings, greedily, measured exactly), offered as
// a runner-up start: on polygon_saddle_k4 its fit ended at 7.3% / 1.57% from the square, 7.24% /
// 1.56% from the rectangle, nearer by Hausdorff only, so never kept, for 48% more CPU.
#pragma once

#include <optional>
#include <vector>

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

}  // namespace curvefold
