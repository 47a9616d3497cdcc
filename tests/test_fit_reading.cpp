// Reading every design reflections make (issue 38, 1), and the start a smooth shape gets (2):
// targets made by recipes unlike the fit's own tests' (tests/support/fold_target_generators.hpp),
// each a case the unfolding once misread, found again exactly; the start surface sized to a
// shape, and the shape's rotational symmetry.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "app/session/design_check.hpp"
#include "cpu_time.hpp"
#include "engine/fit/crease_planes.hpp"
#include "engine/fit/farthest_points.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/placed_start.hpp"
#include "engine/fit/replayed_motion.hpp"
#include "engine/fit/snapped_plane.hpp"
#include "engine/fit/start_surface.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/fit/target_unfolding.hpp"
#include "engine/fit/unfolded_sheet.hpp"
#include "engine/fit/whole_sheet_folds.hpp"
#include "engine/fit/work_share.hpp"
#include "engine/geometry/boundary_edges.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/io/design_document.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "sanitizer_support.hpp"
#include "sheet_fixtures.hpp"
#include "test_paths.hpp"
#include "tests/support/fold_target_generators.hpp"

namespace curvefold {
namespace {

struct ReadCase {
  const char* recipe;
  const char* surface;
  std::size_t folds;
  std::uint64_t seed;
  const char* why;  // what the unfolding once got wrong on it
};

const testing::FoldTargetRecipe& recipeNamed(const std::string& name) {
  for (const testing::FoldTargetRecipe& recipe : testing::foldTargetRecipes())
    if (recipe.name == name) return recipe;
  throw std::invalid_argument(name);
}

void expectFoundExactly(const ReadCase& c) {
  SCOPED_TRACE(std::string(c.recipe) + " " + c.surface + " " + std::to_string(c.folds) +
               " folds, seed " + std::to_string(c.seed) + ": " + c.why);
  const std::optional<testing::FoldTarget> target =
      testing::makeFoldTarget(recipeNamed(c.recipe), c.surface, c.folds, c.seed);
  ASSERT_TRUE(target);
  const FoldFitter fitter(target->exported);
  FoldSession session(target->initial);
  if (!target->design.symmetry.empty())
    session.setSymmetry(parseSymmetry(target->design.symmetry, target->initial));
  FitOptions options;
  options.maxFolds = c.folds;
  options.seconds = 120.0;
  const FitResult result = fitFolds(session, fitter, options);
  EXPECT_EQ(result.stopReason, "the target unfolded: its creases named every fold");
  const SurfaceDistance d = surfaceDistance(meshOf(session.fixed()), target->exported);
  EXPECT_LE(d.relativeHausdorff(), 1e-3);
  // The fitted design is one `check` passes.
  const Design fitted(GeneratedSurface{c.surface, {}}, result.folds, target->design.symmetry);
  const session::DesignCheck check =
      session::checkDesign(fitted, "fitted", target->initial, session.fixed(), false);
  EXPECT_TRUE(check.passed()) << check.firstFailure();
}

// The sheet's farthest point along `along` dragged on `distance` along it: the plane lies past the
// sheet, and all of it moves (no crease left).
void foldTheWholeSheetAlong(FoldSession& folding, glm::dvec3 along, double distance) {
  along = glm::normalize(along);
  const Sheet before = folding.fixed();
  glm::dvec3 farthest = before.positions.front();
  for (const glm::dvec3& p : before.positions)
    if (glm::dot(p, along) > glm::dot(farthest, along)) farthest = p;
  folding.beginDragNear(farthest);
  folding.updateDrag(farthest + distance * along);
  ASSERT_TRUE(folding.commit());
  for (std::size_t v = 0; v < before.vertexCount(); ++v)
    ASSERT_GT(glm::distance(before.positions[v], folding.fixed().positions[v]), 1e-3);
}

// A corner grabbed at `grab` folded up to `drop`, then the sheet moved whole along each of
// `alongs` in turn (foldTheWholeSheetAlong): a creasing fold and a motion of one plane each.
void foldACornerThenMoveWhole(FoldSession& folding, const glm::dvec3& grab, const glm::dvec3& drop,
                              const std::vector<glm::dvec3>& alongs, double distance) {
  folding.beginDragNear(grab);
  folding.updateDrag(drop);
  ASSERT_TRUE(folding.commit());
  for (const glm::dvec3& along : alongs)
    ASSERT_NO_FATAL_FAILURE(foldTheWholeSheetAlong(folding, along, distance));
}

// A rectangle's corner folded up, then the sheet turned and shifted by three whole-sheet folds
// (a motion of three planes).
void foldACornerThenTurnAndShift(FoldSession& folding) {
  foldACornerThenMoveWhole(
      folding, {0.1485, 0.099, 0.0}, {0.07, 0.06, 0.07},
      {glm::dvec3(0.6, -0.3, 0.74), glm::dvec3(-0.2, 0.9, 0.39), glm::dvec3(0.5, 0.5, -0.7)}, 0.2);
}

// A fit of at most `maxFolds` folds with no clock and `evaluations` scored.
FitOptions clockFree(std::size_t maxFolds, std::size_t evaluations) {
  FitOptions options;
  options.maxFolds = maxFolds;
  options.seconds = std::numeric_limits<double>::infinity();
  options.maxEvaluations = evaluations;
  return options;
}

// Fits `target` from `session`'s sheet (its symmetry set) with no time limit, and expects the
// unfolding to name every fold and the fit to reach the target (within `within` of its
// diagonal); returns what the fit did.
FitResult expectFoundByUnfolding(FoldSession& session, const TriangleMesh& target,
                                 std::size_t maxFolds, std::size_t evaluations,
                                 double within = 1e-3) {
  FitResult result = fitFolds(session, FoldFitter(target), clockFree(maxFolds, evaluations));
  EXPECT_EQ(result.stopReason, "the target unfolded: its creases named every fold");
  EXPECT_LE(surfaceDistance(meshOf(session.fixed()), target).relativeHausdorff(), within);
  testing::expectInvariants(session.fixed(), session.initial());
  return result;
}

TEST(FitReading, ASlitDoesNotHideWhichSideASeedIsOn) {
  expectFoundExactly(
      {"anywhere-long", "cylinder", 4, 7932,
       "its first fold's seed lay on the slit, and a grab in 3D took the other side"});
}

TEST(FitReading, TheLastFoldMayLeaveTheShortestCrease) {
  expectFoundExactly({"anywhere-long", "square", 4, 120580,
                      "its last fold left an 8 mm crease: under the least support, and never "
                      "the first unfolded"});
}

TEST(FitReading, ASymmetricSheetDoesNotChooseTheSidesAFoldCannotMove) {
  expectFoundExactly({"anywhere-long", "half_cylinder", 3, 15851,
                      "a mirror of the sheet lay on it too, through a side no drag moves"});
}

TEST(FitReading, AFoldedTipLeavesACreaseOfAFewMillimetres) {
  expectFoundExactly(
      {"outer-short", "star", 3, 15849, "a star's tip folded last leaves a 1.4 mm crease"});
}

TEST(FitReading, ACreaseAlongACylindersFacetsIsAPlaneToo) {
  expectFoundExactly({"outer-short", "cylinder", 5, 23768,
                      "a crease along facets bent apart failed the mirror check, and a loose "
                      "plane took its edges"});
}

TEST(FitReading, SixFoldsMayNeedManyOrdersTried) {
  if (testing::kSanitized) GTEST_SKIP() << "the Release run checks the 160 orders (42 s here)";
  expectFoundExactly({"anywhere-long", "square", 6, 620580,
                      "its unfolding ends on the sheet only after more than 160 orders tried"});
}

// A fold whose plane misses the sheet moves all of it and leaves no crease (a drag away from the
// sheet's edge): the target unfolds to a moved copy of the sheet, which folds of the whole sheet
// put back (whole_sheet_folds.hpp), and the folds read follow. The search toward the moved copy,
// in the same evaluations, did not find two such folds.
TEST(FitReading, FoldsThatMoveTheWholeSheetAreFoundToo) {
  const Sheet initial = makeSurface("square", {{"resolution", 16}});
  FoldSession folding(initial);
  // A corner folded up, then the sheet's farthest point along a direction dragged on along it:
  // the plane lies past the sheet, and all of it moves.
  ASSERT_NO_FATAL_FAILURE(
      foldACornerThenMoveWhole(folding, {0.1, 0.1, 0.0}, {0.03, 0.05, 0.06},
                               {glm::dvec3(0.6, -0.3, 0.74), glm::dvec3(-0.2, 0.9, 0.39)}, 0.15));
  const TriangleMesh target = meshOf(folding.fixed());

  const FoldFitter fitter(target);
  FoldSession session(initial);
  FitOptions options;
  options.maxFolds = 6;
  options.seconds = std::numeric_limits<double>::infinity();
  options.maxEvaluations = 2000;
  const FitResult result = fitFolds(session, fitter, options);
  EXPECT_EQ(result.stopReason, "the target unfolded: its creases named every fold");
  EXPECT_LE(surfaceDistance(meshOf(session.fixed()), target).relativeHausdorff(), 1e-3);
  EXPECT_TRUE(identical(replayFolds(initial, result.folds), session.fixed()));
}

// The sheet the fit folds lies on the target's unfolded copy only as near as a reading's polish
// (a helix's ruling read 0.1 mm off on 353 mm; a short crease left where the unfolding counts
// smooth): a square 0.3% larger than the one folded, then moved whole far off. Registration held
// to 1e-4 of the diagonal found no way and the fit kept no fold (the sheet left a diagonal away);
// within the looser bound the motion is made and the fit ends as near as the sheets' sizes allow.
TEST(FitReading, ASheetReadALittleOffIsStillMovedOntoTheTarget) {
  FoldSession folding(makeSurface("square", {{"resolution", 16}}));
  ASSERT_NO_FATAL_FAILURE(
      foldACornerThenMoveWhole(folding, {0.1, 0.1, 0.0}, {0.03, 0.05, 0.06},
                               {glm::dvec3(0.6, -0.3, 0.74), glm::dvec3(-0.2, 0.9, 0.39)}, 0.15));
  const TriangleMesh target = meshOf(folding.fixed());
  const Sheet readSheet = makeSurface("square", {{"resolution", 16}, {"size", 0.2 * 1.003}});
  FoldSession session(readSheet);
  const double start = surfaceDistance(meshOf(session.fixed()), target).relativeHausdorff();
  ASSERT_GT(start, 0.5);
  const FitResult result = fitFolds(session, FoldFitter(target), clockFree(6, 300));
  EXPECT_FALSE(result.folds.empty());
  EXPECT_LE(surfaceDistance(meshOf(session.fixed()), target).relativeHausdorff(), 0.01);
  testing::expectInvariants(session.fixed(), session.initial());
}

// A target from a design kept in tests/data/reach (README.md there): its sheet, and the target
// (the design replayed, as `export --obj` writes it).
struct ReachTarget {
  Design design;
  Sheet initial;
  TriangleMesh target;
};
ReachTarget reachTarget(const std::string& name) {
  ReachTarget t;
  t.design = loadDesign(std::string(CURVEFOLD_TEST_DATA) + "/reach/" + name + ".curvefold.json");
  t.initial = initialSheet(t.design);
  t.target = meshOf(buildSheet(t.design));
  return t;
}

// The reach target `name` unfolds, within 15 s (150 s sanitized), to `folds` folds that end on
// its sheet.
void expectUnfoldsOntoItsSheet(const std::string& name, std::size_t folds) {
  const ReachTarget t = reachTarget(name);
  const TriangleMesh sheet = meshOf(t.initial);
  const TargetUnfolding plan = unfoldTarget(t.target, sheet, sharpEdgeThreshold(sheet), 8,
                                            Deadline::in(testing::kSanitized ? 150.0 : 15.0));
  EXPECT_FALSE(plan.cutShort);
  EXPECT_EQ(plan.folds.size(), folds);
  ASSERT_EQ(plan.unfolded.size(), t.target.positions.size());
  EXPECT_LE(
      surfaceDistance(TriangleMesh{plan.unfolded, t.target.triangles}, sheet).relativeHausdorff(),
      1e-3);
}

// A sequence read off a reachable target's creases that moves the sheet whole on the way (farther
// first) and ends far nearer than the start, though short of reaching it: the fit fell back on the
// best sequence whose every fold gains, here none, and kept no fold (41.3%). Toward a target
// folded by reflections the nearer end is kept (15.3%, Chamfer 1.09%; since the seed below, the
// target is reached).
TEST(FitReading, ANearerReadSequenceIsKeptThoughAFoldOnItsWayMovesTheSheetFarther) {
  const ReachTarget t = reachTarget("tangent_params_cone_5");
  FoldSession session(t.initial);
  const FoldFitter fitter(t.target);
  const SurfaceDistance start = surfaceDistance(meshOf(session.fixed()), t.target);
  const FitResult result = fitFolds(session, fitter, clockFree(8, 300));
  EXPECT_FALSE(result.folds.empty());
  const SurfaceDistance end = surfaceDistance(meshOf(session.fixed()), t.target);
  EXPECT_LT(end.relativeHausdorff(), 0.5 * start.relativeHausdorff());
  EXPECT_LT(end.chamfer, 0.2 * start.chamfer);
  testing::expectInvariants(session.fixed(), session.initial());
}

// The same cone's third fold moved all but a strip between its crease and the rim, one row of
// faces wide: every inner vertex of the strip lies on the crease, and the unfolding took one of
// them for the fold's seed (the deepest vertex off the boundary), so the fold made again grabbed
// its crease and folded nothing, and the folds read after the whole-sheet folds were never made
// (15.3%, the sheet moved whole). A seed off the plane (a vertex on the rim) folds the strip.
TEST(FitReading, AStripBetweenACreaseAndTheRimIsGrabbedOffTheCrease) {
  const ReachTarget t = reachTarget("tangent_params_cone_5");
  const TriangleMesh sheet = meshOf(t.initial);
  const TargetUnfolding plan = unfoldTarget(t.target, sheet, sharpEdgeThreshold(sheet), 8);
  ASSERT_EQ(plan.folds.size(), 2u);
  const double size = boundingDiagonal(t.target);
  for (const UnfoldedFold& fold : plan.folds)
    EXPECT_GT(std::abs(fold.plane.signedDistance(plan.unfolded[fold.seedVertex])), 1e-3 * size);
}

// A fold that moves all but a corner of the sheet moves every crease made before it whole, but
// one whose end lay in that corner: that crease then lies in two planes. Unfolded first (the
// most crease one reflection takes away), the part in the moved plane leaves the rest to read as
// a fold of its own, 9 folds for 8 (past `--folds 8`: 87 s to read none). A crease that ends
// inside the sheet where another sharp edge goes on is read after those that run from rim to
// rim: the folds made last first, 8 folds, on the sheet.
TEST(FitReading, ACreaseALaterFoldCutIsReadAfterTheFoldsThatCutIt) {
  expectUnfoldsOntoItsSheet("interior_cone_8", 8);
}

// Seven folds, each through a vertex of the sheet as it lay (a plane set to leave a share of the
// vertices behind it): fold 2's plane meets a grid vertex and a crease vertex of fold 1 beside it.
// Its crease read back passes them by 2e-10 m and tilts by 2e-9, and the fold made again cut
// slivers there, which no one shift of the plane took away: refused, the fit searched blind from
// fold 1 (190% of the diagonal). The plane moved through the vertices it all but meets makes it.
TEST(FitReading, AReadPlaneThatPassesSheetVerticesByAHairFoldsThroughThem) {
  const ReachTarget t = reachTarget("most_moved_helix_tangent_7");
  FoldSession session(t.initial);
  expectFoundByUnfolding(session, t.target, 8, 300, 1e-6);
  EXPECT_EQ(session.foldCount(), 7u);
}

// Six folds, each through a vertex of the sheet as it lay (the most-moved cone, seed 21): fold 3's
// plane went through two vertices; its crease read back passes them by 7e-10 of the size on either
// side, and the fold made again, shifted through the nearer, left a piece 1.7e-9 of the size high:
// above the floor, so kept, but the cut of fold 4 through that thin triangle fell under it, and
// fold 4 was refused (the fit searched blind from fold 3: 33.9% of the diagonal). A read fold that
// leaves a piece under the cut size is made through the vertices it all but meets.
TEST(FitReading, AReadFoldThatLeavesASliverIsMadeThroughTheVerticesItAllButMeets) {
  const ReachTarget t = reachTarget("most_moved_cone_6");
  FoldSession session(t.initial);
  const FitResult result = expectFoundByUnfolding(session, t.target, 8, 300, 1e-6);
  EXPECT_EQ(session.foldCount(), 6u);
  const session::DesignCheck check =
      session::checkDesign(Design(GeneratedSurface{"cone", {}}, result.folds), "fitted", t.initial,
                           session.fixed(), false);
  EXPECT_TRUE(check.passed()) << check.firstFailure();
}

// Four folds on the half cylinder, each plane through two vertices of the form (the two-vertex
// generator, seed 25): folds 2-4 lie in nearly one plane (normals within 3 degrees, offsets within
// 1.5 mm), their creases laid along each other. The plane read for fold 3 held fold 2's crease
// beside its own within the consensus tolerance and lay 8e-5 of the diagonal off fold 3's plane
// by fold 2's crease: a vertex of fold 2's crease fell within the unfolding's on-plane tolerance,
// the piece reflected stopped short of it, and the form left read as planes no fold made (5 folds,
// 174% of the diagonal of crease left). A crease is read in the plane that holds most of it to
// the digits the mesh keeps: the 4 folds, on the sheet.
TEST(FitReading, OverlaidCreasesOfNearlyCoplanarFoldsAreReadInTheirOwnPlanes) {
  expectUnfoldsOntoItsSheet("two_vertex_half_cylinder_4", 4);
  const ReachTarget t = reachTarget("two_vertex_half_cylinder_4");
  FoldSession session(t.initial);
  expectFoundByUnfolding(session, t.target, 8, 300, 1e-6);
  EXPECT_EQ(session.foldCount(), 4u);
}

// Two points a hair off a plane, on either side and far apart (a turn and a shift), and one far
// off it: the plane nearest it through both, the far point left where it was.
TEST(SnappedPlane, APlaneIsTurnedAndShiftedThroughThePointsItAllButMeets) {
  const ReflectionPlane plane{{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}};
  const std::vector<glm::dvec3> points = {
      {0.1, 0.0, 3e-10}, {-0.05, 0.02, -1e-10}, {0.0, 0.1, 0.01}};
  const std::optional<ReflectionPlane> snapped =
      planeThroughNearPoints(plane, points, 1e-7, 0.3, 1e-15);
  ASSERT_TRUE(snapped.has_value());
  EXPECT_LE(std::abs(snapped->signedDistance(points[0])), 1e-15);
  EXPECT_LE(std::abs(snapped->signedDistance(points[1])), 1e-15);
  EXPECT_NEAR(snapped->signedDistance(points[2]), 0.01, 1e-8);
  EXPECT_NEAR(glm::length(snapped->normal), 1.0, 1e-15);
  EXPECT_GT(snapped->normal.z, 1.0 - 1e-16);
  // No point within reach; points within reach that no plane holds (a hair off each corner of a
  // small square, alternately above and below).
  EXPECT_FALSE(planeThroughNearPoints(plane, {{0.0, 0.0, 1e-3}}, 1e-7, 0.3, 1e-15));
  const std::vector<glm::dvec3> twisted = {
      {0.0, 0.0, 5e-8}, {1e-9, 0.0, -5e-8}, {0.0, 1e-9, -5e-8}, {1e-9, 1e-9, 5e-8}};
  EXPECT_FALSE(planeThroughNearPoints(plane, twisted, 1e-7, 0.3, 1e-15));
}

// Eight folds, each through an earlier crease: the first unfolding lies on the sheet with 0.08%
// of the diagonal left bent (the half cylinder's own facets), over the 0.01% the unfolding
// stopped at, so it tried 359 more orders (40 s of CPU) for nothing it could prefer. Less crease
// left than one step must take away, on the sheet, ends it.
TEST(FitReading, AnUnfoldingOnTheSheetStopsTryingOrders) {
  expectUnfoldsOntoItsSheet("cuts_half_cylinder_8", 8);
}

// Eight folds, each through an earlier crease: the search over orders meets some forms again by
// another order of the steps before them, each moved by another product of reflections (a pose).
// Their crease planes and pieces are read once, kept in a table by the crease's edges, and moved
// by the pose where the form is met again (issue 38: the most-moved disk's search read 1,261
// nodes for 55 forms); the unfolding still ends on the sheet with the design's 8 folds.
TEST(FitReading, AFormMetAgainByAnotherOrderIsReadOnce) {
  const ReachTarget t = reachTarget("cuts_half_cylinder_8");
  const TriangleMesh sheet = meshOf(t.initial);
  const TargetUnfolding plan = unfoldTarget(t.target, sheet, sharpEdgeThreshold(sheet), 8);
  ASSERT_EQ(plan.folds.size(), 8u);
  EXPECT_LE(
      surfaceDistance(TriangleMesh{plan.unfolded, t.target.triangles}, sheet).relativeHausdorff(),
      1e-3);
  EXPECT_GT(plan.unfoldings, 1u);  // more than one order tried
  EXPECT_LT(plan.formsRead, plan.formsMet);
}

// Eight folds on a swept curve of other parameters (tangent-params, seed 19), 63% more area than
// the kind's default sheet the fit starts from: no order of its folds unfolds onto that sheet,
// and the first search stops at its 600 unfoldings off it. The search went on over the table of
// forms to 3,000 more orders, at each of the fit's readings (the fit: 43 -> 115 s user, the same
// design); a target with more area than the sheet is read by the first search alone.
TEST(FitReading, ATargetWithMoreAreaThanTheSheetIsReadByOneSearch) {
  if (testing::kSanitized) GTEST_SKIP() << "the Release run checks the search (3 s here)";
  const ReachTarget t = reachTarget("tangent_params_swept_curve_8");
  const TriangleMesh sheet = meshOf(initialSheet(Design(GeneratedSurface{"swept_curve", {}}, {})));
  ASSERT_GT(surfaceArea(t.target), 1.5 * surfaceArea(sheet));
  const TargetUnfolding plan = unfoldTarget(t.target, sheet, sharpEdgeThreshold(sheet), 8);
  EXPECT_FALSE(plan.cutShort);
  EXPECT_GT(
      surfaceDistance(TriangleMesh{plan.unfolded, t.target.triangles}, sheet).relativeHausdorff(),
      0.1);
  EXPECT_LE(plan.unfoldings, 600u);  // one search's bound
}

// Whole-sheet folds made between creasing folds (issue 38's drag recipe on the helix's tangent
// developable: 7 folds, 2 of them moved the whole sheet): read with the motion last, the 5 folds
// read leave a turn and a shift along its axis, 4 whole-sheet folds, 9 in all, past 8. One fold
// read made from its other side mirrors what is left to move through its plane, which then takes
// 3: 8 folds, exactly the target.
TEST(FitReading, WholeSheetFoldsBetweenCreasingFoldsFitWithinTheFolds) {
  if (testing::kSanitized) GTEST_SKIP() << "the Release run checks the search (95 s here)";
  const ReachTarget t = reachTarget("drag_outer_helix_tangent_7");
  const FoldFitter fitter(t.target);
  FoldSession session(t.initial);
  FitOptions options;
  options.maxFolds = 8;
  options.seconds = std::numeric_limits<double>::infinity();
  options.maxEvaluations = 300;  // the search, where the reading fails: short and blind
  const FitResult result = fitFolds(session, fitter, options);
  EXPECT_EQ(result.stopReason, "the target unfolded: its creases named every fold");
  EXPECT_LE(session.foldCount(), 8u);
  EXPECT_LE(surfaceDistance(meshOf(session.fixed()), t.target).relativeHausdorff(), 1e-3);
  EXPECT_TRUE(identical(replayFolds(t.initial, result.folds), session.fixed()));
}

// Issue 38's drag recipe on the square (seed 11 of bench/make_outer_third_targets.sh): five
// creasing folds and a fourth that moved the whole sheet (its plane missed it). Unfolding ends
// on a moved copy of the sheet whichever way it goes, and of the unfoldings that end smooth the
// one nearest the sheet won, though none lies on it: one that read six folds, one plane twice (a
// piece of one fold's part at a time), which with the copy's motion takes more than 8 folds. Of
// smooth unfoldings, the fewest folds win, and deeper branches are not read on (the reading took
// 75 s of wall, 17 s of CPU).
TEST(FitReading, AnUnfoldingEndingOffTheSheetReadsNoMoreFoldsThanCrease) {
  if (testing::kSanitized) GTEST_SKIP() << "a real search: about 5 s of CPU in Release";
  const Sheet initial = makeSurface("square", {});
  FoldSession folding(initial);
  // Each fold: the point grabbed on the form, and where it was dropped (the design's records).
  const glm::dvec3 drags[][2] = {
      {{-0.0040403, 0.1, 0.0}, {-0.0592203, 0.0846003, 0.0546523}},
      {{-0.0564710, -0.0861761, 0.0}, {-0.0955553, -0.0841662, 0.0274980}},
      {{-0.0904131, 0.0566383, 0.0}, {-0.0642769, 0.0386392, -0.0192819}},
      {{-0.0740598, -0.0869667, 0.0851646}, {-0.0695279, -0.0835831, 0.1871012}},  // whole
      {{-0.0789742, -0.0909011, 0.2741217}, {-0.1197804, -0.0746314, 0.2425980}},
      {{-0.1011377, -0.0503123, 0.2623251}, {-0.0612477, -0.1350647, 0.2747379}}};
  for (const auto& drag : drags) {
    folding.beginDragNear(drag[0]);
    folding.updateDrag(drag[1]);
    ASSERT_TRUE(folding.commit());
  }
  ASSERT_EQ(folding.foldCount(), 6u);
  const TriangleMesh target = meshOf(folding.fixed());
  const TriangleMesh sheet = meshOf(initial);
  const TargetUnfolding plan = unfoldTarget(target, sheet, sharpEdgeThreshold(sheet), 8);
  EXPECT_FALSE(plan.cutShort);
  EXPECT_LE(plan.sharpLengthLeft, 1e-3 * boundingDiagonal(target));
  EXPECT_EQ(plan.folds.size(), 5u);
  for (std::size_t a = 0; a < plan.folds.size(); ++a)
    for (std::size_t b = a + 1; b < plan.folds.size(); ++b) {
      const ReflectionPlane& p = plan.folds[a].plane;
      const ReflectionPlane& q = plan.folds[b].plane;
      EXPECT_FALSE(std::abs(std::abs(glm::dot(p.normal, q.normal)) - 1.0) < 1e-6 &&
                   std::abs(p.signedDistance(q.point)) < 1e-5 * boundingDiagonal(target))
          << "folds " << a << " and " << b << " read one plane";
    }
}

// Issue 38's drag recipe on the disk (seed 9 of bench/make_outer_third_targets.sh): eight folds,
// the third and the sixth moving the whole sheet. The six creasing folds read with each crease's
// piece reflected ended on a copy of the sheet whose motion took 3 or 4 planes whichever way the
// disk lies on it (its 24 ways times its 479 symmetries): 6 + 3 folds, past the design's 8. Read
// with the design's own sides, the motion left is the two whole-sheet folds': a turn, 2 planes.
TEST(FitReading, AnUnfoldingOnACopyTakesTheSidesWhoseMotionNeedsFewestPlanes) {
  if (testing::kSanitized) GTEST_SKIP() << "a real search: about 12 s of CPU in Release";
  const Sheet initial = makeSurface("disk", {});
  FoldSession folding(initial);
  const glm::dvec3 drags[][2] = {
      {{0.0191495, 0.0855649, 0.0}, {0.0730906, 0.0940977, 0.0547080}},
      {{0.0865346, 0.0095576, 0.0149200}, {0.1225619, -0.0072420, 0.0569096}},
      {{0.0801616, 0.0480743, 0.1723375}, {0.0073805, 0.0301980, 0.1677677}},  // whole
      {{0.0527947, -0.0620372, 0.0550863}, {-0.0002876, -0.1061204, 0.1039591}},
      {{0.0571863, -0.0938212, 0.1050113}, {0.0067033, -0.1193015, 0.1213786}},
      {{0.0219326, -0.1018711, 0.1079264}, {0.0461892, -0.1121948, 0.0705744}},  // whole
      {{0.0432615, -0.1087997, 0.0620937}, {-0.0029958, -0.1812841, 0.0834671}},
      {{-0.0675186, -0.3113606, 0.0382409}, {-0.0587095, -0.2666990, 0.1066064}}};
  for (const auto& drag : drags) {
    folding.beginDragNear(drag[0]);
    folding.updateDrag(drag[1]);
    ASSERT_TRUE(folding.commit());
  }
  ASSERT_EQ(folding.foldCount(), 8u);
  const TriangleMesh target = meshOf(folding.fixed());
  const TriangleMesh sheet = meshOf(initial);
  const double size = boundingDiagonal(target);
  const TargetUnfolding plan = unfoldTarget(target, sheet, sharpEdgeThreshold(sheet), 8);
  EXPECT_LE(plan.sharpLengthLeft, 1e-3 * size);
  EXPECT_EQ(plan.folds.size(), 6u);
  const std::vector<RigidMotion> ways =
      registerSheetOntoAll(sheet, TriangleMesh{plan.unfolded, target.triangles}, 1e-4 * size, 24);
  ASSERT_FALSE(ways.empty());
  std::vector<RigidMotion> symmetries = sheetSymmetries(sheet, 1e-4 * size);
  symmetries.emplace_back();
  std::size_t fewest = 5;
  for (const RigidMotion& way : ways)
    for (const RigidMotion& sym : symmetries)
      fewest = std::min(
          fewest, fewestReflections({way.linear * sym.linear, way.linear * sym.offset + way.offset},
                                    1e-4, 1e-4 * size));
  EXPECT_LE(fewest, 2u);
}

// An unfolding longer than the fit's time (a symmetric disk's 8 folds, which leave it moved
// whole: 600 orders tried, a minute) ran to the search's deadline and, cut short, answered
// nothing: the whole time passed with no candidate scored and no fold kept. Cut short, it names
// what it read by then (an unfolding ended where it was), and the reading has only a share of the
// fit's time: the search after it scores candidates. The unfolding's deadline is a share of CPU
// (work_share.hpp) and the fit's time is stretched as this process's CPU was while it unfolded:
// on the wall clock alone a loaded machine read nothing in 1.5 s, or left the search no candidate.
TEST(FitReading, AnUnfoldingCutShortLeavesTheSearchTimeAndWhatItRead) {
  const ReachTarget t = reachTarget("symmetric_disk_8");
  const TriangleMesh sheet = meshOf(t.initial);
  const auto started = std::chrono::steady_clock::now();
  const double startedCpu = testing::processCpuSeconds();
  const double share = testing::kSanitized ? 6.0 : 1.5;
  const TargetUnfolding plan =
      unfoldTarget(t.target, sheet, sharpEdgeThreshold(sheet), 12, workShare(share, 0.0, 1e10));
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const double cpu = testing::processCpuSeconds() - startedCpu;
  EXPECT_TRUE(plan.cutShort);
  EXPECT_FALSE(plan.folds.empty()) << took << " s, " << cpu << " s of CPU";
  EXPECT_EQ(plan.unfolded.size(), t.target.positions.size());
  // It stopped soon after its share (one order tried past it, at most).
  EXPECT_LT(cpu, share + (testing::kSanitized ? 3.0 : 0.75)) << cpu << " s of CPU";

  const FoldFitter fitter(t.target);
  FoldSession session(t.initial);
  session.setSymmetry(parseSymmetry(t.design.symmetry, t.initial));
  FitOptions options;
  options.maxFolds = 8;
  // The reading alone would take minutes, so it is cut at its share whatever the clock; the rest
  // leaves time to make the folds read and score some. The unfolding is one thread: wall seconds
  // per CPU second above is how much the load stretches this process (at most 8 times here).
  const double stretch = std::clamp(took / std::max(cpu, 1e-3), 1.0, 8.0);
  // The readings may take 84% of it (below), so the search's 16% must hold a step of it under the
  // sanitizers too: at 12 s it scored none in one run of three there.
  options.seconds = (testing::kSanitized ? 20.0 : 6.0) * stretch;
  const FitResult result = fitFolds(session, fitter, options);
  EXPECT_GT(result.evaluations, 0u) << result.stopReason << "; " << options.seconds << " s";
  EXPECT_TRUE(result.timedOut);
  // Every reading (with the images, then read plain, each with 60% of the search's time left)
  // ends within 84% of the time, one order past it at most (4.9 of 6.2 s in Release): so does a
  // reading that keeps to its share; one given 90% ends past the bound.
  EXPECT_GT(result.readingSeconds, 0.0);
  EXPECT_LT(result.readingSeconds,
            0.84 * options.seconds + (testing::kSanitized ? 2.0 : 0.3) * stretch)
      << "of " << options.seconds << " s; " << result.evaluations << " scored";
  EXPECT_NO_THROW(validate(session.fixed()));
}

// Registration toward a copy that nearly lies on the sheet (moved whole, and bent by 1 mm, which
// no rigid motion takes away) finds no way, and uncancelled takes minutes on a large sheet (527 s
// here: 560 starts measured, then start after start refined on every vertex). Its deadline was
// checked only between refinements, and not while the starts were measured (5 s on this sheet):
// a cancel (or the fit's --time) waited for them. It is checked at every step. Measured as the
// CPU spent after the cancel (registration runs on this thread alone), which a loaded machine
// does not stretch as it does the wall clock.
TEST(WholeSheetFolds, RegistrationStopsSoonAfterItsDeadline) {
  const Sheet initial = makeSurface("square", {{"resolution", 96}});
  const TriangleMesh sheet = meshOf(initial);
  TriangleMesh moved = sheet;
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  for (glm::dvec3& p : moved.positions) {
    p.z += 1e-3 * std::cos(10.0 * p.x) * std::cos(7.0 * p.y);  // not rigid: never laid on
    // A turn of 0.6 radians about `axis` (Rodrigues), then a shift.
    const double c = std::cos(0.6), s = std::sin(0.6);
    p = c * p + s * glm::cross(axis, p) + (1.0 - c) * glm::dot(axis, p) * axis +
        glm::dvec3(0.05, 0.02, 0.1);
  }
  std::atomic<bool> cancelled{false};
  Deadline deadline;
  deadline.cancelled = &cancelled;
  testing::CpuAfter afterCancel(std::chrono::steady_clock::now() + std::chrono::milliseconds(300),
                                [&] { cancelled = true; });
  const std::vector<RigidMotion> ways =
      registerSheetOntoAll(sheet, moved, 1e-4 * boundingDiagonal(sheet), 24, deadline);
  const double cpu = afterCancel.seconds();
  EXPECT_TRUE(cancelled.load()) << "registration ended before the cancel: nothing measured";
  EXPECT_TRUE(ways.empty());
  // One step is one closest-point pass over the sheet's 9,409 vertices: milliseconds (tens under
  // the sanitizers); a refinement is up to 200 of them.
  EXPECT_LT(cpu, testing::kSanitized ? 1.5 : 0.25) << cpu << " s of CPU after the cancel";
}

// A sheet with a near-continuous symmetry (the disk, a 96-gon, turned about its normal; the slit
// cylinder about its axis), turned by an angle none of its symmetries makes and then mirrored
// whole by a plane past it, as a target moved whole leaves it. Point-to-point steps slid along
// the near-symmetry, held only by the polygon's corners or the slit: 201 steps on the disk, 460
// on the cylinder (the fit's registration took 9.6 s and over 45 s on such targets under load);
// point-to-plane steps with the boundary's way back take 2 and 4. Counted in steps (closest-point
// passes), not seconds.
// The mesh with each triangle split 1->4 at its edges' midpoints: a copy on a mesh of its own, as
// a target is (creases split its triangles); on the sheet's own mesh the principal axes, sampled
// alike, lay it with no step.
TriangleMesh eachTriangleSplitInFour(const TriangleMesh& sheet) {
  TriangleMesh split = sheet;
  split.triangles.clear();
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
  auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
    const auto [at, added] = midpoints.try_emplace({std::min(a, b), std::max(a, b)},
                                                   std::uint32_t(split.positions.size()));
    if (added) split.positions.push_back(0.5 * (sheet.positions[a] + sheet.positions[b]));
    return at->second;
  };
  for (const auto& t : sheet.triangles) {
    const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]),
                        ca = midpoint(t[2], t[0]);
    split.triangles.push_back({t[0], ab, ca});
    split.triangles.push_back({ab, t[1], bc});
    split.triangles.push_back({ca, bc, t[2]});
    split.triangles.push_back({ab, bc, ca});
  }
  return split;
}

