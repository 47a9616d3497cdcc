// Corners tucked under (issue 38, 2): where the sheet stands past the target's rim (a square's
// corners over a round saddle: 30 mm past a disk of 10 cm radius), fold that part under the sheet
// as a paper artist does, rather than leave it standing out.
//
// Method: the sheet's vertices are measured to the target; those farther than kFar of the
// diagonal whose way to the target runs along the sheet (not across it: a sheet above or below
// the target is the pleats' work) stand past its rim. The farthest few of them, apart, are each
// given a tuck: a hinge line across the outward direction, about as far back from the far point
// as the point stands out (at 0.8, 1.0 and 1.25 of it), and a reflection through a plane through
// the hinge perpendicular to the sheet's tangent there, tilted by eps out of it. Reflected
// through a plane at 90 - eps degrees to the sheet, the corner comes back under (or over) the
// sheet at 2 eps: a tangent plane's reflection mirrors the sheet's curvature about the hinge, so
// the flap follows the sheet to second order and stands off it only by its length times
// sin(2 eps). Each tuck is made on the real sheet (FoldSession), scored by how far the sheet then
// stands out (the squares of its vertices' distances past kFar, summed: the search's
// approximateDistance cuts far distances, and barely sees a corner 24 mm out), kept where that
// falls by a tenth and the search's score rises by no more than 3%, with no more crossings than
// before (self_intersection.hpp), and taken back; each far point's best tuck is kept (where none
// of the usual hinges is, hinges nearer and farther back at a steeper tilt are tried, then hinges
// turned 25 and 45 degrees either way about the sheet's normal, which run beside a narrow pleat
// that a hinge across the outward way would cross), and all of
// them made together as one step; where that is refused (a grown square's corner flap crossing the
// flap of its side's middle), a group grown greedily, farthest point first. The fit makes them as
// its last steps (FitRun::tuckCorners: rounds until no corner stands out, up to eight, each
// judged by the exact distances), and the start chosen by its first step counts them on grown
// sheets (first_step_start.hpp).
//
// Inputs: a session holding a design without symmetry; the fitter's target. Output: up to `count`
// steps, the sheet standing out least first (the tucks of every far point as one group, then
// single tucks); `after` is the search's score. Known limits: the hinge is straight, so a round rim
// is cut as a polygon (one chord per far point); a flap longer than the sheet beside it would stick
// out beyond it; a fold made later may cut through a tucked flap (the search's self-intersection
// checks refuse what crosses).
#pragma once

#include <cstddef>
#include <vector>

#include "engine/fit/deadline.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/geometry/fold_session.hpp"

namespace curvefold {

// Up to `count` tucks for the design `session` holds, best first (see above). The session is left
// as it was. `dearer`: try the nearer and farther hinges where the usual ones fail (the start
// choice, which counts tucks on each grown sheet within a share of the clock, leaves them out).
std::vector<FoldSuggestion> suggestTucks(FoldSession& session, const FoldFitter& fitter,
                                         std::size_t count, const Deadline& deadline,
                                         bool dearer = true);

}  // namespace curvefold
