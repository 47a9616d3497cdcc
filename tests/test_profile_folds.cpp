// Rings of folds toward surfaces of revolution (issue 38, 2; engine/fit/profile_folds.hpp).
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "engine/fit/first_step_start.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/lobed_saddle.hpp"
#include "engine/fit/placed_start.hpp"
#include "engine/fit/profile_folds.hpp"
#include "engine/fit/ring_folds.hpp"
#include "engine/fit/start_surface.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/fit/target_units.hpp"
#include "engine/fit/timed_batches.hpp"
#include "engine/fit/tube_reach.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "tests/fit_settings_support.hpp"
#include "tests/sanitizer_support.hpp"

namespace curvefold {
namespace {

// A surface of revolution about z: radius(h) for h over [low, high], rings of `around`.
template <typename Radius>
TriangleMesh revolved(Radius radius, double low, double high, int around, int along) {
  TriangleMesh mesh;
  for (int j = 0; j <= along; ++j)
    for (int i = 0; i < around; ++i) {
      const double h = low + (high - low) * j / along, a = 2.0 * std::numbers::pi * i / around;
      mesh.positions.emplace_back(radius(h) * std::cos(a), radius(h) * std::sin(a), h);
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

// A surface of revolution about z given as height(r) for r over [inner, outer].
template <typename Height>
TriangleMesh revolvedByRadius(Height height, double inner, double outer, int around, int rings) {
  TriangleMesh mesh;
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i < around; ++i) {
      const double r = inner + (outer - inner) * j / rings, a = 2.0 * std::numbers::pi * i / around;
      mesh.positions.emplace_back(r * std::cos(a), r * std::sin(a), height(r));
    }
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < around; ++i) {
      const auto at = [&](int ii, int jj) {
        return static_cast<std::uint32_t>(jj * around + (ii % around));
      };
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

// Turned by `degrees` about `axis` (Rodrigues).
glm::dvec3 turned(const glm::dvec3& p, glm::dvec3 axis, double degrees) {
  axis = glm::normalize(axis);
  const double a = degrees * std::numbers::pi / 180.0;
  return p * std::cos(a) + glm::cross(axis, p) * std::sin(a) +
         axis * glm::dot(axis, p) * (1.0 - std::cos(a));
}

TEST(RevolutionAxis, IsFoundOnATiltedVaseAndNotOnASaddle) {
  TriangleMesh vase =
      revolved([](double h) { return 0.05 + 0.02 * std::sin(20.0 * h); }, -0.1, 0.1, 48, 30);
  const glm::dvec3 tilt(1.0, 0.4, 0.0), shift(0.03, -0.02, 0.01);
  for (glm::dvec3& p : vase.positions) p = turned(p, tilt, 50.0) + shift;
  const std::optional<RevolutionAxis> axis = revolutionAxis(sampleSurface(vase, 2000, 3));
  ASSERT_TRUE(axis);
  const glm::dvec3 expected = turned({0, 0, 1}, tilt, 50.0);
  EXPECT_GT(std::abs(glm::dot(axis->direction, expected)), std::cos(2.0 * std::numbers::pi / 180));
  // Through the vase's axis (its centroid lies on it).
  const glm::dvec3 off = axis->point - shift;
  EXPECT_LT(glm::length(off - glm::dot(off, expected) * expected), 0.002);

  // A saddle z = xy / 0.2 over a square of 20 cm turns onto itself only by half turns.
  TriangleMesh saddle;
  const int cells = 30;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      const double x = 0.2 * (double(i) / cells - 0.5), y = 0.2 * (double(j) / cells - 0.5);
      saddle.positions.emplace_back(x, y, x * y / 0.2);
    }
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const auto at = [&](int ii, int jj) { return std::uint32_t(jj * (cells + 1) + ii); };
      saddle.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      saddle.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  EXPECT_FALSE(revolutionAxis(sampleSurface(saddle, 2000, 3)));
}

TEST(RevolutionAxis, IsFoundOnACanWithAClosedBottom) {
  // A can of 5 cm radius, 10 cm tall, its bottom closed by a disk (a fifth of its area), tilted:
  // the disk holds every radius from 0 to 5 cm at one height, which read as a spread of 0.11 of
  // the mean radius by height and no axis (a bottle with a closed bottom got no rings).
  TriangleMesh can = revolved([](double) { return 0.05; }, 0.0, 0.1, 48, 20);
  const TriangleMesh bottom = revolvedByRadius([](double) { return 0.0; }, 0.0, 0.05, 48, 12);
  const auto offset = static_cast<std::uint32_t>(can.positions.size());
  can.positions.insert(can.positions.end(), bottom.positions.begin(), bottom.positions.end());
  for (const auto& t : bottom.triangles)
    can.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const glm::dvec3 tilt(0.3, 1.0, 0.2);
  for (glm::dvec3& p : can.positions) p = turned(p, tilt, 35.0);
  const std::optional<RevolutionAxis> axis = revolutionAxis(sampleSurface(can, 2000, 3));
  ASSERT_TRUE(axis);
  const glm::dvec3 expected = turned({0, 0, 1}, tilt, 35.0);
  EXPECT_GT(std::abs(glm::dot(axis->direction, expected)), std::cos(2.0 * std::numbers::pi / 180));
  EXPECT_LT(axis->spread, 0.05);
}

// An oval cup (a steep round cup stretched 1.36 times one way, its cross-sections alike ovals)
// has an axis: the nested rings follow an oblong target's reach each way (nested_rings.hpp), and
// without an axis it got none (a 9.5 x 7 cm cup: no fold kept from the disk).
TEST(RevolutionAxis, IsFoundOnATiltedOvalCup) {
  TriangleMesh cup = revolvedByRadius(
      [](double r) { return 0.05 * std::pow(std::max(0.0, (r - 0.02) / 0.025), 1.5); }, 0.002,
      0.045, 48, 30);
  const glm::dvec3 tilt(-0.5, 0.2, 1.0), shift(0.05, 0.3, -0.1);
  for (glm::dvec3& p : cup.positions) {
    p.x *= 1.36;
    p = turned(p, tilt, 50.0) + shift;
  }
  const std::optional<RevolutionAxis> axis = revolutionAxis(sampleSurface(cup, 2000, 3));
  ASSERT_TRUE(axis);
  const glm::dvec3 expected = turned({0, 0, 1}, tilt, 50.0);
  EXPECT_GT(std::abs(glm::dot(axis->direction, expected)), std::cos(2.0 * std::numbers::pi / 180));
}

// A lampshade about as tall as it is wide (30.7 cm tall, 28 cm across at its foot, a bulge three
// quarters up) has principal variances within 0.1% of each other, so its sampled principal axes
// lie wherever the samples swing them (bench/make_implicit_shapes.py's lampshade_march: 14 degrees
// off, no axis, so no rings): its axis is polished on the spread.
TEST(RevolutionAxis, IsFoundOnASquatLampshade) {
  TriangleMesh shade = revolved(
      [](double h) {
        const double y = h / 0.381;
        return 0.4 * (0.35 - 0.15 * y + 0.07 * std::exp(-std::pow((y - 0.6) / 0.15, 2)));
      },
      0.0, 0.3067, 64, 40);
  const glm::dvec3 tilt(0.7, -0.4, 0.3), shift(0.2, -0.1, 0.4);
  for (glm::dvec3& p : shade.positions) p = turned(p, tilt, 65.0) + shift;
  const std::optional<RevolutionAxis> axis = revolutionAxis(sampleSurface(shade, 2000, 3));
  ASSERT_TRUE(axis);
  const glm::dvec3 expected = turned({0, 0, 1}, tilt, 65.0);
  EXPECT_GT(std::abs(glm::dot(axis->direction, expected)), std::cos(2.0 * std::numbers::pi / 180));
}

// A height field z(x, y) over the square [-half, half]^2 as a grid of `cells` a side, each cell
// cut in two triangles, kept where `keep` holds at the triangle's centroid.
template <typename Height, typename Keep>
TriangleMesh overGrid(Height height, double half, int cells, Keep keep) {
  TriangleMesh mesh;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      const double x = half * (2.0 * i / cells - 1.0), y = half * (2.0 * j / cells - 1.0);
      mesh.positions.emplace_back(x, y, height(x, y));
    }
  const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (cells + 1) + i); };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i)
      for (const std::array<std::uint32_t, 3> t :
           {std::array<std::uint32_t, 3>{at(i, j), at(i + 1, j), at(i + 1, j + 1)},
            std::array<std::uint32_t, 3>{at(i, j), at(i + 1, j + 1), at(i, j + 1)}})
        if (keep((mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0))
          mesh.triangles.push_back(t);
  return mesh;
}

