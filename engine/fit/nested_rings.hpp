// Nested rings toward a bowl or a dish from a flat sheet (issue 38, 2), as a paper artist shapes
// a faceted bowl from a disk: a ring of n folds turns the rim up all around a polygon, a second
// ring farther out turns it up again, steeper, and so on, so the sheet's profile becomes a
// polyline that follows the bowl's. Two close rings turning opposite ways make a step (a pleat
// all around); the rings are the axisymmetric folds of Mitani ("A design method for 3D origami
// based on rotational sweep", CAD&A 2009, [Mit09] in Mitani & Igarashi), approximated by planar
// facets (the sheet is flat: every reflection of it is).
//
// Method: fitted to the target's profile directly, not drawn at random. The sheet, flat across
// the target's axis (profile_folds.hpp's revolutionAxis), is a segment of its radius R in the
// meridian plane (distance r from the axis, height z along it). k creases at distances s_1 < ...
// < s_k from the sheet's centre, each turning what lies beyond it by an angle, and a shift of the
// whole sheet along the axis (one plane across it) make a polyline of the sheet's length; its
// parameters are chosen by NLopt's Subplex to lower the mean two-sided distance between the
// polyline and the target's samples (r, z), each polyline point weighted by its distance s from
// the centre (the sheet's area there), plus a quarter of the farthest profile point's distance
// from the polyline (the goal's Hausdorff / 4: a disk of a deep cap's area is shorter than its
// meridian, and by the mean alone the fit followed the wall and left the rim farther off),
// restarted from random creases and from the best fit with one crease fewer; the fits are made
// again with the farthest point weighed 0.5 (the rim's fits), whose rings are made after the
// usual ones and offered only where they stand no farther out than the usual fits' nearest step.
// An oblong target (its reach about the axis 1.12 times farther one way than another) gets rings
// whose planes stand off the axis in proportion to its reach their way (an oval bowl). A crease
// whose flap points along d_{i-1} and should point along d_i is the plane through its polyline
// vertex with normal d_{i-1} - d_i (the bisector: the reflection takes one direction to the other),
// made at n turns about the axis (a RingShape each, innermost first, so each plane is drawn where
// the rings before it left the flap). Each fit with k = 1..4 creases and n in {8, 12, 16} (and
// first {4, 5, 6} where the fit's wall turns past 60 degrees: a ring's flap is the whole segment
// beyond its chord, which on a steep cup, chords near the centre, spans several polygon sides at n
// = 16 and lays the flaps over each other in a pinwheel that stands out past the wall; at n = 4 to
// 6 only neighbouring corners overlap) is made on the sheet itself (each plane's fold seeded on its
// own flap, beyond its crease), scored with FoldFitter::approximateDistance, checked for passing
// through itself, and taken back.
//
// Inputs: a session whose sheet lies flat across `axis` (height spread at most 2% of its radius,
// or along its own normal within 6 degrees of the axis: liesFlatAcross; any other sheet gets none:
// a folded sheet is no longer a segment in the meridian plane) and the target's area-uniform
// samples. Output: up to `count` FoldSuggestions (all rings of one fit as one step), best first,
// each closer than the sheet was. Within the deadline: the candidates are made in batches, coarsest
// first (the fit nearest the profile at its fewest planes, alone), and a batch the time left would
// not hold is not started; when the clock cuts the step, the candidates made whole are answered (a
// cancel answers nothing), so which are made then depends on the machine. Known limits: where n
// flaps meet at the polygon's corners the sheet has more paper than the bowl; a fold takes what
// lies beyond its plane and is connected to its seed, so the corners fold with one flap and stand
// out (the Hausdorff distance shows them), and on a steep profile a second ring's planes take the
// corner paper of the flaps beside their own and cross it: such a ring is drawn again turned by
// half a polygon side (its planes at the corners) and kept where that crosses nothing, else taken
// back and the rings before it kept. Of the steps within 5% of the nearest by the search's score,
// only the one whose farthest point stands out least is offered (the score cuts far distances).
// Fits with two creases or more are also made outermost first, each ring on the flat sheet
// (nestedRingShapes' outerFirst), where outermostFirstHolds: no ring meets corner paper an inner
// one left, so a lip turning back out is made (a ring drawn so that crosses is taken back alone).
// The model is exact only along each flap's centre line; the sheet's centre is taken to lie on the
// axis (the sheet's own centroid is used as the axis point).
#pragma once

#include <cstddef>
#include <optional>
#include <random>
#include <vector>

