// Catalogue sheets placed where the target lies (issue 38, 2): the start of a fit toward a smooth
// shape that is not in the catalogue's frame (a vase lying along x, a tilted bowl, a saddle), and
// a swept parabola, the developable sheet nearest a saddle or a trough.
//
// The frame is the target's principal axes (PCA of area-uniform samples, Eigen's self-adjoint
// solver), its origin the samples' centroid:
//  - revolution: about each principal axis through the centroid, a least-squares line r = a + b t
//    of the samples' distance r from the axis against their height t gives a cone (its radii at
//    the lowest and highest samples) and a cylinder (the mean radius), each as long as the target;
//    and the line nearest the profile (t, r) across (total least squares), spanning the samples'
//    extreme projections onto it, another cone that reaches a bowl's bottom and rim;
//  - swept parabola: a least-squares quadric w = A u^2 + B uv + C v^2 + D u + E v + F over the
//    plane of the two largest axes (w along the smallest) gives the direction of the strongest
//    curvature; along it the profile w = k s^2 + b s + f is fitted (the rulings tilted to absorb
//    a slope along them) and swept over the target's extent across it, meshed with an exact
//    development (arc length along the profile, distance along the rulings); and the same cut to
//    the target's outline (triangles farther than 3% of its size from every sample, measured
//    across the sheet's normal so the sheet over a saddle's falling rim stays, dropped, kept
//    parts that would only touch at a vertex filled back; offered when valid);
//  - flat: a disk and a square of the target's area in the plane of its two largest axes; and
//    sheets cut to the target's footprint there (its samples boxed at 90 turns over a quarter
//    turn): the square of the turn whose larger side is least, that side long (and one of the
//    mean side, for an oblong footprint), and the rectangle of the least area, each centred on
//    its box. A square outline spreads alike along any two axes in its plane, so the principal
//    axes turn the square of the target's area anyhow, and a curved target's area exceeds its
//    outline's: both put the sheet's corners past the target's sides.
// Each is a catalogue sheet (or the swept one) moved rigidly, so its development is exact.
//
// Known limits: the axis of revolution passes through the centroid (a half vase is placed off
// its axis); the swept parabola is one curve (a sine or an S profile is not fitted); nothing is
// refined after the least-squares fits (no ICP): the caller keeps whichever is nearest.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/fit/surface_samples.hpp"
#include "engine/geometry/sheet.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {

struct PlacedStart {
  std::string surface;           // the catalogue kind ("swept_curve" for the swept parabola)
  SurfaceParameters parameters;  // the kind's, as sized (the swept parabola's: curvature, ...)
  std::string placement;         // how it was placed, for the user: "axis (0, 0, 1) at (...)"
  Sheet sheet;                   // moved into place
};

// The frame the placed sheets lie in: the samples' centroid and principal axes in ascending
// spread, axes[0] the sheet's normal (the samples' mean normal where a steep saddle's least spread
// lies across it, above).
struct PrincipalAxes {
  glm::dvec3 centroid{0.0};
  glm::dvec3 axes[3];
};
PrincipalAxes principalAxes(const std::vector<SurfaceSample>& samples);

// Candidates of `kind` ("" for every kind) placed onto the target described by `samples`
// (area-uniform, at least a few hundred). Candidates a kind's generator refuses are left out.
// The disk and square in the principal plane face the target's narrower end (a bowl's bottom),
// whichever sign its principal axes came with.
std::vector<PlacedStart> placedStarts(const std::vector<SurfaceSample>& samples, double targetArea,
                                      const std::string& kind = "");