// A height field z(x, y) over the equilateral triangle of circumradius `radius` whose corners
// lie at 60, 180 and 300 degrees, as a grid of `cells` a side whose triangles inside it are kept.
template <typename Height>
TriangleMesh overTriangle(Height height, double radius, int cells) {
  // Inside: on the inner side of each edge, whose outward normals point away from the corners.
  return overGrid(height, radius, cells, [&](const glm::dvec3& p) {
    for (const double degrees : {0.0, 120.0, 240.0}) {
      const double a = degrees * std::numbers::pi / 180.0;
      if (p.x * std::cos(a) + p.y * std::sin(a) > 0.5 * radius) return false;
    }
    return true;
  });
}

// A monkey saddle z = 0.8 (x^3 - 3 x y^2) / R^2 over a triangle of circumradius R = 10 cm whose
// corners lie on its falling lobes (bench/make_lattice_saddles.py's monkey_saddle_triangle) holds
// nearly one height at each radius past the triangle's inner circle, so its height spread by
// radius (0.075 of the mean radius) read as a dish's: it had an axis, and the fit laid nested
// rings on it. Its height swings with the turn (3 lobes up, 3 down) where a dish's does not: no
// axis. The dish z = 4 r^2 over the same triangle keeps its axis.
TEST(RevolutionAxis, IsNotFoundOnAMonkeySaddleOverATriangle) {
  const double radius = 0.1;
  const glm::dvec3 tilt(0.4, -1.0, 0.3), shift(0.02, 0.05, -0.03);
  auto placed = [&](TriangleMesh mesh) {
    for (glm::dvec3& p : mesh.positions) p = turned(p, tilt, 40.0) + shift;
    return mesh;
  };
  const TriangleMesh saddle = placed(overTriangle(
      [&](double x, double y) { return 0.8 * (x * x * x - 3.0 * x * y * y) / (radius * radius); },
      radius, 40));
  EXPECT_FALSE(revolutionAxis(sampleSurface(saddle, 2000, 3)));
  const TriangleMesh dish =
      placed(overTriangle([](double x, double y) { return 4.0 * (x * x + y * y); }, radius, 40));
  const std::optional<RevolutionAxis> axis = revolutionAxis(sampleSurface(dish, 2000, 3));
  ASSERT_TRUE(axis);
  const glm::dvec3 expected = turned({0, 0, 1}, tilt, 40.0);
  EXPECT_GT(std::abs(glm::dot(axis->direction, expected)), std::cos(2.0 * std::numbers::pi / 180));
}

// A height field z(x, y) over the square [-half, half]^2 (its corners at 45 degrees), a grid of
// `cells` a side.
template <typename Height>
TriangleMesh overSquare(Height height, double half, int cells) {
  return overGrid(height, half, cells, [](const glm::dvec3&) { return true; });
}

// A saddle of four lobes, z = 0.4 rho^4 cos(4 t) / R^3 over a square of corner radius R = 10 cm
// (its corners on the falling lobes, slope 1.6 there: bench/make_polygon_saddles.py's k4), tilted.
TriangleMesh fourLobedSaddle(const glm::dvec3& tilt) {
  const double half = 0.1 / std::numbers::sqrt2, cube = 0.1 * 0.1 * 0.1;
  TriangleMesh mesh = overSquare(
      [&](double x, double y) {
        return 0.4 * (x * x * x * x - 6.0 * x * x * y * y + y * y * y * y) / cube;
      },
      half, 40);
  for (glm::dvec3& p : mesh.positions) p = turned(p, tilt, 40.0) + glm::dvec3(0.02, 0.05, -0.03);
  return mesh;
}

// The axis revolutionAxis refuses on a lobed saddle for its swing is read with the lobes' order:
// 4 on the saddle over a square, 3 on the monkey saddle over a triangle; a dish has its own axis
// and no lobed one.
TEST(LobedSaddleAxis, IsReadWithTheLobesOrder) {
  const glm::dvec3 tilt(0.4, -1.0, 0.3);
  const glm::dvec3 expected = turned({0, 0, 1}, tilt, 40.0);
  const std::vector<SurfaceSample> four = sampleSurface(fourLobedSaddle(tilt), 2000, 3);
  EXPECT_FALSE(revolutionAxis(four));
  const std::optional<LobedAxis> lobed = lobedSaddleAxis(four);
  ASSERT_TRUE(lobed);
  EXPECT_EQ(lobed->order, 4);
  EXPECT_GT(std::abs(glm::dot(lobed->axis.direction, expected)),
            std::cos(2.0 * std::numbers::pi / 180));
  const double radius = 0.1;
  auto placed = [&](TriangleMesh mesh) {
    for (glm::dvec3& p : mesh.positions) p = turned(p, tilt, 40.0);
    return mesh;
  };
  const std::optional<LobedAxis> monkey = lobedSaddleAxis(
      sampleSurface(placed(overTriangle(
                        [&](double x, double y) {
                          return 0.8 * (x * x * x - 3.0 * x * y * y) / (radius * radius);
                        },
                        radius, 40)),
                    2000, 3));
  ASSERT_TRUE(monkey);
  EXPECT_EQ(monkey->order, 3);
  EXPECT_FALSE(lobedSaddleAxis(sampleSurface(
      placed(overTriangle([](double x, double y) { return 4.0 * (x * x + y * y); }, radius, 40)),
      2000, 3)));
}

// Four planes tilted 30 degrees from the axis, each cutting a sector of the top rim off a
// cylinder along y (20 cm tall, 5 cm radius): four flaps turned in.
Ring fourFlapRim() {
  Ring ring;
  const glm::dvec3 up(0, 1, 0);  // the catalogue cylinder's axis
  const double beta = 30.0 * std::numbers::pi / 180;
  for (int k = 0; k < 4; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 4 + 0.3;
    const glm::dvec3 e(std::cos(a), 0.0, std::sin(a));
    ring.planes.push_back(
        {0.1 * up + 0.036 * e, glm::normalize(std::cos(beta) * e + std::sin(beta) * up)});
  }
  return ring;
}

Sheet tubeSheet() {
  return makeSurface("cylinder", {{"radius", 0.05}, {"height", 0.2}});
}

// An urn 30 cm long with a waist symmetric about its middle, its axis tilted: the waist bends its
// ring of edges by about 13 degrees (more than a gridded smooth shape's 12) and mirrors its faces
// as a fold's crease would, but the rings beside it bend nearly as much: smooth, not a design
// folded from the cylinder (which would keep the cylinder's defaults, placed nowhere).
TEST(StartSurface, ASmoothUrnsWaistIsNoCrease) {
  TriangleMesh urn = revolved([](double h) { return 0.1 - 0.05 * std::exp(-h * h / 0.0043); },
                              -0.15, 0.15, 48, 30);
  for (glm::dvec3& p : urn.positions) p = turned(p, {1.0, 0.3, 0.0}, 35.0);
  EXPECT_TRUE(isSmoothOrScanned(urn));
  const StartChoice start = chooseStart(urn, "cylinder");
  EXPECT_FALSE(start.creased);
  EXPECT_FALSE(start.parameters.empty());
}

TEST(RingFolds, ARingIsMadeAllAroundAndKeepsTheSheetValid) {
  FoldSession session(tubeSheet());
  EXPECT_EQ(makeRing(session, fourFlapRim()), 4u);
  EXPECT_EQ(session.foldCount(), 4u);
  validate(session.fixed());
  EXPECT_TRUE(findSelfIntersections(session.fixed()).intersections.empty());
  // Every flap was turned in: rim vertices lie inside the cylinder in each quarter.
  std::vector<int> inside(4, 0);
  for (const glm::dvec3& p : session.fixed().positions)
    if (p.y > 0.08 && std::hypot(p.x, p.z) < 0.045) {
      const double a = std::atan2(p.z, p.x) - 0.3 + 4.0 * std::numbers::pi + std::numbers::pi / 4;
      ++inside[static_cast<int>(a / (std::numbers::pi / 2)) % 4];
    }
  for (int k = 0; k < 4; ++k) EXPECT_GT(inside[k], 0) << "flap " << k;
}