TEST(WholeSheetFolds, ANearlySymmetricSheetTurnedALittleIsRegisteredInFewSteps) {
  for (const char* surface : {"disk", "cylinder"}) {
    SCOPED_TRACE(surface);
    const TriangleMesh sheet = meshOf(makeSurface(surface));
    const double diagonal = boundingDiagonal(sheet);
    // The disk lies in z = 0, the cylinder's axis is y: a turn about either, by 2.9 degrees (a
    // 96-gon's corners repeat every 3.75).
    const glm::dvec3 axis =
        std::string(surface) == "disk" ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.4, 0.85));
    double highest = -1e300;
    for (const glm::dvec3& p : sheet.positions) highest = std::max(highest, glm::dot(n, p));
    const ReflectionPlane past{(highest + 0.2 * diagonal) * n, n};
    // On a mesh of its own, as a target is (creases split its triangles): each triangle split
    // 1->4 (on the sheet's own mesh the principal axes, sampled alike, laid it with no step).
    TriangleMesh moved = eachTriangleSplitInFour(sheet);
    const double c = std::cos(0.05), s = std::sin(0.05);
    for (glm::dvec3& p : moved.positions)
      p = past.reflect(c * p + s * glm::cross(axis, p) + (1.0 - c) * glm::dot(axis, p) * axis);
    int steps = 0;
    const std::vector<RigidMotion> ways =
        registerSheetOntoAll(sheet, moved, 1e-4 * diagonal, 1, {}, &steps);
    ASSERT_EQ(ways.size(), 1u);
    // Laid on the copy: every vertex within the tolerance (the function checks both ways).
    const SurfaceDistanceQuery copy(moved, "copy");
    for (const glm::dvec3& p : sheet.positions)
      ASSERT_LE(copy.distance(ways[0](p)), 1e-4 * diagonal);
    EXPECT_LE(steps, 40);
  }
}

