#include "interaction/live_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "engine/simulation/design_input.hpp"
#include "engine/simulation/hinge_unfolding.hpp"

namespace curvefold {

std::uint32_t liveStepsPerFrame(std::size_t vertexCount) {
  constexpr std::size_t kVertexStepsPerFrame = 50000;
  const std::size_t steps = kVertexStepsPerFrame / std::max<std::size_t>(vertexCount, 1);
  return std::uint32_t(std::clamp<std::size_t>(steps, 4, 60));
}

SimulationInput liveSimulationInput(double percent, const Sheet& design) {
  return {std::clamp(percent, 0.0, 100.0), liveStepsPerFrame(design.vertexCount()), std::nullopt};
}

std::optional<SimulationPull> SimulationPuller::update(const InputFrame::PointHand& hand,
                                                       bool onSheet,
                                                       const LiveSimulation* simulation,
                                                       const Pose& worldFromSheet, double viewScale,
                                                       double press, double release, double reach) {
  const bool wasHeld = held_;
  if (!hand.tracked || hand.select <= release) held_ = false;
  if (hand.tracked && hand.select >= press) held_ = true;
  if (!held_ || !simulation) {
    pulled_.reset();
    return std::nullopt;
  }
  const glm::dvec3 tip = worldFromSheet.inverse().apply(hand.position) / viewScale;
  if (!wasHeld && onSheet) {
    const std::uint32_t nearest = simulation->nearestVertex(tip);
    if (glm::distance(simulation->sheet().positions[nearest], tip) * viewScale <= reach)
      pulled_ = nearest;
  }
  if (!pulled_) return std::nullopt;
  return SimulationPull{*pulled_, tip};
}

namespace {

class CpuLiveSolver final : public LiveSolver {
 public:
  void advance(const BarHingeModel& model, double timeStep, double amount, std::uint32_t steps,
               const std::optional<LivePull>& pull, SimulationState& state) override {
    DynamicOptions options;
    options.timeStep = timeStep;
    if (!pull) {
      stepDynamic(model, amount, state, steps, options);
      return;
    }
    for (std::uint32_t step = 0; step < steps; ++step) {
      state.velocities[pull->vertex] += pull->impulse * (pull->to - state.positions[pull->vertex]);
      stepDynamic(model, amount, state, 1, options);
    }
  }
};

}  // namespace

std::unique_ptr<LiveSolver> cpuLiveSolver() {
  return std::make_unique<CpuLiveSolver>();
}

LiveSimulation::LiveSimulation(const Sheet& design, bool onWorker, const LiveSolverFactory& solver)
    : design_(design.positions), shown_(design), onWorker_(onWorker) {
  model_ = buildModel(designPattern(design).pattern);
  state_ = flatState(model_);
  timeStep_ = stableTimeStep(model_);
  if (design_.size() == model_.vertexCount())
    path_ = std::make_unique<FoldInterpolation>(model_, design_);
  solver_ = solver ? solver(model_, state_) : cpuLiveSolver();
  placeNext();
  show();
}

LiveSimulation::~LiveSimulation() {
  if (job_.valid()) job_.wait();
}

void LiveSimulation::advance(const SimulationInput& input) {
  finish();
  percent_ = std::clamp(input.percent, 0.0, 100.0);
  pull_ = input.pull;
  if (pull_ && pull_->vertex >= model_.vertexCount()) pull_.reset();
  SimulationInput frame = input;
  frame.percent = percent_;
  frame.pull = pull_;
  if (!onWorker_) {
    step(frame, placement_);
    show();
    return;
  }
  job_ =
      std::async(std::launch::async, [this, frame, before = placement_] { step(frame, before); });
}

void LiveSimulation::finish() {
  if (!job_.valid()) return;
  job_.get();
  show();
}

void LiveSimulation::step(const SimulationInput& input, const RigidPlacement& before) {
  std::optional<LivePull> pull;
  if (input.pull && !model_.pinned[input.pull->vertex]) {
    // The target in the model's frame: the inverse of the shown state's placement.
    const glm::dvec3 to = glm::transpose(before.rotation) * (input.pull->to - before.translation);
    // dt k / m with k = c m / dt^2
    pull = LivePull{input.pull->vertex, to, kPullStiffness / timeStep_};
  }
  const double amount = input.percent / 100.0;
  // Tried where the slider rests (its last frame's amount again, or either end), not while it
  // moves: a try costs about as much as the frame's steps at 10k vertices.
  const bool atRest = amount == previousAmount_ || amount == 0.0 || amount == 1.0;
  const double fromAmount = previousAmount_;
  previousAmount_ = amount;
  if (!input.pull && atRest && amount != predictedAmount_) {
    predictedAmount_ = amount;
    if (tryPredictor(amount)) solver_->setState(state_);
  } else if (!input.pull && !atRest && path_) {
    // The path's update is the frame's work in place of its steps (1.6 times their CPU at 10k).
    takePath(fromAmount, amount);
    solver_->setState(state_);
    placeNext();
    return;
  }
  solver_->advance(model_, timeStep_, amount, input.steps, pull, state_);
  placeNext();
}

bool LiveSimulation::tryPredictor(double amount) {
  const std::vector<double> targets = hingeTargets(model_, amount);
  SimulationState predicted = unfoldedState(model_, targets);
  const double current = modelEnergy(model_, state_.positions, targets, state_.hingeAngles);
  if (!(modelEnergy(model_, predicted.positions, targets, predicted.hingeAngles) < current))
    return false;
  // Where the sheet is now, so only its shape changes; at rest.
  const RigidPlacement onto = bestRigidPlacement(predicted.positions, state_.positions);
  for (std::size_t v = 0; v < predicted.positions.size(); ++v)
    state_.positions[v] = onto.apply(predicted.positions[v]);
  state_.velocities.assign(model_.vertexCount(), glm::dvec3(0.0));
  state_.hingeAngles = predicted.hingeAngles;  // a rigid motion keeps every angle
  ++predictions_;
  return true;
}

void LiveSimulation::takePath(double fromAmount, double amount) {
  const std::vector<glm::dvec3> along =
      path_->onward(state_.positions, fromAmount, amount, kPathRelaxations, kPathPull);
  // Where the sheet is now, so only its shape changes; at rest.
  const RigidPlacement onto = bestRigidPlacement(along, state_.positions);
  for (std::size_t v = 0; v < along.size(); ++v) state_.positions[v] = onto.apply(along[v]);
  state_.velocities.assign(model_.vertexCount(), glm::dvec3(0.0));
  state_.hingeAngles = hingeAngles(model_, state_.positions, state_.hingeAngles);
  ++pathFrames_;
}

void LiveSimulation::placeNext() {
  nextPlacement_ = bestRigidPlacement(state_.positions, design_);
  // Into the buffer the last show() gave back: no allocation a frame.
  nextPositions_.resize(state_.positions.size());
  for (std::size_t v = 0; v < state_.positions.size(); ++v)
    nextPositions_[v] = nextPlacement_.apply(state_.positions[v]);
}

void LiveSimulation::show() {
  placement_ = nextPlacement_;
  std::swap(shown_.positions, nextPositions_);
  shownModel_ = state_.positions;
  shownSteps_ = state_.steps;
  strainCurrent_ = false;
}

std::uint32_t LiveSimulation::nearestVertex(const glm::dvec3& sheetPoint) const {
  std::uint32_t best = 0;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < shown_.positions.size(); ++v) {
    const double d = glm::distance(shown_.positions[v], sheetPoint);
    if (d < bestDistance) {
      bestDistance = d;
      best = std::uint32_t(v);
    }
  }
  return best;
}

const std::vector<double>& LiveSimulation::vertexStrain() const {
  if (strainCurrent_) return strain_;
  const std::vector<double> strain = edgeStrain(model_, shownModel_);
  strain_.assign(model_.vertexCount(), 0.0);
  for (std::size_t e = 0; e < model_.bars.size(); ++e)
    for (std::uint32_t v : model_.bars[e]) strain_[v] = std::max(strain_[v], std::abs(strain[e]));
  strainCurrent_ = true;
  return strain_;
}

}  // namespace curvefold
