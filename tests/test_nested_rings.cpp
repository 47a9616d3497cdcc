// Nested rings fitted to a bowl's profile, from a flat disk (issue 38, 2;
// engine/fit/nested_rings.hpp).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/fit/farthest_points.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/nested_rings.hpp"
#include "engine/fit/profile_folds.hpp"
#include "engine/fit/start_surface.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/fit/work_share.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/triangle_mesh.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "tests/cpu_time.hpp"
#include "tests/fit_settings_support.hpp"
#include "tests/sanitizer_support.hpp"

namespace curvefold {
namespace {

// A cap of revolution about z given as height(r) for r over (0, outer], a fan at the centre.
template <typename Height>
TriangleMesh capOf(Height height, double outer, int around, int rings) {
  TriangleMesh mesh;
  mesh.positions.emplace_back(0.0, 0.0, height(0.0));
  for (int j = 1; j <= rings; ++j)
    for (int i = 0; i < around; ++i) {
      const double r = outer * j / rings, a = 2.0 * std::numbers::pi * i / around;
      mesh.positions.emplace_back(r * std::cos(a), r * std::sin(a), height(r));
    }
  const auto at = [&](int i, int j) {
    return j == 0 ? 0u : static_cast<std::uint32_t>(1 + (j - 1) * around + (i % around));
  };
  for (int i = 0; i < around; ++i) mesh.triangles.push_back({at(i, 0), at(i, 1), at(i + 1, 1)});
  for (int j = 1; j < rings; ++j)
    for (int i = 0; i < around; ++i) {
      mesh.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  return mesh;
}

// A step of nested rings toward `target` from `disk` as the fit makes it: a fitter of 800 / 800 /
// 8000 samples, 1500 target samples, seed 5.
struct RingStep {
  RingStep(const TriangleMesh& target, const Sheet& disk)
      : fitter(target, testing::sampledSettings(800, 800, 8000)),
        samples(sampleSurface(target, 1500, 3)),
        axis(revolutionAxis(samples)),
        session(disk) {}
  // One step of rings of 1 to `mostCreases` creases from the session as it is; `before` is the
  // session's approximate distance.
  std::vector<FoldSuggestion> step(std::size_t mostCreases) {
    before = fitter.approximateDistance(session.fixed());
    std::mt19937_64 random(5);
    return suggestNestedRings(session, fitter, *axis, samples, 1, {}, random, mostCreases);
  }
  // The one suggestion such a step makes, checked to be a valid sheet that does not cross itself;
  // none (and a failure) when it made none or several.
  std::optional<FoldSuggestion> validStep(std::size_t mostCreases) {
    std::vector<FoldSuggestion> steps = step(mostCreases);
    EXPECT_EQ(steps.size(), 1u);
    if (steps.size() != 1u) return std::nullopt;
    validate(steps.front().sheet);
    EXPECT_TRUE(findSelfIntersections(steps.front().sheet).intersections.empty());
    return std::move(steps.front());
  }
  FoldFitter fitter;
  std::vector<SurfaceSample> samples;
  std::optional<RevolutionAxis> axis;
  FoldSession session;
  double before = 0.0;
};

// The profile (r, z) of a paraboloid bowl 16 cm across and 4 cm deep, its bottom at z = -0.02.
std::vector<glm::dvec2> paraboloidProfile() {
  std::vector<glm::dvec2> profile;
  for (int i = 0; i < 300; ++i) {
    const double r = 0.08 * i / 299.0;
    profile.push_back({r, r * r / 0.16 - 0.02});
  }
  return profile;
}

TEST(NestedRings, ProfileCreasesFollowAParaboloidCloserWithEachCrease) {
  const std::vector<glm::dvec2> profile = paraboloidProfile();
  const double radius = 0.088;  // a disk of about the bowl's area
  std::mt19937_64 random(5);
  // The flat sheet at its best height, and the fits with one and three creases.
  // (Their mean distances: the fit also weighs the farthest point.)
  const double flatMean = fitProfileCreases(profile, radius, 0, nullptr, random).mean;
  const ProfileCreases one = fitProfileCreases(profile, radius, 1, nullptr, random);
  const ProfileCreases three = fitProfileCreases(profile, radius, 3, &one, random);
  ASSERT_EQ(three.arcs.size(), 3u);
  EXPECT_LT(one.mean, 0.6 * flatMean);
  EXPECT_LT(three.mean, 0.5 * one.mean);
  EXPECT_LT(three.mean, 0.004 * 0.18);  // under 0.4% of the bowl's size
  // The polyline keeps the sheet's length (the meridian of a flat disk folded isometrically), and
  // the bowl opens upward: the rim above the centre.
  const std::vector<glm::dvec2> polyline = profilePolyline(three, radius);
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i)
    length += glm::length(polyline[i + 1] - polyline[i]);
  EXPECT_NEAR(length, radius, 1e-12);
  EXPECT_GT(polyline.back().y, polyline.front().y + 0.02);
}

// A deep cap (a sphere of radius 5 cm to 75 degrees, as the judge-style bowls), its profile
// points spread by area, and a sheet of its area: the disk's radius is the chord from the
// bottom to the rim, shorter than the meridian, so the polyline cannot follow the whole wall and
// also reach the rim. By the mean distance alone the fit follows the wall and leaves the rim
// farther off; the profile's farthest point counts too (nested_rings.hpp, kProfileFarthest).
TEST(NestedRings, ADeepCapsProfileFitReachesTowardItsRim) {
  const double sphere = 0.05, deepest = 75.0 * std::numbers::pi / 180.0;
  std::vector<glm::dvec2> profile;
  for (int i = 0; i < 300; ++i) {
    const double u = (i + 0.5) / 300.0, theta = std::acos(1.0 - u * (1.0 - std::cos(deepest)));
    profile.push_back({sphere * std::sin(theta), sphere * (1.0 - std::cos(theta))});
  }
  const double radius = 2.0 * sphere * std::sin(0.5 * deepest);  // the disk of the cap's area
  std::mt19937_64 random(5);
  const ProfileCreases one = fitProfileCreases(profile, radius, 1, nullptr, random);
  const ProfileCreases two = fitProfileCreases(profile, radius, 2, &one, random);
  const std::vector<glm::dvec2> polyline = profilePolyline(two, radius);
  double farthest = 0.0;
  for (const glm::dvec2& p : profile) {
    double nearest = 1e300;
    for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
      const glm::dvec2 ab = polyline[i + 1] - polyline[i];
      const double t = std::clamp(glm::dot(p - polyline[i], ab) / glm::dot(ab, ab), 0.0, 1.0);
      nearest = std::min(nearest, glm::length(p - (polyline[i] + t * ab)));
    }
    farthest = std::max(farthest, nearest);
  }
  // 4.31 mm; 5.23 mm by the mean alone (its rim left 0.7 mm farther than its wall's worst).
  EXPECT_LT(farthest, 0.0048) << "score " << two.score;
}

// Drawn outermost first, each ring on the flat sheet, the rings fold the sheet's centre line into
// the same polyline as inner first: each crease's turn flipped once for each ring inside it (a
// reflection reverses a turn), a lip turning back down included.
TEST(NestedRings, RingsDrawnOutermostFirstOnTheFlatSheetMakeTheSameProfile) {
  ProfileCreases creases;
  creases.shift = -0.01;
  creases.arcs = {0.015, 0.03, 0.045, 0.055};
  creases.angles = {0.3, 0.7, 1.0, 0.9};  // the last turns back a little: a lip
  const double radius = 0.065;
  const std::vector<glm::dvec2> polyline = profilePolyline(creases, radius);
  const std::vector<NestedRing> rings = nestedRingShapes(creases, 12, 0.0, radius, true);
  ASSERT_EQ(rings.size(), 5u);  // the plane across, then four rings
  // The centre line: points at distance s from the centre, flat at height 0, each fold reflecting
  // the points beyond its crease (the flap it takes), in the rings' order.
  std::vector<double> arcs;
  std::vector<glm::dvec2> line;
  for (int i = 0; i <= 130; ++i) {
    arcs.push_back(radius * i / 130.0);
    line.push_back({arcs.back(), 0.0});
  }
  for (const NestedRing& ring : rings) {
    const glm::dvec2 normal(std::cos(ring.shape.tilt), std::sin(ring.shape.tilt));
    const glm::dvec2 at = ring.shape.order == 1 ? glm::dvec2(0.0, ring.shape.height)
                                                : glm::dvec2(ring.shape.radius, ring.shape.height);
    for (std::size_t i = 0; i < line.size(); ++i) {
      const double side = glm::dot(
          ring.shape.order == 1 ? glm::dvec2(0.0, normal.y > 0 ? 1 : -1) : normal, line[i] - at);
      if (ring.shape.order == 1) {
        line[i].y = 2.0 * at.y - line[i].y;  // the plane across moves the whole sheet
      } else if (arcs[i] > ring.shape.radius + 1e-12 && side > -1e-9) {
        line[i] -= 2.0 * side * normal;
      }
    }
  }
  // Each point lies on the polyline at its distance along it.
  for (std::size_t i = 0; i < line.size(); ++i) {
    double s = arcs[i];
    glm::dvec2 expected = polyline.back();
    for (std::size_t j = 0; j + 1 < polyline.size(); ++j) {
      const double length = glm::length(polyline[j + 1] - polyline[j]);
      if (s <= length + 1e-12) {
        expected =
            polyline[j] + (length > 0.0 ? s / length : 0.0) * (polyline[j + 1] - polyline[j]);
        break;
      }
      s -= length;
    }
    EXPECT_LT(glm::distance(line[i], expected), 1e-9) << "at s = " << arcs[i];
  }
  EXPECT_TRUE(outermostFirstHolds(creases, radius));
  // A lip turning down by more than half the turn inside it reaches back across that ring's
  // plane (its fold would cut the flap there): the rings cannot be drawn outermost first.
  creases.angles = {0.3, 0.7, 1.0, 0.3};
  EXPECT_FALSE(outermostFirstHolds(creases, radius));
}

// A bowl whose rim turns back out into a flat lip: inner first, the lip's ring (turning the other
// way, at the steep wall's top) takes the corner paper of the flaps beside its own and is taken
// back; outermost first it is made on the flat sheet, and the step reaches the lip.
TEST(NestedRings, ALippedBowlsRimIsReachedByRingsDrawnOutermostFirst) {
  // A spherical cap of radius 5 cm to 50 degrees, then a lip 2 cm wide rising 3 mm.
  const double sphere = 0.05, edge = sphere * std::sin(50.0 * std::numbers::pi / 180.0);
  const auto height = [&](double r) {
    if (r <= edge) return sphere - std::sqrt(sphere * sphere - r * r);
    const double top = sphere - std::sqrt(sphere * sphere - edge * edge);
    return top + 0.003 * std::sin(0.5 * std::numbers::pi * (r - edge) / 0.02);
  };
  const double outer = edge + 0.02;
  const TriangleMesh target = capOf(height, outer, 48, 16);
  const Sheet disk =
      makeSurface("disk", {{"radius", 0.061}, {"resolution", testing::kSanitized ? 12.0 : 24.0}});
  RingStep ring(target, disk);
  ASSERT_TRUE(ring.axis);
  const std::optional<FoldSuggestion> made = ring.validStep(2);
  ASSERT_TRUE(made);
  const FoldSuggestion& step = *made;
  // The farthest of the target's rim from the sheet (its vertices: the disk is fine).
  double rimApart = 0.0;
  for (const glm::dvec3& p : target.positions) {
    if (std::hypot(p.x, p.y) < outer - 1e-9) continue;
    double nearest = 1e300;
    for (const glm::dvec3& q : step.sheet.positions)
      nearest = std::min(nearest, glm::distance(p, q));
    rimApart = std::max(rimApart, nearest);
  }
  // 5.1 mm here (under 6.5 on the sanitized run's coarser disk too); 8.2 mm with the rings
  // inner first only (8.4 on the coarser disk).
  EXPECT_LT(rimApart, 0.0065) << "before " << ring.before << ", after " << step.after;
  EXPECT_LT(step.after, 0.6 * ring.before);
}

// A steep cup 7 cm across and 4 deep (its wall 74 degrees at the rim): the flaps of a ring of many
// planes overlap far past their polygon's corners (a ring of 16 on a disk leaves a pinwheel whose
// overlap stands out past the wall), so a steep fit is also made with rings of 4 to 6 planes.
TEST(NestedRings, ASteepCupIsFoldedByRingsOfFewPlanesNotAPinwheel) {
  const TriangleMesh target =
      capOf([](double r) { return 0.04 * std::pow(r / 0.035, 3.0); }, 0.035, 48, 12);
  const Sheet disk =
      makeSurface("disk", {{"radius", 0.05}, {"resolution", testing::kSanitized ? 12.0 : 20.0}});
  RingStep ring(target, disk);
  ASSERT_TRUE(ring.axis);
  const std::optional<FoldSuggestion> made = ring.validStep(2);
  ASSERT_TRUE(made);
  const FoldSuggestion& step = *made;
  // 0.41 of the disk's distance (both resolutions); 0.49-0.51 with rings of 8 to 16 planes alone.
  EXPECT_LT(step.after, 0.45 * ring.before)
      << "before " << ring.before << ", " << step.folds.size() << " folds";
}

// A disk placed a degree and a half off a steep cup's axis is still folded by rings, about its
// own normal: on a cup about as deep as wide the placed disk's normal (placed_start.cpp) and the
// target's axis (revolutionAxis) are two estimates of one principal axis from different samples,
// 1-4 degrees apart, and the disk's height along the axis spanned 3.5-13% of its radius, over the
// 2% a flat sheet may, so the rings were never tried (bench/make_cup16_targets.py's tulip_cup and
// wavy_cup_mm: one fold, Chamfer 9.1-9.7%). Ten degrees off is no sheet across the axis.
TEST(NestedRings, ADiskADegreeOffASteepCupsAxisIsStillFoldedByRings) {
  const TriangleMesh target =
      capOf([](double r) { return 0.04 * std::pow(r / 0.035, 3.0); }, 0.035, 48, 12);
  const auto tilted = [](double degrees) {
    Sheet disk =
        makeSurface("disk", {{"radius", 0.05}, {"resolution", testing::kSanitized ? 12.0 : 16.0}});
    const double t = degrees * std::numbers::pi / 180.0;
    for (glm::dvec3& p : disk.positions)
      p = {p.x, p.y * std::cos(t) - p.z * std::sin(t), p.y * std::sin(t) + p.z * std::cos(t)};
    return disk;
  };
  const Sheet disk = tilted(1.5);
  RingStep ring(target, disk);
  ASSERT_TRUE(ring.axis);
  EXPECT_GT(std::abs(ring.axis->direction.z), std::cos(0.5 * std::numbers::pi / 180.0));
  EXPECT_FALSE(liesFlatAcross(tilted(10.0), *ring.axis));
  ASSERT_TRUE(liesFlatAcross(disk, *ring.axis));
  const std::optional<RevolutionAxis> about = ringsAxis(disk, *ring.axis);
  ASSERT_TRUE(about);
  const double t = 1.5 * std::numbers::pi / 180.0;
  EXPECT_GT(std::abs(glm::dot(about->direction, glm::dvec3(0.0, -std::sin(t), std::cos(t)))),
            std::cos(0.1 * std::numbers::pi / 180.0));
  const std::optional<FoldSuggestion> made = ring.validStep(2);
  ASSERT_TRUE(made);
  EXPECT_GE(made->folds.size(), 8u);  // rings, not a fold
  EXPECT_LT(made->after, 0.5 * ring.before) << "before " << ring.before;
}

TEST(NestedRings, FoldADiskMoreThanTwiceCloserToABowlInOneStep) {
  // The paraboloid about z, a fan at its centre, from a disk of about its area at its bottom
  // (coarser under the sanitizers: each candidate folds the whole sheet dozens of times).
  const TriangleMesh target = capOf([](double r) { return r * r / 0.16; }, 0.08, 48, 16);
  const Sheet disk =
      makeSurface("disk", {{"radius", 0.088}, {"resolution", testing::kSanitized ? 12.0 : 24.0}});
  RingStep ring(target, disk);
  ASSERT_TRUE(ring.axis);
  const std::optional<FoldSuggestion> made = ring.validStep(testing::kSanitized ? 2 : 3);
  ASSERT_TRUE(made);
  const FoldSuggestion& step = *made;
  EXPECT_GE(step.folds.size(), 16u);  // rings, not a fold
  EXPECT_LT(step.after, 0.45 * ring.before) << "before " << ring.before;
  EXPECT_NEAR(step.after, ring.fitter.approximateDistance(step.sheet), 1e-12);
  EXPECT_EQ(ring.session.foldCount(), 0u);  // the session is left as it was
  // The folds replay on a session of their own to the same sheet (a design keeps them).
  FoldSession replayed(disk);
  replayed.applyRecords(step.folds);
  EXPECT_EQ(replayed.foldCount(), step.folds.size());
  double moved = 0.0;
  for (std::size_t v = 0; v < step.sheet.positions.size(); ++v)
    moved = std::max(moved, glm::distance(step.sheet.positions[v], replayed.fixed().positions[v]));
  EXPECT_LT(moved, 1e-9);
}

// The same deep cap's profile fitted for the rim (nested_rings.cpp, kRimFarthest: the farthest
// point weighed 0.5 beside the mean, not 0.25), from the same random starts: the rim's fit comes
// nearer the profile's farthest point than the usual fit, at a larger mean. suggestNestedRings
// makes both fits' rings and keeps the nearer step (on a judge's 75 degree cap, 10 cm, the rim's:
// docs/performance.md, issue 38, bowl11).
TEST(NestedRings, ADeepCapsRimFitReachesNearerItsRimThanTheUsualFit) {
  const double sphere = 0.05, deepest = 75.0 * std::numbers::pi / 180.0;
  std::vector<glm::dvec2> profile;
  for (int i = 0; i < 300; ++i) {
    const double u = (i + 0.5) / 300.0, theta = std::acos(1.0 - u * (1.0 - std::cos(deepest)));
    profile.push_back({sphere * std::sin(theta), sphere * (1.0 - std::cos(theta))});
  }
  const double radius = 2.0 * sphere * std::sin(0.5 * deepest);
  const auto farthestOf = [&](const ProfileCreases& creases) {
    const std::vector<glm::dvec2> polyline = profilePolyline(creases, radius);
    double farthest = 0.0;
    for (const glm::dvec2& p : profile) {
      double nearest = 1e300;
      for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
        const glm::dvec2 ab = polyline[i + 1] - polyline[i];
        const double t = std::clamp(glm::dot(p - polyline[i], ab) / glm::dot(ab, ab), 0.0, 1.0);
        nearest = std::min(nearest, glm::length(p - (polyline[i] + t * ab)));
      }
      farthest = std::max(farthest, nearest);
    }
    return farthest;
  };
  std::mt19937_64 usualRandom(5), rimRandom(5);
  const ProfileCreases usualOne = fitProfileCreases(profile, radius, 1, nullptr, usualRandom);
  const ProfileCreases usualTwo = fitProfileCreases(profile, radius, 2, &usualOne, usualRandom);
  const ProfileCreases usual = fitProfileCreases(profile, radius, 3, &usualTwo, usualRandom);
  const ProfileCreases rimOne = fitProfileCreases(profile, radius, 1, nullptr, rimRandom, 0.5);
  const ProfileCreases rimTwo = fitProfileCreases(profile, radius, 2, &rimOne, rimRandom, 0.5);
  const ProfileCreases rim = fitProfileCreases(profile, radius, 3, &rimTwo, rimRandom, 0.5);
  // The usual fit's farthest point 4.39 mm from the polyline (mean 0.52 mm), the rim's 3.27 mm
  // (mean 0.97 mm); with the weight not passed to the fit, the same 4.39 mm.
  EXPECT_LT(farthestOf(rim), 0.85 * farthestOf(usual))
      << "usual " << farthestOf(usual) << " mean " << usual.mean << ", rim mean " << rim.mean;
  EXPECT_GT(rim.mean, usual.mean);
}