// A slit cone's or cylinder's sides meet in space, so as a set of points the sheet is whole and
// lies on its copy turned any way about its axis: registration on the surface alone returned the
// turn its nearest start (every 15 degrees) began at, not the development's, and the folds read
// then took 3-4 whole-sheet planes where the design had one (issue 38, 1: the slit cone and
// cylinder misses of reach9 and reach10). The slit fixes the turn: the sheet's boundary (rims and
// slit) lies on the copy's, not only its surface on the copy's surface. (Its mirror through the
// plane of the axis and the slit, or the cylinder's end for end, lays it as well: a symmetry.)
TEST(WholeSheetFolds, ASlitSheetTurnedAboutItsAxisIsRegisteredSlitOnSlit) {
  // The cone alone under the sanitizers (about 1 s of CPU each here).
  const std::vector<const char*> surfaces = testing::kSanitized
                                                ? std::vector<const char*>{"cone"}
                                                : std::vector<const char*>{"cone", "cylinder"};
  for (const char* surface : surfaces) {
    SCOPED_TRACE(surface);
    const TriangleMesh sheet = meshOf(makeSurface(surface));
    const double diagonal = boundingDiagonal(sheet);
    // Both about the y axis; 52.5 degrees lies halfway between two starts.
    const glm::dvec3 axis(0, 1, 0), n = glm::normalize(glm::dvec3(0.3, -0.4, 0.85));
    const double angle = 52.5 * std::numbers::pi / 180.0;
    double highest = -1e300;
    for (const glm::dvec3& p : sheet.positions) highest = std::max(highest, glm::dot(n, p));
    const ReflectionPlane past{(highest + 0.2 * diagonal) * n, n};
    auto moveOf = [&](const glm::dvec3& p) {
      const double c = std::cos(angle), s = std::sin(angle);
      return past.reflect(c * p + s * glm::cross(axis, p) + (1.0 - c) * glm::dot(axis, p) * axis);
    };
    TriangleMesh moved = eachTriangleSplitInFour(sheet);
    for (glm::dvec3& p : moved.positions) p = moveOf(p);
    const std::vector<RigidMotion> ways = registerSheetOntoAll(sheet, moved, 1e-4 * diagonal, 1);
    ASSERT_EQ(ways.size(), 1u);
    const SurfaceDistanceQuery copy(moved, "copy");
    std::vector<std::pair<glm::dvec3, glm::dvec3>> copyEdges;
    for (const auto& [edge, faces] : edgeFaces(moved))
      if (faces.size() == 1)
        copyEdges.emplace_back(moved.positions[edge.first], moved.positions[edge.second]);
    double offSurface = 0.0, offBoundary = 0.0;
    for (const auto& [edge, faces] : edgeFaces(sheet)) {
      if (faces.size() != 1) continue;
      const glm::dvec3 p = ways[0](sheet.positions[edge.first]);
      offSurface = std::max(offSurface, copy.distance(p));
      double nearest = 1e300;
      for (const auto& [a, b] : copyEdges) {
        const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
        nearest = std::min(nearest, glm::distance(p, a + t * (b - a)));
      }
      offBoundary = std::max(offBoundary, nearest);
    }
    EXPECT_LE(offSurface, 1e-4 * diagonal);
    EXPECT_LE(offBoundary, 1e-4 * diagonal) << "a boundary vertex lands " << offBoundary / diagonal
                                            << " of the diagonal off the copy's boundary";
  }
}

// A cone moved whole by two folds (each plane past the sheet) has no crease left, so the fit
// reads it as a smooth shape, and a fold toward a smooth shape is kept only while the farthest
// point stays near: the first whole-sheet fold moves it farther, and the two folds that laid the
// cone on the target were both dropped (0 folds, 112% off). A sequence that reaches the target
// is kept whole.
// A motion measured on a replay is about 1e-6 off: a turn with that much shift along its axis is
// no longer two planes (they make no shift along it). Snapped, it is again, and a mirror stays one.
TEST(WholeSheetFolds, AMeasuredMotionNearOneOrTwoPlanesIsMadeWithThem) {
  const Sheet initial = makeSurface("square", {{"resolution", 6}});
  auto mirrorThrough = [](glm::dvec3 n, double d) {  // the plane n.x = d
    n = glm::normalize(n);
    return RigidMotion{glm::dmat3(1.0) - 2.0 * glm::outerProduct(n, n), 2.0 * d * n};
  };
  const RigidMotion first = mirrorThrough({0.3, -0.5, 0.8}, 0.15);
  const RigidMotion second = mirrorThrough({0.1, 0.2, 1.0}, 0.3);
  const RigidMotion turn{second.linear * first.linear,
                         second.linear * first.offset + second.offset};
  for (const RigidMotion& exact : {first, turn}) {
    const std::size_t planes = glm::determinant(exact.linear) < 0.0 ? 1 : 2;
    ASSERT_EQ(wholeSheetReflections(exact, initial.positions, planes).size(), planes);
    RigidMotion measured = exact;
    measured.offset += glm::dvec3(2e-6, -1e-6, 3e-6);  // a few micrometres off
    if (planes == 2) {
      EXPECT_TRUE(wholeSheetReflections(measured, initial.positions, 2).empty());
    }
    const RigidMotion snapped = snappedToFewPlanes(measured, 1e-3, 1e-3);
    EXPECT_EQ(wholeSheetReflections(snapped, initial.positions, planes).size(), planes);
    for (const glm::dvec3& p : initial.positions)
      EXPECT_LT(glm::distance(snapped(p), exact(p)), 1e-5);
  }
}

