// Unfolding a target that was folded by reflection (issue 27): working back from the target to
// the sheet. The last fold's crease is never moved after it is made, so it lies whole in that
// fold's plane [Mitani & Igarashi 2011, Sec. 3.3], and the part the fold reflected meets the rest
// only along it: the target's vertices strictly on one side of the plane, grown from a vertex
// next to the crease, are that part (or the rest), with any vertex within the plane's tolerance
// whose neighbours off the plane all lie in it (a grid vertex a crease passed by a micrometre).
// Reflecting it back through the plane makes the crease smooth again, and the target is as it was
// before its last fold; repeated, the target unfolds to the sheet it was folded from, and its
// folds, read backwards, fold the sheet onto it.
//
// Each step takes, among the target's crease planes (crease_planes.hpp) and the pieces next to
// their creases, a reflection that takes crease away (any bend beyond the sheet's own facets is
// crease), up to four planes a step, best first (a crease that ends inside the sheet where another
// sharp edge goes on, which a later fold cut, last) and depth first, up to 600 unfoldings or until
// one ends smooth and on the sheet (the fold made last may leave the shortest crease, and a crease
// a later fold moved can be unfolded first and lead nowhere). It stops when no reflection takes
// away a crease. Without symmetryImages the search keeps a table of forms: other orders of the
// same steps meet the same form again in another pose (a product of reflections apart), so each
// form's crease planes and pieces are read once, kept keyed by the edges its crease bends, and
// moved by the pose (found from three far vertices, checked on all). Where that search stops at
// its 600 unfoldings off the sheet, it goes on with the same table, in at most half the time
// left, to 600 unfoldings that read a form none before had (3,000 in all), kept only where it
// ends smooth on the sheet; not where the target has more area than the sheet (folded from
// another sheet: no order ends on this one).
// Reflecting a piece or the rest of the target unfolds its crease alike, one reflection of the
// whole apart; of every such choice along an unfolding, one whose result lies on the initial sheet
// is kept (the part that never moved stays where the sheet is), with rests only where the rest lies
// whole on one side of the plane (a drag moves no other) and as few as may be (a symmetric sheet
// lies on itself several ways). Of the unfoldings that end smooth, the one with the fewest folds
// wins (one more counted where it ends off the sheet, on a rigid copy of it that whole-sheet folds
// must move), then the one on the sheet, then the closest to it; no branch is read deeper than
// that. One that ends on a copy (no symmetryImages) takes the sides whose copy's motion needs the
// fewest planes (the sheet registered onto it, times its own symmetries: whole_sheet_folds.hpp),
// then the fewest rests. Of unfoldings that stop short alike, the closest to the sheet wins.
//
// Known limits: a target must carry its creases as mesh edges (a folded sheet written as a mesh
// does; a remeshed scan does not); a crease whose faces meet at less than the sharp-edge
// threshold is not seen; an unfolding that ends off the sheet names folds that do not fold the
// sheet onto the target (the fit then finds its folds by search alone). Which side of each crease
// stays is tried every way for up to kExhaustiveSides creases, and beyond that flipped one crease
// at a time while the result comes closer to the sheet (it may then miss the best choice).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/fit/deadline.hpp"
#include "engine/geometry/reflection.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {

struct UnfoldedFold {
  ReflectionPlane plane;
  // A vertex of the target deep in the part the fold reflected, where it lay before the fold,
  // and its index: where it lies on the sheet (TargetUnfolding::unfolded) names it in the
  // development, which no fold moves. Off the fold's plane (a seed on it grabs the crease and
  // folds nothing), and off the target's boundary, but for a part whose inner vertices all lie on
  // the crease (a strip one row of faces wide along a rim): then on a rim, never on a slit (its
  // two sides lie at one place: a point there names either).
  glm::dvec3 seedBefore{0.0};
  std::uint32_t seedVertex = 0;
  // A symmetric design's fold whose image moved the whole sheet (its plane missed the folded
  // sheet, so it left no crease): that image's plane, which the fold brings when made.
  std::optional<ReflectionPlane> wholeImage;
};

struct TargetUnfolding {
  std::vector<UnfoldedFold> folds;   // in folding order: the first fold first
  std::vector<glm::dvec3> unfolded;  // the target's vertices before its first fold
  double sharpLengthLeft = 0.0;      // sharp edges the unfolded target still has, metres
  // The deadline came first: the folds are those of the unfolding that had taken away the most
  // crease by then (it may stop short of the sheet, like one that cannot place a crease).
  bool cutShort = false;
  // The search's work: the forms whose crease planes were read (each once: a form met again by
  // another order of the steps before it, in another pose, is found in a table of those read),
  // the times a form's planes were asked for, and the unfoldings that ended.
  std::size_t formsRead = 0, formsMet = 0, unfoldings = 0;
};

// Creases whose sides are tried every way (2^n choices); more are chosen one at a time.
constexpr std::size_t kExhaustiveSides = 10;

// `sheet`: the initial sheet the target was folded from (the part that stays is found on it);
// `minDihedralDegrees`: the sharp-edge threshold (above the sheet's own bends). Stops at its next
// check once `deadline` passes, with what it read by then and cutShort set (within one step:
// finding one node's crease planes and pieces). `symmetryImages`: a symmetric design's
// isometries (Symmetry::images()): where no choice of sides ends on the sheet, one fold whose
// image moved the whole sheet (a fold of most of a sheet with rotational:2 mirrors the rest of it
// through the image plane, which then cuts nothing) is tried at each step, for up to kImageSteps
// creases.
// `sheetBendDegrees`: how much the sheet's facets bend (any bend beyond is crease), where not
// `sheet`'s own (negative): a target folded from the kind at other parameters than `sheet`'s.
TargetUnfolding unfoldTarget(const TriangleMesh& target, const TriangleMesh& sheet,
                             double minDihedralDegrees, std::size_t maxFolds,
                             const Deadline& deadline = {},
                             const std::vector<Isometry>& symmetryImages = {},
                             double sheetBendDegrees = -1.0);

// Creases up to which one fold's whole-sheet image is looked for (2^n sides, times n images).
constexpr std::size_t kImageSteps = 6;

// The planes a whose image b = g(a) reflects a onto `moved` (R_b(a) = moved): where a fold
// through a made the image through b move the whole sheet, its crease then lies in `moved`.
// Found on a grid of normals and refined (Gauss-Newton); each plane once.
std::vector<ReflectionPlane> planesBeforeWholeImage(const ReflectionPlane& moved,
                                                    const Isometry& g);

}  // namespace curvefold