// An oval serving bowl (an elliptic paraboloid over an ellipse 1.5 : 1 across, 18 x 12 cm, 4 cm
// deep: no axis of revolution, its rim as deep all around) from a disk of about its area. Round
// rings turn the disk up at one distance from the axis all around: past the oval's narrow sides
// the wall stands out, and along its long ends it stops short of the rim. The rings follow the
// oval's reach instead (each plane off the axis in proportion to the target's reach its way:
// nested_rings.cpp, kOblong), so the step ends nearer, by both the mean and the farthest point.
TEST(NestedRings, AnOvalBowlsRingsFollowItsReachNotACircle) {
  TriangleMesh target =
      capOf([](double r) { return 0.04 * (r / 0.06) * (r / 0.06); }, 0.06, 48, 12);
  for (glm::dvec3& p : target.positions) p.x *= 1.5;
  const Sheet disk =
      makeSurface("disk", {{"radius", 0.085}, {"resolution", testing::kSanitized ? 12.0 : 20.0}});
  RingStep ring(target, disk);
  ASSERT_TRUE(ring.axis);
  EXPECT_GT(std::abs(ring.axis->direction.z), 0.99);
  const std::optional<FoldSuggestion> made = ring.validStep(2);
  ASSERT_TRUE(made);
  const FoldSuggestion& step = *made;
  const FarthestPoints far = farthestPoints(meshOf(step.sheet), target, 3000, 7);
  const double farthest = std::max(far.fromA, far.fromB);
  // 0.566 (12 segments) and 0.572 (20) of the disk's distance, the farthest 25.2 and 24.3 mm;
  // with round rings (kOblong past any ratio) 0.583 and 0.591, 27.1 and 28.8 mm.
  EXPECT_LT(step.after, 0.577 * ring.before) << "before " << ring.before;
  EXPECT_LT(farthest, 0.0262) << "after " << step.after << ", " << step.folds.size() << " folds";
}