// A disk (a 120-gon at its defaults) lies on a moved copy of itself 240 ways times its two sides,
// one every 3 degrees; registration returns the ways its starts (every 15 degrees) lead to, and
// the design's own way, the one its whole-sheet folds made, may not be among them: each way found
// then takes 3-4 planes where the design used 2 (issue 38, 1; the disk miss of seed 9 was first
// taken for this, and turned out a misreading: docs/performance.md, reach12). The sheet's own
// turns and flips, read from its boundary, times a way found give every way, and one of them is
// the design's two planes again.
TEST(WholeSheetFolds, ADisksOwnTurnsTakeAWayFoundToTheDesignsTwoPlanes) {
  const TriangleMesh sheet = meshOf(makeSurface("disk"));
  const double diagonal = boundingDiagonal(sheet);
  auto mirrorPast = [&](glm::dvec3 n, const std::vector<glm::dvec3>& points) {
    n = glm::normalize(n);
    double highest = -1e300;
    for (const glm::dvec3& p : points) highest = std::max(highest, glm::dot(n, p));
    const double d = highest + 0.1 * diagonal;  // the plane n.x = d, past the sheet
    return RigidMotion{glm::dmat3(1.0) - 2.0 * glm::outerProduct(n, n), 2.0 * d * n};
  };
  // The design's motion: two whole-sheet folds, each plane past the sheet where it lay then.
  const RigidMotion first = mirrorPast({0.3, -0.5, 0.8}, sheet.positions);
  std::vector<glm::dvec3> moved = sheet.positions;
  for (glm::dvec3& p : moved) p = first(p);
  const RigidMotion second = mirrorPast({-0.6, 0.1, 0.5}, moved);
  const RigidMotion design{second.linear * first.linear,
                           second.linear * first.offset + second.offset};
  ASSERT_EQ(wholeSheetReflections(design, sheet.positions, 2).size(), 2u);
  // A way registration may return: the design's after the disk's own turn by three corners
  // about its centre, which takes more planes.
  const std::size_t corners = boundaryEdges(sheet).size();  // at its defaults, one edge a side
  const double angle = 3.0 * 2.0 * std::numbers::pi / double(corners);
  const glm::dmat3 turn(glm::dvec3(std::cos(angle), std::sin(angle), 0.0),
                        glm::dvec3(-std::sin(angle), std::cos(angle), 0.0), glm::dvec3(0, 0, 1));
  const RigidMotion found{design.linear * turn, design.offset};
  const double shift = 1e-4 * diagonal;
  ASSERT_GT(fewestReflections(found, 1e-4, shift), 2u);
  ASSERT_EQ(fewestReflections(design, 1e-4, shift), 2u);

  const std::vector<RigidMotion> symmetries = sheetSymmetries(sheet, 1e-4 * diagonal);
  // A turn and a flip per corner, each also through the sheet's plane (a flat sheet's two
  // sides), less the identity.
  EXPECT_EQ(symmetries.size(), 4 * corners - 1);
  // The design's copy: each way made by two planes lays the sheet on it.
  TriangleMesh copy = sheet;
  for (glm::dvec3& p : copy.positions) p = design(p);
  const SurfaceDistanceQuery onCopy(copy, "copy");
  std::size_t twoPlaneWays = 0;
  for (const RigidMotion& s : symmetries) {
    const RigidMotion way{found.linear * s.linear, found.linear * s.offset + found.offset};
    if (fewestReflections(way, 1e-4, shift) > 2) continue;
    // Two planes that miss the sheet (a turn about a line through it takes none).
    const std::vector<ReflectionPlane> planes =
        wholeSheetReflections(snappedToFewPlanes(way, 1e-4, shift), sheet.positions, 2);
    if (planes.empty()) continue;
    ++twoPlaneWays;
    double apart = 0.0;
    for (const glm::dvec3& p : sheet.positions)
      apart = std::max(apart, onCopy.distance(planes[1].reflect(planes[0].reflect(p))));
    EXPECT_LE(apart, 1e-4 * diagonal);
  }
  EXPECT_GE(twoPlaneWays, 1u);
}

// A design whose whole-sheet folds came between its creasing folds (issue 38, 1: C C W C C W C C
// on the disk of seed 9 was thought such a case; docs/performance.md, unfold14): where the sheet
// lies first and last, every plane of the motion cuts it, and only as it lay in between does one
// miss it. The fit made whole-sheet folds only first
// or last; placed among the folds read, each where it misses the sheet then, they are made.
// Stages as a fold leaves a flat sheet: a square, then its corner folded far off to one side
// (the rest smaller), then unfolded wide again.
TEST(WholeSheetFolds, AMotionsPlanesArePlacedWhereTheSheetLetsThemMiss) {
  auto square = [](double x0, double x1, double y0, double y1) {
    std::vector<glm::dvec3> points;
    for (int i = 0; i <= 10; ++i)
      for (int j = 0; j <= 10; ++j)
        points.emplace_back(x0 + (x1 - x0) * i / 10.0, y0 + (y1 - y0) * j / 10.0, 0.0);
    return points;
  };
  const std::vector<glm::dvec3> wide = square(-1.0, 1.0, -1.0, 1.0);
  const std::vector<glm::dvec3> aside = square(0.5, 1.0, -0.5, 0.5);
  auto mirrorThrough = [](glm::dvec3 n, double d) {  // the plane n.x = d
    n = glm::normalize(n);
    return RigidMotion{glm::dmat3(1.0) - 2.0 * glm::outerProduct(n, n), 2.0 * d * n};
  };
  // A mirror through x = 0.2, and a turn of 40 degrees about the line x = 0.2, y = 0 (two
  // planes through it): both cut the wide sheet, and miss the one aside.
  const RigidMotion mirror = mirrorThrough({1.0, 0.0, 0.0}, 0.2);
  const double a = 40.0 * std::numbers::pi / 180.0;
  const glm::dvec3 n2(std::cos(0.5 * a), std::sin(0.5 * a), 0.0);
  const RigidMotion second = mirrorThrough(n2, glm::dot(n2, glm::dvec3(0.2, 0.0, 0.0)));
  const RigidMotion turn{second.linear * mirror.linear,
                         second.linear * mirror.offset + second.offset};
  for (const RigidMotion& motion : {mirror, turn}) {
    const std::size_t count = glm::determinant(motion.linear) < 0.0 ? 1 : 2;
    SCOPED_TRACE(count);
    // First or last only (the stages the fit tried before): none.
    EXPECT_TRUE(wholeSheetReflections(motion, wide, count).empty());
    EXPECT_TRUE(placedWholeSheetReflections(motion, {wide, wide}, count).empty());
    const std::vector<PlacedPlane> placed =
        placedWholeSheetReflections(motion, {wide, aside, wide}, count);
    ASSERT_EQ(placed.size(), count);
    RigidMotion made;
    for (const PlacedPlane& p : placed) {
      EXPECT_EQ(p.after, 1u);
      // Each misses the sheet aside as the planes before it left it.
      bool above = false, below = false;
      for (const glm::dvec3& q : aside) {
        const double d = p.plane.signedDistance(made(q));
        EXPECT_GT(std::abs(d), 1e-3);
        (d > 0.0 ? above : below) = true;
      }
      EXPECT_FALSE(above && below);
      made = then(made, reflectionOf(p.plane));
    }
    for (const glm::dvec3& q : wide) EXPECT_LT(glm::distance(made(q), motion(q)), 1e-9);
  }
}

// The same in a fit: a rectangle's right part folded up (C), the sheet mirrored whole through
// x = 0.1 (W, its plane past the part left flat), then the flap's top folded out past that plane
// (C). Read with the mirror first or last, its plane cuts the sheet (the rectangle reaches 0.1485
// first, the flap's top 0.1185 last), and within three folds no other way or flip takes one
// plane; made after the first fold read, it misses the sheet.
TEST(FitReading, AWholeSheetFoldBetweenCreasingFoldsIsMadeWhereItWasMade) {
  if (testing::kSanitized)
    GTEST_SKIP() << "a real search (registration and replays); "
                    "WholeSheetFolds.AMotionsPlanesArePlacedWhereTheSheetLetsThemMiss covers the "
                    "placement";
  const Sheet initial = makeSurface("rectangle", {{"resolution", 12}});
  FoldSession folding(initial);
  auto fold = [&](glm::dvec3 grab, glm::dvec3 drop) {
    folding.beginDragNear(grab);
    folding.updateDrag(drop);
    return folding.commit();
  };
  ASSERT_TRUE(fold({0.1485, 0.0, 0.0}, {0.05, 0.0, 0.0985}));  // up about x = 0.05
  const Sheet before = folding.fixed();
  ASSERT_TRUE(fold({-0.1485, 0.0, 0.0}, {0.3485, 0.0, 0.0}));  // mirrored whole through x = 0.1
  for (std::size_t v = 0; v < before.vertexCount(); ++v)
    ASSERT_GT(glm::distance(before.positions[v], folding.fixed().positions[v]), 1e-3);
  ASSERT_TRUE(fold({0.15, 0.0, 0.0985}, {0.0815, 0.0, 0.03}));  // the flap's top folded out
  const TriangleMesh target = testing::exportedWithoutDevelopment(folding.fixed());

  FoldSession session(initial);
  const FitResult result = expectFoundByUnfolding(session, target, 3, 300);
  EXPECT_EQ(session.foldCount(), 3u);
}

// A fold that creases the sheet, then the sheet moved whole by three folds whose planes miss it
// (a turn and a shift): the motion takes three whole-sheet folds, more than the one that two
// folds leave, first, last, flipped or placed among the folds read. Where the start may be moved
// (FitOptions::mayPlaceStart: `fit --from KIND` without parameters), it starts moved by the
// motion and makes the creasing fold alone; the design embeds the moved sheet, passes `check`
// and replays to the fitted sheet. Where it may not, the fit stays on the sheet as given.
TEST(FitReading, AMotionPastTheFoldsLeftStartsTheSheetPlaced) {
  const Sheet initial = makeSurface("rectangle", {{"resolution", 12}});
  FoldSession folding(initial);
  ASSERT_NO_FATAL_FAILURE(foldACornerThenTurnAndShift(folding));
  const TriangleMesh target = testing::exportedWithoutDevelopment(folding.fixed());

  const FoldFitter fitter(target);
  FitOptions options = clockFree(2, 300);
  {
    FoldSession session(initial);
    const FitResult result = fitFolds(session, fitter, options);
    EXPECT_FALSE(result.placedStart);
    EXPECT_TRUE(identical(session.initial(), initial));
  }
  options.mayPlaceStart = true;
  // The start reported is the placed sheet's, before any search line.
  std::vector<FitProgress> reported;
  bool searchedBeforeStart = false;
  options.progress = [&](const FitProgress& step) { reported.push_back(step); };
  options.searching = [&](std::size_t, double, double) {
    searchedBeforeStart = searchedBeforeStart || reported.empty();
  };
  FoldSession session(initial);
  const FitResult result = fitFolds(session, fitter, options);
  EXPECT_EQ(result.stopReason, "the target unfolded: its creases named every fold");
  ASSERT_TRUE(result.placedStart);
  ASSERT_FALSE(reported.empty());
  EXPECT_EQ(reported.front().fold, 0u);
  EXPECT_FALSE(searchedBeforeStart);
  EXPECT_EQ(reported.front().chamfer, result.steps.front().chamfer);
  const SurfaceDistance placedStart = surfaceDistance(meshOf(*result.placedStart), target);
  const SurfaceDistance catalogueStart = surfaceDistance(meshOf(initial), target);
  EXPECT_NEAR(reported.front().chamfer, placedStart.chamfer, 0.05 * placedStart.chamfer)
      << "the catalogue sheet's " << catalogueStart.chamfer;
  EXPECT_TRUE(identical(session.initial(), *result.placedStart));
  EXPECT_EQ(session.foldCount(), 1u);
  EXPECT_LE(surfaceDistance(meshOf(session.fixed()), target).relativeHausdorff(), 1e-3);
  testing::expectInvariants(session.fixed(), session.initial());
  EXPECT_TRUE(identical(replayFolds(*result.placedStart, result.folds), session.fixed()));
  const Design fitted(*result.placedStart, result.folds);
  const session::DesignCheck check =
      session::checkDesign(fitted, "fitted", *result.placedStart, session.fixed(), false);
  EXPECT_TRUE(check.passed()) << check.firstFailure();
}

// judge17's an17-half_cylinder-3-4-0 (mirror:y, three folds; at resolution 12 here): read with
// its images, a fold's replay brings an image the target lacks and the reading ends on a moved
// copy that no whole-sheet fold made about the sheet's centre reaches (the fit ended 25.7% of the
// diagonal away); read without the symmetry it is four plain folds. A symmetric fit now reads it
// so where its own reading misses (FitResult::readPlain): the folds reach the target, and the
// design, its symmetry kept for the folds made after, passes `check`.
TEST(FitReading, ASymmetricDesignItsImagesCannotReadIsReadAsPlainFolds) {
  const Sheet initial = makeSurface("half_cylinder", {{"resolution", 12}});
  const Symmetry symmetry = parseSymmetry("mirror:y", initial);
  auto fold = [](glm::dvec2 seed, glm::dvec3 point, glm::dvec3 normal) {
    FoldRecord record;
    record.seed = seed;
    record.plane = {point, glm::normalize(normal)};
    return record;
  };
  const std::vector<FoldRecord> made{
      fold({-0.0825398, -0.0802083}, {-0.0601593, -0.0818944, 0.0151907},
           {-0.318359, -0.403772, 0.857680}),
      fold({-0.0270263, -0.0889583}, {-0.0310884, -0.0905886, 0.0553104},
           {-0.921075, -0.301732, 0.246127}),
      fold({0.0927659, 0.0941151}, {-0.000872317, 0.0101575, 0.210758},
           {0.785224, 0.617731, 0.0427978})};
  const Sheet folded = replayFolds(initial, made);
  const TriangleMesh target = testing::exportedWithoutDevelopment(folded);

  FoldSession session(initial);
  session.setSymmetry(symmetry);
  const FitResult result = expectFoundByUnfolding(session, target, 8, 300);
  EXPECT_TRUE(result.readPlain);
  ASSERT_NE(session.symmetry(), nullptr);  // kept for the folds made after
  EXPECT_TRUE(identical(replayFolds(initial, result.folds), session.fixed()));
  const Design fitted(GeneratedSurface{"half_cylinder", {{"resolution", 12}}}, result.folds,
                      "mirror:y");
  const session::DesignCheck check =
      session::checkDesign(fitted, "fitted", initial, session.fixed(), false);
  EXPECT_TRUE(check.passed()) << check.firstFailure();
}

// A corner of a rectangle folded with rotational:2:z (the fold and its image), then the sheet
// moved whole by three folds: read with the symmetry, the motion takes three planes where --folds
// leaves one, and a symmetric design was never placed. Read as plain folds where the start may
// be moved, it starts placed and makes the two creasing folds; the placed sheet drops the
// symmetry (it need not hold about the moved sheet's frame).
TEST(FitReading, ASymmetricDesignPastTheFoldsLeftStartsPlacedAsPlainFolds) {
  const Sheet initial = makeSurface("rectangle", {{"resolution", 12}});
  FoldSession folding(initial);
  folding.setSymmetry(parseSymmetry("rotational:2:z", initial));
  ASSERT_NO_FATAL_FAILURE(foldACornerThenTurnAndShift(folding));
  ASSERT_EQ(folding.folds()[1].group, 1u);  // the corner's image
  const TriangleMesh target = testing::exportedWithoutDevelopment(folding.fixed());

  const FoldFitter fitter(target);
  FitOptions options = clockFree(3, 300);
  options.mayPlaceStart = true;
  FoldSession session(initial);
  session.setSymmetry(parseSymmetry("rotational:2:z", initial));
  const FitResult result = fitFolds(session, fitter, options);
  EXPECT_EQ(result.stopReason, "the target unfolded: its creases named every fold");
  EXPECT_TRUE(result.readPlain);
  ASSERT_TRUE(result.placedStart);
  EXPECT_EQ(session.symmetry(), nullptr);
  EXPECT_EQ(session.foldCount(), 2u);
  EXPECT_LE(surfaceDistance(meshOf(session.fixed()), target).relativeHausdorff(), 1e-3);
  testing::expectInvariants(session.fixed(), session.initial());
  EXPECT_TRUE(identical(replayFolds(*result.placedStart, result.folds), session.fixed()));
}

