// How close a tube's rings could bring it to a vase (issue 38, 2), estimated before any ring is
// made: the start's choice without `--from` (start_surface.hpp) compares a placed cone, near at
// once, with the tube as wide as the belly, which the rings (ring_folds.hpp) narrow; by the
// distance at the start the cone won, and its rings ended farther (bench/make_judge20_shapes.py's
// vase: cone 6.36% / 1.68% Hausdorff / Chamfer of the diagonal, the widest tube 3.36% / 0.996%).
//
// The model (bench/inward_fold_bound.py's): every ring turns a part of the tube toward the axis
// and a crease stays where it lay, so the sheet's outer envelope is at most the start's radius
// r_s(h) and, where the rings cut it, a concave function of the height; the rings cut as far as
// the target's profile r(h) lets them stand on it, its upper concave hull H(h) (the least concave
// function over it). The envelope is then e(h) = min(r_s(h), H(h)): a belly that stands outside
// the start stays that far off (no ring widens), a waist under the hull stays as far as the
// hull's chord passes over it (no ring turns a part back out). The reach is the mean of |e - r|
// over the target's height bands plus a quarter of its largest (the goal's Hausdorff beside its
// Chamfer, nested_rings.hpp's kProfileFarthest), in the target's units.
// TubeHull::EndsMayStandLevel: an end past the last ring may stand level at the radius that ring
// left it: the hull may leave out up to a quarter of the bands at either end, held at its end
// band's radius over them, the reach the least over those hulls (a lip flared over a band above a
// neck is cut in, not bridged to from the belly: bench/make_stl_soup_targets.py's open_vase_mm,
// open25). It ranks the widest tube a runner-up only (start_surface.cpp, open26): as the rule's
// model it traded Hausdorff for Chamfer on four vases.
//
// Inputs: a sheet (a cone or a cylinder, as placed), the target's area-uniform samples and its
// axis of revolution. Output: the reach, or none where the sheet is no tube about the axis
// (ring_folds.hpp, tubeAbout) or the samples give no profile (placed_start.hpp, heightBands).
// Limits: a model, meant to rank starts, not to foretell the fit: the rings' star of lobes and
// their corners lie inside the envelope (the fit ends 1.5-3 times farther by Chamfer), a ring
// narrows a tube to about 0.65 of its radius per ring, and a neck is reached ring by ring; the
// sheet's radius is its least-squares line of height (exact for the catalogue's cone and tube);
// a band past the sheet's ends counts the line's extension (placed tubes span the target).
#pragma once

#include <optional>
#include <vector>

#include "engine/fit/profile_folds.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/geometry/sheet.hpp"

namespace curvefold {

enum class TubeHull { Whole, EndsMayStandLevel };

std::optional<double> tubeRingsReach(const Sheet& tube, const std::vector<SurfaceSample>& samples,
                                     const RevolutionAxis& axis,
                                     TubeHull hullKind = TubeHull::Whole);

// The upper concave hull of profile points (height, radius) sorted by height, evaluated at each
// point's height (tubeRingsReach's H): exposed for its test.
std::vector<double> upperConcaveHull(const std::vector<glm::dvec2>& profile);

}  // namespace curvefold