// The disk placed across a bowl faces the same way on the bowl however the bowl is turned: the
// principal axes' signs are arbitrary, and a judge's bowl turned 50 degrees about (1, 2, 3) got
// its disk from the other side, where the nested rings made 9 folds and Chamfer 2.66% (upright:
// 33 folds, 1.26%; bench/make_judge_shapes.py, issue 38).
TEST(PlacedStarts, TheDiskAcrossABowlFacesItsBottomHoweverTheBowlIsTurned) {
  const TriangleMesh dish = revolvedByRadius(
      [](double r) { return r < 0.06 ? 0.0 : 0.025 * std::pow((r - 0.06) / 0.08, 2.0); }, 0.005,
      0.14, 48, 16);
  std::mt19937 random(38);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int checked = 0;
  for (int k = 0; k < 16; ++k) {
    const glm::dvec3 axis =
        k == 0 ? glm::dvec3(1, 0, 0) : glm::dvec3(unit(random), unit(random), unit(random));
    const double degrees = k == 0 ? 0.0 : 180.0 * (1.0 + unit(random));
    TriangleMesh target = dish;
    for (glm::dvec3& p : target.positions) p = turned(p, axis, degrees);
    const std::vector<PlacedStart> disks =
        placedStarts(sampleSurface(target, 1500, 2), surfaceArea(target), "disk");
    ASSERT_EQ(disks.size(), 1u);
    const Sheet& disk = disks.front().sheet;
    glm::dvec3 normal(0.0);
    for (const auto& t : disk.triangles)
      normal += glm::cross(disk.positions[t[1]] - disk.positions[t[0]],
                           disk.positions[t[2]] - disk.positions[t[0]]);
    normal = glm::normalize(normal);
    // The dish rises toward +z from its flat bottom: its bottom lies along -z.
    const glm::dvec3 bottom = turned({0.0, 0.0, -1.0}, axis, degrees);
    EXPECT_GT(glm::dot(normal, bottom), 0.99) << "turned " << degrees << " degrees about ("
                                              << axis.x << ", " << axis.y << ", " << axis.z << ")";
    ++checked;
  }
  EXPECT_EQ(checked, 16);
}

TEST(RingFolds, BringADiskCloserToADishThanAnySingleFold) {
  // A dish about z: a flat bottom of 6 cm radius rising to a rim 2.5 cm high, 14 cm out.
  const TriangleMesh target = revolvedByRadius(
      [](double r) { return r < 0.06 ? 0.0 : 0.025 * std::pow((r - 0.06) / 0.08, 2.0); }, 0.005,
      0.14, 48, 16);
  // From a disk of its area in its principal plane (the start fit places).
  const std::vector<PlacedStart> disks =
      placedStarts(sampleSurface(target, 1500, 2), surfaceArea(target), "disk");
  ASSERT_EQ(disks.size(), 1u);
  FitSettings settings;
  settings.proposals = testing::kSanitized ? 24 : 48;
  settings.rings = testing::kSanitized ? 64 : 256;
  settings.refineEvaluations = 30;  // the single folds' refinement: a few seconds in all
  FitSettings single = settings;
  single.rings = 0;
  settings.nestedRings = false;  // the profile rings alone (nested_rings.hpp has its own tests)
  const FoldFitter withRings(target, settings), singleFolds(target, single);
  FoldSession session(disks.front().sheet);
  const double before = withRings.approximateDistance(session.fixed());
  const std::vector<FoldSuggestion> one = singleFolds.suggest(session, 1);
  const std::vector<FoldSuggestion> ring = withRings.suggest(session, 1);
  ASSERT_FALSE(ring.empty());
  EXPECT_GT(ring.front().folds.size(), 1u);  // a ring, not one fold
  EXPECT_LT(ring.front().after, 0.8 * before);
  if (!one.empty()) {
    EXPECT_LT(ring.front().after, one.front().after);
  }
  validate(ring.front().sheet);
  EXPECT_EQ(session.foldCount(), 0u);  // the session is left as it was
}

TEST(NeckRings, TheCutTubesMeanRadiusMatchesTheStarDrawnPointByPoint) {
  for (const int order : {6, 8, 16})
    for (const double q : {1.0, 0.995, 0.98, std::cos(std::numbers::pi / order)}) {
      // n planes at q from the axis of a unit circle, each reflecting what lies beyond it.
      const int points = 20000;
      double sum = 0.0;
      for (int i = 0; i < points; ++i) {
        const double a = 2.0 * std::numbers::pi * (i + 0.5) / points;
        glm::dvec2 p(std::cos(a), std::sin(a));
        for (int k = 0; k < order; ++k) {
          const double b = 2.0 * std::numbers::pi * k / order;
          const glm::dvec2 e(std::cos(b), std::sin(b));
          const double beyond = glm::dot(p, e) - std::max(q, std::cos(std::numbers::pi / order));
          if (beyond > 0.0) p -= 2.0 * beyond * e;
        }
        sum += glm::length(p);
      }
      EXPECT_NEAR(ringCutRadius(q, order), sum / points, 1e-4) << order << " planes at " << q;
    }
}

TEST(NeckRings, ARingSolvedOnTheProfileFollowsATaperingNeck) {
  // The catalogue's tube (5 cm radius, 20 cm along y, centred) toward one that keeps its radius
  // up to its middle and narrows to 4.6 cm at its top.
  const Sheet tube = tubeSheet();
  auto neck = [](double y) { return y <= 0.0 ? 0.05 : 0.05 - 0.04 * y; };
  TriangleMesh target = revolved(neck, -0.1, 0.1, 64, 40);
  for (glm::dvec3& p : target.positions) p = {p.x, p.z, -p.y};  // about y, top at y = 0.1
  const std::vector<SurfaceSample> targetSamples = sampleSurface(target, 3000, 5);
  const std::vector<SurfaceSample> sheetSamples = sampleSurface(meshOf(tube), 3000, 6);
  const std::optional<RevolutionAxis> axis = revolutionAxis(targetSamples);
  ASSERT_TRUE(axis);
  ASSERT_GT(std::abs(axis->direction.y), 0.999);

  // The mean radius by height of samples, over 10 bands of the tube's length.
  auto profile = [](const std::vector<glm::dvec3>& points) {
    std::vector<double> sum(10, 0.0), count(10, 0.0);
    for (const glm::dvec3& p : points) {
      const int b = std::clamp(static_cast<int>((p.y + 0.1) / 0.02), 0, 9);
      sum[b] += std::hypot(p.x, p.z);
      count[b] += 1.0;
    }
    for (int b = 0; b < 10; ++b) sum[b] /= std::max(count[b], 1.0);
    return sum;
  };
  std::vector<glm::dvec3> targetPoints;
  for (const SurfaceSample& s : targetSamples) targetPoints.push_back(s.position);
  const std::vector<double> wanted = profile(targetPoints);
  auto worstGap = [&](const std::vector<glm::dvec3>& points) {
    const std::vector<double> got = profile(points);
    double worst = 0.0;
    for (int b = 0; b < 10; ++b) worst = std::max(worst, std::abs(got[b] - wanted[b]));
    return worst;
  };
  std::vector<glm::dvec3> points, normals;
  for (const SurfaceSample& s : sheetSamples) {
    points.push_back(s.position);
    normals.push_back(s.normal);
  }
  const double untouched = worstGap(points);
  EXPECT_GT(untouched, 0.003);  // the top band: 5 cm against about 4.64 cm

  const std::vector<RingShape> rings = neckRings(sheetSamples, targetSamples, *axis);
  ASSERT_FALSE(rings.empty());
  double best = 1e300;
  RingShape chosen;
  for (const RingShape& shape : rings) {
    std::vector<glm::dvec3> p = points, n = normals;
    previewRing(ringOf(shape, *axis), p, n);
    if (const double gap = worstGap(p); gap < best) {
      best = gap;
      chosen = shape;
    }
  }
  // Solved, not searched: the band means follow the neck within a fifth of the tube's gap.
  EXPECT_LT(best, 0.2 * untouched) << "best ring leaves " << best << " m";

  // Made on the sheet, the ring keeps it valid and passes nothing through itself.
  FoldSession session(tube);
  EXPECT_EQ(makeRing(session, ringOf(chosen, *axis)), static_cast<std::size_t>(chosen.order));
  validate(session.fixed());
  EXPECT_TRUE(findSelfIntersections(session.fixed()).intersections.empty());
}

// A vase about z, 20 cm tall: a belly of 5.5 cm at its middle narrowing to 4 cm at the foot and
// the neck (rings narrow a tube: the belly is where the tube starts).
TriangleMesh bellyVase() {
  return revolved([](double h) { return 0.04 + 0.015 * std::cos(std::numbers::pi * h / 0.2); },
                  -0.1, 0.1, 64, 40);
}