TEST(FitReading, WholeSheetFoldsThatReachACreaselessTargetAreKept) {
  const Sheet initial = makeSurface("cone", {{"resolution", 24}});
  FoldSession folding(initial);
  for (const glm::dvec3& along : {glm::dvec3(0.6, 0.6, 0.3), glm::dvec3(0.4, 0.0, 0.9)})
    ASSERT_NO_FATAL_FAILURE(foldTheWholeSheetAlong(folding, along, 0.12));
  const TriangleMesh target = testing::exportedWithoutDevelopment(folding.fixed());

  const FoldFitter fitter(target);
  ASSERT_TRUE(fitter.smoothTarget());  // no crease: the case the bound on the way tripped
  FoldSession session(initial);
  FitOptions options;
  options.maxFolds = 3;
  options.seconds = std::numeric_limits<double>::infinity();
  options.maxEvaluations = 300;
  fitFolds(session, fitter, options);
  EXPECT_LE(surfaceDistance(meshOf(session.fixed()), target).relativeHausdorff(), 1e-3);
  EXPECT_GE(session.foldCount(), 1u);
  testing::expectInvariants(session.fixed(), session.initial());
}

// What a fit reads of a smooth target: only what could be the sheet moved whole. A curved shape
// (a vase: no reflection design has an angle defect) or a flat one of another area (every fold
// keeps the area) has no creases to read, and reading it cost a third of a fit's time (half on a
// scan's noise) for nothing; the cone moved whole above, a flat sheet moved whole and a folded
// target are read as before.
TEST(FitReading, ASmoothTargetIsReadOnlyWhereItMayBeTheSheetMovedWhole) {
  const Sheet cylinder = makeSurface("cylinder");
  TriangleMesh vase;  // about y: a belly between a narrower foot and neck, 48 around, 30 along
  const int around = 48, along = 30;
  for (int j = 0; j <= along; ++j) {
    const double h = -0.1 + 0.2 * j / along;
    const double r = 0.04 + 0.015 * std::cos(std::numbers::pi * h / 0.2);
    for (int i = 0; i < around; ++i) {
      const double a = 2.0 * std::numbers::pi * i / around;
      vase.positions.push_back({r * std::cos(a), h, r * std::sin(a)});
    }
  }
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < around; ++i) {
      const auto v = [&](int jj, int ii) { return std::uint32_t(jj * around + ii % around); };
      vase.triangles.push_back({v(j, i), v(j + 1, i), v(j + 1, i + 1)});
      vase.triangles.push_back({v(j, i), v(j + 1, i + 1), v(j, i + 1)});
    }
  const FoldFitter toVase(vase);
  ASSERT_TRUE(toVase.smoothTarget());
  EXPECT_FALSE(toVase.readsCreasesFrom(cylinder));

  const Sheet square = makeSurface("square");
  TriangleMesh wider = meshOf(makeSurface("square", {{"size", 1.5 * sheetSize(square)}}));
  const FoldFitter toWider(wider);
  ASSERT_TRUE(toWider.smoothTarget());
  EXPECT_FALSE(toWider.readsCreasesFrom(square));
  // The square itself, moved whole (turned and shifted): it may be the sheet moved whole.
  TriangleMesh moved = meshOf(square);
  for (glm::dvec3& p : moved.positions) p = glm::dvec3(p.y, p.z + 0.03, p.x);
  EXPECT_TRUE(FoldFitter(moved).readsCreasesFrom(square));

  const Sheet cone = makeSurface("cone", {{"resolution", 24}});
  FoldSession folding(cone);
  for (const glm::dvec3& along : {glm::dvec3(0.6, 0.6, 0.3), glm::dvec3(0.4, 0.0, 0.9)})
    ASSERT_NO_FATAL_FAILURE(foldTheWholeSheetAlong(folding, along, 0.12));
  const FoldFitter toMovedCone(testing::exportedWithoutDevelopment(folding.fixed()));
  ASSERT_TRUE(toMovedCone.smoothTarget());
  EXPECT_TRUE(toMovedCone.readsCreasesFrom(cone));

  FoldSession creasing(square);  // a corner folded over: creased, read
  creasing.beginDragNear(square.positions.front());
  creasing.updateDrag(0.6 * square.positions.front() + glm::dvec3(0.0, 0.0, 0.05));
  ASSERT_TRUE(creasing.commit());
  const FoldFitter toFolded(meshOf(creasing.fixed()));
  ASSERT_FALSE(toFolded.smoothTarget());
  EXPECT_TRUE(toFolded.readsCreasesFrom(square));
}

// A symmetric sheet (a star) lies on a moved copy of itself several ways, one its symmetry times
// another: registered any way, the fold that mirrored it whole took up to five whole-sheet folds
// (the star's turn as well as the mirror) and no longer fitted in the folds allowed. Of every way,
// the one with the fewest folds: a tip folded, then the star mirrored whole, is two folds again.
TEST(FitReading, ASymmetricSheetMirroredWholeTakesOneFold) {
  const Sheet initial = makeSurface("star", {{"resolution", 12}});
  FoldSession folding(initial);
  glm::dvec3 tip = initial.positions.front();
  for (const glm::dvec3& p : initial.positions)
    if (p.x > tip.x) tip = p;
  folding.beginDragNear(tip);
  folding.updateDrag(0.75 * tip + glm::dvec3(0.0, 0.0, 0.3 * tip.x));  // a tip folded up
  ASSERT_TRUE(folding.commit());
  // The plane past the sheet: all of it mirrored.
  ASSERT_NO_FATAL_FAILURE(foldTheWholeSheetAlong(folding, {-0.3, 0.8, 0.5}, 0.1));
  const TriangleMesh target = meshOf(folding.fixed());

  const FoldFitter fitter(target);
  FoldSession session(initial);
  FitOptions options;
  options.maxFolds = 2;
  options.seconds = std::numeric_limits<double>::infinity();
  options.maxEvaluations = 500;
  const FitResult result = fitFolds(session, fitter, options);
  EXPECT_EQ(result.stopReason, "the target unfolded: its creases named every fold");
  EXPECT_LE(surfaceDistance(meshOf(session.fixed()), target).relativeHausdorff(), 1e-3);
  EXPECT_EQ(session.foldCount(), 2u);
}

// A symmetric design's fold brings the images of its seed that the fold itself does not move: a
// fold of most of a square with rotational:4 moves every image of its grab, so it has none. The
// unfolding names another seed, deep in the part, one of whose images the fold leaves in place:
// made from it, the fold brought an image the target lacks (a 40 mm miss). Made from a seed whose
// images are folds read, it is the target again.
TEST(FitReading, ASymmetricFoldIsMadeWithTheImagesTheTargetHas) {
  const Sheet initial = makeSurface("square", {{"resolution", 16}});
  const Symmetry symmetry = parseSymmetry("rotational:4:z", initial);
  FoldSession folding(initial);
  folding.setSymmetry(symmetry);
  folding.beginDragNear({-0.0734, 0.0221, 0.0});
  folding.updateDrag({-0.1318, -0.0478, 0.0187});
  ASSERT_TRUE(folding.commit());
  ASSERT_EQ(folding.foldCount(), 1u);  // every image's seed moved by the fold: none made
  const TriangleMesh target = testing::exportedWithoutDevelopment(folding.fixed());

  FoldSession session(initial);
  session.setSymmetry(symmetry);
  expectFoundByUnfolding(session, target, 2, 300);
  EXPECT_EQ(session.foldCount(), 1u);
}

// A fold of most of a rectangle with rotational:2 (a corner side folded up past the middle)
// leaves its image's plane clear of the folded sheet: the image mirrors the whole of it and
// leaves no crease. Then a fold of most of it again (all but a tip). Read without the symmetry,
// the unfolding ended on a copy of the sheet mirrored and turned (73% of the diagonal off it) and
// the fit ended 30% away; read with it, the image is undone before its fold.
TEST(FitReading, AnImageThatMovedTheWholeSheetIsUndoneWithItsFold) {
  const Sheet initial = makeSurface("rectangle", {{"resolution", 16}});
  const Symmetry symmetry = parseSymmetry("rotational:2:z", initial);
  FoldSession folding(initial);
  folding.setSymmetry(symmetry);
  folding.beginDragNear({-0.0696, 0.0068, 0.0});
  folding.updateDrag({-0.0268, 0.0635, 0.0440});
  ASSERT_TRUE(folding.commit());
  ASSERT_EQ(folding.foldCount(), 2u);                      // the fold and its image
  for (std::size_t v = 0; v < initial.vertexCount(); ++v)  // the image moved every vertex
    ASSERT_GT(glm::distance(initial.positions[v], folding.fixed().positions[v]), 1e-4);
  folding.beginDragNear({0.0239, 0.0418, 0.1169});
  folding.updateDrag({0.0499, 0.0587, 0.1174});
  ASSERT_TRUE(folding.commit());
  const TriangleMesh target = testing::exportedWithoutDevelopment(folding.fixed());

  FoldSession session(initial);
  session.setSymmetry(symmetry);
  expectFoundByUnfolding(session, target, 4, testing::kSanitized ? 100 : 400);
}

// A fold of most of a rectangle with rotational:2 whose image mirrors the whole sheet (as above),
// then the sheet moved whole by one more fold: the unfolding ends on a turned copy of the sheet,
// and the fold read, replayed, brings its whole-sheet image again. Taking the copy's motion for
// what is left to make after the replay, the fit missed by 30-75% of the diagonal; what is left
// is measured on the replayed sheet (one mirror: two groups).
TEST(FitReading, AFoldWhoseImageMovedTheSheetThenMovedWholeIsFoundToo) {
  const Sheet initial = makeSurface("rectangle", {{"resolution", 12}});
  const Symmetry symmetry = parseSymmetry("rotational:2:z", initial);
  FoldSession folding(initial);
  folding.setSymmetry(symmetry);
  folding.beginDragNear({-0.0696, 0.0068, 0.0});
  folding.updateDrag({-0.0268, 0.0635, 0.0440});
  ASSERT_TRUE(folding.commit());
  ASSERT_EQ(folding.foldCount(), 2u);  // the fold and its image, which moved every vertex
  ASSERT_NO_FATAL_FAILURE(foldTheWholeSheetAlong(folding, {0.5, -0.4, 0.77}, 0.12));
  const TriangleMesh target = testing::exportedWithoutDevelopment(folding.fixed());

  FoldSession session(initial);
  session.setSymmetry(symmetry);
  expectFoundByUnfolding(session, target, 3, testing::kSanitized ? 50 : 200);
}

// A whole-sheet fold made after a symmetric fold with its images (four corners folded up by
// rotational:4, then the sheet moved whole along a drag): the target is two groups, the corners'
// and the whole sheet's (whose images are none: it moves every image of its grab).
TEST(FitReading, AWholeSheetFoldAfterASymmetricFoldIsFoundToo) {
  if (testing::kSanitized) GTEST_SKIP() << "the Release run checks the search (35 s here)";
  const Sheet initial = makeSurface("square", {{"resolution", 16}});
  const Symmetry symmetry = parseSymmetry("rotational:4:z", initial);
  FoldSession folding(initial);
  folding.setSymmetry(symmetry);
  folding.beginDragNear({0.1, 0.1, 0.0});
  folding.updateDrag({0.03, 0.05, 0.06});  // a corner folded up, and its three images
  ASSERT_TRUE(folding.commit());
  ASSERT_EQ(folding.foldCount(), 4u);
  ASSERT_NO_FATAL_FAILURE(foldTheWholeSheetAlong(folding, {0.6, -0.3, 0.74}, 0.15));
  const TriangleMesh target = testing::exportedWithoutDevelopment(folding.fixed());

  FoldSession session(initial);
  session.setSymmetry(symmetry);
  const FitResult result = expectFoundByUnfolding(session, target, 6, 2000);
  EXPECT_TRUE(identical(replayFolds(initial, result.folds), session.fixed()));
}

// A blintz (a square's four corners laid by its centre, 1-4 mm above the sheet: folds of about
// 179 degrees; 1 cm short of the centre, so the flaps do not touch) leaves every crease in the
// sheet's plane, which mirrors each crease's faces onto each other (not reversed, as a fold turns
// a face over): read so, it took every crease and named no fold. Each crease names the plane
// across the two layers it joins, and the blintz unfolds exactly.
TEST(FitReading, FlapsLaidFlatOnTheSheetNameThePlanesAcrossIt) {
  const Sheet initial = makeSurface("square", {{"resolution", 16}});
  FoldSession folding(initial);
  const double half = 0.1;  // the square is 0.2 m, centred on the origin
  int k = 0;
  for (const glm::dvec2 corner :
       {glm::dvec2(1, 1), glm::dvec2(-1, 1), glm::dvec2(-1, -1), glm::dvec2(1, -1)}) {
    folding.beginDragNear({half * corner.x, half * corner.y, 0.0});
    folding.updateDrag({0.01 * corner.x, 0.01 * corner.y, 0.001 * ++k});
    ASSERT_TRUE(folding.commit()) << "corner " << k;
  }
  ASSERT_TRUE(findSelfIntersections(folding.fixed()).intersections.empty());
  const TriangleMesh target = meshOf(folding.fixed());
  const double size = boundingDiagonal(target);

  CreasePlaneOptions read;
  read.minDihedralDegrees = sharpEdgeThreshold(meshOf(initial));
  const std::vector<CreasePlane> planes = findCreasePlanes(target, read);
  ASSERT_FALSE(planes.empty());
  for (const CreasePlane& c : planes)
    EXPECT_LT(std::abs(c.plane.normal.z), 0.1)
        << "a plane along the sheet holds " << c.support << " m of creases";
  for (const FoldRecord& fold : folding.folds())
    EXPECT_TRUE(std::any_of(planes.begin(), planes.end(), [&](const CreasePlane& c) {
      return std::abs(std::abs(glm::dot(c.plane.normal, fold.plane.normal)) - 1.0) < 1e-6 &&
             std::abs(fold.plane.signedDistance(c.plane.point)) < 1e-6 * size;
    })) << "a corner's fold plane was not read";

  const FoldFitter fitter(target);
  FoldSession session(initial);
  FitOptions options;
  options.maxFolds = 6;
  options.seconds = std::numeric_limits<double>::infinity();
  options.maxEvaluations = 500;
  const FitResult result = fitFolds(session, fitter, options);
  EXPECT_EQ(result.stopReason, "the target unfolded: its creases named every fold");
  EXPECT_LE(surfaceDistance(meshOf(session.fixed()), target).relativeHausdorff(), 1e-3);
  EXPECT_EQ(session.foldCount(), 4u);
  EXPECT_NO_THROW(validate(session.fixed()));
}

