// The geometry's tolerances, in one place (docs/design.md 1 and 2). Each is relative to the sheet's
// size, the diagonal of its development's bounding box, which no fold changes, unless its name or
// comment says otherwise. They nest (on-plane < feature = isometry < cut floor < shortest drag <
// grab snap < largest plane move), each an order above the one below but for the feature size and
// the isometry tolerance, which are the same value (design.md 2: "feature 1e-9 = isometry"), so
// what one step snaps or refuses the next never mistakes for something else; the static_asserts at
// the end hold that.
// Limits of interaction (pinch bands, hover radius: interaction/interaction_core.hpp) are in
// metres of the user's world, not of the sheet, and stay with the interaction.
#pragma once

namespace curvefold {

// On the plane: a signed distance within this counts as zero. A vertex snapped onto a plane stays
// where it is, which costs up to 2 * epsilon of edge length in the reflected part, so the snap
// sits an order below the isometry tolerance.
inline constexpr double kRelativeEpsilon = 1e-10;

// Every edge as long in 3D as in the development (validate(), unfold, self-intersection contact):
// a few hundred folds of rounding stay far inside it.
inline constexpr double kRelativeIsometryTolerance = 1e-9;

// The minimum feature size (0.3 nm on a 30 cm sheet): validate() refuses a triangle thinner than
// this (its smallest height in the development), so no edge is shorter either. Ten times the
// on-plane tolerance, far below anything printable, and far above rounding (a normal computed
// from such a triangle is good to 1e-7).
inline constexpr double kRelativeFeatureSize = 1e-9;

// What an edit makes keeps ten times clear of the floor: a cut piece thinner than this moves the
// fold's plane (reflection.hpp), a grab that would make one snaps to a vertex (surface_point.hpp),
// so later cuts through a thin piece stay above the floor.
inline constexpr double kRelativeCutFeatureSize = 10 * kRelativeFeatureSize;

// The shortest drag that folds (20 nm on a 20 cm sheet). Its bisector lies at least half of it
// from the grabbed point, 500 times the on-plane tolerance, so a micro-drag off a flat sheet
// cannot put the whole sheet "on the plane" and crease it everywhere.
inline constexpr double kRelativeMinimumDrag = 1e-7;

// A grabbed point within this of an existing vertex or edge snaps to it instead of making a
// sliver.
inline constexpr double kRelativeGrabSnap = 1e-6;

// How far a fold's plane may move to pass through a vertex instead of cutting a sliver next to
// it (3 micrometres on a 30 cm sheet: below what a hand or a mouse places).
inline constexpr double kRelativeMaxPlaneShift = 1e-5;

// The isometry an imported OBJ is held to (and its largest angle defect, in radians): its text
// carries about six digits, so its edges agree with its development to about 1e-6 of its size,
// not the 1e-9 of generated sheets; ten times that leaves room for the folds.
inline constexpr double kObjRelativeTolerance = 1e-5;

// Self-intersection tests: corners within this of the other triangle's plane count as on it, and
// cuts must overlap by more than it. The isometry tolerance: layers a flat fold lays on each other
// are that close and are contact, not a crossing. Symmetry finds the image of a vertex within it.
inline constexpr double kRelativeContactTolerance = kRelativeIsometryTolerance;

// A symmetric fold's image seed that moved farther than this between the sheet before the group
// and now was moved by an earlier image (the image is then left out). A grab could not tell
// closer points apart; rounding of locating one point in two triangulations is far below it.
inline constexpr double kRelativeImageSeedMoved = kRelativeGrabSnap;

// A vertex this close to a plane is in it: a crease curve in its fold's plane (`check`), a vertex
// in a triangle's plane for planar simplification (the display's coarse sheet). The isometry
// tolerance, far below a pixel. Planar simplification refuses a new triangle lower than the
// height floor, since a sliver would make the next fold's cuts fragile.
inline constexpr double kRelativePlaneTolerance = kRelativeIsometryTolerance;
inline constexpr double kRelativeSimplifiedMinHeight = 1e-6;

// Development edges cross when a cross product exceeds this, relative to the size squared: edges
// that only touch within rounding (about 1e-16 of it) do not count.
inline constexpr double kRelativeCrossingArea = 1e-12;

// A crease whose |fold angle| is below this (degrees, not relative) is reported as flat.
inline constexpr double kFlatCreaseDegrees = 1e-6;

// A plane's normal read from a file may be this far from unit length (not relative): a bisector
// plane's normal is normalised in double precision, a few ulps off.
inline constexpr double kUnitNormalTolerance = 1e-9;

// The nesting docs/design.md 2 describes.
static_assert(2 * kRelativeEpsilon < kRelativeIsometryTolerance);
static_assert(kRelativeEpsilon < kRelativeFeatureSize);
static_assert(kRelativeFeatureSize == kRelativeIsometryTolerance);
static_assert(kRelativeFeatureSize < kRelativeCutFeatureSize);
static_assert(kRelativeCutFeatureSize < kRelativeMinimumDrag);
static_assert(kRelativeMinimumDrag / 2 >= 100 * kRelativeEpsilon);
static_assert(kRelativeMinimumDrag < kRelativeGrabSnap);
static_assert(kRelativeGrabSnap < kRelativeMaxPlaneShift);
// An imported OBJ is held looser than a generated sheet, never tighter.
static_assert(kRelativeIsometryTolerance < kObjRelativeTolerance);
// A simplified triangle stays clear of what a cut may make.
static_assert(kRelativeCutFeatureSize < kRelativeSimplifiedMinHeight);

}  // namespace curvefold