TEST(StartSurface, AVasesCylinderIsAsWideAsItsBelly) {
  const StartChoice start = chooseStart(bellyVase(), "cylinder");
  ASSERT_TRUE(start.placed);
  EXPECT_EQ(start.surface, "cylinder");
  // The widest of 16 bands of height: 5.5 cm less the band's own narrowing (the mean radius of
  // the whole vase is about 4.95 cm).
  EXPECT_NEAR(start.parameters.at("radius"), 0.0549, 0.0006);
  EXPECT_NEAR(start.parameters.at("height"), 0.2, 0.002);
}

// A vase 2.5 radii tall (two principal axes nearly alike) with two holes, as a scan leaves it:
// its principal axes lie 30 degrees off the one it turns about, and without a kind asked for the
// start was a cone placed on them, 5.1% of the diagonal away (Chamfer) against `--from
// cylinder`'s 1.75% (judge19). The tube and the cone about its own axis are candidates too.
TEST(StartSurface, AScannedSquatVaseStartsAboutItsOwnAxis) {
  TriangleMesh vase = revolved(
      [](double h) {
        return 0.04 * (1.0 + 0.15 * std::sin(std::numbers::pi * (h + 0.05) / 0.1 + 0.5));
      },
      -0.05, 0.05, 48, 30);
  const std::vector<std::pair<glm::dvec3, double>> holes = {{{0.045, 0.0, 0.02}, 0.02},
                                                            {{-0.03, 0.03, -0.03}, 0.015}};
  std::erase_if(vase.triangles, [&](const auto& t) {
    const glm::dvec3 c = (vase.positions[t[0]] + vase.positions[t[1]] + vase.positions[t[2]]) / 3.0;
    return std::any_of(holes.begin(), holes.end(),
                       [&](const auto& hole) { return glm::length(c - hole.first) < hole.second; });
  });
  const StartChoice tube = chooseStart(vase, "cylinder");
  const StartChoice any = chooseStart(vase);
  ASSERT_TRUE(any.placed);
  EXPECT_TRUE(any.surface == "cylinder" || any.surface == "cone") << any.surface;
  EXPECT_LT(any.chamfer, 1.1 * tube.chamfer) << any.placement;
}

// bench/make_judge20_shapes.py's vase about z, in metres (see below).
TriangleMesh judge20Vase() {
  return revolved(
      [](double h) {
        const double s = (h + 0.105) / 0.21;
        return 0.045 + 0.011 * std::sin(1.7 * std::numbers::pi * s) -
               0.006 * (2.0 * s - 1.0) * (2.0 * s - 1.0);
      },
      -0.105, 0.105, 48, 24);
}

// bench/make_judge20_shapes.py's vase about z: a belly low (5.5 cm), a foot of 3.9 cm, a neck
// narrowing to 3 cm. The cone placed through its profile starts nearer, but its belly stands
// outside it, where no ring reaches; without a kind asked for the start was that cone, whose
// fit ended at 6.36% Hausdorff against 3.36% from the tube as wide as the belly (judge20). The
// tubes' reach (tube_reach.hpp) now picks the widest tube.
TEST(StartSurface, AVaseWhoseBellyStandsOutsideThePlacedConeStartsFromItsWidestTube) {
  const TriangleMesh vase = judge20Vase();
  const StartChoice start = chooseStart(vase);
  ASSERT_TRUE(start.placed);
  EXPECT_EQ(start.surface, "cylinder") << start.placement;
  EXPECT_NEAR(start.parameters.at("radius"), 0.055, 0.0015) << start.placement;
}

// The same vase in millimetres: the start's note gives the rings' reach in the target's own
// numbers, as the fit's lines do (target_units.hpp), not as metres it is not in ("2.28e+03 mm").
TEST(StartSurface, AVaseInMillimetresIsToldItsRingsReachInItsOwnUnits) {
  TriangleMesh vase = judge20Vase();
  for (glm::dvec3& p : vase.positions) p *= 1000.0;
  const StartChoice start = chooseStart(vase);
  ASSERT_TRUE(start.placed);
  EXPECT_EQ(start.surface, "cylinder") << start.placement;
  EXPECT_NE(start.placement.find("its rings could come within"), std::string::npos)
      << start.placement;
  EXPECT_NE(start.placement.find(" units of the target's profile"), std::string::npos)
      << start.placement;
  EXPECT_EQ(start.placement.find(" mm"), std::string::npos) << start.placement;
}

// The same vase in inches (10.3 across its diagonal: 36 times the default square's, within the
// hundredfold that the check of a sheet keeps): its lengths are its own numbers too, not metres
// (bench/make_stl_soup_targets.py's lamp_bulge_in, 18.7 inches across, printed "842 mm").
TEST(StartSurface, AVaseInInchesIsToldItsRingsReachInItsOwnUnits) {
  TriangleMesh vase = judge20Vase();
  for (glm::dvec3& p : vase.positions) p /= 0.0254;
  EXPECT_FALSE(lengthsInMetres(boundingDiagonal(vase)));
  EXPECT_TRUE(lengthsInMetres(0.0254 * boundingDiagonal(vase)));  // the vase in metres
  const StartChoice start = chooseStart(vase);
  ASSERT_TRUE(start.placed);
  EXPECT_NE(start.placement.find(" units of the target's profile"), std::string::npos)
      << start.placement;
  EXPECT_EQ(start.placement.find(" mm"), std::string::npos) << start.placement;
}

// A vase open at both ends (bench/make_stl_soup_targets.py's open_vase_mm, in metres): a belly
// of 10 cm, a neck of 4.1 cm and a lip flared back to 6 cm over its top band. The hull of the
// whole profile bridges the neck from the belly to that lip, so the widest tube's rings rank no
// nearer than the placed cone's (14.6 mm against 14.5 mm) and the cone stays the start; with the
// hulls' ends standing level the tube's rings reach (a ratio of 0.31), so it is folded beside the
// cone as a runner-up (open26: open_vase_mm's fit kept it, nearer by both measures).
TEST(StartSurface, AnOpenVaseWithALipFlaredAboveItsNeckHasItsWidestTubeAsARunnerUp) {
  const TriangleMesh vase = revolved(
      [](double h) {
        const double t = h / 0.35;
        return 0.041 + 0.059 * std::exp(-std::pow((t - 0.35) / 0.28, 2.0)) +
               0.0205 * std::exp(-std::pow((t - 1.0) / 0.08, 2.0));
      },
      0.0, 0.35, 48, 36);
  const StartChoice start = chooseStart(vase);
  EXPECT_EQ(start.surface, "cone") << start.placement;
  const auto tube =
      std::find_if(start.runnersUp.begin(), start.runnersUp.end(),
                   [](const RunnerUpStart& r) { return r.surface == "cylinder" && r.placed; });
  ASSERT_NE(tube, start.runnersUp.end()) << start.placement;
  EXPECT_NEAR(tube->parameters.at("radius"), 0.1, 0.003) << tube->why;
  EXPECT_NE(tube->why.find("standing level"), std::string::npos) << tube->why;
}

// The tubes' reach: the upper concave hull passes over a waist by the chord from the belly to
// the lip, and a profile already concave is its own hull.
TEST(TubeReach, TheHullBridgesAWaistAndKeepsAConcaveProfile) {
  const std::vector<double> waist =
      upperConcaveHull({{0.0, 1.0}, {1.0, 2.0}, {2.0, 1.0}, {3.0, 1.5}, {4.0, 1.0}});
  ASSERT_EQ(waist.size(), 5u);
  EXPECT_DOUBLE_EQ(waist[2], 1.75);  // the chord from (1, 2) to (3, 1.5)
  EXPECT_DOUBLE_EQ(waist[1], 2.0);
  EXPECT_DOUBLE_EQ(waist[4], 1.0);
  const std::vector<glm::dvec2> belly = {{0.0, 1.0}, {1.0, 1.8}, {2.0, 2.0}, {3.0, 1.8}};
  const std::vector<double> same = upperConcaveHull(belly);
  for (std::size_t i = 0; i < belly.size(); ++i) EXPECT_DOUBLE_EQ(same[i], belly[i].y);
}

