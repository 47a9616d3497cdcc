// Self-contact of the bar-and-hinge model in paper mode (engine/simulation/contact.hpp, issue 39):
// the barrier's force is its energy's gradient, a sheet folded flat keeps its layers the paper's
// thickness apart, and patterns that fold flat in layers settle without passing through
// themselves.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/contact.hpp"
#include "engine/simulation/dynamic_solver.hpp"
#include "engine/simulation/static_solver.hpp"
#include "tests/simulation_test_support.hpp"

namespace curvefold {
namespace {

constexpr double kThickness = 1e-4;  // 0.1 mm paper

ModelOptions paperOptions(bool contact) {
  ModelOptions options;
  options.mode = SimulationMode::Paper;
  options.paper.thickness = kThickness;
  options.contact.enabled = contact;
  return options;
}

CreasePattern scaled(CreasePattern pattern, double factor) {
  for (glm::dvec2& v : pattern.vertices) v *= factor;
  return pattern;
}

// Within a stage the static solver's energy never rises.
void expectEnergyNeverRises(const StaticResult& result) {
  for (std::size_t k = 1; k < result.history.size(); ++k)
    if (result.history[k].stage == result.history[k - 1].stage) {
      EXPECT_LE(result.history[k].energy, result.history[k - 1].energy) << "iteration " << k;
    }
}

// The force addContactForces gives is minus the gradient of contactEnergy (central differences),
// on a sheet folded so that its halves lie within the activation gap of each other.
TEST(Contact, ForceIsTheBarriersGradient) {
  const BarHingeModel model =
      buildModel(scaled(testing::creasedSquare(4, 2, 180.0), 0.01), paperOptions(true));
  ASSERT_TRUE(model.contact.enabled);
  // The right half turned over onto the left, 1.5 thicknesses above it, then jittered.
  std::vector<glm::dvec3> x = model.flatPositions;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-0.2 * kThickness, 0.2 * kThickness);
  for (glm::dvec3& p : x) {
    if (p.x > 0.005) p = {0.01 - p.x, p.y, 1.5 * kThickness};
    p += glm::dvec3(jitter(random), jitter(random), jitter(random));
  }
  ASSERT_FALSE(findContactPairs(model, x, model.contact.activation).empty());
  std::vector<glm::dvec3> force(model.vertexCount(), glm::dvec3(0.0));
  addContactForces(model, x, force);
  double largest = 0.0;
  for (const glm::dvec3& f : force) largest = std::max(largest, glm::length(f));
  ASSERT_GT(largest, 0.0);
  const double h = 1e-4 * kThickness;
  for (std::size_t v = 0; v < model.vertexCount(); ++v)
    for (int c = 0; c < 3; ++c) {
      std::vector<glm::dvec3> plus = x, minus = x;
      plus[v][c] += h;
      minus[v][c] -= h;
      const double slope = (contactEnergy(model, plus) - contactEnergy(model, minus)) / (2.0 * h);
      EXPECT_NEAR(force[v][c], -slope, 1e-5 * largest) << "vertex " << v << " axis " << c;
    }
}

// One straight crease driven to 180 degrees in paper mode (a 40 mm sheet): without contact its
// halves close onto each other (the layers 0 apart); with it they settle a thickness apart or a
// little more, no triangle crossing another, and the static solver still reaches its tolerance
// with its energy never rising.
TEST(Contact, OneCreaseAt180DegreesSettlesWithItsLayersAThicknessApart) {
  const CreasePattern pattern = scaled(testing::creasedSquare(8, 4, 180.0), 0.04);
  const BarHingeModel model = buildModel(pattern, paperOptions(true));
  SimulationState state = flatState(model);
  const StaticOptions options;
  const StaticResult result = settle(model, 1.0, state, options);
  EXPECT_TRUE(result.converged);
  EXPECT_LE(result.residual, options.tolerance);
  expectEnergyNeverRises(result);
  EXPECT_EQ(crossingTrianglePairs(model, state.positions), 0u);
  const double gap = smallestLayerDistance(model, state.positions, kThickness, 0.01);
  EXPECT_GE(gap, kThickness);
  EXPECT_LE(gap, 2.0 * kThickness);
  // Folded: the crease within 10 degrees of flat (its first row of triangles holds the layers
  // apart), and the free edge lies on the one it was folded onto, a few thicknesses above it.
  const std::vector<double> error =
      creaseAngleError(model, state.positions, 1.0, state.hingeAngles);
  for (std::size_t j = 0; j < model.hinges.size(); ++j)
    if (model.hingeCrease[j]) {
      EXPECT_LT(std::abs(error[model.hingeEdge[j]]), 10.0) << j;
    }
  for (std::uint32_t v = 0; v < model.vertexCount(); ++v)
    if (pattern.vertices[v].x > 0.04 - 1e-9) {
      const std::uint32_t mirror = v - 8;  // the vertex at x = 0 of the same row
      const double apart = glm::distance(state.positions[v], state.positions[mirror]);
      EXPECT_LT(apart, 10.0 * kThickness) << v;
    }
}

// Patterns that fold flat in layers, at 100%: the waterbomb base (100 mm) and a Miura-ori of 4 by 4
// cells (60 mm). Every layer keeps the thickness from the others and no triangle crosses another.
TEST(Contact, FlatFoldingPatternsSettleWithoutSelfIntersection) {
  const std::vector<std::pair<const char*, CreasePattern>> patterns = {
      {"waterbomb", scaled(testing::waterbombBase(), 0.05)},
      {"miura", testing::miuraOri(4, 4, 0.015, 0.015, 0.005, std::numbers::pi)},
  };
  for (const auto& [name, pattern] : patterns) {
    SCOPED_TRACE(name);
    const BarHingeModel model = buildModel(pattern, paperOptions(true));
    SimulationState state = flatState(model);
    const StaticResult result = settle(model, 1.0, state);
    expectEnergyNeverRises(result);
    EXPECT_EQ(crossingTrianglePairs(model, state.positions), 0u);
    EXPECT_GE(smallestLayerDistance(model, state.positions, kThickness, 0.01), kThickness);
  }
}

// The dynamic solver gets the same force: the crease driven to 180 degrees by damped steps keeps
// its layers apart and does not pass through itself.
TEST(Contact, DynamicStepsKeepTheLayersApart) {
  const CreasePattern pattern = scaled(testing::creasedSquare(6, 3, 180.0), 0.03);
  const BarHingeModel model = buildModel(pattern, paperOptions(true));
  SimulationState state = flatState(model);
  settle(model, 0.9, state);  // most of the way, then the last stretch by steps
  stepDynamic(model, 1.0, state, 20000);
  EXPECT_EQ(crossingTrianglePairs(model, state.positions), 0u);
  EXPECT_GE(smallestLayerDistance(model, state.positions, kThickness, 0.01), 0.9 * kThickness);
  EXPECT_GT(state.contactPairs.rebuilds, 0u);
}

// Design mode has no thickness and keeps none; paper mode's contact can be turned off.
TEST(Contact, OnlyInPaperMode) {
  const CreasePattern pattern = testing::creasedSquare(2, 1, 90.0);
  EXPECT_FALSE(buildModel(pattern).contact.enabled);
  EXPECT_TRUE(buildModel(pattern, paperOptions(true)).contact.enabled);
  EXPECT_FALSE(buildModel(pattern, paperOptions(false)).contact.enabled);
  const BarHingeModel model = buildModel(pattern, paperOptions(true));
  EXPECT_DOUBLE_EQ(model.contact.thickness, kThickness);
  EXPECT_EQ(contactEnergy(model, model.flatPositions), 0.0);
}

}  // namespace
}  // namespace curvefold