// Designs on the swept sine (swept_curve) as bench/reach_targets.py folded them (its records,
// replayed bit for bit): where cylinder and cone targets came back, these did not.

// A fold as its record holds it: seed (development), plane, grabbed and dropped points.
struct RecordedFold {
  glm::dvec2 seed;
  ReflectionPlane plane;
  glm::dvec3 grabbed, target;
};

Sheet sweptFoldedBy(const std::vector<RecordedFold>& folds) {
  std::vector<FoldRecord> records;
  for (const RecordedFold& f : folds) {
    FoldRecord record;
    record.seed = f.seed;
    record.plane = f.plane;
    record.grabbed = f.grabbed;
    record.target = f.target;
    records.push_back(record);
  }
  FoldSession folding(makeSurface("swept_curve"));
  folding.applyRecords(records);
  return folding.fixed();
}

// Fits `target` from swept_curve at its defaults and expects it found exactly, by its reading,
// in a design `check` passes.
void expectSweptFitExactly(const TriangleMesh& target) {
  const Sheet initial = makeSurface("swept_curve");
  const FoldFitter fitter(target);
  FoldSession session(initial);
  FitOptions options;
  options.maxFolds = 6;
  options.seconds = 120.0;
  const FitResult result = fitFolds(session, fitter, options);
  EXPECT_EQ(result.stopReason, "the target unfolded: its creases named every fold");
  EXPECT_LE(surfaceDistance(meshOf(session.fixed()), target).relativeHausdorff(), 1e-3);
  const Design fitted(GeneratedSurface{"swept_curve", {}}, result.folds, "");
  const session::DesignCheck check =
      session::checkDesign(fitted, "fitted", initial, session.fixed(), false);
  EXPECT_TRUE(check.passed()) << check.firstFailure();
}

// The first fold's crease passes a vertex of the sine's grid 0.6 micrometres away (within the
// reading's on-plane tolerance, 1e-5 of the diagonal): left behind when its piece was reflected
// back, its sliver triangles stayed bent, and the unfolding stopped with 7% of the diagonal of
// crease left. The second fold's plane misses the sheet: it moves it whole.
TEST(FitReading, AGridVertexAMicrometreOffACreaseMovesWithItsPiece) {
  const Sheet folded =
      sweptFoldedBy({{{-0.04473225481778155, -0.020000000000000004},
                      {{-0.04196546597093753, -0.0457262524438729, -0.03432827722479854},
                       {-0.09087887432530711, -0.7202534059806955, -0.6877325507597938}},
                      {-0.038719423892837994, -0.020000000000000004, -0.009763615582380295},
                      {-0.04521150804903708, -0.0714525048877458, -0.058892938867216776}},
                     {{0.06961455752811442, 0.05499999999999999},
                      {{0.04645002881708235, -0.03502980661831246, -0.18857283718099574},
                       {0.10462381526047651, 0.779005519647416, -0.6182267040812788}},
                      {0.039082675707820064, -0.08988546948071394, -0.1450388251665935},
                      {0.05381738192634464, 0.019825856244089016, -0.23210684919539798}}});
  validate(folded);
  const TriangleMesh target = testing::exportedWithoutDevelopment(folded);
  const TriangleMesh sheet = meshOf(makeSurface("swept_curve"));
  const double diagonal = boundingDiagonal(target);
  const TargetUnfolding plan = unfoldTarget(target, sheet, sharpEdgeThreshold(sheet), 6);
  EXPECT_EQ(plan.folds.size(), 1u);  // the whole-sheet fold left no crease
  EXPECT_LE(plan.sharpLengthLeft, 1e-4 * diagonal);
  // Unfolded, it is the sheet moved whole.
  EXPECT_TRUE(registerSheetOnto(sheet, {plan.unfolded, target.triangles}, 1e-4 * diagonal));
  expectSweptFitExactly(target);
}

// Read whole, this design is four folds of the whole sheet and the small flap read: the flap,
// made last, lowers the Chamfer distance by 0.03 mm (under the least gain, 1e-4 of the
// diagonal) and the Hausdorff distance from 13 mm to none. Trimmed as gaining too little, it left
// the sheet 3.8% away, short of reaching the target, and the whole reading was dropped for the
// start: no fold at all.
TEST(FitReading, ASmallFlapReadLastIsKeptThoughTheChamferBarelyFalls) {
  const Sheet folded =
      sweptFoldedBy({{{0.1143455395569992, 0.08499999999999999},
                      {{0.10979385783326823, 0.08883562038269269, 0.003615207665988381},
                       {0.8593223269006705, 0.2454148859572861, 0.448705551827242}},
                      {0.09636340018394372, 0.08499999999999999, -0.003397668320334197},
                      {0.12322431548259272, 0.0926712407653854, 0.010628083652310959}},
                     {{0.09445242056626303, 0.07},
                      {{0.1419622444405506, 0.09646329346602428, 0.0056053066048336545},
                       {-0.22778189966442985, 0.45399659362548883, -0.8613956693423275}},
                      {0.14579847935237214, 0.0888172180540625, 0.02011267591069658},
                      {0.1381260095287291, 0.10410936887798608, -0.008902062701029272}}});
  validate(folded);
  expectSweptFitExactly(testing::exportedWithoutDevelopment(folded));
}

// Corners laid onto the centre itself, where the four flaps meet: the stubs of the creases that
// meet there let a plane turned a degree about one crease hold a few micrometres more of edge than
// the fold's own plane. Each crease's plane is read from its whole line, and refitted to it.
TEST(CreasePlanes, AStraightCreaseIsReadFromItsWholeLine) {
  const Sheet initial = makeSurface("square", {{"resolution", 16}});
  FoldSession folding(initial);
  int k = 0;
  for (const glm::dvec2 corner :
       {glm::dvec2(1, 1), glm::dvec2(-1, 1), glm::dvec2(-1, -1), glm::dvec2(1, -1)}) {
    folding.beginDragNear({0.1 * corner.x, 0.1 * corner.y, 0.0});
    folding.updateDrag({0.0, 0.0, 0.001 * ++k});
    ASSERT_TRUE(folding.commit()) << "corner " << k;
  }
  const TriangleMesh target = meshOf(folding.fixed());
  CreasePlaneOptions read;
  read.minDihedralDegrees = sharpEdgeThreshold(meshOf(initial));
  const std::vector<CreasePlane> planes = findCreasePlanes(target, read);
  for (const FoldRecord& fold : folding.folds())
    EXPECT_TRUE(std::any_of(
        planes.begin(), planes.end(),
        [&](const CreasePlane& c) {
          return std::abs(std::abs(glm::dot(c.plane.normal, fold.plane.normal)) - 1.0) < 1e-6 &&
                 std::abs(fold.plane.signedDistance(c.plane.point)) < 1e-6;
        }))
        << "fold " << (&fold - folding.folds().data()) + 1 << "'s plane was not read exactly";
}

