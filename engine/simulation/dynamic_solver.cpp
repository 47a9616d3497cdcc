#include "engine/simulation/dynamic_solver.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace curvefold {

double stableTimeStep(const BarHingeModel& model) {
  std::vector<double> stiffness(model.vertexCount(), 0.0);
  for (std::size_t i = 0; i < model.bars.size(); ++i)
    for (std::uint32_t v : model.bars[i]) stiffness[v] += 2.0 * model.barStiffness[i];
  for (std::size_t j = 0; j < model.hinges.size(); ++j) {
    const Hinge& h = model.hinges[j];
    const auto& p = model.flatPositions;
    const auto gradient = hingeAngleGradient(p[h.a], p[h.b], p[h.c], p[h.d]);
    double sum = 0.0;  // a row of k g g^T sums to at most k |g_v| sum |g_w|
    for (const glm::dvec3& g : gradient) sum += glm::length(g);
    const std::uint32_t vertices[4] = {h.a, h.b, h.c, h.d};
    for (int k = 0; k < 4; ++k)
      stiffness[vertices[k]] += model.hingeStiffness[j] * glm::length(gradient[k]) * sum;
  }
  for (const auto& pair : model.glue)
    for (std::uint32_t v : pair) stiffness[v] += 2.0 * model.glueStiffness;
  double omegaSquared = 0.0;
  for (std::size_t v = 0; v < model.vertexCount(); ++v)
    omegaSquared = std::max(omegaSquared, stiffness[v] / model.mass[v]);
  if (omegaSquared == 0.0) return 1.0;
  // Semi-implicit Euler is stable below 2 / omega; half of that.
  return 1.0 / std::sqrt(omegaSquared);
}

void stepDynamic(const BarHingeModel& model, double foldAmount, SimulationState& state,
                 std::size_t steps, const DynamicOptions& options) {
  const double dt = options.timeStep > 0.0 ? options.timeStep
                    : model.timeStep > 0.0 ? model.timeStep
                                           : stableTimeStep(model);
  const double keep = 1.0 - options.velocityDamping;
  std::vector<double>& targets = state.targets;  // no allocation after the first call
  targets.resize(model.hinges.size());
  for (std::size_t j = 0; j < targets.size(); ++j) targets[j] = model.target(j, foldAmount);
  if (state.hingeAngles.size() != model.hinges.size())
    state.hingeAngles = hingeAngles(model, state.positions);
  state.velocities.resize(model.vertexCount(), glm::dvec3(0.0));

  for (std::size_t step = 0; step < steps; ++step) {
    elementForces(model, state.positions, targets, state.hingeAngles, state.hingeAngles,
                  state.slotForces, state.velocities.data(), options.dampingRatio);
    const glm::dvec3* contact = dynamicContactForces(model, state);  // null without contact
    const glm::dvec3* forces = state.slotForces.data();
    glm::dvec3* v = state.velocities.data();
    glm::dvec3* positions = state.positions.data();
    const std::uint32_t* offsets = model.gatherOffsets.data();
    const std::uint32_t* slots = model.gatherSlots.data();
    forEachIndex(model.vertexCount(), [&](std::size_t vertex) {
      if (model.pinned[vertex]) return;
      glm::dvec3 total(0.0);
      for (std::uint32_t s = offsets[vertex]; s < offsets[vertex + 1]; ++s)
        total += forces[slots[s]];
      if (contact) total += contact[vertex];
      v[vertex] = (v[vertex] + (dt / model.mass[vertex]) * total) * keep;
      positions[vertex] += dt * v[vertex];
    });
    ++state.steps;
  }
}

}  // namespace curvefold
