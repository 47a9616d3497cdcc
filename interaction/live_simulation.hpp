// The live simulation (issue 39, 4; docs/design.md "Simulating the fold"): the committed design's
// sheet folded by the bar-and-hinge model in design mode (engine/simulation), from its flat
// development (0%) toward the design (100%), a fixed number of dynamic steps per frame, and
// optionally one vertex pulled toward a hand by a spring. The design itself is never changed: the
// simulation keeps its own copy of the sheet, whose positions it replaces.
//
// The model floats free (nothing is pinned), so each frame the simulated positions are shown
// after their best rigid placement onto the design (engine/simulation/rigid_placement.hpp): the
// simulated sheet sits where the design does and follows the sheet hand as the design does. A
// pull's target, given in sheet coordinates, is taken into the model's frame through that same
// placement.
//
// Deterministic: the same design and the same sequence of SimulationInput give the same positions
// bit for bit (stepDynamic is; the spring is applied step by step in a fixed order), which is what
// lets a recording replay the simulation.
//
// The spring: force k (to - x) on the pulled vertex, applied as the velocity impulse dt k (to -
// x) / m before each step, which is the same as adding it to that step's force in the solver's
// semi-implicit Euler. k = kPullStiffness m / dt^2 keeps it well inside explicit stability.
//
// On a worker (the live window, issue 39, 4): advance() starts the frame's steps on a worker
// thread and returns at once, showing the state after the previous frame's input while the
// window draws; the next advance() (or finish()) waits for them. The states are the very same
// (the same inputs in the same order; stepDynamic is bit for bit the same on any thread), only
// shown a frame later, so a recording still replays bit for bit (replays step synchronously).
//
// The solver (issue 39, 4): the frame's steps are taken by a LiveSolver, the CPU's dynamic
// solver (cpuLiveSolver, the default and the only one a replay uses) or one the host makes, such
// as the Vulkan compute solver (app/desktop/gpu_live_solver.hpp), whose state stays on its device
// and comes back as positions each frame. Which one is input (SimulationInput::solver), so a
// recording says which solver made it.
//
// The predictor (issue 39, 4): whenever the fold amount comes to rest at a new value (a frame
// with the previous frame's amount, or 0 or 100%), and no pull is held, the state
// unfoldedState makes at the new amount (engine/simulation/hinge_unfolding.hpp: every hinge of a
// spanning tree at its target) is tried, as the static solver's settle tries it, and taken,
// rigidly placed onto the state and at rest, when its energy at the new targets is lower than
// the state's. For a design in design mode at 100% that state is the design itself, so the sheet
// reaches it on the frame the slider does. Without it the dynamic steps alone crept for
// thousands of frames (docs/performance.md, "From flat by the dynamic solver alone"): the step is
// set by the sliver triangles of reflection cuts (25 to 300 times shorter than the median
// vertex's), and the per-step velocity damping overdamps the sheet's soft bending, which had to
// pull creases 50 degrees short of their angle back through stretched bars. Between 0 and 100%
// the targets of a curved design cannot all be met at once; there the predicted state tears
// (vertices placed by the first triangle to reach them) and is higher in energy, and the dynamic
// state stays.
//
// The fold path (issue 39, 4): while the fold amount moves (a frame whose amount differs from
// the last frame's, not at either end) and no pull is held, the frame's state is the fold path's
// (engine/simulation/fold_interpolation.hpp): each triangle's rotation in the state now, turned
// on about its own axis by its share of the change of amount and kPathPull of the way back toward
// its rotation on the path from flat to the design, then kPathRelaxations local-global
// (as-rigid-as-possible) iterations toward the flat triangles' shapes, rigidly placed onto the
// state and at rest; that update replaces the frame's dynamic steps (about 1.6 times their CPU
// at 10k vertices). Without it the dynamic steps left a curved design's creases 22 to 75 degrees
// (mean) behind the slider and the predictor then jumped the sheet to the design in one frame
// where the slider came to rest (docs/performance.md, "The live slider's ramp"); with it the
// creases stay within a few degrees of their targets and the sheet moves a little each frame. A
// flap folded flat turns the way its hinge's target says (FoldInterpolation(model, design)).
// The price: between flat and the design a curved design's targets cannot all be met at once,
// and the path's states are only nearly isometric (median edge strain about 0.1 to 0.5% mid-ramp,
// a few percent on the worst sliver edges). Where the slider rests, the dynamic steps (and at the
// ends the predictor) take over from the path's state.
//
// Known limits: design mode only (every edge driven toward the design; paper mode's very stiff
// bars need far more steps than a frame allows); no self-contact (the model has none).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <vector>

