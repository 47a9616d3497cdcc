// The joint ring fit for tubes (issue 38, 2: vases, bottles, lampshades from a cylinder), as a
// paper artist narrows a tube of paper toward a vase: rings of folds, each turning n wedges of
// the tube inward about their chords (Mitani, "A design method for 3D origami based on
// rotational sweep", CAD&A 2009, [Mit09] in Mitani & Igarashi, approximated by planar facets:
// every reflection of a tube is).
//
// A reflection ring only narrows a tube (profile_folds.hpp, neckRings: a fold along a circle
// keeps its radius), so a vase with a belly wider than its neck and foot starts from the tube of
// its widest radius (start_surface.hpp) and the rings cut it down toward the neck and the foot,
// each ring's planes tilted so its cut deepens toward one end, to the profile's radius there.
//
// Method: several rings along the axis, chosen as a chain on the target's radius profile r(h)
// rather than one ring per step of the search. Two chains of up to `mostRings` rings:
//  - grown on the sheet itself: at each step every ring neckRings solves for the sheet as the
//    rings before it left it (4 orders, each end, two turns: 16) is made, checked for passing
//    the sheet through itself, and measured; the closest is kept while it brings the sheet closer;
//  - solved jointly on a preview (previewRing: each sample on a plane's far side reflected, plane
//    after plane): grown the same way on the preview, then refined as a whole by NLopt's Subplex
//    over every ring's height, depth and tilt at once (no ring cut deeper than solved), then made
//    ring after ring (a ring that crosses the sheet is tried again shallower, then given up with
//    those after it).
// Rings are chosen, and the chains ranked, by the Chamfer distance (surface_distance.hpp, 1500
// samples a side), not the search's robust distance, which caps far points: a tube's untouched
// neck is all far points. Each chain's closest prefix is its suggestion, its `after` the search's
// distance before scaled by the Chamfer distance's fall (the beam ranks by it).
//
// Inputs: a session whose sheet is a tube about the target's axis direction (every vertex within
// 3% of one radius from a line within 11 degrees of `axis.direction` through the middle of its
// bounding box, at least half a radius long; any other sheet gets none: a folded tube's profile
// is no longer one radius per height) and the target's area-uniform samples. Output: up to
// `count` FoldSuggestions (all rings of one chain as one step), best first, each closer than the
// sheet was by both distances. The preview ignores which parts each fold takes: on the example
// vase the joint chain previews far closer than it is made, and the grown chain wins. Known limits:
// a ring's wedges stay apart only down to about cos(pi / n) of the radius, so a neck narrower than
// about 0.7 of the tube is approached, not reached; the cut tube is a star of n lobes, not a
// circle; greedy: a first ring is never cut shallower to let a second go deeper.
#pragma once

#include <cstddef>
#include <optional>
#include <random>
#include <vector>

#include "engine/fit/deadline.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/profile_folds.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/sheet.hpp"

namespace curvefold {

// The tube `sheet` is about a line along `direction` (its axis through the sheet's centroid, its
// mean radius), or none when it is no such tube (see above).
struct TubeAxis {
  RevolutionAxis axis;
  double radius = 0.0;
};
std::optional<TubeAxis> tubeAbout(const Sheet& sheet, const glm::dvec3& direction);

// Up to `count` chains of rings (see above) for the tube `session` holds, toward the fitter's
// target of revolution about `axis` (its direction is used; the tube's own centroid is the axis
// point) whose samples are `targetSamples`. The session is not changed.
std::vector<FoldSuggestion> suggestTubeRings(const FoldSession& session, const FoldFitter& fitter,
                                             const RevolutionAxis& axis,
                                             const std::vector<SurfaceSample>& targetSamples,
                                             std::size_t count, const Deadline& deadline,
                                             std::mt19937_64& random, std::size_t mostRings = 4);

}  // namespace curvefold