// An oval bowl asked of the disk starts from the disk of its area stretched to its footprint:
// the round disk stands past the narrow sides and stops short of the long ends.
TEST(NestedRings, AnOvalBowlFromTheDiskStartsOnItsFootprintsEllipse) {
  TriangleMesh target =
      capOf([](double r) { return 0.04 * (r / 0.06) * (r / 0.06); }, 0.06, 48, 12);
  for (glm::dvec3& p : target.positions) p.x *= 1.5;
  const StartChoice start = chooseStart(target, "disk");
  ASSERT_TRUE(start.placed);
  EXPECT_EQ(start.surface, "ellipse") << start.placement;
  validate(*start.placed);
  // Its extents along the oval's axes (x and y here) in the footprint's proportions, 1.5.
  glm::dvec3 low(1e300), high(-1e300);
  for (const glm::dvec3& p : start.placed->positions) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  EXPECT_NEAR((high.x - low.x) / (high.y - low.y), 1.5, 0.1);
  // It reaches both ends of the oval (9 cm out) and no farther past its narrow sides than there.
  EXPECT_GT(0.5 * (high.x - low.x), 0.09);
  EXPECT_LT(0.5 * (high.y - low.y) - 0.06, 0.5 * (high.x - low.x) - 0.09);
}

// A steep cup (7 cm across, 4 deep, its wall 74 degrees at the rim) from the disk of its area:
// the search's score cuts far distances, so of the steps about as near by it (within 5%), only the
// one standing out least is offered (on the bench's small_cup two such stood 7.4 and 12.4 mm out,
// and the farther one was kept).
TEST(NestedRings, OfStepsAboutAsNearOnlyTheOneStandingOutLeastIsOffered) {
  if (testing::kSanitized) GTEST_SKIP() << "a 3-crease step on a 16-ring disk: seconds of CPU";
  const TriangleMesh target =
      capOf([](double r) { return 0.04 * std::pow(r / 0.035, 3.0); }, 0.035, 48, 14);
  const Sheet disk = makeSurface("disk", {{"radius", 0.05}, {"resolution", 16.0}});
  RingStep ring(target, disk);
  ASSERT_TRUE(ring.axis);
  std::mt19937_64 random(5);
  const std::vector<FoldSuggestion> steps =
      suggestNestedRings(ring.session, ring.fitter, *ring.axis, ring.samples, 500, {}, random, 3);
  ASSERT_FALSE(steps.empty());
  std::size_t tied = 0;
  for (const FoldSuggestion& step : steps)
    if (step.after <= 1.05 * steps.front().after) ++tied;
  // Without the rule, two: 1.126 and 1.173 mm (approximate).
  EXPECT_EQ(tied, 1u) << "nearest " << steps.front().after;
  EXPECT_LT(steps.front().after, 0.5 * ring.fitter.approximateDistance(ring.session.fixed()));
}