#include "engine/geometry/sheet.hpp"
#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/dynamic_solver.hpp"
#include "engine/simulation/fold_interpolation.hpp"
#include "engine/simulation/rigid_placement.hpp"
#include "interaction/input_frame.hpp"

namespace curvefold {

// The spring's stiffness as a fraction of m / dt^2 (explicit Euler is stable below 4).
inline constexpr double kPullStiffness = 0.05;

// The fold path's update while the slider moves (above): local-global iterations, and the share
// of each triangle's rotation returned toward the path's in one frame.
// Six, not two: the cones' median strain over a ramp 0.52% -> 0.28% (crown_vessel 0.13% ->
// 0.04%) for about 1.6 times the moving frame's CPU at 10k vertices (docs/performance.md).
inline constexpr std::size_t kPathRelaxations = 6;
inline constexpr double kPathPull = 0.1;

// Dynamic steps per frame for a sheet of this many vertices: about 50k vertex-steps a frame
// (4 steps, about 6 ms of CPU at 10k vertices, bench_live_simulation; lavapipe's drawing of the
// frame costs as much again), at least 4 and at most 60.
std::uint32_t liveStepsPerFrame(std::size_t vertexCount);

class LiveSimulation;

// One vertex pulled toward a point in the model's frame: before each step its velocity gains
// impulse (to - x) (dt k / m per metre; see above).
struct LivePull {
  std::uint32_t vertex = 0;
  glm::dvec3 to{0.0};
  double impulse = 0.0;
};

// What steps the live simulation's model. advance() takes `steps` fixed steps of `timeStep`
// toward the fold amount (0..1) with the pull, if any (never on a pinned vertex), and leaves at
// least the positions and the step count in `state` (the CPU solver the whole state).
class LiveSolver {
 public:
  virtual ~LiveSolver() = default;
  virtual void advance(const BarHingeModel& model, double timeStep, double amount,
                       std::uint32_t steps, const std::optional<LivePull>& pull,
                       SimulationState& state) = 0;
  // The state was replaced (the predictor's, above): a solver that keeps its own copy takes it.
  virtual void setState(const SimulationState& /*state*/) {}
};

// The CPU's dynamic solver (stepDynamic): bit for bit on any machine and thread count.
std::unique_ptr<LiveSolver> cpuLiveSolver();

// Makes a solver for a model and its flat state (the host's, e.g. on its Vulkan device); throws
// what it cannot (the simulation then reports it, as a model it cannot build).
using LiveSolverFactory =
    std::function<std::unique_ptr<LiveSolver>(const BarHingeModel&, const SimulationState&)>;

// A frame's simulation input toward `percent` at liveStepsPerFrame of the design, with no pull.
SimulationInput liveSimulationInput(double percent, const Sheet& design);

// The hand's side of pulling (the headset's dominant hand): the trigger, pressed within
// `reach` (metres) of the simulated sheet, takes its nearest vertex, which follows the hand until
// the trigger is released. Thresholds as the core's (InteractionThresholds::selectPress and
// selectRelease).
class SimulationPuller {
 public:
  // The pull this frame, from the hand's tip (world) and trigger, the sheet's placement and
  // the simulation as it is before this frame (none yet: no pull).
  std::optional<SimulationPull> update(const InputFrame::PointHand& hand, bool onSheet,
                                       const LiveSimulation* simulation, const Pose& worldFromSheet,
                                       double viewScale, double press, double release,
                                       double reach);
  void reset() { pulled_.reset(), held_ = false; }

