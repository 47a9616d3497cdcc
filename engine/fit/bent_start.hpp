// A square (or a rectangle) bent into a cylinder patch (issue 38, 2): the curved start toward a
// saddle, as a paper artist would start one, the sheet rolled along the saddle's one curvature
// and its ends then pleated down along the other (pleat_folds.hpp: a family of parallel pleats
// across the rulings). A bent sheet is still developable, so the design stays printable, and
// every fold after it keeps it so.
//
// Why: from a flat sheet the first step (a cross, first_step_start.hpp) bends each end by one
// hinge turned at most 35 degrees, and a steep saddle's rising ends stand at 70 degrees
// (saddle_steep_turned: z = (x^2 - y^2) / 0.06 over 18 cm, slope 3 at its rim); rolled, the sheet
// follows the rising ends whole, and only the falling ones are left to the pleats.
//
// Method: in the target's principal frame (placed_start.hpp, principalAxes: the mean normal as
// the sheet's where a steep saddle's spread is larger in height), the least-squares quadric
// w = A u^2 + B uv + C v^2 + D u + E v + F; its Hessian's two eigenvectors are the directions of
// the two curvatures. Along each (the stronger first) the sheet is the quadric's own centre line,
// w(s, 0) = a s^2 + d s + F, swept along the rulings across it (tilted by the slope e along
// them, as sweptAbout tilts a swept parabola's), and as long along each side as the target's arc
// there: the profile over the samples' extent along s, and across it the arc of w(0, t), which
// the pleats' turned ends must reach (a flat sheet as wide as the target's extent ends short of a
// steep saddle's falling ends). A square takes the longer of the two arcs for both sides (the
// profile widened about its middle until its arc is as long); a rectangle takes each. The
// development is that square or rectangle exactly (chords of the profile's samples along, the
// rulings across: sweptParabola), so `check` and `export` see the sheet as it was cut.
//
// Inputs: area-uniform samples of the target (a few thousand), `kind` "square" or "rectangle",
// `mostPaper` the most paper (m^2) a sheet's bend may bring: the rectangle of its two arcs, along
// and across, is measured against it, not the square's sides, since a square's paper past that
// rectangle is the kind's, asked for, and a flat square carries it too (lean_saddle_rect, 24 x 16
// cm and slopes to 3.8: its square, a side of 50 cm on its 50 and 22 cm arcs, 2.9 times the
// target's paper where the arcs' rectangle is 1.3 times).
// Output: up to two PlacedStarts (surface "bent_square" or "bent_rectangle", parameters the
// sides and the profile's curvature), the stronger curvature's first; none where the samples do
// not spread over a plane or the quadric is flat (curvature under 0.05 of the inverse size), and
// none along a direction where the profile's arc is under 1.3 times its reach (a gentle saddle:
// the flat square's cross reaches its ends, and a bent square that its first step chose over a
// round saddle ended 3 times farther by Hausdorff). Known limits: the profile is one parabola (a
// saddle's rising end that steepens faster than one is left short); a cone patch is not offered.
#pragma once

#include <string>
#include <vector>

#include "engine/fit/placed_start.hpp"
#include "engine/fit/surface_samples.hpp"

namespace curvefold {

std::vector<PlacedStart> bentStarts(const std::vector<SurfaceSample>& samples,
                                    const std::string& kind, double mostPaper = 1e300);

}  // namespace curvefold