// Without --from, a steep cup (7 cm across, 4 deep, its wall 74 degrees at the rim) starts from
// the disk its nested rings fold (start_surface.hpp), not the placed cone, which is nearer at
// once by Chamfer (the rings' model 0.96 mm against 1.47 mm: 0.65, over the old rule's 0.2) but
// leaves the cup's bottom standing off (Hausdorff 11.8 mm against the model's 5.5 mm; the bench's
// small_cup folds from the cone to Hausdorff 11.1%, from the disk to 7.2%). Also past the
// choice's share of the clock: the disk came last among the placed sheets and the rings' fit was
// skipped past the deadline, so a loaded machine kept the cone.
TEST(NestedRings, ASteepCupStartsFromTheDiskItsRingsFoldAlsoPastTheDeadline) {
  if (testing::kSanitized)
    GTEST_SKIP()
        << "two start choices, 1.3 s of CPU in Release; under the sanitizers "
           "StartSurface.AFootedBowlStartsFromTheDiskItsRingsFoldNotTheNearerCone and "
           "StartSurface.TheChoiceStopsMeasuringAtItsDeadlineButStillPlacesASheetOnTheTarget "
           "run the same code";
  const TriangleMesh cup =
      capOf([](double r) { return 0.04 * std::pow(r / 0.035, 3.0); }, 0.035, 48, 14);
  const StartChoice whole = chooseStart(cup);
  EXPECT_EQ(whole.surface, "disk") << whole.placement;
  EXPECT_TRUE(whole.placed);
  const StartChoice cut = chooseStart(cup, "", "", Deadline::in(0.0));
  EXPECT_TRUE(cut.cutShort);
  EXPECT_EQ(cut.surface, "disk") << cut.placement;
  EXPECT_TRUE(cut.placed);
}

