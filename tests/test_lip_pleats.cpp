// A flare's lip stepped out by pleats across the axis (issue 38, 2; engine/fit/lip_pleats.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/fit/floor_rings.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/lip_pleats.hpp"
#include "engine/fit/profile_folds.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "tests/fit_settings_support.hpp"

namespace curvefold {
namespace {

// An open surface of revolution about y, radius `radius(v)` at height 0.15 (1 - v) for v in
// [0, 1] (v = 1 at the bottom, y = 0), rings of `around`.
TriangleMesh lathe(const std::function<double(double)>& radius, int around = 48) {
  constexpr int kRings = 30;
  TriangleMesh mesh;
  for (int j = 0; j <= kRings; ++j) {
    const double v = static_cast<double>(j) / kRings;
    for (int i = 0; i < around; ++i) {
      const double a = 2.0 * std::numbers::pi * i / around;
      mesh.positions.emplace_back(radius(v) * std::cos(a), 0.15 * (1.0 - v),
                                  radius(v) * std::sin(a));
    }
  }
  const auto at = [&](int ring, int i) {
    return static_cast<std::uint32_t>(ring * around + (i % around));
  };
  for (int j = 0; j < kRings; ++j)
    for (int i = 0; i < around; ++i) {
      mesh.triangles.push_back({at(j, i), at(j, i + 1), at(j + 1, i + 1)});
      mesh.triangles.push_back({at(j, i), at(j + 1, i + 1), at(j + 1, i)});
    }
  return mesh;
}

// The largest distance from the y axis of the sheet's vertices within 5 mm of height y.
double outerRadiusAt(const Sheet& sheet, double y) {
  double widest = 0.0;
  for (const glm::dvec3& p : sheet.positions)
    if (std::abs(p.y - y) < 0.005) widest = std::max(widest, std::hypot(p.x, p.z));
  return widest;
}

// The catalogue's cone (narrow end up), its base at y = 0, fitted to a bell's narrow part.
Sheet coneAlong(double baseRadius, double topRadius) {
  Sheet cone = makeSurface("cone", {{"base_radius", baseRadius},
                                    {"top_radius", topRadius},
                                    {"height", 0.15},
                                    {"resolution", 40.0}});
  double lowest = 1e300;
  for (const glm::dvec3& p : cone.positions) lowest = std::min(lowest, p.y);
  for (glm::dvec3& p : cone.positions) p.y -= lowest;
  return cone;
}

// A bell whose radius grows as the square of the depth (3 cm at the top, 13 cm at the lip) and
// the cone along its upper half's slope (3 -> 8 cm): the lip stands 5 cm out of the cone. The
// pleats step it out, nothing crossing, and the lip comes nearer.
TEST(LipPleats, AConeInsideABellsLipHasItSteppedOut) {
  const TriangleMesh bell = lathe([](double v) { return 0.03 + 0.1 * v * v; });
  const Sheet cone = coneAlong(0.08, 0.03);
  const auto coneRadius = [](double y) { return 0.08 - y / 3.0; };

  const FoldFitter fitter(bell, testing::sampledSettings(400, 1500, 2000));
  const std::vector<SurfaceSample> samples = sampleSurface(bell, 2000, 7);
  const RevolutionAxis axis{glm::dvec3(0.0, 0.075, 0.0), glm::dvec3(0.0, 1.0, 0.0), 0.0};
  const std::optional<ConeProfile> profile = coneProfile(cone, axis.direction);
  ASSERT_TRUE(profile.has_value());
  EXPECT_LT(profile->axis.direction.y, -0.99);  // toward the wide end, down
  EXPECT_FALSE(lipStaircases(*profile, samples).empty());

  const std::vector<FoldSuggestion> step =
      suggestLipPleats(FoldSession(cone), fitter, axis, samples,
                       Deadline::in(std::numeric_limits<double>::infinity()));
  ASSERT_EQ(step.size(), 1u);
  const Sheet& stepped = step.front().sheet;
  validate(stepped);
  EXPECT_TRUE(findSelfIntersections(stepped).intersections.empty());
  EXPECT_GE(step.front().folds.size(), 2u);
  EXPECT_EQ(step.front().folds.size() % 2, 0u);  // whole pleats
  // The lip stepped out: at the stepped sheet's wide end (its rim retreats by the pleats'
  // widths), over a centimetre outside the cone's radius at that height.
  double lowest = 1e300;
  for (const glm::dvec3& p : stepped.positions) lowest = std::min(lowest, p.y);
  EXPECT_GT(outerRadiusAt(stepped, lowest + 0.002), coneRadius(lowest + 0.002) + 0.01);
  EXPECT_LT(floorMeasure(stepped, fitter), floorMeasure(cone, fitter));
}

// A conical shade the cone already follows has no lip standing out: no pleats, and a cylinder
// (no taper: a pleat moves it along itself unchanged) is no cone to step.
TEST(LipPleats, OnlyAFlareStandingOutOfATaperedConeIsStepped) {
  const TriangleMesh shade = lathe([](double v) { return 0.03 + 0.05 * v; });
  const Sheet cone = coneAlong(0.08, 0.03);
  const std::vector<SurfaceSample> samples = sampleSurface(shade, 2000, 7);
  const std::optional<ConeProfile> profile = coneProfile(cone, glm::dvec3(0.0, 1.0, 0.0));
  ASSERT_TRUE(profile.has_value());
  EXPECT_TRUE(lipStaircases(*profile, samples).empty());
  const Sheet cylinder = makeSurface("cylinder", {{"radius", 0.05}, {"height", 0.15}});
  EXPECT_FALSE(coneProfile(cylinder, glm::dvec3(0.0, 1.0, 0.0)).has_value());
}

}  // namespace
}  // namespace curvefold