 private:
  std::optional<std::uint32_t> pulled_;
  bool held_ = false;
};

class LiveSimulation {
 public:
  // Builds the model of `design` (design mode) and starts flat. Throws SimulationInputError or
  // InvalidSheet for a sheet the model cannot be built from, and what `solver` throws. onWorker:
  // see above (the host's solver must allow stepping from a worker then). No factory: the CPU's.
  explicit LiveSimulation(const Sheet& design, bool onWorker = false,
                          const LiveSolverFactory& solver = {});
  ~LiveSimulation();
  LiveSimulation(const LiveSimulation&) = delete;
  LiveSimulation& operator=(const LiveSimulation&) = delete;

  // One frame: input.steps dynamic steps toward input.percent, pulled by input.pull if any
  // (on a worker: started; shown from the next frame).
  void advance(const SimulationInput& input);
  // Waits for the steps under way, if any, and shows their state.
  void finish();

  // The design's sheet at the shown simulated positions, placed onto the design (sheet
  // coordinates).
  const Sheet& sheet() const { return shown_; }
  // The last frame's input.
  double percent() const { return percent_; }
  const std::optional<SimulationPull>& pull() const { return pull_; }
  // Steps taken to the shown state.
  std::size_t steps() const { return shownSteps_; }
  // How often the predictor's state was taken (on a worker: after finish()).
  std::size_t predictions() const { return predictions_; }
  // How many frames took the fold path's state (on a worker: after finish()).
  std::size_t pathFrames() const { return pathFrames_; }
  const BarHingeModel& model() const { return model_; }
  // The model's state; on a worker, only after finish() (the worker writes it meanwhile). With a
  // host's solver, perhaps only the positions and the step count (LiveSolver).
  const SimulationState& state() const { return state_; }

  // The shown vertex nearest a point (sheet coordinates).
  std::uint32_t nearestVertex(const glm::dvec3& sheetPoint) const;
  // Per vertex of the shown state: the largest |strain| of its edges (edgeStrain), for a picture
  // to colour (a renderer with per-vertex colour; see docs/design.md). Computed once per shown
  // state (the panel and the picture both ask).
  const std::vector<double>& vertexStrain() const;

 private:
  // The steps of one frame and the placement of their state (the worker's part).
  void step(const SimulationInput& input, const RigidPlacement& before);
  // The rigid placement of the model's state onto the design, and its placed positions.
  void placeNext();
  // The worker's state becomes the shown one.
  void show();
  // The predictor at the fold amount (0..1), taken when lower in energy (see above); true if so.
  bool tryPredictor(double amount);
  // The state becomes the fold path's on from fromAmount to amount (0..1; above), placed onto
  // it, at rest.
  void takePath(double fromAmount, double amount);

  BarHingeModel model_;
  SimulationState state_;
  std::unique_ptr<LiveSolver> solver_;
  std::vector<glm::dvec3> design_;  // the design's positions, which the state is placed onto
  Sheet shown_;
  std::vector<glm::dvec3> shownModel_;  // the shown state's positions in the model's frame
  std::size_t shownSteps_ = 0;
  RigidPlacement placement_;  // the shown state's: model frame -> sheet coordinates
  // The worker's results, shown by show().
  std::vector<glm::dvec3> nextPositions_;
  RigidPlacement nextPlacement_;
  double timeStep_ = 0.0;
  double percent_ = 0.0;
  double predictedAmount_ = 0.0;             // the last amount the predictor was tried at (flat: 0)
  double previousAmount_ = 0.0;              // the last frame's
  std::size_t predictions_ = 0;              // how often it was taken
  std::unique_ptr<FoldInterpolation> path_;  // flat to the design (fold_interpolation.hpp)
  // (none where the design's vertices are not the model's)
  std::size_t pathFrames_ = 0;  // frames the path's state was taken
  std::optional<SimulationPull> pull_;
  bool onWorker_ = false;
  std::future<void> job_;
  mutable std::vector<double> strain_;
  mutable bool strainCurrent_ = false;
};

}  // namespace curvefold
