#include "engine/simulation/hinge_unfolding.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "engine/simulation/rigid_placement.hpp"

namespace curvefold {
namespace {

// Rodrigues' rotation about a unit axis.
glm::dmat3 rotation(const glm::dvec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const glm::dmat3 cross(glm::dvec3(0, axis.z, -axis.y), glm::dvec3(-axis.z, 0, axis.x),
                         glm::dvec3(axis.y, -axis.x, 0));
  return glm::dmat3(1.0) + s * cross + (1.0 - c) * (cross * cross);
}

struct Placement {
  glm::dmat3 rotation{1.0};
  glm::dvec3 translation{0.0};
  glm::dvec3 apply(const glm::dvec3& p) const { return rotation * p + translation; }
};

}  // namespace

SimulationState unfoldedState(const BarHingeModel& model, double foldAmount) {
  return unfoldedState(model, hingeTargets(model, foldAmount));
}

SimulationState unfoldedState(const BarHingeModel& model, const std::vector<double>& targets) {
  const std::size_t triangleCount = model.triangles.size();
  // The hinges of each triangle.
  std::vector<std::vector<std::uint32_t>> triangleHinges(triangleCount);
  for (std::size_t j = 0; j < model.hinges.size(); ++j)
    for (std::uint32_t t : model.hingeTriangles[j])
      triangleHinges[t].push_back(static_cast<std::uint32_t>(j));

  std::vector<Placement> placement(triangleCount);
  std::vector<std::uint8_t> isPlaced(triangleCount, 0), vertexPlaced(model.vertexCount(), 0);
  SimulationState state;
  state.positions = model.flatPositions;
  const auto& flat = model.flatPositions;
  auto placeVertices = [&](std::uint32_t t) {
    for (std::uint32_t v : model.triangles[t])
      if (!vertexPlaced[v]) {
        state.positions[v] = placement[t].apply(flat[v]);
        vertexPlaced[v] = 1;
      }
  };
  std::deque<std::uint32_t> queue;
  for (std::uint32_t seed = 0; seed < triangleCount; ++seed) {
    if (isPlaced[seed]) continue;
    isPlaced[seed] = 1;
    placeVertices(seed);
    queue.push_back(seed);
    while (!queue.empty()) {
      const std::uint32_t t = queue.front();
      queue.pop_front();
      for (std::uint32_t j : triangleHinges[t]) {
        const auto [left, right] = model.hingeTriangles[j];
        const std::uint32_t next = left == t ? right : left;
        if (isPlaced[next]) continue;
        const Hinge& h = model.hinges[j];
        // A bridge across slivers (bar_hinge_model.cpp) joins triangles with no common edge.
        auto hasEdge = [&](std::uint32_t triangle) {
          const auto& vertices = model.triangles[triangle];
          return std::count(vertices.begin(), vertices.end(), h.a) == 1 &&
                 std::count(vertices.begin(), vertices.end(), h.b) == 1;
        };
        if (!hasEdge(t) || !hasEdge(next)) continue;
        const double target = targets[j];
        // Turn the neighbour about the edge as it lies in t's placement; the sense of the turn is
        // whichever gives the hinge its target (the two differ in sign unless the target is 0).
        const glm::dvec3 a = placement[t].apply(flat[h.a]);
        const glm::dvec3 axis = glm::normalize(placement[t].rotation * (flat[h.b] - flat[h.a]));
        Placement best;
        double bestError = INFINITY;
        for (double sense : {1.0, -1.0}) {
          Placement candidate;
          const glm::dmat3 turn = rotation(axis, sense * target);
          candidate.rotation = turn * placement[t].rotation;
          candidate.translation = a - candidate.rotation * flat[h.a];
          const Placement& pl = left == t ? placement[t] : candidate;
          const Placement& pr = left == t ? candidate : placement[t];
          const double angle = hingeAngle(pl.apply(flat[h.a]), pl.apply(flat[h.b]),
                                          pl.apply(flat[h.c]), pr.apply(flat[h.d]), target);
          const double error = std::abs(angle - target);
          if (error < bestError) {
            bestError = error;
            best = candidate;
          }
        }
        placement[next] = best;
        isPlaced[next] = 1;
        placeVertices(next);
        queue.push_back(next);
      }
    }
  }
  // Pinned vertices stay where they are flat: the whole state is moved to fit them best.
  std::vector<glm::dvec3> from, to;
  for (std::size_t v = 0; v < model.vertexCount(); ++v)
    if (model.pinned[v]) {
      from.push_back(state.positions[v]);
      to.push_back(flat[v]);
    }
  if (!from.empty()) {
    RigidPlacement fit = bestRigidPlacement(from, to);
    if (from.size() < 3) fit = {glm::dmat3(1.0), to.front() - from.front()};
    state.positions = placed(fit, state.positions);
    for (std::size_t v = 0; v < model.vertexCount(); ++v)
      if (model.pinned[v]) state.positions[v] = flat[v];
  }
  state.velocities.assign(model.vertexCount(), glm::dvec3(0.0));
  state.hingeAngles = hingeAngles(model, state.positions, targets);
  return state;
}

}  // namespace curvefold
