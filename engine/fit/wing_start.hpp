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
// Method: the sheet's centre and plane; for 16 directions in it and hinges at 0.2 to 0.65 of the
// sheet's reach that way, the end beyond the hinge turned rigidly about it (one reflection through
// the plane at half the turn, as the cross bends its ends) by the least-squares slope of the
// target's height over the sheet in a wedge of 30 degrees either side of the direction beyond the
// hinge (at 1 and 0.6 of it), by the slope out to the wedge's far half (a wing that steepens toward
// its tip) and by the slope over the whole flap (as wide as the sheet: a lobe's neighbours too);
// ranked by the squared height each removes from a model of the sheet (each kept wing a ramp beyond
// its hinge), the best 24 made on the real sheet (FoldSession: slivers refused) and measured
// exactly (surfaceDistance, 600 samples a side) by Chamfer + 0.5 Hausdorff, as startByFirstStep
// scores. The best that lowers the score by 2% and crosses the sheet no more than before is kept (a
// flap that stands out past its wing's rim is left to the tucks, as the fit makes them), and so on
// greedily, up to 6 wings; a later wing's hinge lies on the sheet's unmoved middle and its seed on
// the part no wing moved.
//
// Inputs: a flat candidate (PlacedStart, square or rectangle), the fitter of the target, a
// deadline (stops the wings made so far). Output: the sheet with its wings folded (surface
// "winged_" + the flat kind, the flat kind's parameters, its development unchanged), or none where
// `flat` is not flat or no wing lowers the score. Known limits: hinges are straight chords (a
// wing's rim is left to the pleats and tucks); directions are fixed to the sheet, not to the
// target's lobes; the paper is the flat sheet's (a wing's arc longer than the sheet's reach is
// left short); a flap as wide as the sheet covers its neighbours' corners, so after 3-4 wings the
// next ones cross the earlier flaps or gain under 2%, and the farthest of six equal wings stays.
#pragma once

#include <optional>

#include "engine/fit/deadline.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/placed_start.hpp"

namespace curvefold {

std::optional<PlacedStart> wingStart(const PlacedStart& flat, const FoldFitter& fitter,
                                     const Deadline& deadline);

}  // namespace curvefold
