// Rings of folds toward a surface of revolution (issue 38, 2: vases, bowls, lampshades), as a
// paper artist shapes a cup or a lampshade from a tube or a disk: the same fold made at n
// turns about the axis, so the sheet bends in or out all around it at once.
//
// A single reflection keeps a shape of revolution only through a plane across its axis (which
// turns the part beyond back on itself: a rim turned over) or through the axis itself (no
// change). Any other fold leaves one flap; approaching a vase's waist, a bowl's rim or a
// lampshade's bulge needs the fold repeated around the axis: the axisymmetric curved origami of
// Mitani ("A design method for 3D origami based on rotational sweep", CAD&A 2009, [Mit09] in
// Mitani & Igarashi, whose planar curved folds reflection reconstructs). The ring is built about
// the target's axis, wherever the sheet was placed on it (placed_start.hpp), as plain folds made
// one after another (a symmetric design's images need the sheet's own frame, symmetry.hpp).
//
// revolutionAxis: the target's axis, among its principal axes through its centroid (PCA), the
// one about which the distance of samples from the axis varies least at each height (its
// samples binned by height; the spread is the root mean square deviation from each bin's mean
// radius, over the mean radius; or its samples binned by radius, a disk's). Caps across the axis
// (samples whose normal lies within 18 degrees of it: a bottle's closed bottom, a level shoulder)
// are left out of the spread by height while they are under a quarter of the samples: they hold
// every radius at one height. A principal axis whose variance is within 1.25 of another's (a
// squat lampshade or pot, about as tall as it is wide: its principal axes lie wherever the
// samples swing them) is turned to the direction of least spread first (Subplex, 200 passes over
// the samples, within about 45 degrees; the axis still through the centroid). Failing that, an oval
// cup's, bowl's or vase's axis: the same spread with each sample's radius divided by the target's
// reach in its direction (the farthest sample of 24 turns about the axis, over their mean), so
// cross-sections alike ovals count as round (the nested rings follow an oblong target's reach each
// way). A target that is neither (spread above the bound both ways: a saddle, a leaning cup) has
// none; nor has one held by radius alone whose height swings with the turn about the axis (its
// harmonics of order 2 to 6 in the turn, within the radii it covers all around, outweigh the rise
// of its mean height from the middle and hold most of its spread there): a saddle over an outline
// whose corners lie on its falling lobes (a monkey saddle over a triangle) holds nearly one
// height at each radius, as a dish does, but its height swings about the axis, a dish's does not.
// Known limit: a flat patch off the axis, normal to it, passes as a cap.
//
// ringProposals: rings drawn where the sheet's radius profile r(h) departs from the target's (both
// binned along the axis, the bins weighted by the gap, and by the radius of the one alone where
// only one of them reaches): plane k of a ring of n passes through the point at height h and
// distance rho from the axis at angle phi + 2 pi k / n, with normal cos(beta) e_k + sin(beta) a
// (e_k radial, a the axis), and folds the part of the sheet on the side its normal points to;
// beta = 90 degrees is the single plane across the axis (drawn at any height over both: past the
// sheet's end it moves the sheet whole along the axis). Heights where the sheet lies, rho up to
// the sheet's radius there, beta, n (4 to 16) and phi drawn from the generator. suggestRings
// scores many on sheet samples (previewRing), refines the best few by NLopt's Subplex over
// (h, rho, beta, phi), and makes those on the sheet.
//
// neckRings: rings solved on the radius profile rather than drawn (for a tube-like sheet: a
// cylinder or a steep cone about the axis). A ring of n planes parallel to the axis at distance
// q R from it turns each of n wedges of a tube of radius R inward about its chord; the wedges
// stay apart while q >= cos(pi / n), and the tube's mean radius at that height falls to
// ringCutRadius(q, n) R (down to 0.83 R for n = 6, 0.90 R for n = 8, 0.97 R for n = 16). Tilting
// the planes by beta makes that depth vary linearly along the axis, q R = rho - tan(beta) (t - h):
// a neck or a taper. The ring is solved on the radius profile, not drawn: for each n and each
// end of the sheet, the height t0 where the cut begins and its depth at that end (from just
// short of cos(pi / n), where the wedges would meet and cross, to 1) over a grid of 25 x 8,
// the pair whose predicted mean radius by height (ringCutRadius) comes nearest the target's
// (summed over the heights both reach) kept when nearer than the sheet as it is. A waist takes
// one ring from each end. What a tube cannot reach by reflection: a crease along a circle about the
// axis keeps the circle's geodesic curvature (dr/ds over r, s the profile's arc length), so past
// it the radius goes on changing at the same rate and only the direction along the axis may flip
// (the plane across the axis: the sheet heads back). A cone's profile stays monotone in radius
// under such folds: no waist, no bulge, and a cylinder keeps its radius. Only rings of n flaps
// (or pleats) narrow a tube, and the cut tube is a star of n lobes, not a circle (the lobes'
// depth, about (1 - cos(pi / n)) R, bounds how close it comes).
//
// makeRing: a ring made on a session, each plane's fold seeded at the sheet vertex farthest on
// its side (the fold takes the part connected to it); the folds a session refuses (a sliver, a
// plane missing the sheet as it lies by then) are left out.
//
// Known limits: the axis passes through the target's centroid (a half vase's does not); the
// rings are plain folds, not a symmetric design's images, so a design saves them one by one and
// undo takes them one at a time; a ring whose folds reach each other's flaps folds those flaps
// again (the search scores what results and keeps it only when closer and not self-crossing).
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <span>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <glm/vec3.hpp>

