// A flat sheet folded toward a steep or lobed saddle's wings before any pleat (issue 38, 2): a
// start candidate for startByFirstStep (first_step_start.hpp), offered beside the flat and bent
// sheets and chosen only where its first step lands nearer than theirs.
//
// Why: from a flat sheet the first step (a cross) bends each end by one hinge, and a bent sheet
// follows one curvature; a monkey saddle's three rising and three falling wings, or a saddle over
// a triangle, are followed by neither, and the pleats that come after leave the wings 17-28% of
// the diagonal away. Lifts made after the search crossed the pleated sheet (saddle23: 44 of 48 on
// wing_saddle_k3); made first, on the flat sheet, no pleat is there to cross.
//
// Method: the sheet's centre and plane; for 16 directions in it and hinges at 0.2 to 0.65
// of the sheet's reach that way, the end beyond the hinge turned rigidly about it (one reflection
// through the plane at half the turn, as the cross bends its ends) by the least-squares slope of
// the target's height over the sheet in a wedge of 30 degrees either side of the direction beyond
// the hinge (at 1 and 0.6 of it, the slope out to the wedge's far half, and the slope over the
// whole flap); ranked by the squared height each removes from a model of the sheet (each kept
// wing a ramp beyond its hinge), the best 10 made on the real
// sheet (FoldSession: slivers refused), measured exactly (surfaceDistance, a few hundred samples a
// side) by Chamfer + 0.5 Hausdorff, as startByFirstStep scores; the best that lowers the score by
// 2% and crosses the sheet no more than before is kept, and so on greedily, up to 6 wings. A wing
// made after another is solved on the sheet as the first left it (its hinge on the sheet's unmoved
// middle).
//
// Inputs: a flat candidate (PlacedStart, square or rectangle), the fitter of the target, a
// deadline (stops the wings made so far). Output: the sheet with its wings folded (surface
// "winged_" + the flat kind, the flat kind's parameters, its development unchanged), or none where
// `flat` is not flat or no wing lowers the score. Known limits: hinges are straight chords (a
// wing's rim is left to the pleats and tucks); directions are fixed to the sheet, not to the
// target's lobes; a wing's turn is solved once on its wedge, not against its neighbours.
#pragma once

#include <optional>

#include "engine/fit/deadline.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/placed_start.hpp"

namespace curvefold {

std::optional<PlacedStart> wingStart(const PlacedStart& flat, const FoldFitter& fitter,
                                     const Deadline& deadline);

}  // namespace curvefold