// From the widest tube, the fit's first step is a chain of rings solved together on the
// profile (ring_folds.hpp), narrowing the tube toward the foot and the neck: one step, without a
// clock, more than 1.6 times closer, every ring valid and free of self-intersections.
TEST(TubeRings, TheFitsFirstStepNarrowsTheWidestTubeTowardAVase) {
  // A whole first step with its chains: 117 s under the sanitizers, whose run
  // TubeRings.ANeckOfHalfTheTubeIsCutByCoarseRingsAndTheirCreasesFoldedIn's chain covers.
  if (testing::kSanitized) GTEST_SKIP() << "the Release run checks the first step (117 s here)";
  const TriangleMesh vase = bellyVase();
  const StartChoice start = chooseStart(vase, "cylinder");
  ASSERT_TRUE(start.placed);
  // The same tube, coarser (each ring is made and measured 20 times a step), turned onto z.
  Sheet tube = makeSurface("cylinder", {{"radius", start.parameters.at("radius")},
                                        {"height", start.parameters.at("height")},
                                        {"resolution", testing::kSanitized ? 16.0 : 24.0}});
  for (glm::dvec3& p : tube.positions) p = {p.x, -p.z, p.y};
  const FoldFitter fitter(vase, testing::sampledSettings(400, 1500, 4000));
  ASSERT_TRUE(fitter.revolutionTarget());
  ASSERT_TRUE(tubeAbout(tube, {0.0, 0.0, 1.0}));
  FoldSession session(tube);
  FitOptions options;
  options.maxFolds = 1;
  options.seconds = std::numeric_limits<double>::infinity();
  options.distanceSamples = 4000;
  const FitResult result = fitFolds(session, fitter, options);
  EXPECT_GE(result.folds.size(), 12u);  // two rings at least, as one step
  EXPECT_LT(result.steps.back().chamfer, result.steps.front().chamfer / 1.6)
      << result.steps.front().chamfer << " -> " << result.steps.back().chamfer << " m";
  validate(session.fixed());
  EXPECT_TRUE(findSelfIntersections(session.fixed()).intersections.empty());
}

// The tube rings' one step (ring_folds.hpp) from a coarse tube of radius `radius` and `length`
// about z toward `target`: the distance before and after (4000 samples a side) of the best
// chain, which must be valid and free of self-intersections.
struct TubeStep {
  SurfaceDistance before, after;
};
TubeStep tubeRingsStep(const TriangleMesh& target, double radius, double length) {
  Sheet tube = makeSurface(
      "cylinder",
      {{"radius", radius}, {"height", length}, {"resolution", testing::kSanitized ? 16.0 : 24.0}});
  for (glm::dvec3& p : tube.positions) p = {p.x, -p.z, p.y};
  const FoldFitter fitter(target, testing::sampledSettings(400, 1500, 4000));
  const std::vector<SurfaceSample> targetSamples = sampleSurface(target, 1500, 11);
  const std::optional<RevolutionAxis> axis = revolutionAxis(targetSamples);
  TubeStep step;
  step.before = step.after = surfaceDistance(meshOf(tube), target, 4000);
  if (!axis) {
    ADD_FAILURE() << "no axis";
    return step;
  }
  std::mt19937_64 random(5);
  const std::vector<FoldSuggestion> rings =
      suggestTubeRings(FoldSession(tube), fitter, *axis, targetSamples, 1,
                       Deadline::in(std::numeric_limits<double>::infinity()), random);
  if (rings.size() != 1) {
    ADD_FAILURE() << rings.size() << " chains";
    return step;
  }
  step.after = surfaceDistance(meshOf(rings.front().sheet), target, 4000);
  validate(rings.front().sheet);
  EXPECT_TRUE(findSelfIntersections(rings.front().sheet).intersections.empty());
  return step;
}

// A bottle whose shoulder narrows to half its body, below what a ring of 6 reaches (0.83 of the
// tube): rings of 4 and 5 cut deeper (with rings of 6 to 16 only, the step ends 1.7 times closer
// by Chamfer; with them, 3.9 times), and corner rings fold in the creases a ring leaves on the
// tube's radius, where the Hausdorff distance lies (without them it falls from 25 to 21 mm; with
// them, to 15 mm).
TEST(TubeRings, ANeckOfHalfTheTubeIsCutByCoarseRingsAndTheirCreasesFoldedIn) {
  const TriangleMesh bottle = revolved(
      [](double h) {
        const double s = std::clamp((h + 0.02) / 0.1, 0.0, 1.0);  // the shoulder, smoothstep
        return 0.05 - 0.025 * s * s * (3.0 - 2.0 * s);
      },
      -0.1, 0.1, 64, 40);
  const TubeStep step = tubeRingsStep(bottle, 0.05, 0.2);
  EXPECT_LT(step.after.chamfer, step.before.chamfer / 2.5)
      << step.before.chamfer << " -> " << step.after.chamfer << " m";
  EXPECT_LT(step.after.hausdorff, 0.7 * step.before.hausdorff)
      << step.before.hausdorff << " -> " << step.after.hausdorff << " m";
}

// A bottle closed at the bottom (bench/make_meridian_vases.py's bottle_short_neck, about z):
// its body the tube itself, a shoulder narrowing to a neck of 0.3 of it. The search's robust
// distance counts the far neck at a tenth and every millimetre the rings' tilted cuts move the
// body in full, so it rose (0.00149 -> 0.00151) while the rings' own measure halved, and the
// chains were dropped: the bottle got no rings (fit: one fold, Hausdorff 14.8%; with them 8.1%).
TEST(TubeRings, AClosedBottleIsNarrowedTowardItsNeck) {
  // The meridian (r, h) by its parameter u: bottom, rounded foot, body, shoulder, neck.
  const auto meridian = [](double u) -> std::pair<double, double> {
    const double quarter = 0.5 * std::numbers::pi;
    if (u < 0.15) return {0.037 * u / 0.15, 0.0};
    if (u < 0.2) {
      const double a = quarter * (u - 0.15) / 0.05;
      return {0.037 + 0.008 * std::sin(a), 0.008 * (1.0 - std::cos(a))};
    }
    if (u < 0.55) return {0.045, 0.008 + 0.162 * (u - 0.2) / 0.35};
    if (u < 0.8) {
      const double a = quarter * (u - 0.55) / 0.25;
      return {0.014 + 0.031 * std::cos(a), 0.17 + 0.045 * std::sin(a)};
    }
    return {0.014, 0.215 + 0.035 * (u - 0.8) / 0.2};
  };
  const int around = 48, along = 60;
  TriangleMesh bottle;
  for (int j = 0; j <= along; ++j)
    for (int i = 0; i < around; ++i) {
      const auto [r, h] = meridian(static_cast<double>(j) / along);
      const double a = 2.0 * std::numbers::pi * (i + 0.5 * (j % 2)) / around;
      bottle.positions.emplace_back(r * std::cos(a), r * std::sin(a), h - 0.125);
    }
  for (int j = 1; j < along; ++j)  // the row on the axis (j = 0) is left out: a fan of slivers
    for (int i = 0; i < around; ++i) {
      const auto at = [&](int ii, int jj) {
        return static_cast<std::uint32_t>(jj * around + (ii % around));
      };
      const int shift = j % 2;
      bottle.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1 - shift, j + 1)});
      bottle.triangles.push_back(
          {at(i, j), at(i + 1 - shift, j + 1), at(i + around - shift, j + 1)});
    }
  // As `fit` measures (its default samples), from the tube of the body's radius.
  Sheet tube = makeSurface("cylinder", {{"radius", 0.045}, {"height", 0.25}});
  for (glm::dvec3& p : tube.positions) p = {p.x, -p.z, p.y};
  const FoldFitter fitter(bottle, FitSettings{});
  const std::vector<SurfaceSample> targetSamples = sampleSurface(bottle, 1500, 11);
  const std::optional<RevolutionAxis> axis = revolutionAxis(targetSamples);
  ASSERT_TRUE(axis);
  std::mt19937_64 random(5);
  const std::vector<FoldSuggestion> rings =
      suggestTubeRings(FoldSession(tube), fitter, *axis, targetSamples, 2, Deadline{}, random);
  // Both chains (rings of 6 to 16, of 4 to 16) bring it closer by the rings' measure; here the
  // robust distance rose on one of them (0.00144 -> 0.00149), which was dropped.
  ASSERT_EQ(rings.size(), 2u);
  const SurfaceDistance before = surfaceDistance(meshOf(tube), bottle, 4000);
  const SurfaceDistance after = surfaceDistance(meshOf(rings.front().sheet), bottle, 4000);
  EXPECT_LT(after.chamfer, 0.8 * before.chamfer) << before.chamfer << " -> " << after.chamfer;
  EXPECT_LT(after.hausdorff, before.hausdorff) << before.hausdorff << " -> " << after.hausdorff;
  validate(rings.front().sheet);
  EXPECT_TRUE(findSelfIntersections(rings.front().sheet).intersections.empty());
}