TEST(NestedRings, ASymmetricDesignMakesEachRingAsOneFoldAndItsImages) {
  const TriangleMesh target = capOf([](double r) { return r * r / 0.16; }, 0.08, 48, 16);
  const Sheet disk =
      makeSurface("disk", {{"radius", 0.088}, {"resolution", testing::kSanitized ? 12.0 : 24.0}});
  RingStep ring(target, disk);
  ASSERT_TRUE(ring.axis);
  ring.session.setSymmetry(parseSymmetry("rotational:12:z", disk));
  const std::optional<FoldSuggestion> made = ring.validStep(2);
  ASSERT_TRUE(made);
  const FoldSuggestion& step = *made;
  // Each ring is one fold and its images (one group), at most two rings and a plane across.
  std::vector<int> groups;
  for (const FoldRecord& fold : step.folds)
    if (groups.empty() || groups.back() != int(fold.group)) groups.push_back(int(fold.group));
  EXPECT_LE(groups.size(), 3u);
  EXPECT_GT(step.folds.size(), groups.size());  // images beside the folds
  // Such a ring about halves the distance (0.494 of it on the disk of 24 rings, 0.501 on the
  // sanitized run's 12): the bound says it helps, with room for the coarser disk.
  EXPECT_LT(step.after, 0.6 * ring.before) << "before " << ring.before;
}

