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
// Method: several rings along the axis, chosen as a chain grown on the sheet itself rather than
// one ring per step of the search. At each step every ring neckRings solves for the sheet as the
// rings before it left it (each order, each end, two turns), and each ring already in the chain
// turned by half a step (its creases stay on the tube's radius: a reflection keeps its plane, and
// only planes facing them fold those corners in), and the neck corner rings (per distinct turn of
// the chain's rings, planes through the corners' radius where the sheet's largest radius begins
// to stand out of the target's and, where it stands out most, through the target's radius plus
// 0.5 or 0.75 of the excess: a narrow neck's corners folded in), is made, checked for passing the
// sheet through itself, and measured; the closest is kept while it brings the sheet closer. Within
// the deadline: the two chains grow side by side, a ring each per step, and each step's candidates
// are scored in two batches (the solved rings at turn 0, then those at half a turn and the corner
// rings; timed_batches.hpp); a batch the time left would not finish is not started, and when the
// clock cuts the step the chains are answered as far as they got, each ring made whole (a cancel
// answers nothing), so how many rings a cut step holds depends on the machine. Two chains: one of
// rings of 6 to 16 planes, one of 4 to 16 (a ring of n narrows a tube to about 0.65 R for 4, 0.76
// R for 5, 0.83 R for 6, 0.97 R for 16: ringCutRadius); a greedy chain begun with a deep ring of 4
// can end farther than one of finer rings, so both are grown and the closer kept.
// Rings are chosen, and the chains ranked, by Chamfer + Hausdorff / 4 (surface_distance.hpp,
// 1500 samples a side: each distance over the goal's bound, 1.5% and 6% of the diagonal), not the
// search's robust distance, which caps far points: a tube's untouched neck is all far points; by
// the Chamfer distance alone a ring of 4 that lays a flap near the axis wins (the example vase
// 1.39% / 9.8% against 1.57% / 4.32%). Each chain's suggestion is all its rings; its `after` the
// search's distance before scaled by the measure's fall (the beam ranks by it). (A chain solved
// jointly on a preview of the sheet's samples and refined by Subplex was tried beside these: it
// never came closer, 14 of 14 fits of 7 vases, and was removed.)
//
// Inputs: a session whose sheet is a tube or a cone about the target's axis direction (every
// vertex's distance from a line within 11 degrees of `axis.direction` through the middle of its
// box across that line (a tilted cone's box about the world's axes is off its axis) within 3% of
// the mean radius of a least-squares line of radius against height,
// whose slope is at most kTubeRingSteepestTaper; at least half a radius long; any other sheet
// gets none: a folded tube's profile is no longer one radius per height) and the target's
// area-uniform samples. A cone is cut as a tube is (neckRings reads the sheet's radius at each
// height): the start `fit` places on a vase is a cone (start_surface.hpp), whose first step was
// single folds that the exact measure rejected (the example vase: no fold kept in 3000
// evaluations; with the chain from the cone, 1.59% -> 1.22% of the diagonal, Chamfer). Output: up
// to `count` FoldSuggestions (all rings of one chain as one step), best first, each closer than the
// sheet was by the rings' measure (not also by the search's robust distance, which on a closed
// bottle rose while the measure halved, and its rings were dropped), its `after` scaled by the
// measure's fall. Known limits:
// a ring's wedges stay apart only down to about cos(pi / n) of the radius, so a neck narrower than
// about 0.65 of the tube is approached, not reached; the cut tube is a star of n lobes, not a
// circle, its creases on the tube until a corner ring folds them; greedy: a first ring is never
// cut shallower to let a second go deeper; a waist between two bellies (a gourd) is cut only from
// the ends (a tilted ring deepens toward one end). A waist under a flaring lip: every ring here
// turns its part toward the axis and a crease stays where it lay, so the sheet's outer envelope
// (its largest radius by height) is about the least of the tube's radius and the cutting planes'
// lines, a concave function of height, which a V-shaped waist's profile is not; how near such an
// envelope comes is bench/inward_fold_bound.py's bound (bench/make_judge_shapes.py's vase_y: about
// 6% of the diagonal by Hausdorff, the goal's bound; docs/performance.md, issue 38, vase17), so
// only a fold that turns a part back out (neckPleat) reaches past it.
#pragma once

#include <array>
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

// The steepest cone the rings narrow: its radius changes by at most this much per length along
// its axis (about 20 degrees): a vase's cone (0.13 on the example vase), not a bowl's flat one.
inline constexpr double kTubeRingSteepestTaper = 0.36;