// A cone about z, 20 cm tall, its radius 5.25 cm at the foot and 3.75 cm at the top, and a vase
// inside it: the cone's radius at its middle, 0.8 of it at the foot and at the neck.
double coneRadius(double h) {
  return 0.045 - 0.075 * h;
}
TriangleMesh vaseInsideCone() {
  return revolved(
      [](double h) { return coneRadius(h) * (0.8 + 0.2 * std::cos(std::numbers::pi * h / 0.2)); },
      -0.1, 0.1, 64, 40);
}

// A vase's cone is a tube the rings narrow as they narrow a cylinder (ring_folds.hpp): the tube
// rings' chain from a cone about the vase's axis, toward the foot and the neck, more than 1.5
// times closer by Chamfer and nearer its farthest point (with cones left out of tubeAbout there is
// no chain at all: the fit's first step from the cone it places on a vase was single folds).
TEST(TubeRings, AConeIsNarrowedTowardAVaseAsATubeIs) {
  if (testing::kSanitized) GTEST_SKIP() << "the Release run checks the cone's chain (82 s here)";
  Sheet cone = makeSurface("cone", {{"base_radius", coneRadius(-0.1)},
                                    {"top_radius", coneRadius(0.1)},
                                    {"height", 0.2},
                                    {"resolution", testing::kSanitized ? 16.0 : 32.0}});
  for (glm::dvec3& p : cone.positions) p = {p.x, -p.z, p.y};  // its axis y onto z
  const std::optional<TubeAxis> tube = tubeAbout(cone, {0.0, 0.0, 1.0});
  ASSERT_TRUE(tube);
  EXPECT_NEAR(tube->radius, 0.045, 0.002);

  const TriangleMesh vase = vaseInsideCone();
  const FoldFitter fitter(vase, testing::sampledSettings(400, 1500, 4000));
  const std::vector<SurfaceSample> targetSamples = sampleSurface(vase, 1500, 11);
  const std::optional<RevolutionAxis> axis = revolutionAxis(targetSamples);
  ASSERT_TRUE(axis);
  std::mt19937_64 random(5);
  const std::vector<FoldSuggestion> rings =
      suggestTubeRings(FoldSession(cone), fitter, *axis, targetSamples, 1,
                       Deadline::in(std::numeric_limits<double>::infinity()), random);
  ASSERT_EQ(rings.size(), 1u);
  const SurfaceDistance before = surfaceDistance(meshOf(cone), vase, 4000);
  const SurfaceDistance after = surfaceDistance(meshOf(rings.front().sheet), vase, 4000);
  EXPECT_LT(after.chamfer, before.chamfer / 1.5) << before.chamfer << " -> " << after.chamfer;
  EXPECT_LT(after.hausdorff, before.hausdorff) << before.hausdorff << " -> " << after.hausdorff;
  validate(rings.front().sheet);
  EXPECT_TRUE(findSelfIntersections(rings.front().sheet).intersections.empty());
}

// The mean radius about z of `samples` in each of `bins` bands of height over [low, high].
std::vector<glm::dvec2> radiusByHeight(const std::vector<glm::dvec3>& points, double low,
                                       double high, int bins) {
  std::vector<glm::dvec2> sum(bins, glm::dvec2(0.0));
  std::vector<int> count(bins, 0);
  for (const glm::dvec3& p : points) {
    const int b = std::clamp(static_cast<int>((p.z - low) / (high - low) * bins), 0, bins - 1);
    sum[b] += glm::dvec2(p.z, std::hypot(p.x, p.y));
    ++count[b];
  }
  std::vector<glm::dvec2> out;
  for (int b = 0; b < bins; ++b)
    if (count[b] > 0) out.push_back(sum[b] / static_cast<double>(count[b]));
  return out;
}

// The cone around a vase's profile (placed_start.hpp, enclosingCone) lies outside every band's
// mean radius and touches the belly, tapering as the vase does; the cone fitted through the
// profile (the start fit places) lies inside the belly, where no ring reaches.
TEST(TubeStart, TheConeAroundAVaseEnclosesItsBelly) {
  const TriangleMesh vase = vaseInsideCone();
  const std::vector<SurfaceSample> samples = sampleSurface(vase, 4000, 3);
  const std::optional<PlacedStart> around =
      enclosingCone(samples, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, kTubeRingSteepestTaper);
  ASSERT_TRUE(around);
  EXPECT_EQ(around->surface, "cone");
  // Its radius at each height, read from its own vertices, against the vase's.
  std::vector<glm::dvec3> targetPoints;
  for (const SurfaceSample& s : samples) targetPoints.push_back(s.position);
  const std::vector<glm::dvec2> sheet = radiusByHeight(around->sheet.positions, -0.1, 0.1, 8);
  const std::vector<glm::dvec2> target = radiusByHeight(targetPoints, -0.1, 0.1, 8);
  ASSERT_EQ(sheet.size(), target.size());
  double leastGap = 1e300;
  for (std::size_t b = 0; b < sheet.size(); ++b) {
    EXPECT_GE(sheet[b].y, target[b].y - 5e-4) << "band at " << target[b].x;
    leastGap = std::min(leastGap, sheet[b].y - target[b].y);
  }
  EXPECT_LT(leastGap, 1.5e-3);  // it touches the belly, not a tube far outside
  const StartChoice nearest = chooseStart(vase);
  ASSERT_TRUE(nearest.placed);
  const std::vector<glm::dvec2> inside = radiusByHeight(nearest.placed->positions, -0.1, 0.1, 8);
  double deepest = 0.0;
  for (std::size_t b = 0; b < std::min(inside.size(), target.size()); ++b)
    deepest = std::max(deepest, target[b].y - inside[b].y);
  EXPECT_GT(deepest, 1e-3) << "the nearest start should lie inside the belly";
}

// The cone around a vase's profile is not taken where its rings land nearer by Chamfer but leave
// the sheet farther from the target by Hausdorff than the start's own rings (first_step_start.hpp,
// reviseTubeByFirstStep): on this vase, whose belly stands outside the cone fitted through its
// profile, the cone around's two rings land at 1.81 / 7.48 mm (Chamfer / Hausdorff), the cone
// through's at 1.82 / 6.05 mm; without the guard the cone around was taken, and the fit started
// where its farthest point is farther (the lathe vase's fit ended 7.06% -> 10.2% by Hausdorff).
TEST(TubeStart, TheConeAroundIsNotTakenWhereItsRingsLandFartherByHausdorff) {
  // Two full starts each given chains of rings: 90 s under the sanitizers, whose run the other
  // tube tests' chains already cover; the Release run checks the choice.
  if (testing::kSanitized) GTEST_SKIP() << "the Release run checks the choice (90 s here)";
  const TriangleMesh vase = vaseInsideCone();
  const FoldFitter fitter(vase, testing::sampledSettings(400, 1500, 4000));
  ASSERT_TRUE(fitter.revolutionTarget());
  StartChoice start = chooseStart(vase);
  ASSERT_TRUE(start.placed);
  const Sheet nearest = *start.placed;
  const std::optional<FirstStepStart> chosen = reviseTubeByFirstStep(start, fitter, "", {});
  if (chosen) {
    ADD_FAILURE() << "the cone around was taken: its rings land " << chosen->chamfer << " / "
                  << chosen->hausdorff << " m against " << chosen->replacedChamfer << " / "
                  << chosen->replacedHausdorff << " m";
  }
  ASSERT_TRUE(start.placed);
  EXPECT_EQ(start.placed->positions, nearest.positions);
}

// bench/make_judge_shapes.py's vase profile about z, 20 cm tall, belly 5 cm: a neck of 0.24 of
// the belly at 0.8 of the height under a lip flaring to 0.57 of it.
TriangleMesh judgeVase() {
  return revolved(
      [](double h) {
        const double t = (h + 0.1) / 0.2;
        return 0.05 * (0.45 + 0.55 * std::exp(-std::pow((t - 0.35) / 0.25, 2.0)) -
                       0.25 * std::exp(-std::pow((t - 0.8) / 0.1, 2.0)) +
                       0.25 * std::max(t - 0.88, 0.0) / 0.12);
      },
      -0.1, 0.1, 48, 30);
}