// A coarse hemisphere (7 rings, tilted): each ring's edges bend as much as a fold's crease and
// lie in one plane, yet it is no folded sheet (not developable: its vertices have angle defects),
// so it gets a placed disk and the rings, not the catalogue disk at its defaults. A disk folded
// once keeps its crease.
TEST(NestedRings, ACoarseHemisphereIsSmoothAndAFoldedDiskIsNot) {
  // Ring j of 6 j vertices at 90 j / 7 degrees from the pole, stitched to ring j + 1 by angle.
  TriangleMesh hemisphere;
  std::vector<std::uint32_t> starts{0};
  hemisphere.positions.emplace_back(0.0, 0.0, 0.0);
  for (int j = 1; j <= 7; ++j) {
    starts.push_back(std::uint32_t(hemisphere.positions.size()));
    const double phi = 0.5 * std::numbers::pi * j / 7.0;
    for (int i = 0; i < 6 * j; ++i) {
      const double a = 2.0 * std::numbers::pi * i / (6 * j);
      hemisphere.positions.emplace_back(0.045 * std::sin(phi) * std::cos(a),
                                        0.045 * std::sin(phi) * std::sin(a),
                                        0.045 * (1.0 - std::cos(phi)));
    }
  }
  for (int j = 0; j < 7; ++j) {
    const int inner = std::max(1, 6 * j), outer = 6 * (j + 1);
    const auto in = [&](int a) { return j == 0 ? 0u : starts[j] + std::uint32_t(a % inner); };
    const auto out = [&](int b) { return starts[j + 1] + std::uint32_t(b % outer); };
    for (int a = 0, b = 0; a < (j == 0 ? 0 : inner) || b < outer;) {
      if (b < outer && (j == 0 || a >= inner || (b + 1) * inner <= (a + 1) * outer)) {
        hemisphere.triangles.push_back({in(a), out(b), out(b + 1)});
        ++b;
      } else {
        hemisphere.triangles.push_back({in(a), out(b), in(a + 1)});
        ++a;
      }
    }
  }
  const glm::dvec3 tilt = glm::normalize(glm::dvec3(1.0, 1.0, 0.0));
  const double angle = 35.0 * std::numbers::pi / 180.0;
  for (glm::dvec3& p : hemisphere.positions)  // Rodrigues' rotation about `tilt`
    p = p * std::cos(angle) + glm::cross(tilt, p) * std::sin(angle) +
        tilt * glm::dot(tilt, p) * (1.0 - std::cos(angle)) + glm::dvec3(0.2, -0.1, 0.05);
  EXPECT_TRUE(isSmoothOrScanned(hemisphere));

  FoldSession folded(makeSurface("disk"));
  const Sheet& flat = folded.initial();
  VertexIndex end = 0;
  for (VertexIndex v = 0; v < flat.vertexCount(); ++v)
    if (flat.positions[v].x > flat.positions[end].x) end = v;
  const ReflectionPlane plane{{0.02, 0.0, 0.0}, glm::normalize(glm::dvec3(1.0, 0.2, 0.5))};
  folded.updateDrag(plane.reflect(folded.beginDragAtDevelopment(flat.development[end])));
  ASSERT_TRUE(folded.commit());
  EXPECT_FALSE(isSmoothOrScanned(meshOf(folded.fixed())));
}