// A tube of revolution about y (radius 5 cm, 18 cm tall), gridded.
TriangleMesh tube(double radius, double height, int around, int along) {
  TriangleMesh mesh;
  for (int j = 0; j <= along; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2.0 * 3.14159265358979 * i / around;
      mesh.positions.emplace_back(radius * std::sin(a), height * (double(j) / along - 0.5),
                                  radius * std::cos(a));
    }
  for (int j = 0; j < along; ++j)
    for (int i = 0; i < around; ++i) {
      const auto at = [&](int ii, int jj) {
        return static_cast<std::uint32_t>(jj * around + (ii % around));
      };
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

// Issue 38, 3: a scan (noise on every vertex: sharp edges everywhere) is taken for smooth by the
// cheap tests alone. It once went through the crease-plane search first (hundreds of plane
// hypotheses, each a pass over every sharp edge), twice before any deadline (the fitter, then the
// start's choice): on a 100k-triangle scan seconds of CPU, so `fit --time 5` took 16-24 s on a
// loaded machine. The claim is on work, against one pass over the edges, not on the clock.
TEST(StartSurface, ANoisyScanIsTakenForSmoothWithoutSearchingItsCreasePlanes) {
  // 25,600 triangles about 1.2 mm apart, each vertex 0.8 mm off (finer than bench's 100k scan,
  // twice its noise): most edges bend past the smooth threshold, 12 degrees.
  TriangleMesh scan = tube(0.03, 0.1, 160, 80);
  std::mt19937_64 random(38);
  std::normal_distribution<double> noise(0.0, 0.0008);
  for (glm::dvec3& p : scan.positions) {
    const double r = std::hypot(p.x, p.z), scale = (r + noise(random)) / r;
    p.x *= scale;
    p.z *= scale;
  }
  const int passes = 5;
  const double before = testing::processCpuSeconds();
  double largest = 0.0;
  for (int k = 0; k < passes; ++k) largest += largestDihedralDegrees(scan);
  const double onePass = (testing::processCpuSeconds() - before) / passes;
  ASSERT_GT(largest, 5.0 * passes);  // noisy: faces turn by degrees
  const double start = testing::processCpuSeconds();
  EXPECT_TRUE(isSmoothOrScanned(scan));
  const double cost = testing::processCpuSeconds() - start;
  std::printf("isSmoothOrScanned %.4f s of CPU, one pass over the edges %.4f s\n", cost, onePass);
  // Measured: 0.5 passes' worth; through the plane search first, 8.
  EXPECT_LT(cost, 3.0 * std::max(onePass, 1e-4))
      << cost << " s of CPU, one pass over the edges " << onePass << " s";
}

TEST(StartSurface, ATubeStartsFromACylinderOfItsSizeAndItsRingOfSymmetry) {
  const TriangleMesh target = tube(0.05, 0.18, 96, 30);
  const StartChoice start = chooseStart(target);
  EXPECT_EQ(start.surface, "cylinder");
  EXPECT_NEAR(start.parameters.at("radius"), 0.05, 0.002);
  EXPECT_NEAR(start.parameters.at("height"), 0.18, 0.002);
  EXPECT_LT(start.chamfer, 0.005 * boundingDiagonal(target));
  const Sheet sheet = makeSurface(start.surface, start.parameters);
  EXPECT_EQ(detectRotationalSymmetry(target, sheet), "rotational:12:y");
}

TEST(StartSurface, ANamedKindIsSizedAndAShapeWithoutATurnHasNoSymmetry) {
  const TriangleMesh target = tube(0.05, 0.18, 96, 30);
  // Sized to the target's area, or at its defaults where that starts closer.
  const StartChoice start = chooseStart(target, "square");
  EXPECT_EQ(start.surface, "square");
  if (!start.parameters.empty()) {
    EXPECT_NEAR(start.parameters.at("size"), std::sqrt(surfaceArea(target)), 1e-9);
  }
  const double defaults = surfaceDistance(meshOf(makeSurface("square")), target, 4000).chamfer;
  const double sized =
      surfaceDistance(meshOf(makeSurface("square", {{"size", std::sqrt(surfaceArea(target))}})),
                      target, 4000)
          .chamfer;
  EXPECT_DOUBLE_EQ(start.chamfer, std::min(defaults, sized));
  // A tube with one fold turns onto itself no more.
  const std::optional<testing::FoldTarget> folded =
      testing::makeFoldTarget(testing::foldTargetRecipes()[0], "cylinder", 1, 7932);
  ASSERT_TRUE(folded);
  EXPECT_EQ(detectRotationalSymmetry(folded->exported, folded->initial), "");
  // and, creased, was folded from the cylinder the catalogue makes: kept at its defaults.
  const StartChoice again = chooseStart(folded->exported, "cylinder");
  EXPECT_EQ(again.surface, "cylinder");
  EXPECT_TRUE(again.parameters.empty()) << again.parameters.size() << " " << again.chamfer;
}

// The start is the sheet the target was folded from: its parameters within 0.2%, as read.
void expectStartsFrom(const StartChoice& start, const SurfaceParameters& made) {
  EXPECT_TRUE(start.creased);
  EXPECT_FALSE(start.placed);
  for (const auto& [name, value] : made) {
    ASSERT_TRUE(start.parameters.count(name)) << name;
    EXPECT_NEAR(start.parameters.at(name), value, 2e-3 * value) << name;
  }
}

// Issue 38's recipe (bench/make_outer_third_targets.sh): a fold that turns most of the half
// cylinder about a corner leaves a crease of 1.7% of the diagonal, under the 3% a crease plane
// needs, and one whose plane misses the disk moves it whole, leaving none. Both read as smooth,
// and a sheet sized (radius 0.161, not 0.06) or placed on the target started nearer than the
// one they were folded from, which the unfolding cannot read back onto: `fit` ended 88.4% away.
// A cone of other parameters than the defaults, folded twice: `--from cone` alone (a target made
// at other parameters, the kind named) starts from the sheet the target unfolds to, not from the
// defaults, onto which no unfolding lies (folds keep the area; the defaults' is another).
TEST(StartSurface, ACreasedTargetOfAnotherAreaStartsFromTheSheetItUnfoldsTo) {
  const SurfaceParameters made{{"base_radius", 0.06}, {"height", 0.1}, {"angle", 300.0}};
  FoldSession folding(makeSurface("cone", made));
  for (const glm::dvec3& along : {glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1)}) {
    const std::vector<glm::dvec3>& at = meshOf(folding.fixed()).positions;
    const glm::dvec3 farthest =
        *std::max_element(at.begin(), at.end(), [&](const glm::dvec3& a, const glm::dvec3& b) {
          return glm::dot(a, along) < glm::dot(b, along);
        });
    folding.beginDragNear(farthest);
    folding.updateDrag(farthest - 0.04 * along + glm::dvec3(0.0, 0.03, 0.0));
    ASSERT_TRUE(folding.commit());
  }
  const StartChoice start = chooseStart(meshOf(folding.fixed()), "cone");
  expectStartsFrom(start, made);
}

// Folds `made` of `kind` once, its corner farthest along x dragged in and up, and moves the result
// whole by `turn` (radians about (1, 2, 3)) and `shift`: as folds whose planes missed the sheet
// move it, leaving no crease.
TriangleMesh foldedAndMovedWhole(const std::string& kind, const SurfaceParameters& made,
                                 double turn, const glm::dvec3& shift) {
  FoldSession folding(makeSurface(kind, made));
  const std::vector<glm::dvec3>& at = meshOf(folding.fixed()).positions;
  const glm::dvec3 farthest = *std::max_element(
      at.begin(), at.end(), [](const glm::dvec3& a, const glm::dvec3& b) { return a.x < b.x; });
  folding.beginDragNear(farthest);
  folding.updateDrag(farthest + glm::dvec3(-0.04, 0.03, 0.0));
  EXPECT_TRUE(folding.commit());
  TriangleMesh target = meshOf(folding.fixed());
  const glm::dvec3 axis = glm::normalize(glm::dvec3(1, 2, 3));
  const double c = std::cos(turn), s = std::sin(turn);
  for (glm::dvec3& p : target.positions)  // Rodrigues' turn
    p = c * p + s * glm::cross(axis, p) + (1.0 - c) * glm::dot(axis, p) * axis + shift;
  return target;
}

// The reading's polish measures sheets of one grid (the parameters it moves keep it): their
// boundary is found once per grid, not once per sheet measured (issue 38, 3: the start 2-6 times
// slower under ASan with it found per sheet); the sheets measured stay within the readings' bound.
TEST(StartSurface, TheUnfoldedSheetsPolishFindsItsGridsBoundaryOnce) {
  const SurfaceParameters made{{"base_radius", 0.06}, {"height", 0.1}, {"angle", 300.0}};
  UnfoldingWork work;
  const std::optional<SurfaceParameters> read = parametersFromUnfolding(
      foldedAndMovedWhole("cone", made, 0.0, glm::dvec3(0.0)), "cone", {}, &work);
  ASSERT_TRUE(read);
  for (const auto& [name, value] : made) {
    ASSERT_TRUE(read->count(name)) << name;
    EXPECT_NEAR(read->at(name), value, 2e-3 * value) << name;
  }
  EXPECT_GE(work.evaluations, 50u);
  EXPECT_LE(work.evaluations, 6000u);  // two readings at most, 3000 sheets each
  // A cone's grid follows its angle: a polish crossing steps of it finds each grid's anew.
  EXPECT_LE(20 * work.boundaries, work.evaluations) << work.boundaries << " boundaries";
}

// tangent-params-1-2-00-half_cylinder (make_tangent_targets.py, seed 15): a fold whose plane
// missed the sheet moved it whole, so the unfolding ends on a copy of the half cylinder turned and
// shifted, which no choice of sides puts back where the catalogue makes it: `--from
// half_cylinder` started from a sheet sized on the target, 14.6% away at the time limit. Its
// shape (the normals' plane, the circle across the axis, the arc's middle) puts it back.
TEST(StartSurface, AKindOfOtherParametersMovedWholeStartsFromTheSheetItUnfoldsTo) {
  const SurfaceParameters made{{"radius", 0.075}, {"height", 0.23}};
  const StartChoice start = chooseStart(
      foldedAndMovedWhole("half_cylinder", made, 0.7, {0.05, -0.03, 0.08}), "half_cylinder");
  expectStartsFrom(start, made);
}

// tangent-params-1-2-00-cylinder: a 210-degree tube of radius 0.031 (the defaults': 0.06, whole)
// bends its facets more than the defaults' threshold allows (13.3 degrees), so every facet read
// as crease and nothing unfolded (`--from cylinder` ended 9.85% away). The target's own bends
// set the threshold.
TEST(StartSurface, ATubeOfOtherFacetsStartsFromTheSheetItUnfoldsTo) {
  const SurfaceParameters made{{"radius", 0.031}, {"height", 0.25}, {"angle", 210.0}};
  const StartChoice start =
      chooseStart(foldedAndMovedWhole("cylinder", made, 0.0, glm::dvec3(0.0)), "cylinder");
  expectStartsFrom(start, made);
}

// tangent-params-1-2-00-helix_tangent (make_tangent_targets.py, seed 15): a fold whose plane
// missed the sheet moved a helix of other parameters whole, and no frame put a helix back where
// the catalogue makes it: `--from helix_tangent` started from the defaults, 9.92% away at `--time
// 60` (and the 3-4 and 5-8 helices, 103% and 111%). Its normals' cone names the axis and the
// rise, the principal normals the axis's place and the radius; a reflection's mirror image too.
TEST(StartSurface, AHelixOfOtherParametersMovedWholeStartsFromTheSheetItUnfoldsTo) {
  const SurfaceParameters made{{"radius", 0.033}, {"pitch", 0.105}, {"turns", 0.6}};
  const TriangleMesh turned = foldedAndMovedWhole("helix_tangent", made, 0.7, {0.05, -0.03, 0.08});
  expectStartsFrom(chooseStart(turned, "helix_tangent"), made);
  TriangleMesh mirrored = turned;
  for (glm::dvec3& p : mirrored.positions) p.x = 0.02 - p.x;
  for (auto& t : mirrored.triangles) std::swap(t[1], t[2]);
  expectStartsFrom(chooseStart(mirrored, "helix_tangent"), made);
}

// Seed-19 tangent-params-3-4-00-helix_tangent (tests/data/reach): its ruling width was read 1%
// short (0.07922 for 0.08), a sheet one grid row short of the unfolded target, whose far row (34
// vertices a ruling, every 4th taken in index order) no point of the target's spread met: both
// measures read 0 there, and the fit ended 70.1% away. The target's rim is measured too.
TEST(StartSurface, AHelixReadShortIsSeenAtTheUnfoldedTargetsRim) {
  const ReachTarget t = reachTarget("tangent_params_helix_tangent_3");
  const std::optional<SurfaceParameters> read = parametersFromUnfolding(t.target, "helix_tangent");
  ASSERT_TRUE(read);
  SurfaceParameters made = std::get<GeneratedSurface>(t.design.surface).parameters;
  made.emplace("ruling_start", 0.02);  // the defaults
  made.emplace("ruling_width", 0.08);
  for (const auto& [name, value] : made) {
    const double got = read->count(name) ? read->at(name) : (name == "ruling_start" ? 0.02 : 0.08);
    EXPECT_NEAR(got, value, 1e-4 * value) << name;
  }
}

// The reading's coarse measure takes every 4th point of a sheet's rim: in index order a grid's
// rim alternates its near and far row, so every 4th met one row only (a helix's far rim, a row
// wider than the unfolded target's, measured 0: its width read 1.2% wide, judge20). Along the rim
// each offset meets every side.
TEST(BoundaryEdges, EveryFourthVertexAlongARimMeetsEachSideOfTheGrid) {
  const TriangleMesh sheet = meshOf(makeSurface("helix_tangent", {{"radius", 0.0390782},
                                                                  {"pitch", 0.121837},
                                                                  {"turns", 0.946481},
                                                                  {"ruling_width", 0.1155286}}));
  constexpr std::size_t kRulings = 65, kRows = 30;  // grid vertex i * kRows + j
  ASSERT_EQ(sheet.positions.size(), kRulings * kRows);
  const std::vector<std::uint32_t> rim = boundaryVerticesAlong(sheet);
  EXPECT_EQ(rim.size(), 2 * (kRulings + kRows) - 4);
  for (std::size_t offset = 0; offset < 4; ++offset) {
    bool near = false, far = false, first = false, last = false;
    for (std::size_t k = offset; k < rim.size(); k += 4) {
      near = near || rim[k] % kRows == 0;
      far = far || rim[k] % kRows == kRows - 1;
      first = first || rim[k] / kRows == 0;
      last = last || rim[k] / kRows == kRulings - 1;
    }
    EXPECT_TRUE(near && far && first && last) << "offset " << offset;
  }
}

// tangent-params-5-8-00-cone and -swept_curve: folds whose planes missed the sheet moved a
// whole cone, and a swept sine, of other parameters, and nothing put them back where the catalogue
// makes them (`--from cone`: 40.9%, `--from swept_curve`: 77.5% at `--time 60`). A cone's apex is
// where its faces' planes meet, its axis its normals' cone's; a swept sine's rulings lie across
// its normals, its curve leans off its principal axis by what the sine's best fit says.
TEST(StartSurface, AConeOrASweptCurveOfOtherParametersMovedWholeStartsFromTheSheetItUnfoldsTo) {
  const SurfaceParameters cone{{"base_radius", 0.1}, {"height", 0.075}};
  expectStartsFrom(chooseStart(foldedAndMovedWhole("cone", cone, 0.7, {0.05, -0.03, 0.08}), "cone"),
                   cone);
  const SurfaceParameters swept{{"amplitude", 0.01}, {"wavelength", 0.17}};
  expectStartsFrom(chooseStart(foldedAndMovedWhole("swept_curve", swept, 0.7, {0.05, -0.03, 0.08}),
                               "swept_curve"),
                   swept);
}

// crossing-params-1-2-00-cone (make_crossing_targets.py, seed 19): a full cone of other
// parameters creased once and moved whole, its apex then on the far side of the origin along its
// axis. The frame's apex was told from the base by a sum of area-weighed centroids taken for their
// mean (a point near the origin, wherever the sheet lay), so the cone was read upside down and no
// sheet lay on it: `--from cone` started from the defaults and ended 22.5% away.
TEST(StartSurface, AConeMovedWholeFarFromTheOriginReadsItsApexAbove) {
  const SurfaceParameters made{{"base_radius", 0.1045}, {"height", 0.0842}};  // angle 360
  const std::optional<SurfaceParameters> read =
      parametersFromUnfolding(foldedAndMovedWhole("cone", made, 0.7, {0.1, -0.6, 0.2}), "cone");
  ASSERT_TRUE(read);
  for (const auto& [name, value] : made) {
    ASSERT_TRUE(read->count(name)) << name;
    EXPECT_NEAR(read->at(name), value, 2e-3 * value) << name;
  }
  if (read->count("angle")) {
    EXPECT_NEAR(read->at("angle"), 360.0, 0.5);
  }
}

// tangent-params-3-4-00-star (make_tangent_targets.py, seed 15; its three folds): a 7-point star
// creased once, then moved whole twice (planes that missed it). The frame turned onto its first
// point lies on the unfolded copy exactly, but measured at the defaults' 5 points and radii scaled
// by the area it lay farther than the frame turned by the principal axis (a star's is any), whose
// polish ended 0.27% of the diagonal off: `--from star` started from the defaults, 36.9% away. The
// points' count and radii are read off the shape first.
TEST(StartSurface, AStarOfOtherPointsMovedWholeStartsFromTheSheetItUnfoldsTo) {
  const SurfaceParameters made{{"points", 7.0},
                               {"outer_radius", 0.09884354781292355},
                               {"inner_radius", 0.052015951886228616}};
  std::vector<FoldRecord> folds(3);
  folds[0].seed = {0.0754284361, 0.0581414368};
  folds[0].plane = {{0.08359355096504403, 0.017191825242014954, 0.00946846325},
                    {0.19070337096855883, -0.9564138556242826, 0.22114420876686364}};
  folds[1].seed = {0.06817850496604175, 0.05917223192497795};
  folds[1].plane = {{0.10474202430334893, 0.006084887428761546, 0.01639977018519419},
                    {0.4993955745426573, 0.8614099568174572, -0.09261180498703046}};
  folds[2].seed = {0.02869134658956938, 0.004055324565259008};
  folds[2].plane = {{0.0207738437618391, 0.01988398970364085, -0.03608542142337006},
                    {-0.6233489943454277, -0.6763515355072013, -0.3924087558472606}};
  FoldSession folding(makeSurface("star", made));
  folding.applyRecords(folds);
  expectStartsFrom(chooseStart(meshOf(folding.fixed()), "star"), made);
}

// tangent-params-3-4-00-swept_curve (make_tangent_targets.py, seed 15; its three folds): a sine
// of amplitude 0.026 and wavelength 0.127 bends its facets by up to 19.2 degrees, more than nine
// tenths of its edges (9.3) and than the defaults' (a threshold of 26.6 reads its creases, but
// the defaults' facets bend less: 1.2 m of its own bends were left as crease; the target's own
// threshold of 15.9 read its facets as creases). `--from swept_curve` started from the defaults,
// 11.6% away. Its creases bend by 77.5 degrees and more: the gap between parts them.
TEST(StartSurface, ASweptCurveWhoseFacetsBendAsMuchAsACreaseStartsFromTheSheetItUnfoldsTo) {
  const SurfaceParameters made{{"amplitude", 0.025786187231774},
                               {"wavelength", 0.12664931558204076}};
  std::vector<FoldRecord> folds(3);
  folds[0].seed = {-0.01916571151236993, 0.0701925139};
  folds[0].plane = {{0.01164351236393005, 0.032312734520000004, 0.025993616036697885},
                    {0.395369121333999, -0.6258573810039787, 0.6722988892884045}};
  folds[1].seed = {-0.058447648415007505, 0.09999999967207115};
  folds[1].plane = {{0.033292494930235825, -0.024730326310061057, 0.13194237815024584},
                    {0.16868583801135517, -0.21383010095699836, 0.9621963292276305}};
  folds[2].seed = {-0.0007328137582164286, -0.1};
  folds[2].plane = {{0.042580942865611635, -0.145622274330513, 0.23055727505877305},
                    {0.4350319109652398, 0.5503296524518875, 0.7126601645062789}};
  FoldSession folding(makeSurface("swept_curve", made));
  folding.applyRecords(folds);
  expectStartsFrom(chooseStart(meshOf(folding.fixed()), "swept_curve"), made);
}

// tangent-params-1-2-00-swept_curve (make_tangent_targets.py, seed 19; its one fold): a sine
// steeper than the defaults' at their resolution bends its facets by up to 26.5 degrees, under the
// defaults' threshold (26.6) but over their facets' 16.4, and its curved crease bends by 32 to 176
// along its length (no gap parts them from the facets: a ratio of 1.2). The first reading saw the
// crease and unfolded it, but counted the facets as 2.4 m of crease left; the target's own
// threshold read facets as creases: `--from swept_curve` started from the defaults, 4.91% away.
TEST(StartSurface, ASweptCurveWhoseFacetsBendUnderTheThresholdButMoreThanTheDefaultsIsRead) {
  const SurfaceParameters made{{"amplitude", 0.016393522164296303},
                               {"wavelength", 0.08477901237237805}};
  FoldRecord fold;
  fold.seed = {0.12207820340211872, 0.06663515350000002};
  fold.plane = {{0.08213509964487392, 0.07146796845, -0.0047430210846902575},
                {-0.5861528578474959, 0.2702810891123646, -0.7637885571972437}};
  FoldSession folding(makeSurface("swept_curve", made));
  folding.applyRecords({fold});
  const std::optional<SurfaceParameters> read =
      parametersFromUnfolding(meshOf(folding.fixed()), "swept_curve");
  ASSERT_TRUE(read);
  for (const auto& [name, value] : made) {
    ASSERT_TRUE(read->count(name)) << name;
    EXPECT_NEAR(read->at(name), value, 2e-3 * value) << name;
  }
}

TEST(StartSurface, AFoldedSheetWithShortOrNoCreasesStartsFromItsKindsDefaults) {
  FoldRecord fold;
  fold.seed = {-0.0021913213800000032, -0.07875};
  fold.plane = {{0.02885831870827024, -0.0908670455, 0.07829668305110718},
                {0.8162094215265654, -0.3185237145727927, 0.48202160062181804}};
  fold.grabbed = {-0.002191321383459527, -0.07875, 0.05995997090221436};
  fold.target = {0.0599079588, -0.102984091, 0.0966333952};
  FoldSession corner(makeSurface("half_cylinder"));
  corner.applyRecords({fold});
  const StartChoice turned = chooseStart(meshOf(corner.fixed()), "half_cylinder");
  EXPECT_TRUE(turned.parameters.empty()) << turned.parameters.size() << " " << turned.chamfer;
  EXPECT_FALSE(turned.placed);
  TriangleMesh moved = meshOf(makeSurface("disk"));
  for (glm::dvec3& p : moved.positions)
    p = glm::dvec3(0.6 * p.x - 0.8 * p.z + 0.03, p.y - 0.02, 0.8 * p.x + 0.6 * p.z + 0.05);
  const StartChoice whole = chooseStart(moved, "disk");
  EXPECT_TRUE(whole.parameters.empty()) << whole.parameters.size() << " " << whole.chamfer;
  EXPECT_FALSE(whole.placed) << whole.placement;
}

}  // namespace
}  // namespace curvefold

