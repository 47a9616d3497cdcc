#include "engine/simulation/dynamic_solver.hpp"

#include "engine/simulation/hinge_kernel.hpp"
#include "engine/simulation/lane_clones.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

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
      stiffness[vertices[k]] += (model.hingeStiffness[j] + std::abs(model.hingeWrongSide[j])) *
                                glm::length(gradient[k]) * sum;
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

namespace {

// Elements (bars, hinges, glue) and vertices a task takes: few enough tasks that two cores do not
// spend a 10k-vertex step scheduling them, enough that a loaded core's share is taken by the other.
constexpr std::size_t kElementGrain = 4096;
constexpr std::size_t kVertexGrain = 2048;
// Below this many vertices a step runs on one thread: waking the second core for each of the
// step's two passes costs more than it shares (idle, 2 cores, BM_DynamicStep against
// BM_DynamicStepOneThread: 10,201 vertices 1.06 ms on two threads, 0.80 ms on one; 30,276
// vertices 2.76 against 3.58 ms). The result is the same bits either way.
constexpr std::size_t kOneThreadBelow = 16384;

// Bars a lane block takes (as kHingeLanes for hinges).
constexpr std::size_t kBarLanes = 16;

// `count` (<= kBarLanes) bars from `bars` on: each one's force on its first end into barForces
// (in bar order; moveVertices reads it from both ends), by hinge_kernel::barForce on every lane at
// once (the same bits as one bar at a time).
CURVEFOLD_LANE_CLONES void barLanes(const std::array<std::uint32_t, 2>* bars, std::size_t count,
                                    const glm::dvec3* x, const glm::dvec3* velocity,
                                    const double* stiffness, const double* restLength,
                                    const double* damping, double dampingRatio,
                                    glm::dvec3* barForces) {
  constexpr std::size_t kLanes = kBarLanes;
  alignas(64) double in[6][kLanes], parameters[3][kLanes], out[3][kLanes];
  for (std::size_t k = 0; k < kLanes; ++k) {
    const std::size_t i = std::min(k, count - 1);
    const glm::dvec3 delta = x[bars[i][1]] - x[bars[i][0]];
    const glm::dvec3 relative = velocity[bars[i][1]] - velocity[bars[i][0]];
    for (int axis = 0; axis < 3; ++axis) {
      in[axis][k] = delta[axis];
      in[3 + axis][k] = relative[axis];
    }
    parameters[0][k] = stiffness[i];
    parameters[1][k] = restLength[i];
    parameters[2][k] = dampingRatio * damping[i];
  }
  for (std::size_t k = 0; k < kLanes; ++k) {
    const glm::dvec3 force = hinge_kernel::barForce(
        glm::dvec3(in[0][k], in[1][k], in[2][k]), glm::dvec3(in[3][k], in[4][k], in[5][k]),
        parameters[0][k], parameters[1][k], parameters[2][k]);
    for (int axis = 0; axis < 3; ++axis) out[axis][k] = force[axis];
  }
  for (std::size_t k = 0; k < count; ++k)
    barForces[k] = glm::dvec3(out[0][k], out[1][k], out[2][k]);
}

// Hinges a lane block takes: the kernel runs on local arrays of this many, one hinge a lane, so
// the compiler vectorizes it.
constexpr std::size_t kHingeLanes = 8;

// `count` (<= kHingeLanes) hinges from `hinges` on: their angles unwrapped in place and their
// forces into their slots. The positions and parameters are copied into lanes (the last hinge's
// repeated to fill them), angleWithGradientUsual, the moment and the four forces run on every
// lane at once (the scalar tail only stores them: it was a third of the lanes' time), and a hinge
// it cannot take goes through angleWithGradient alone; each hinge's bits are angleWithGradient's
// and hingeMoment's either way.
CURVEFOLD_LANE_CLONES void hingeLanes(const Hinge* hinges, std::size_t count, const glm::dvec3* x,
                                      double* angles, const double* stiffness, const double* target,
                                      const double* wrongSide, const std::uint32_t* scatter,
                                      glm::dvec3* forces) {
  constexpr std::size_t kLanes = kHingeLanes;
  alignas(64) double in[12][kLanes], previous[kLanes], parameters[3][kLanes];
  alignas(64) double out[12][kLanes], angle[kLanes], usual[kLanes];
  static_assert(kLanes % 4 == 0);
  for (std::size_t k0 = 0; k0 < kLanes; k0 += 4) {
    std::uint32_t vertices[4][4];  // [corner][lane]
    for (std::size_t q = 0; q < 4; ++q) {
      const Hinge& h = hinges[std::min(k0 + q, count - 1)];
      vertices[0][q] = h.a;
      vertices[1][q] = h.b;
      vertices[2][q] = h.c;
      vertices[3][q] = h.d;
    }
    for (int v = 0; v < 4; ++v)
      for (int axis = 0; axis < 3; ++axis)
        storeLaneQuad(&in[3 * v + axis][k0], x[vertices[v][0]][axis], x[vertices[v][1]][axis],
                      x[vertices[v][2]][axis], x[vertices[v][3]][axis]);
  }
  for (std::size_t k = 0; k < kLanes; ++k) {
    const std::size_t j = std::min(k, count - 1);
    previous[k] = angles[j];
    parameters[0][k] = target[j];
    parameters[1][k] = stiffness[j];
    parameters[2][k] = wrongSide[j];
  }
  for (std::size_t k = 0; k < kLanes; ++k) {
    std::array<glm::dvec3, 4> gradient;
    double a;
    const bool ok = hinge_kernel::angleWithGradientUsual(
        glm::dvec3(in[0][k], in[1][k], in[2][k]), glm::dvec3(in[3][k], in[4][k], in[5][k]),
        glm::dvec3(in[6][k], in[7][k], in[8][k]), glm::dvec3(in[9][k], in[10][k], in[11][k]),
        previous[k], a, gradient);
    angle[k] = a;
    usual[k] = ok ? 1.0 : 0.0;
    const double torque =
        -hinge_kernel::hingeMoment(a, parameters[0][k], parameters[1][k], parameters[2][k]);
    for (int v = 0; v < 4; ++v)
      for (int axis = 0; axis < 3; ++axis) out[3 * v + axis][k] = torque * gradient[v][axis];
  }
  for (std::size_t k = 0; k < count; ++k) {
    if (usual[k] != 0.0) {
      angles[k] = angle[k];
      for (int v = 0; v < 4; ++v)
        forces[scatter[4 * k + v]] =
            glm::dvec3(out[3 * v][k], out[3 * v + 1][k], out[3 * v + 2][k]);
      continue;
    }
    std::array<glm::dvec3, 4> gradient;
    const Hinge& h = hinges[k];
    angles[k] =
        hinge_kernel::angleWithGradient(x[h.a], x[h.b], x[h.c], x[h.d], previous[k], gradient);
    const double torque =
        -hinge_kernel::hingeMoment(angles[k], target[k], stiffness[k], wrongSide[k]);
    for (int v = 0; v < 4; ++v) forces[scatter[4 * k + v]] = torque * gradient[v];
  }
}

// Every element's force on each of its vertices, written where that vertex reads it
// (BarHingeModel::scatterSlots); every hinge's angle unwrapped in place. The same expressions as
// elementForces, so the same bits.
void scatterElementForces(const BarHingeModel& model, const std::vector<double>& targets,
                          double dampingRatio, SimulationState& state, std::size_t grain) {
  const glm::dvec3* x = state.positions.data();
  const glm::dvec3* velocity = state.velocities.data();
  glm::dvec3* forces = state.slotForces.data();
  glm::dvec3* barForces = state.barForces.data();
  double* angles = state.hingeAngles.data();
  const std::uint32_t* scatter = model.scatterSlots.data();
  const std::array<std::uint32_t, 2>* bars = model.bars.data();
  const double* barStiffness = model.barStiffness.data();
  const double* barLength = model.barLength.data();
  const double* barDamping = model.barDamping.data();
  const Hinge* hinges = model.hinges.data();
  const double* hingeStiffness = model.hingeStiffness.data();
  const double* hingeWrongSide = model.hingeWrongSide.data();
  const double* target = targets.data();
  const std::size_t barCount = model.bars.size(), hingeCount = model.hinges.size();
  const std::size_t hingeEnd = barCount + hingeCount;
  const std::uint32_t* hingeScatter = scatter + model.hingeSlot0;
  const std::uint32_t* glueScatter = scatter + model.glueSlot0;
  forEachRange(hingeEnd + model.glue.size(), grain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i0 = begin; i0 < std::min(end, barCount); i0 += kBarLanes)
      barLanes(bars + i0, std::min(kBarLanes, std::min(end, barCount) - i0), x, velocity,
               barStiffness + i0, barLength + i0, barDamping + i0, dampingRatio, barForces + i0);
    const std::size_t hingeBegin = std::max(begin, barCount) - barCount;
    const std::size_t hingeStop = std::max(std::min(end, hingeEnd), barCount) - barCount;
    for (std::size_t j0 = hingeBegin; j0 < hingeStop; j0 += kHingeLanes)
      hingeLanes(hinges + j0, std::min(kHingeLanes, hingeStop - j0), x, angles + j0,
                 hingeStiffness + j0, target + j0, hingeWrongSide + j0, hingeScatter + 4 * j0,
                 forces);
    for (std::size_t e = std::max(begin, hingeEnd); e < end; ++e) {
      const std::size_t g = e - hingeEnd;
      const std::uint32_t a = model.glue[g][0], b = model.glue[g][1];
      const glm::dvec3 force = model.glueStiffness * (x[b] - x[a]);
      forces[glueScatter[2 * g]] = force;
      forces[glueScatter[2 * g + 1]] = -force;
    }
  });
}