// From a flat disk toward a bowl the fit's first step is the nested rings alone: tried before
// the single folds' search (hundreds of candidates), which does not run in that step, so the
// rings fit a short --time. One step, without a clock: the count of candidates scored says it.
// On a loaded machine the clock can pass while the rings are made: the step must still land
// (issue 38, 2: "no step in 60 s" on the example bowl). The deadline here is a few times the CPU
// the profile fits alone take on this machine (measured first, so it holds under the sanitizers;
// the whole step spends about 8 times as much), far less than every candidate's rings: the
// coarsest candidate, made first, is answered; before, a step the clock cut answered nothing.
// Counted in CPU (a share of work, work_share.hpp), not on the wall clock: under load the fits'
// wall time and the step's stretched apart, and the step was cut before its coarsest rings or
// not at all.
TEST(NestedRings, AStepTheClockCutsStillAnswersTheCoarsestRingsMadeWhole) {
  const TriangleMesh target = capOf([](double r) { return r * r / 0.16; }, 0.08, 48, 16);
  const Sheet disk =
      makeSurface("disk", {{"radius", 0.088}, {"resolution", testing::kSanitized ? 16.0 : 28.0}});
  const FoldFitter fitter(target, testing::sampledSettings(600, 600, 4000));
  const std::vector<SurfaceSample> samples = sampleSurface(target, 1500, 3);
  const std::optional<RevolutionAxis> axis = revolutionAxis(samples);
  ASSERT_TRUE(axis);
  FoldSession session(disk);
  // What the whole step makes, with no clock.
  std::mt19937_64 random(5);
  std::atomic<std::uint64_t> all{0};
  const std::vector<FoldSuggestion> whole = suggestNestedRings(
      session, fitter, *axis, samples, 1, testing::counting(Deadline{}, all), random, 3);
  ASSERT_EQ(whole.size(), 1u);
  // The profile fits alone (as the step makes them), timed.
  // As the step takes it: 300 of the samples.
  const std::vector<glm::dvec2> profile = meridianProfile(samples, axis->point, *axis, 300);
  const double started = processCpuSeconds();
  std::mt19937_64 fitRandom(5);
  const ProfileCreases one = fitProfileCreases(profile, 0.088, 1, nullptr, fitRandom);
  const ProfileCreases two = fitProfileCreases(profile, 0.088, 2, &one, fitRandom);
  fitProfileCreases(profile, 0.088, 3, &two, fitRandom);
  const double fitCpu = processCpuSeconds() - started;
  std::atomic<std::uint64_t> evaluations{0};
  std::mt19937_64 again(5);
  const std::vector<FoldSuggestion> cut = suggestNestedRings(
      session, fitter, *axis, samples, 1,
      testing::counting(workShare(3.0 * fitCpu, 0.0, 1e10), evaluations), again, 3);
  ASSERT_EQ(cut.size(), 1u) << "a step the clock cut answered nothing";
  // Fewer candidates were made than in the whole step: the clock cut it (or the time left would
  // not hold the next batch, judged by the last).
  EXPECT_LT(evaluations.load(), all.load());
  EXPECT_LT(cut.front().after, cut.front().before);
  EXPECT_LE(cut.front().after, 0.6 * cut.front().before);
  EXPECT_GE(cut.front().after, whole.front().after);
  validate(cut.front().sheet);
  EXPECT_TRUE(findSelfIntersections(cut.front().sheet).intersections.empty());
  EXPECT_EQ(session.foldCount(), 0u);
}

