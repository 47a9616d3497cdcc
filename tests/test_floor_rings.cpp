// A steep cup's floor closed from a cone start (issue 38, 2; engine/fit/floor_rings.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/fit/floor_rings.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/profile_folds.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "tests/fit_settings_support.hpp"

namespace curvefold {
namespace {

// A steep cup about y, its flat floor (radius 4 cm) at y = 0.05 and its rim (5 cm) at y = -0.05,
// as the catalogue's cone stands (narrow end up): rings of `around` over a centre vertex.
TriangleMesh flatFlooredCup(int around = 48) {
  std::vector<glm::dvec2> profile;  // (radius, height) from the floor's centre to the rim
  for (int i = 1; i <= 6; ++i) profile.emplace_back(0.04 * i / 6.0, 0.05);
  for (int j = 1; j <= 12; ++j) profile.emplace_back(0.04 + 0.01 * j / 12.0, 0.05 - 0.1 * j / 12.0);
  TriangleMesh mesh;
  mesh.positions.emplace_back(0.0, 0.05, 0.0);
  for (const glm::dvec2& p : profile)
    for (int i = 0; i < around; ++i) {
      const double a = 2.0 * std::numbers::pi * i / around;
      mesh.positions.emplace_back(p.x * std::cos(a), p.y, p.x * std::sin(a));
    }
  const auto at = [&](std::size_t ring, int i) {
    return static_cast<std::uint32_t>(1 + ring * around + (i % around));
  };
  for (int i = 0; i < around; ++i) mesh.triangles.push_back({0, at(0, i + 1), at(0, i)});
  for (std::size_t r = 0; r + 1 < profile.size(); ++r)
    for (int i = 0; i < around; ++i) {
      mesh.triangles.push_back({at(r, i), at(r, i + 1), at(r + 1, i + 1)});
      mesh.triangles.push_back({at(r, i), at(r + 1, i + 1), at(r + 1, i)});
    }
  return mesh;
}

double nearestVertex(const Sheet& sheet, const glm::dvec3& point) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const glm::dvec3& p : sheet.positions) nearest = std::min(nearest, glm::length(p - point));
  return nearest;
}

// The cone along the cup's wall, reaching half the heel's radius past its floor (as the cone
// placed across a cup's profile reaches past it, narrower): its open end leaves the floor's
// centre 3.9 cm from the sheet; the floor ring turns the band in, and the centre comes within
// half that.
TEST(FloorRings, AConeUnderAFlatFlooredCupHasTheFloorsCentreBroughtNearer) {
  const TriangleMesh cup = flatFlooredCup();
  const double band = 0.5 * 0.04, taper = 0.1;
  Sheet cone = makeSurface("cone", {{"base_radius", 0.05},
                                    {"top_radius", 0.04 - taper * band},
                                    {"height", 0.1 + band},
                                    {"resolution", 40.0}});
  for (glm::dvec3& p : cone.positions) p.y += 0.5 * band;  // the rim stays at y = -0.05
  const glm::dvec3 centre(0.0, 0.05, 0.0);
  const double before = nearestVertex(cone, centre);
  ASSERT_GT(before, 0.038);

  const FoldFitter fitter(cup, testing::sampledSettings(400, 1500, 2000));
  const std::vector<SurfaceSample> samples = sampleSurface(cup, 1500, 7);
  const std::optional<TargetFloor> floor =
      targetFloor(samples, glm::dvec3(0.0), glm::dvec3(0.0, -1.0, 0.0));
  ASSERT_TRUE(floor.has_value());
  EXPECT_GT(floor->toward.y, 0.99);
  EXPECT_NEAR(floor->height, 0.05, 1e-6);

  const RevolutionAxis axis{glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0), 0.0};
  const std::vector<FoldSuggestion> step =
      suggestFloorRing(FoldSession(cone), fitter, axis, samples,
                       Deadline::in(std::numeric_limits<double>::infinity()));
  ASSERT_EQ(step.size(), 1u);
  const Sheet& closed = step.front().sheet;
  validate(closed);
  EXPECT_TRUE(findSelfIntersections(closed).intersections.empty());
  EXPECT_LT(nearestVertex(closed, centre), 0.5 * before);
  EXPECT_LT(floorMeasure(closed, fitter), floorMeasure(cone, fitter));
}

// A cup with no floor (a tube open at both ends) has none to close; a flat-floored cup's floor is
// found at its end, whichever way the axis is given.
TEST(FloorRings, OnlyACupWithAFloorHasOne) {
  const TriangleMesh cup = flatFlooredCup();
  TriangleMesh open = cup;
  open.triangles.erase(open.triangles.begin(), open.triangles.begin() + 48 + 2 * 48 * 5);
  const std::vector<SurfaceSample> cupSamples = sampleSurface(cup, 1500, 3);
  const std::vector<SurfaceSample> openSamples = sampleSurface(open, 1500, 3);
  EXPECT_FALSE(targetFloor(openSamples, glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0)).has_value());
  for (const double sign : {1.0, -1.0}) {
    const std::optional<TargetFloor> floor =
        targetFloor(cupSamples, glm::dvec3(0.0, 0.01, 0.0), glm::dvec3(0.0, sign, 0.0));
    ASSERT_TRUE(floor.has_value());
    EXPECT_GT(floor->toward.y, 0.99);
    EXPECT_NEAR(floor->height, 0.04, 1e-6);
  }
}

}  // namespace
}  // namespace curvefold