// Each free vertex sums its forces, one run in gather order, and moves by semi-implicit Euler.
// `contact` is the self-contact force per vertex, null without contact (dynamicContactForces).
void moveVertices(const BarHingeModel& model, double dt, double keep, const glm::dvec3* contact,
                  SimulationState& state, std::size_t grain) {
  const glm::dvec3* forces = state.slotForces.data();
  glm::dvec3* velocity = state.velocities.data();
  glm::dvec3* positions = state.positions.data();
  const glm::dvec3* barForces = state.barForces.data();
  const std::uint32_t* offsets = model.gatherOffsets.data();
  const std::uint32_t* barEnd = model.gatherBarEnd.data();
  const std::uint32_t* slots = model.gatherSlots.data();
  const std::uint8_t* pinned = model.pinned.data();
  const double* mass = model.mass.data();
  forEachRange(model.vertexCount(), grain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      if (pinned[v]) continue;
      glm::dvec3 total(0.0);
      // Its bars' forces (slot 2i: +f, 2i + 1: -f), then its other slots, in gather order.
      std::uint32_t k = offsets[v];
      for (; k < barEnd[v]; ++k) {
        const glm::dvec3& force = barForces[slots[k] >> 1];
        total += (slots[k] & 1u) ? -force : force;
      }
      for (; k < offsets[v + 1]; ++k) total += forces[k];
      if (contact) total += contact[v];
      velocity[v] = (velocity[v] + (dt / mass[v]) * total) * keep;
      positions[v] += dt * velocity[v];
    }
  });
}

}  // namespace

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
  state.slotForces.resize(model.slotCount);  // the bars' slots stay unused (barForces)
  state.barForces.resize(model.bars.size());

  const bool oneThread = model.vertexCount() < kOneThreadBelow;
  const std::size_t elementGrain =
      oneThread ? std::numeric_limits<std::size_t>::max() : kElementGrain;
  const std::size_t vertexGrain =
      oneThread ? std::numeric_limits<std::size_t>::max() : kVertexGrain;
  for (std::size_t step = 0; step < steps; ++step) {
    scatterElementForces(model, targets, options.dampingRatio, state, elementGrain);
    moveVertices(model, dt, keep, dynamicContactForces(model, state), state, vertexGrain);
    ++state.steps;
  }
}

}  // namespace curvefold