// The flat sheets cut to the target's footprint alone (the square of its box, the rectangle, and
// disks: the one that covers it and, for an oblong footprint, one of its mean reach; see above): a
// flat start for the cross of pleats (pleat_folds.hpp) where a curved one starts nearer. The disks
// come first where the footprint is round (few samples outside the ellipse inscribed in its box),
// and before them, where that round footprint is oblong (its box's sides 3% apart), ellipses:
// that inscribed one and the one scaled about its centre to cover every sample ("ellipse", its
// width and height: the catalogue's disk stretched, its development alike, so still exact).
// `kind` "disk" gives the disks alone.
std::vector<PlacedStart> footprintStarts(const std::vector<SurfaceSample>& samples,
                                         const std::string& kind = "");

// Where the samples' mean normal overrode their least spread's axis (a steep saddle, above), the
// flat sheets of `kind` ("" every flat kind) in the plane of the least spread, as they were placed
// before: a steep hypar's square on edge passes nearer its falling corners than the footprint's
// square across it (hypar_steep_mm: Hausdorff 16.8% against 28.6%), so the start's first step
// chooses between them. None where the two agree.
std::vector<PlacedStart> leastSpreadStarts(const std::vector<SurfaceSample>& samples,
                                           double targetArea, const std::string& kind = "");

// The cylinder and the cone (kind "" both, "cylinder" or "cone" the one) fitted to the samples'
// radii about the line through `point` along `direction` (unit), as placedStarts makes them about
// each principal axis: the mean radius, and the line through the radii (a cone where it tapers
// by over 2%). For the axis a target turns about when its principal axes miss it (a vase about
// sqrt(6) radii tall has two of them alike, and a scan's holes turn them anywhere in that plane).
std::vector<PlacedStart> revolutionStarts(const std::vector<SurfaceSample>& samples,
                                          const glm::dvec3& point, const glm::dvec3& direction,
                                          const std::string& kind);

// The samples' extent [lo, hi] along `direction` (unit) from `point`, cut into 16 bands of
// height, and (the band's middle height, its samples' mean distance from the axis) for each band
// holding at least 8 samples (fewer say little of the radius there); none where the extent is
// empty or no band is full enough. The profile the tube starts below are sized from.
struct HeightBands {
  double lo = 0.0, hi = 0.0;
  std::vector<glm::dvec2> profile;
};
std::optional<HeightBands> heightBands(const std::vector<SurfaceSample>& samples,
                                       const glm::dvec3& point, const glm::dvec3& direction);

// The cylinder of the samples' widest radius about the line through `point` along `direction`
// (unit), as long as they reach along it: the largest mean distance from the line over 16 bins
// of height (bins of under 8 samples left out). The start of a vase's joint ring fit
// (ring_folds.hpp): rings only narrow a tube, so it starts as wide as the belly. None where the
// samples do not spread along the line.
// `share`: the tube's radius as this share of the widest (a narrower tube lowers a neck's
// corners and leaves the belly that far outside: StartChoice::runnersUp).
std::optional<PlacedStart> widestCylinder(const std::vector<SurfaceSample>& samples,
                                          const glm::dvec3& point, const glm::dvec3& direction,
                                          double share = 1.0);

// The cone around the samples about the line through `point` along `direction` (unit): of the
// lines r = a + b t above every height bin's mean radius (16 bins, bins of under 8 samples left
// out), taper |b| <= `steepest`, the one with the least mean gap over the bins (it touches the
// profile at two bins, a belly and a lip, or at one as a cylinder); as long as the samples reach
// along the line. A vase's start from outside (first_step_start.hpp): rings only narrow a tube,
// so one that lies inside a belly never reaches it. A cylinder where the line is level within 2%
// of its radius; none where the samples do not spread along the line.
std::optional<PlacedStart> enclosingCone(const std::vector<SurfaceSample>& samples,
                                         const glm::dvec3& point, const glm::dvec3& direction,
                                         double steepest);

// A swept profile w = curvature s^2 + slope s over s in [from, to], ruled over [0, length],
// `resolution` segments along the longer side, in the catalogue's frame (s along x, rulings
// along y, w along z), with an exact development.
Sheet sweptParabola(double curvature, double slope, double from, double to, double length,
                    int resolution = 64);

}  // namespace curvefold