#include <glm/vec2.hpp>

#include "engine/fit/deadline.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/profile_folds.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/geometry/fold_session.hpp"

namespace curvefold {

// A flat sheet's profile as a polyline: starting at (0, shift), along +r, turning at each
// crease (distance `arcs[i]` from the centre along the sheet) to the absolute angle `angles[i]`
// (radians, from +r toward +z), to the sheet's radius.
struct ProfileCreases {
  double shift = 0.0;
  std::vector<double> arcs, angles;
  // What the fit lowers (metres): the mean two-sided distance to the target's profile (`mean`)
  // plus a quarter of the profile's farthest point's distance (see above).
  double score = 0.0, mean = 0.0;
};

// The polyline's vertices: the centre, each crease, the rim.
std::vector<glm::dvec2> profilePolyline(const ProfileCreases& creases, double sheetRadius);

// The target's meridian profile: up to `pointCount` of `samples` (every k-th, in order) as
// (distance from `axis.direction` through `centre`, height along it).
std::vector<glm::dvec2> meridianProfile(const std::vector<SurfaceSample>& samples,
                                        const glm::dvec3& centre, const RevolutionAxis& axis,
                                        std::size_t pointCount);

// The best `creaseCount` creases for a flat sheet of radius `sheetRadius` toward the target's
// profile points (r, z) (see above). `start`: a fit with fewer creases to grow from (may be empty).
// The profile's farthest point from the polyline counts this much beside the mean (the goal's
// Hausdorff / 4): by the mean alone a deep cap's rim, a sliver of the profile, is left unreached.
inline constexpr double kProfileFarthest = 0.25;
// `farthestWeight`: how much the farthest profile point counts beside the mean.
ProfileCreases fitProfileCreases(const std::vector<glm::dvec2>& target, double sheetRadius,
                                 std::size_t creaseCount, const ProfileCreases* start,
                                 std::mt19937_64& random, double farthestWeight = kProfileFarthest);

// The rings that fold a flat sheet centred at `axis.point` into `creases`' polyline: first a
// plane across the axis when the shift is not negligible, then one ring of `order` planes per
// crease, innermost first. `flap`: from each ring's crease (in the meridian: r, z) to a point of
// the flap beyond it as the sheet lies before that ring (where its folds are seeded).
struct NestedRing {
  RingShape shape;
  glm::dvec2 flap{0.0};
};
// `outerFirst`: the rings outermost first, each drawn on the flat sheet (at the crease's distance
// s_i from the centre, turned by the crease's turn with the sign flipped once for each ring inside
// it: a reflection reverses a turn), so no ring's planes meet the corner paper an inner ring left.
std::vector<NestedRing> nestedRingShapes(const ProfileCreases& creases, int order, double turn,
                                         double sheetRadius, bool outerFirst = false);

// Whether the rings drawn outermost first fold the sheet's centre line into `creases`' polyline:
// each inner ring's fold takes what lies beyond its plane, and the flap beyond it, turned the
// other way by the rings outside, can reach back across that plane (a lip turning down more than
// half the turn inside it), where the fold would cut it.
bool outermostFirstHolds(const ProfileCreases& creases, double sheetRadius);

// Whether `sheet` lies flat across `axis` (the nested rings' start, below): its height spread
// along `axis.direction` at most 2% of its radius, or along its own normal where that normal lies
// within 6 degrees of the axis (a disk placed on a cup as deep as wide, whose normal and axis are
// two estimates of one principal axis from different samples, differ by 1-4 degrees).
bool liesFlatAcross(const Sheet& sheet, const RevolutionAxis& axis);

// The axis the nested rings fold such a sheet about: through the sheet's centroid, along
// `axis.direction` or the sheet's own normal (as above); none where the sheet is not flat.
std::optional<RevolutionAxis> ringsAxis(const Sheet& sheet, const RevolutionAxis& axis);

// Up to `count` nested-ring steps for the design `session` holds, toward the fitter's target of
// revolution about `axis` whose samples are `targetSamples` (see above), with 1 to `mostCreases`
// creases. The session is not changed.
std::vector<FoldSuggestion> suggestNestedRings(const FoldSession& session, const FoldFitter& fitter,
                                               const RevolutionAxis& axis,
                                               const std::vector<SurfaceSample>& targetSamples,
                                               std::size_t count, const Deadline& deadline,
                                               std::mt19937_64& random,
                                               std::size_t mostCreases = 4);

}  // namespace curvefold