#include "engine/fit/deadline.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/reflection.hpp"
#include "engine/geometry/sheet.hpp"

namespace curvefold {

struct RevolutionAxis {
  glm::dvec3 point{0.0};                // on the axis (the samples' centroid)
  glm::dvec3 direction{0.0, 1.0, 0.0};  // unit
  double spread = 0.0;                  // radius deviation within heights, of the mean radius
};

// The axis of a target given by area-uniform samples (at least a few hundred), when its radius
// varies by at most `maxSpread` (of the mean radius) at each height; none otherwise.
std::optional<RevolutionAxis> revolutionAxis(const std::vector<SurfaceSample>& samples,
                                             double maxSpread = 0.1);

// A ring: its planes in folding order; each folds the part of the sheet its normal points to.
// `seeds`, when not empty (one a plane): the fold of each plane takes the part of the sheet on
// its side nearest that point rather than the part holding its farthest vertex (a pleat's return
// fold, ring_folds.hpp: its side also holds the tube's far wall, which must stay).
struct Ring {
  std::vector<ReflectionPlane> planes;
  std::vector<glm::dvec3> seeds;
};

// A ring's shape about an axis (see above): height h along it, distance rho from it, tilt beta
// (radians; +-pi/2: one plane across the axis), turn phi of the first plane, n planes.
// `seeded`: each plane's fold is seeded nearest the point at height seedHeight and distance
// seedRadius along the plane's own direction e_k (Ring::seeds).
struct RingShape {
  double height = 0.0, radius = 0.0, tilt = 0.0, turn = 0.0;
  int order = 1;
  bool seeded = false;
  double seedHeight = 0.0, seedRadius = 0.0;
};

Ring ringOf(const RingShape& shape, const RevolutionAxis& axis);

// `count` ring shapes for the sheet `sheetSamples` describes toward the target `targetSamples`
// describes, both area-uniform, about `axis`.
std::vector<RingShape> ringProposals(const std::vector<SurfaceSample>& sheetSamples,
                                     const std::vector<SurfaceSample>& targetSamples,
                                     const RevolutionAxis& axis, std::size_t count,
                                     std::mt19937_64& random);

// The mean distance from the axis, over R, of a tube of radius R cut by a ring of `order`
// planes parallel to its axis at q R from it (q in [cos(pi / order), 1]; clamped there).
double ringCutRadius(double q, int order);

// Rings solved on the radius profile (neckRings above): for each of `orders` (at least 3), one
// ring from each end of the sheet, turned by `turn`. Fewer planes cut deeper (a ring of n narrows
// a tube to ringCutRadius(cos(pi / n), n): 0.65 R for 4, 0.76 R for 5, 0.83 R for 6, 0.97 R for
// 16) and leave a coarser star.
inline constexpr int kNeckRingOrders[] = {6, 8, 12, 16};
std::vector<RingShape> neckRings(const std::vector<SurfaceSample>& sheetSamples,
                                 const std::vector<SurfaceSample>& targetSamples,
                                 const RevolutionAxis& axis, double turn = 0.0,
                                 std::span<const int> orders = kNeckRingOrders);

// Sheet samples (points and unit normals) as a ring leaves them, approximately: each point on
// the side a plane's normal points to reflected, plane after plane (which parts connect is not
// asked: what makeRing does where each plane's side is one part). Cheap enough to refine a ring
// on; the search scores the rings it keeps on the sheet itself.
void previewRing(const Ring& ring, std::vector<glm::dvec3>& points,
                 std::vector<glm::dvec3>& normals);

// The ring's folds made on `session` (committed); returns how many were made. The session's
// drag in progress, if any, is cancelled first. Each fold is seeded at the sheet vertex farthest
// on its plane's side, or, where the ring has seeds, at the vertex on that side nearest its seed.
std::size_t makeRing(FoldSession& session, const Ring& ring);

// Rings tried on the sheet itself, in parallel: each thread's own copy of `session` (its initial
// sheet and its folds so far, replayed once a thread), on which a ring is made, handed on where it
// is made and passes through the sheet no more than `mostCrossings` allows (std::nullopt: crossing
// allowed), then taken back. One home for what the ring searches share (ring_folds.hpp,
// floor_rings.hpp, suggestRings below).
class RingTrials {
 public:
  RingTrials(const FoldSession& session, std::optional<std::size_t> mostCrossings);
  // Makes `ring` on this thread's copy; where at least `leastFolds` of its folds are made and the
  // crossings hold, calls `made(copy)`; then undoes the copy to `session`'s folds. Safe to call
  // from several threads at once (tbb::parallel_for).
  void tryRing(const Ring& ring, std::size_t leastFolds,
               const std::function<void(const FoldSession&)>& made);
  std::size_t baseFolds() const { return records_.size(); }

 private:
  const FoldSession& session_;
  std::vector<FoldRecord> records_;
  std::optional<std::size_t> mostCrossings_;
  tbb::enumerable_thread_specific<std::unique_ptr<FoldSession>> copies_;
};

// Up to `count` rings of `proposals` drawn (ringProposals, toward the fitter's target whose
// samples are `targetSamples`) that bring the session's design closer (the fitter's distance)
// and pass nothing through itself (unless the fitter allows it), best first. The session is not
// changed; rings are scored on sessions of their own, on all cores.
std::vector<FoldSuggestion> suggestRings(const FoldSession& session, const FoldFitter& fitter,
                                         const RevolutionAxis& axis,
                                         const std::vector<SurfaceSample>& targetSamples,
                                         std::size_t count, std::size_t proposals,
                                         const Deadline& deadline, std::mt19937_64& random);

}  // namespace curvefold