namespace curvefold {
namespace {

TEST(FarthestPoints, AreWhereASheetLeavesARampMost) {
  const TriangleMesh flat = meshOf(makeSurface("square"));
  TriangleMesh ramp = flat;
  for (glm::dvec3& p : ramp.positions) p.z += 0.05 * std::max(0.0, p.x);
  const FarthestPoints far = farthestPoints(flat, ramp, 20'000);
  // The flat sheet's far edge (x = 0.1) lies 0.005 / sqrt(1.0025) below the ramp's plane.
  EXPECT_GT(far.onA.x, 0.098);
  EXPECT_NEAR(far.fromA, 0.005 / std::sqrt(1.0025), 1e-4);
  EXPECT_GT(far.onB.x, 0.098);
  EXPECT_NEAR(far.fromB, 0.005, 1e-4);
}

}  // namespace
}  // namespace curvefold

namespace curvefold {
namespace {

// `mesh` turned by `degrees` about `axis` and moved by `shift`.
TriangleMesh moved(TriangleMesh mesh, glm::dvec3 axis, double degrees, glm::dvec3 shift) {
  axis = glm::normalize(axis);
  const double a = degrees * 3.14159265358979 / 180.0;
  for (glm::dvec3& p : mesh.positions)  // Rodrigues' rotation
    p = p * std::cos(a) + glm::cross(axis, p) * std::sin(a) +
        axis * glm::dot(axis, p) * (1.0 - std::cos(a)) + shift;
  return mesh;
}

// A gridded z = f(x, y) over a square of side `size` about the origin.
template <typename F>
TriangleMesh heightField(double size, int cells, F f) {
  TriangleMesh mesh;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      const double x = size * (double(i) / cells - 0.5), y = size * (double(j) / cells - 0.5);
      mesh.positions.emplace_back(x, y, f(x, y));
    }
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const auto at = [&](int ii, int jj) { return std::uint32_t(jj * (cells + 1) + ii); };
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

TEST(StartSurface, ATiltedTubeStartsFromACylinderPlacedOnItsAxis) {
  const TriangleMesh target =
      moved(tube(0.05, 0.18, 96, 30), {1.0, 0.3, 0.5}, 65.0, {0.02, -0.01, 0.03});
  const StartChoice start = chooseStart(target);
  ASSERT_TRUE(start.placed);
  EXPECT_EQ(start.surface, "cylinder");
  EXPECT_NEAR(start.parameters.at("radius"), 0.05, 0.002);
  EXPECT_LT(start.chamfer, 0.005 * boundingDiagonal(target));
  validate(*start.placed);  // moved rigidly: still isometric to its development
  // The same from a named kind.
  const StartChoice named = chooseStart(target, "cylinder");
  ASSERT_TRUE(named.placed);
  EXPECT_LT(named.chamfer, 0.005 * boundingDiagonal(target));
}

// A symmetry asked for (issue 38): a cylinder placed on a tilted tube's axis has none of the
// catalogue's mirrors, so the start is one in the catalogue's frame that has it.
TEST(StartSurface, ASymmetryAskedForIsKeptByTheStart) {
  const TriangleMesh target =
      moved(tube(0.05, 0.18, 96, 30), {1.0, 0.3, 0.5}, 65.0, {0.02, -0.01, 0.03});
  ASSERT_TRUE(chooseStart(target, "cylinder").placed);
  const StartChoice start = chooseStart(target, "cylinder", "mirror:y");
  EXPECT_FALSE(start.placed);
  EXPECT_EQ(parseSymmetry("mirror:y", makeSurface(start.surface, start.parameters)).name(),
            "mirror:y");
  EXPECT_THROW(chooseStart(target, "cylinder", "mirror:q"), InvalidSymmetry);
}

// The choice of the start keeps to its deadline (issue 38, 3: --time bounds the whole fit): past
// it, only the first of the catalogue's sheets and the first sheet placed on a smooth target are
// measured, and the choice says it was cut short. The placed one is measured however short the
// clock: the catalogue's sheets lie in its own frame (the old choice kept the square of the
// tube's area about the origin, Chamfer 45 mm, 15% of the diagonal; the placed tube 16 mm).
TEST(StartSurface, TheChoiceStopsMeasuringAtItsDeadlineButStillPlacesASheetOnTheTarget) {
  const TriangleMesh target =
      moved(tube(0.05, 0.18, 96, 30), {1.0, 0.3, 0.5}, 65.0, {0.02, -0.01, 0.03});
  const StartChoice cut = chooseStart(target, "", "", Deadline::in(0.0));
  EXPECT_TRUE(cut.cutShort);
  EXPECT_TRUE(cut.placed) << "no sheet placed on the target was measured";
  const double diagonal = surfaceDistance(target, target, 100).diagonal;
  EXPECT_LT(cut.chamfer, 0.1 * diagonal) << cut.surface;
  const StartChoice whole = chooseStart(target, "");
  EXPECT_FALSE(whole.cutShort);
  EXPECT_TRUE(whole.placed);
}

TEST(StartSurface, ASaddleStartsFromASweptParabolaNearerThanAFlatSheet) {
  // Turned off the catalogue's axes: the swept parabola follows the strongest curvature.
  const TriangleMesh target =
      moved(heightField(0.2, 40, [](double x, double y) { return (x * x - 0.5 * y * y) / 0.2; }),
            {0.2, 0.1, 1.0}, 40.0, {0.0, 0.01, 0.0});
  const StartChoice start = chooseStart(target);
  ASSERT_TRUE(start.placed);
  EXPECT_EQ(start.surface, "swept_curve");
  EXPECT_NEAR(std::abs(start.parameters.at("curvature")), 5.0, 0.5);
  const StartChoice flat = chooseStart(target, "square");
  EXPECT_LT(start.chamfer, 0.7 * flat.chamfer) << start.chamfer << " " << flat.chamfer;
  validate(*start.placed);
}

TEST(StartSurface, ABowlStartsFromAConeThatReachesItsBottomAndRim) {
  // A paraboloid bowl, 16 cm across and 4 cm deep, a small hole at its bottom, tilted.
  TriangleMesh bowl;
  const int around = 64, out = 20;
  for (int j = 0; j <= out; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2.0 * 3.14159265358979 * i / around, r = 0.004 + 0.076 * j / out;
      bowl.positions.emplace_back(r * std::cos(a), r * std::sin(a), r * r / 0.16);
    }
  for (int j = 0; j < out; ++j)
    for (int i = 0; i < around; ++i) {
      const auto at = [&](int ii, int jj) { return std::uint32_t(jj * around + ii % around); };
      bowl.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      bowl.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  const TriangleMesh target = moved(bowl, {1.0, 0.5, 0.0}, 30.0, {0.0, 0.0, 0.01});
  // The cone asked for: without a kind the disk its nested rings fold starts such a bowl
  // (start_surface.hpp; StartSurface.AFootedBowlStartsFromTheDiskItsRingsFoldNotTheNearerCone).
  const StartChoice start = chooseStart(target, "cone");
  ASSERT_TRUE(start.placed);
  EXPECT_EQ(start.surface, "cone");
  // The least-squares radius line stops 2 cm short of the bottom (Hausdorff 8%); the line across
  // the profile reaches it.
  const SurfaceDistance distance = surfaceDistance(meshOf(*start.placed), target, 4000);
  EXPECT_LT(distance.chamfer, 0.01 * distance.diagonal);
  EXPECT_LT(distance.hausdorff, 0.06 * distance.diagonal);
  EXPECT_LT(start.parameters.at("top_radius"), 0.015);
}

// Without a kind asked for, a bowl with a flat foot (a footed dish 20 cm across, its wall a
// sphere's arc 60 degrees at the rim, tilted): the placed cone is nearest at once (1.3% of the
// diagonal, Chamfer) but folds little closer (1.0% with 16 folds), while the disk's nested rings
// fold it to 0.32% (docs/performance.md, bowl8). The start is the disk, and it says why.
TEST(StartSurface, AFootedBowlStartsFromTheDiskItsRingsFoldNotTheNearerCone) {
  const auto height = [](double r) {
    const double foot = 0.035, sphere = 0.075, d = std::max(0.0, r - foot);
    return sphere - std::sqrt(sphere * sphere - d * d);
  };
  TriangleMesh bowl;
  const int around = 64, out = 20;
  bowl.positions.emplace_back(0.0, 0.0, 0.0);
  for (int j = 1; j <= out; ++j)
    for (int i = 0; i < around; ++i) {
      const double a = 2.0 * std::numbers::pi * i / around, r = 0.1 * j / out;
      bowl.positions.emplace_back(r * std::cos(a), r * std::sin(a), height(r));
    }
  const auto at = [&](int i, int j) {
    return j == 0 ? 0u : static_cast<std::uint32_t>(1 + (j - 1) * around + i % around);
  };
  for (int i = 0; i < around; ++i) bowl.triangles.push_back({at(i, 0), at(i, 1), at(i + 1, 1)});
  for (int j = 1; j < out; ++j)
    for (int i = 0; i < around; ++i) {
      bowl.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      bowl.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  const TriangleMesh target = moved(bowl, {1.0, 0.4, 0.0}, 25.0, {0.3, -0.1, 0.05});
  const StartChoice start = chooseStart(target);
  ASSERT_TRUE(start.placed);
  EXPECT_EQ(start.surface, "disk") << start.placement;
  // The cone was nearer as it lies (named in the line, with its distance): the disk was chosen
  // for what its rings reach.
  EXPECT_NE(start.placement.find("nested rings"), std::string::npos) << start.placement;
  EXPECT_NE(start.placement.find("the nearest sheet (cone)"), std::string::npos) << start.placement;
  validate(*start.placed);
  // Its rings' profile within 0.13 of the cone's (1.09 mm, 8.16 mm), far from the rule's threshold:
  // none folded beside it (a bowl's fit keeps its whole budget).
  EXPECT_TRUE(start.runnersUp.empty()) << start.runnersUp.front().why;
}

// A steep cup (make_footed_bowls.py's steep_tumbler: 8 cm across, 7 cm deep, slightly flared) on
// a polar grid of 20 rings of 40. The rule takes the disk (its nested rings' profile 5.4 mm against
// the placed cone's 7.74 mm, Chamfer + Hausdorff / 4: 0.70, under its 0.75), but close: the cone
// is its runner-up, which `fit` folds too (the cone's fit ended nearer by both measures,
// docs/performance.md, portfolio24). The footed bowl's disk (above) is clear of the cone: none.
TEST(StartSurface, ASteepCupsDiskHasTheConeItPassedOverAsARunnerUp) {
  const double table[][2] = {
      {0.0, 0.0}, {0.025, 0.002}, {0.033, 0.02}, {0.036, 0.045}, {0.04, 0.07}};
  const auto profile = [&](double u) {  // eased between the table's points
    const double at = u * 4.0;
    const int i = std::min(static_cast<int>(at), 3);
    const double f = 0.5 - 0.5 * std::cos(std::numbers::pi * (at - i));
    return glm::dvec2(table[i][0] + f * (table[i + 1][0] - table[i][0]),
                      table[i][1] + f * (table[i + 1][1] - table[i][1]));
  };
  TriangleMesh cup;
  const int around = 40, rings = 20;
  cup.positions.emplace_back(0.0, 0.0, 0.0);
  for (int j = 1; j <= rings; ++j)
    for (int i = 0; i < around; ++i) {
      const glm::dvec2 rz = profile(static_cast<double>(j) / rings);
      const double a = 2.0 * std::numbers::pi * (i + 0.5 * (j % 2)) / around;
      cup.positions.emplace_back(rz.x * std::cos(a), rz.x * std::sin(a), rz.y);
    }
  const auto at = [&](int i, int j) {
    return j == 0 ? 0u : static_cast<std::uint32_t>(1 + (j - 1) * around + i % around);
  };
  for (int i = 0; i < around; ++i) cup.triangles.push_back({at(i, 0), at(i, 1), at(i + 1, 1)});
  for (int j = 1; j < rings; ++j)
    for (int i = 0; i < around; ++i) {
      cup.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      cup.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  const StartChoice start = chooseStart(cup);
  ASSERT_TRUE(start.placed);
  EXPECT_EQ(start.surface, "disk") << start.placement;
  ASSERT_EQ(start.runnersUp.size(), 1u);
  const RunnerUpStart& cone = start.runnersUp.front();
  EXPECT_EQ(cone.surface, "cone");
  ASSERT_TRUE(cone.placed);
  validate(*cone.placed);
  // Placed on the cup: near it at once (the floor's centre its farthest point).
  const SurfaceDistance distance = surfaceDistance(meshOf(*cone.placed), cup, 4000);
  EXPECT_LT(distance.chamfer, 0.03 * distance.diagonal);
  // Its line names both numbers of the model.
  EXPECT_NE(cone.why.find("nested rings' profile"), std::string::npos) << cone.why;
}

TEST(StartSurface, ASaddleOverADiskStartsFromAParabolaCutToItsOutline) {
  TriangleMesh target =
      heightField(0.2, 40, [](double x, double y) { return 0.5 * (x * x / 0.08 - y * y / 0.12); });
  // Only the triangles within 9 cm of the middle: a round outline.
  std::vector<std::array<std::uint32_t, 3>> inside;
  for (const auto& t : target.triangles) {
    const glm::dvec3 c =
        (target.positions[t[0]] + target.positions[t[1]] + target.positions[t[2]]) / 3.0;
    if (std::hypot(c.x, c.y) < 0.09) inside.push_back(t);
  }
  target.triangles.assign(inside.begin(), inside.end());
  const StartChoice start = chooseStart(target);
  ASSERT_TRUE(start.placed);
  EXPECT_EQ(start.surface, "swept_curve");
  EXPECT_NE(start.placement.find("cut to the target's outline"), std::string::npos)
      << start.placement;
  validate(*start.placed);
  // The rectangle's corners stood 14% of the diagonal out past the round outline.
  const SurfaceDistance distance = surfaceDistance(meshOf(*start.placed), target, 4000);
  EXPECT_LT(distance.hausdorff, 0.15 * distance.diagonal);
}

TEST(StartSurface, TheSweptParabolaIsDevelopedExactly) {
  const Sheet sheet = sweptParabola(6.0, 0.3, -0.1, 0.12, 0.15, 40);
  validate(sheet);
  // Its profile lies on w = 6 s^2 + 0.3 s.
  for (const glm::dvec3& p : sheet.positions) EXPECT_NEAR(p.z, 6.0 * p.x * p.x + 0.3 * p.x, 1e-12);
  EXPECT_NEAR(developmentBounds(sheet).high.y - developmentBounds(sheet).low.y, 0.15, 1e-12);
}

}  // namespace
}  // namespace curvefold