// The most rings a chain grows in one step of the fit. Each ring cuts the corners the rings
// before it left standing on the tube's radius only so far, and a narrow neck takes ring after
// ring: on bench/make_judge_shapes.py's vase_y (a neck 0.22 of its belly) the chains of 4 rings
// were still closing in when they stopped (2.43% Chamfer; 5 rings, 2.27%).
inline constexpr std::size_t kTubeChainRings = 8;

// How much the Hausdorff distance counts beside the Chamfer distance in the rings' measure (each
// over the goal's bound for it, 1.5% and 6% of the diagonal; see above).
inline constexpr double kTubeHausdorffWeight = 0.25;

// The tube or cone `sheet` is about a line along `direction` (its axis through the middle of the
// sheet's box across it, its mean radius), or none when it is no such tube (see above).
// `steepestTaper`: the steepest cone taken (lip_pleats.hpp takes steeper ones).
struct TubeAxis {
  RevolutionAxis axis;
  double radius = 0.0;
};
std::optional<TubeAxis> tubeAbout(const Sheet& sheet, const glm::dvec3& direction,
                                  double steepestTaper = kTubeRingSteepestTaper);

// A neck pleat: a ring cut in and turned back out (as a paper artist pleats a collar), for a
// waist under a flaring lip, which a ring's planes alone cut only as deep as they cut the lip
// beyond it (a plane's cut grows linearly along the axis). The first ring of `order` planes
// turned by `turn` folds each wedge in about its chord, from where the sheet's largest radius
// begins to stand out of the target's mean radius (by height, 24 bins of the samples of the sheet
// and of the target) to the neck, where that excess peaks, its flaps' middles reaching the
// target's radius there, deepening toward the end `side` (+1 the axis's end, -1 the other). The
// cut goes on deepening to the sheet's end, where the wedges must still stay apart: at the rim
// (q >= cos(pi / n) of the radius) and within (a flap's bulge stays in its own sector while q >=
// 1 / (2 sin(pi / n)); a ring of 3 cut deeper passes through itself near the axis), so only rings
// of 3 to 5 cut a pleat, and the far end bounds how deep the neck is cut. The second, the return
// ring, has one plane parallel to the axis through each flap's middle at the neck, facing the
// axis, each seeded in its own flap's far end (RingShape::seeded: the plane's side also holds the
// tube's far wall), so past the neck the flap heads back out as steeply as it came in. None where
// no height stands out by a twentieth of the radius, the cut cannot deepen, or the flap's far end
// lies no deeper than its middle at the neck.
// Not offered by suggestTubeRings: on bench/make_judge_shapes.py's vase_y (a neck of 0.24 of the
// belly under a lip of 0.57) a pleat never scored best at any step of either chain, and a third
// chain begun with the best pleat ended farther than the coarse chain (docs/performance.md, issue
// 38, vase12); its first ring's creases stay on the tube's radius, and its lip's flaps widen at the
// rate the neck's narrowed, not the target's.
std::optional<std::array<RingShape, 2>> neckPleat(const std::vector<SurfaceSample>& sheetSamples,
                                                  const std::vector<SurfaceSample>& targetSamples,
                                                  const RevolutionAxis& axis, int order,
                                                  double turn, int side);

// The chains as far as one call grew them, to be grown on by a later call on the same sheet
// (the start's probe, first_step_start.hpp, hands its winner's chains to the search, which
// otherwise grew the same first rings again: about a quarter of a chain's CPU).
struct TubeChains {
  std::vector<glm::dvec3> sheet;               // the positions of the sheet they were grown on
  std::vector<std::vector<RingShape>> chains;  // each chain's rings in order (fine, then all)
};

// Up to `count` chains of rings (see above) for the tube `session` holds, toward the fitter's
// target of revolution about `axis` (its direction is used; the tube's own centroid is the axis
// point) whose samples are `targetSamples`, each of at most `mostRings` rings. The session is not
// changed. `resume`: chains grown before on this very sheet (its positions equal `resume->sheet`;
// otherwise ignored), remade ring by ring (makeRing is deterministic) and grown on from there.
// `grown`: where the chains as grown are written (with the sheet's positions), when given.
std::vector<FoldSuggestion> suggestTubeRings(
    const FoldSession& session, const FoldFitter& fitter, const RevolutionAxis& axis,
    const std::vector<SurfaceSample>& targetSamples, std::size_t count, const Deadline& deadline,
    std::mt19937_64& random, std::size_t mostRings = kTubeChainRings,
    const TubeChains* resume = nullptr, TubeChains* grown = nullptr);

}  // namespace curvefold