// A neck far narrower than the belly (bench/make_judge_shapes.py's vase: 0.22 of it) is cut by
// ring after ring, each cutting the corners the rings before it left on the tube's radius
// (ring_folds.hpp, kTubeChainRings): the chain goes on past four rings and ends closer than the
// same chain stopped at four (the first four rings are the same: the same seed draws them).
TEST(TubeRings, ANarrowNeckIsCutByMoreThanFourRings) {
  // Two chains of up to eight rings: 110 s under the sanitizers, whose run the other tube tests'
  // chains already cover; the Release run checks the chain's length.
  if (testing::kSanitized) GTEST_SKIP() << "the Release run checks the chain (110 s here)";
  const TriangleMesh vase = judgeVase();
  Sheet tube = makeSurface(
      "cylinder",
      {{"radius", 0.05}, {"height", 0.2}, {"resolution", testing::kSanitized ? 16.0 : 24.0}});
  for (glm::dvec3& p : tube.positions) p = {p.x, -p.z, p.y};
  const FoldFitter fitter(vase, testing::sampledSettings(400, 1500, 4000));
  const std::vector<SurfaceSample> targetSamples = sampleSurface(vase, 1500, 11);
  const std::optional<RevolutionAxis> axis = revolutionAxis(targetSamples);
  ASSERT_TRUE(axis);
  const FoldSession session(tube);
  std::mt19937_64 random(5), again(5);
  const std::vector<FoldSuggestion> chain =
      suggestTubeRings(session, fitter, *axis, targetSamples, 1, Deadline{}, random);
  const std::vector<FoldSuggestion> four =
      suggestTubeRings(session, fitter, *axis, targetSamples, 1, Deadline{}, again, 4);
  ASSERT_EQ(chain.size(), 1u);
  ASSERT_EQ(four.size(), 1u);
  EXPECT_GT(chain.front().folds.size(), four.front().folds.size());
  const SurfaceDistance fourAfter = surfaceDistance(meshOf(four.front().sheet), vase, 4000);
  const SurfaceDistance after = surfaceDistance(meshOf(chain.front().sheet), vase, 4000);
  EXPECT_LT(after.chamfer, fourAfter.chamfer) << fourAfter.chamfer << " -> " << after.chamfer;
  validate(chain.front().sheet);
  EXPECT_TRUE(findSelfIntersections(chain.front().sheet).intersections.empty());
}

// A neck pleat (ring_folds.hpp, neckPleat; a ring of 3): its first ring folds each wedge in down
// to the neck, its return ring turns each flap's part past the neck back out, so the lip stands
// wider than the neck (the first ring alone leaves it narrower), and the return folds take their
// own flaps, not the tube's far wall, which their planes' sides also hold (seeded at the farthest
// vertex, each return fold mirrored the whole tube across its plane: the uncut foot left the axis).
TEST(TubeRings, ANeckPleatTurnsItsFlapsBackOutPastTheNeck) {
  const TriangleMesh vase = judgeVase();
  Sheet tube = makeSurface("cylinder", {{"radius", 0.05}, {"height", 0.2}, {"resolution", 24.0}});
  for (glm::dvec3& p : tube.positions) p = {p.x, -p.z, p.y};
  const std::vector<SurfaceSample> targetSamples = sampleSurface(vase, 1500, 11);
  const std::vector<SurfaceSample> sheetSamples = sampleSurface(meshOf(tube), 1200, 3);
  const std::optional<RevolutionAxis> axis = revolutionAxis(targetSamples);
  ASSERT_TRUE(axis);
  ASSERT_GT(std::abs(axis->direction.z), 0.999);
  const int lipEnd = axis->direction.z > 0.0 ? 1 : -1;
  const std::optional<std::array<RingShape, 2>> pleat =
      neckPleat(sheetSamples, targetSamples, *axis, 3, 0.0, lipEnd);
  ASSERT_TRUE(pleat);

  FoldSession session(tube);
  ASSERT_EQ(makeRing(session, ringOf((*pleat)[0], *axis)), 3u);
  // Mean radius about z of 10 bands over the height: the neck at 0.8 (band 8), the lip band 9.
  const auto bands = [](const Sheet& sheet) {
    return radiusByHeight(sheet.positions, -0.1, 0.1, 10);
  };
  const std::vector<glm::dvec2> cut = bands(session.fixed());
  ASSERT_EQ(cut.size(), 10u);
  EXPECT_LT(cut[9].y, cut[8].y) << "the first ring alone deepens past the neck";
  ASSERT_EQ(makeRing(session, ringOf((*pleat)[1], *axis)), 3u);
  const std::vector<glm::dvec2> pleated = bands(session.fixed());
  ASSERT_EQ(pleated.size(), 10u);
  EXPECT_GT(pleated[9].y, pleated[8].y + 0.002) << "the lip turned back out past the neck";
  EXPECT_LT(pleated[8].y, 0.045);  // the neck cut in from the tube's 5 cm
  // The foot, uncut, stays on the axis (the middle of its box: the seam's vertices are twice).
  glm::dvec2 low(1e300), high(-1e300);
  for (const glm::dvec3& p : session.fixed().positions)
    if (p.z < -0.09) {
      low = glm::min(low, glm::dvec2(p));
      high = glm::max(high, glm::dvec2(p));
    }
  ASSERT_LT(low.x, high.x);
  EXPECT_LT(glm::length(0.5 * (low + high)), 1e-3) << "the foot moved off the axis";
  EXPECT_NEAR(pleated[0].y, 0.05, 1e-3);
  validate(session.fixed());
  EXPECT_TRUE(findSelfIntersections(session.fixed()).intersections.empty());
}

// The batches' clock (timed_batches.hpp): the first batch runs, and one the time left would not
// finish at the last batch's rate is not started (nor any after it). Two candidates of 60 ms
// each, then four more of the same cost with 180 ms left at most: refused.
TEST(TimedBatches, ABatchTheTimeLeftWouldNotFinishIsNotStarted) {
  const Deadline deadline = Deadline::in(0.3);
  TimedBatches batches(deadline);
  std::atomic<int> ran{0};
  const auto slow = [&](std::size_t) {
    std::this_thread::sleep_for(std::chrono::milliseconds(60));
    ++ran;
  };
  tbb::task_arena one(1);  // one at a time, whatever the machine's cores
  one.execute([&] {
    EXPECT_TRUE(batches.run(0, 2, 2.0, slow));
    EXPECT_FALSE(batches.run(2, 6, 4.0, slow));
    EXPECT_FALSE(batches.run(6, 7, 0.5, slow));  // none after a refusal
  });
  EXPECT_EQ(ran.load(), 2);
  EXPECT_TRUE(batches.cut());
  // Without a clock every batch runs.
  TimedBatches never{Deadline{}};
  EXPECT_TRUE(never.run(0, 1, 1.0, [&](std::size_t) { ++ran; }));
  EXPECT_TRUE(never.run(1, 3, 100.0, [&](std::size_t) { ++ran; }));
  EXPECT_EQ(ran.load(), 5);
  EXPECT_FALSE(never.cut());
}

// A step's batches differ in cost per unit (the nested rings' solved rings and searched shapes:
// 1.9-3.8 ms per fold made in one step), so the next batch is judged by the dearest rate seen, not
// the last (a batch judged by a cheap one ran past the fit's deadline: the final measure of
// NestedRings.TheFinalMeasureOfManyRingsKeepsWithinTheTime then fell after the limit). One
// candidate of 100 ms per unit, four of 10 ms per unit, then ten units with under 0.9 s left:
// refused at the dearest rate (1 s), though the last (0.1 s) would start it.
TEST(TimedBatches, ABatchIsJudgedByTheDearestRateItsStepHasSeen) {
  const Deadline deadline = Deadline::in(1.0);
  TimedBatches batches(deadline);
  std::atomic<int> ran{0};
  const auto taking = [&](int milliseconds) {
    return [&ran, milliseconds](std::size_t) {
      std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds));
      ++ran;
    };
  };
  tbb::task_arena one(1);  // one at a time, whatever the machine's cores
  one.execute([&] {
    EXPECT_TRUE(batches.run(0, 1, 1.0, taking(100)));
    EXPECT_TRUE(batches.run(1, 5, 4.0, taking(10)));
    EXPECT_FALSE(batches.run(5, 15, 10.0, taking(1)));
  });
  EXPECT_EQ(ran.load(), 5);
  EXPECT_TRUE(batches.cut());
}

