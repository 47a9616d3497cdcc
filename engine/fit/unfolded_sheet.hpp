// The sheet a creased target was folded from, when it is the named kind at other parameters
// (issue 38, 1): `fit T --from cone` on a target folded from a cone of another radius, height or
// angle. Folds keep the area, so a target whose area is not the kind's at its defaults was not
// folded from them, and the unfolding cannot read it back onto them. Unfolded against the
// defaults all the same (the creases and pieces it reads do not depend on the sheet), it ends
// smooth on the sheet the design started from, where the part that never moved lies as the
// catalogue made it; the kind's continuous parameters are then fitted to that unfolded sheet
// (subplex on the two-sided mean distance, from the defaults' lengths scaled to the target's area,
// or what the shape says: a star's points counted at its farthest vertices, its inner radius from
// the area; a star's number of points tried 3 to 12 first), and kept where the sheet lies on it.
//
// Inputs: the target (a folded design written as a mesh), the kind's name, a deadline (the
// unfolding's and the fit's share of a fit's time). Output: the parameters that differ from the
// defaults' (lengths, angles, a star's points; never the resolution), or nothing: the defaults
// hold the target's area, the unfolding leaves creases, the deadline passed, or no parameters lay
// the sheet within 1e-3 of the diagonal (on average) of the unfolded one.
//
// An unfolding that ends on the sheet moved whole (folds whose planes missed it) is put back in
// the catalogue's frame by its shape alone, for tubes (the normals' plane gives the axis, a circle
// fitted across it the centre, the arc's middle or a whole tube's slit the turn), cones (the
// normals' cone the axis, its faces' planes the apex, then as a tube), swept curves (the rulings
// across the normals; the sine's lean and wavelength by least squares on a grid, refined),
// helices' tangent developables (the normals' cone the axis and the rise, the principal normals'
// lines the axis's place and the radius, the faces' angles the start and the turns; both hands)
// and flat sheets (the plane and centroid of its area, turned by its principal axis or its
// farthest point). A choice of sides that lies near a sheet is polished before the frames. Where
// the defaults' sharp-edge threshold reads nothing (a tube of another radius or arc bends its
// facets more, or its crease less, than the defaults'), the reading runs again with the target's
// own (facetBendDegrees, crease_planes.hpp), and where that reads nothing either (facets that bend
// unevenly, a swept curve's up to as much as a crease's threshold), a third time with the bends
// below the widest gap in the target's bends taken as facets (facetBendBelowGap), and where that
// reads nothing, at the defaults' threshold with every bend under it taken as the facets'
// (largestBendBelow: a steeper sine whose facets bend more than the defaults' but under their
// threshold, its curved crease's bend falling near theirs along it, so no gap parts them). A
// cone's apex is told from its base by the area's centroid.
//
// The measure's points each way: a spread of the vertices (every k-th in index order) and the whole
// rim, in the order a walk along it meets it (boundaryVerticesAlong), so that the coarse measure's
// every 4th meets each side of a grid: a sheet a row longer or shorter than the unfolded target
// differs there alone (a helix's ruling width was read 1% off where only the spread, or the rim
// in index order, was measured).
//
// Cost (issue 38, 3): each sheet measured is made and its closest-point tree built; the points
// measured on it (a spread and its boundary) are found once per grid, not per sheet; the unfolded
// target's rim once per reading. A polish runs
// first on a coarse measure (a quarter of the points each way), and the fine one (300 sheets at
// most, from a tenth of the first steps) only where the coarse one ended within 4 times the limit
// above; each reading measures 3000 sheets at most (choices of sides, frames, a star's counts and
// polishes together), and stops at the deadline. UnfoldingWork counts the sheets and boundaries.
//
// Known limits: the frames were tried on moderate parameters only (a helix of many turns, a swept
// curve of under half a wave, a very thin cone: not tried); a kind whose parameters leave its area
// alone (a cylinder's radius at a fixed arc) is told apart only by the unfolding; the second
// and third readings add to the cost where the first fails.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "engine/fit/deadline.hpp"
#include "engine/geometry/triangle_mesh.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {

// What parametersFromUnfolding spent: sheets measured (each a sheet made and measured against the
// unfolded target), and the sheets' boundaries found (once per polish: a polish keeps its grid).
struct UnfoldingWork {
  std::size_t evaluations = 0;
  std::size_t boundaries = 0;
};

std::optional<SurfaceParameters> parametersFromUnfolding(const TriangleMesh& target,
                                                         const std::string& kind,
                                                         const Deadline& deadline = {},
                                                         UnfoldingWork* work = nullptr);

}  // namespace curvefold