TEST(NestedRings, TheFitsFirstStepFromADiskIsTheRingsWithoutTheSingleFoldsSearch) {
  const TriangleMesh target = capOf([](double r) { return r * r / 0.16; }, 0.08, 48, 16);
  // Coarser under the sanitizers: each ring candidate folds the whole sheet dozens of times.
  const Sheet disk =
      makeSurface("disk", {{"radius", 0.088}, {"resolution", testing::kSanitized ? 8.0 : 12.0}});
  const FoldFitter fitter(target, testing::sampledSettings(400, 600, 4000));
  ASSERT_TRUE(fitter.nestedRingsFrom(disk));
  FoldSession session(disk);
  FitOptions options;
  options.maxFolds = 1;
  options.seconds = std::numeric_limits<double>::infinity();
  options.distanceSamples = 2000;
  const FitResult result = fitFolds(session, fitter, options);
  EXPECT_GE(result.folds.size(), 8u);  // a ring at least, as one step
  // The profile fits and the ring candidates only (4 + 4 * 3, and 3 * 3 drawn outermost first;
  // twice: the usual fits and the rim's), not the single folds' hundreds.
  EXPECT_LE(result.evaluations, 50u);
  EXPECT_LT(result.steps.back().chamfer, 0.6 * result.steps.front().chamfer);
  validate(session.fixed());
}

// The fit's final phase keeps to its time (issue 38, 3: the example bowl's 65 rings' folds ran
// `fit --time 60` to 65.8 and 71 s): the search stops early enough to measure and report the
// rings it found (an estimate from the largest design found: folding it again, its exact measure
// and the report's self-intersection check), and a group that would not fit is not kept. The
// report here does what the command's does (a self-intersection check of each step's sheet). "In
// time" is counted in the CPU spent after the limit, which a loaded machine does not stretch as
// it does the wall clock; ignoring the limit spends the whole final phase there.
TEST(NestedRings, TheFinalMeasureOfManyRingsKeepsWithinTheTime) {
  const TriangleMesh target = capOf([](double r) { return r * r / 0.16; }, 0.08, 48, 16);
  const Sheet disk =
      makeSurface("disk", {{"radius", 0.088}, {"resolution", testing::kSanitized ? 16.0 : 48.0}});
  const FoldFitter fitter(target);
  FoldSession session(disk);
  FitOptions options;
  options.maxFolds = 16;
  options.seconds = testing::kSanitized ? 20.0 : 5.0;
  // Measures as dear as the time allows (a tenth of it for the start's: samplesWithinTime), so
  // the final phase is seconds of work, as a large design's is under --time 60.
  options.distanceSamples = 1'000'000;
  std::size_t reported = 0;
  options.progress = [&](const FitProgress& step) {
    if (step.fold > 0) reported += findSelfIntersections(session.fixed()).intersections.size() + 1;
  };
  const auto [result, seconds, cpu] =
      testing::runPastLimit(options.seconds, [&] { return fitFolds(session, fitter, options); });
  EXPECT_TRUE(result.timedOut) << result.stopReason;
  EXPECT_EQ(reported, result.steps.size() - 1);  // every step kept was reported, crossing none
  // The final phase is one thread's work: its measure, commit and report past the limit were
  // 0.22-0.33 s of CPU here with the search's reserve for them removed (the fit 6-10% over its
  // time); with it, a millisecond.
  EXPECT_LT(cpu, testing::kSanitized ? 2.0 : 0.02 * options.seconds)
      << cpu << " s of CPU after the limit; " << seconds << " s in all, " << result.folds.size()
      << " folds";
  validate(session.fixed());
}

}  // namespace
}  // namespace curvefold