// The chains cut short by the clock (issue 38, 2: at --time 60 on a loaded machine a vase kept no
// fold, the chain answering nothing until every ring of both chains was made): the step still
// answers the rings the chains made whole. The deadline is a quarter of what the whole step took
// here (timed first, so it holds under the sanitizers and under load): the first batch (the fine
// chain's solved rings) always runs, later batches the time left would not hold do not start.
// A ring may be of 4 planes (the coarse chain, kAllOrders): under load in CI the cut answered
// that chain's ring of 4 folds.
TEST(TubeRings, AStepTheClockCutsStillAnswersTheRingsMadeWhole) {
  const TriangleMesh bottle = revolved(
      [](double h) {
        const double s = std::clamp((h + 0.02) / 0.1, 0.0, 1.0);
        return 0.05 - 0.025 * s * s * (3.0 - 2.0 * s);
      },
      -0.1, 0.1, 48, 30);
  Sheet tube = makeSurface(
      "cylinder",
      {{"radius", 0.05}, {"height", 0.2}, {"resolution", testing::kSanitized ? 16.0 : 24.0}});
  for (glm::dvec3& p : tube.positions) p = {p.x, -p.z, p.y};
  FitSettings settings;
  settings.sheetSamples = 400;
  settings.targetSamples = 1500;
  settings.denseTargetSamples = 4000;
  const FoldFitter fitter(bottle, settings);
  const std::vector<SurfaceSample> targetSamples = sampleSurface(bottle, 1500, 11);
  const std::optional<RevolutionAxis> axis = revolutionAxis(targetSamples);
  ASSERT_TRUE(axis);
  const FoldSession session(tube);
  std::atomic<std::uint64_t> all{0};
  std::mt19937_64 random(5);
  const auto started = std::chrono::steady_clock::now();
  const std::vector<FoldSuggestion> whole = suggestTubeRings(
      session, fitter, *axis, targetSamples, 1, testing::counting(Deadline{}, all), random, 2);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  ASSERT_EQ(whole.size(), 1u);

  std::atomic<std::uint64_t> evaluations{0};
  std::mt19937_64 again(5);
  const std::vector<FoldSuggestion> cut =
      suggestTubeRings(session, fitter, *axis, targetSamples, 1,
                       testing::counting(Deadline::in(0.25 * seconds), evaluations), again, 2);
  ASSERT_EQ(cut.size(), 1u) << "a step the clock cut answered nothing";
  EXPECT_LT(evaluations.load(), all.load());  // the clock cut it
  EXPECT_GE(cut.front().folds.size(), 4u);    // a ring at least (the fewest planes: 4)
  EXPECT_LT(cut.front().after, cut.front().before);
  const SurfaceDistance before = surfaceDistance(meshOf(tube), bottle, 3000);
  const SurfaceDistance after = surfaceDistance(meshOf(cut.front().sheet), bottle, 3000);
  EXPECT_LT(after.chamfer, before.chamfer) << before.chamfer << " -> " << after.chamfer;
  validate(cut.front().sheet);
  EXPECT_TRUE(findSelfIntersections(cut.front().sheet).intersections.empty());
  EXPECT_EQ(session.foldCount(), 0u);
}

// The chains the start's probe grew are handed to the search (ring_folds.hpp, TubeChains;
// first_step_start.hpp, reviseTubeByFirstStep), which used to grow the same first rings again on
// the same sheet. Handed a chain as long as it may grow, a step scores no candidate and answers
// the handed rings themselves; allowed one ring more, it scores only that ring's candidates;
// handed chains grown on another sheet are not used.
TEST(TubeRings, AChainHandedOnIsGrownOnNotGrownAgain) {
  const TriangleMesh bottle = revolved(
      [](double h) {
        const double s = std::clamp((h + 0.02) / 0.1, 0.0, 1.0);
        return 0.05 - 0.025 * s * s * (3.0 - 2.0 * s);
      },
      -0.1, 0.1, 48, 30);
  Sheet tube = makeSurface("cylinder", {{"radius", 0.05}, {"height", 0.2}, {"resolution", 16.0}});
  for (glm::dvec3& p : tube.positions) p = {p.x, -p.z, p.y};
  const FoldFitter fitter(bottle, testing::sampledSettings(400, 1500, 4000));
  const std::vector<SurfaceSample> targetSamples = sampleSurface(bottle, 1500, 11);
  const std::optional<RevolutionAxis> axis = revolutionAxis(targetSamples);
  ASSERT_TRUE(axis);
  const FoldSession session(tube);
  TubeChains handed;
  std::atomic<std::uint64_t> probe{0};
  std::mt19937_64 random(5);
  const std::vector<FoldSuggestion> first =
      suggestTubeRings(session, fitter, *axis, targetSamples, 1,
                       testing::counting(Deadline{}, probe), random, 1, nullptr, &handed);
  ASSERT_EQ(first.size(), 1u);
  ASSERT_EQ(handed.chains.size(), 2u);
  EXPECT_EQ(handed.sheet, tube.positions);
  EXPECT_GT(probe.load(), 0u);

  std::atomic<std::uint64_t> full{0};
  std::mt19937_64 other(6);
  const std::vector<FoldSuggestion> again =
      suggestTubeRings(session, fitter, *axis, targetSamples, 1,
                       testing::counting(Deadline{}, full), other, 1, &handed);
  EXPECT_EQ(full.load(), 0u) << "the handed rings were searched again";
  ASSERT_EQ(again.size(), 1u);
  ASSERT_EQ(again.front().folds.size(), first.front().folds.size());
  for (std::size_t f = 0; f < first.front().folds.size(); ++f) {
    EXPECT_EQ(again.front().folds[f].plane.normal, first.front().folds[f].plane.normal);
  }

  std::atomic<std::uint64_t> fresh{0}, grownOn{0};
  std::mt19937_64 a(7), b(7);
  suggestTubeRings(session, fitter, *axis, targetSamples, 1, testing::counting(Deadline{}, fresh),
                   a, 2);
  const std::vector<FoldSuggestion> longer =
      suggestTubeRings(session, fitter, *axis, targetSamples, 1,
                       testing::counting(Deadline{}, grownOn), b, 2, &handed);
  EXPECT_LT(grownOn.load(), fresh.load());
  ASSERT_EQ(longer.size(), 1u);
  EXPECT_LT(longer.front().after, longer.front().before);

  // Chains grown on another sheet (the tube moved along its axis) are not remade on this one.
  TubeChains elsewhere = handed;
  for (glm::dvec3& p : elsewhere.sheet) p.y += 0.01;
  std::atomic<std::uint64_t> ignored{0};
  std::mt19937_64 c(6);
  suggestTubeRings(session, fitter, *axis, targetSamples, 1, testing::counting(Deadline{}, ignored),
                   c, 1, &elsewhere);
  EXPECT_GT(ignored.load(), 0u);
}

// A cone tilted off the world's axes is a tube about its own axis (ring_folds.hpp, tubeAbout):
// its axis point is the middle of its box across that axis, not of its box about the world's
// axes, which a tilted cone's wide base pulls off the axis (the placed cones of the tilted
// lathe, fluted and gourd vases were no tubes, and their rings were never offered).
TEST(TubeRings, ATiltedConeIsATubeAboutItsAxis) {
  Sheet cone =
      makeSurface("cone", {{"base_radius", 0.064}, {"top_radius", 0.036}, {"height", 0.2}});
  const glm::dvec3 tilt(1.0, 0.0, 1.0);
  for (glm::dvec3& p : cone.positions) p = turned(p, tilt, 35.0) + glm::dvec3(0.08, 0.04, 0.25);
  const glm::dvec3 axis = turned({0.0, 1.0, 0.0}, tilt, 35.0);
  const std::optional<TubeAxis> tube = tubeAbout(cone, axis);
  ASSERT_TRUE(tube);
  EXPECT_NEAR(tube->radius, 0.05, 0.002);
  // On the cone's axis: the centre of its middle circle.
  const glm::dvec3 offAxis = tube->axis.point - glm::dvec3(0.08, 0.04, 0.25);
  EXPECT_LT(glm::length(offAxis - glm::dot(offAxis, axis) * axis), 1e-3);
}

// A bowl's flat cone is no tube: its radius changes faster than kTubeRingSteepestTaper.
TEST(TubeRings, ABowlsFlatConeIsNoTube) {
  Sheet cone = makeSurface("cone", {{"base_radius", 0.08}, {"top_radius", 0.01}, {"height", 0.05}});
  EXPECT_FALSE(tubeAbout(cone, {0.0, 1.0, 0.0}));
}

}  // namespace
}  // namespace curvefold
