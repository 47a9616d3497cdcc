// Wings lifted toward (issue 38, 2): where the target rises or falls far from the sheet (a steep
// or monkey saddle's wing 8-13 cm above a square whose one bend follows the other direction),
// turn the part of the sheet under that wing about a hinge across the way to it, as a paper artist
// tucks the sheet toward each wing in turn.
//
// Method: the target's vertices are measured to the sheet; the farthest few (beyond kFar of the
// diagonal, apart by a quarter of the sheet) are its wings. For each wing q, the sheet's point p
// nearest it and the outward way u there (from the sheet's centre, in the sheet's tangent plane):
// hinges back from p along u (where p and q are as far from the hinge, and at fixed shares of p's
// reach from the centre), each turning the end beyond it about the hinge's line by the angle that
// carries p toward q (and 0.7 of it), made either as one fold (a plane through the hinge at half
// the turn: the end is mirrored, which a flat sheet does not see) or as a pleat's two folds
// (pleat_folds.hpp's pleatPlanes: the end keeps its own curvature). Each is made on the real sheet
// (FoldSession), refused where it crosses the sheet more than before, and measured exactly on a
// few thousand samples: kept where the wing's far target points come nearer by a fifth, the sheet
// stands out no farther than the Hausdorff distance before, and the Chamfer distance rises by 2%
// at most. Each wing's best lift (its far points nearest), then all wings' best as one step
// (grown greedily where together they cross), since a wing lifted alone leaves the Hausdorff
// distance at the next wing's.
//
// Inputs: a session holding a design without symmetry; the fitter's target. Output: up to `count`
// steps, each a FoldSuggestion of one group (`before` and `after` are exact Hausdorff distances
// on the samples, not the search's score), the group of every wing first where it is nearer than
// the best single lift, then single lifts by Hausdorff distance. The fit offers them in its final
// rounds beside the corner tucks (FitRun::tuckCorners), where the exact measure keeps a step only
// if it brings the sheet nearer. Known limits: the hinge is straight and one turn per wing, so a
// wing that curls is met at one point; a wing beyond the sheet's reach is not reached.
#pragma once

#include <cstddef>
#include <vector>

#include "engine/fit/deadline.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/geometry/fold_session.hpp"

namespace curvefold {

// Up to `count` lifts for the design `session` holds, best first (see above). The session is left
// as it was.
std::vector<FoldSuggestion> suggestWingLifts(FoldSession& session, const FoldFitter& fitter,
                                             std::size_t count, const Deadline& deadline);

}  // namespace curvefold
