// The folding simulation's Vulkan compute path (engine/simulation_vk) against the CPU path
// (engine/simulation), on whatever Vulkan device the loader finds (lavapipe on a machine without a
// GPU) with the Khronos validation layer and its synchronization checks on: any validation message
// fails the test.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "app/desktop/gpu_live_solver.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/io/fold_crease_pattern.hpp"
#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/dynamic_solver.hpp"
#include "engine/simulation_vk/gpu_dynamic_solver.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "interaction/interaction_core.hpp"
#include "test_paths.hpp"
#include "tests/cli_test_support.hpp"
#include "tests/sanitizer_support.hpp"
#include "tests/simulation_test_support.hpp"

namespace curvefold {
namespace {

using testing::creasedSquare;
using testing::miuraOri;
using testing::squareTwistFold;

constexpr double kDegrees = 180.0 / std::numbers::pi;

double diagonal(const BarHingeModel& model) {
  glm::dvec3 low(1e300), high(-1e300);
  for (const glm::dvec3& p : model.flatPositions) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  return glm::distance(low, high);
}

double largestDistance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  double largest = 0.0;
  for (std::size_t v = 0; v < a.size(); ++v) largest = std::max(largest, glm::distance(a[v], b[v]));
  return largest;
}

// One context for the suite (instance creation with validation takes a while); every test checks
// that no validation message arrived during it.
class SimulationVk : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // The layer's synchronization checks too: a missing barrier between the kernels is a hazard
    // it reports (lavapipe runs dispatches in order, so the state alone would not show it).
    setenv("VK_LAYER_ENABLES", "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT", 0);
    ContextOptions options;
    options.instance.validation = true;
    context_ = std::make_unique<VulkanContext>(options);
  }
  static void TearDownTestSuite() { context_.reset(); }
  void SetUp() override { messagesBefore_ = context_->validationMessageCount(); }
  void TearDown() override {
    EXPECT_EQ(context_->validationMessageCount(), messagesBefore_) << [&] {
      std::string all;
      for (const std::string& m : context_->validationMessages()) all += m + "\n";
      return all;
    }();
  }

  static std::unique_ptr<VulkanContext> context_;
  std::size_t messagesBefore_ = 0;
};
std::unique_ptr<VulkanContext> SimulationVk::context_;

// From the same flat state, N steps on each path end within a stated tolerance of each other:
// the device runs in float (about 7 digits), the CPU in double, and float's rounding of each
// step's forces moves the state by a few parts in 1e7 of the sheet; the damped step does not
// amplify it, so after hundreds of steps the paths stay within 1e-5 of the sheet's diagonal and
// 0.01 degree of every hinge angle. Bars, hinges, glue and pins all take part.
TEST_F(SimulationVk, GpuAndCpuPathsAgreeAfterTheSameSteps) {
  struct Case {
    const char* name;
    CreasePattern pattern;
    ModelOptions options;
    double amount;
  };
  std::vector<Case> cases;
  cases.push_back({"crease", creasedSquare(12, 6, 90.0, 0.2), {}, 0.6});
  ModelOptions pinnedAndGlued;
  pinnedAndGlued.pins = {0, 1};
  pinnedAndGlued.glue = {{6, 20}};  // the right side's corner to its middle
  cases.push_back(
      {"miura, pins and glue", miuraOri(6, 4, 0.02, 0.02, 0.006, 2.0), pinnedAndGlued, 0.5});
  ModelOptions paper;
  paper.mode = SimulationMode::Paper;
  cases.push_back({"paper", creasedSquare(10, 4, -120.0, 0.2), paper, 0.8});
  // Creases pressing on the one-sided term's bound (hingeWrongSide): without it on the device
  // the twist folds a mountain as a valley within these steps, as the CPU's symmetric model did.
  cases.push_back(
      {"square twist", readFoldCreasePatternText(squareTwistFold(), "twist.fold"), {}, 0.3});
  for (const Case& c : cases) {
    const BarHingeModel model = buildModel(c.pattern, c.options);
    SimulationState cpu = flatState(model);
    constexpr std::size_t kSteps = 400;
    stepDynamic(model, c.amount, cpu, kSteps);
    GpuDynamicSolver gpu(*context_, model);
    gpu.step(c.amount, kSteps);
    SimulationState device;
    gpu.state(device);
    EXPECT_EQ(device.steps, kSteps);
    // The fold moved the sheet: agreement of two states still at rest would say nothing.
    const double travel = largestDistance(cpu.positions, model.flatPositions);
    EXPECT_GT(travel, 1e-3 * diagonal(model)) << c.name;
    EXPECT_LE(largestDistance(device.positions, cpu.positions), 1e-5 * diagonal(model)) << c.name;
    double angleError = 0.0;
    for (std::size_t j = 0; j < model.hinges.size(); ++j)
      angleError = std::max(angleError, std::abs(device.hingeAngles[j] - cpu.hingeAngles[j]));
    EXPECT_LE(angleError * kDegrees, 0.01) << c.name;
  }
}

// A pull (the live window's spring to the hand) on the device is the CPU path's: before each
// step the pulled vertex's velocity gains impulse (to - x), as LiveSimulation does between
// single CPU steps. Both end within the paths' tolerance, and the pull moved the sheet well past
// it.
TEST_F(SimulationVk, APullMovesTheSheetAsTheCpuPathsPull) {
  const BarHingeModel model = buildModel(creasedSquare(12, 6, 90.0, 0.2));
  const GpuPull pull{5, model.flatPositions[5] + glm::dvec3(0.0, 0.0, 0.05), 0.05 / model.timeStep};
  constexpr std::size_t kSteps = 300;
  SimulationState cpu = flatState(model), unpulled = flatState(model);
  for (std::size_t s = 0; s < kSteps; ++s) {
    cpu.velocities.resize(model.vertexCount(), glm::dvec3(0.0));
    cpu.velocities[pull.vertex] += pull.impulse * (pull.to - cpu.positions[pull.vertex]);
    stepDynamic(model, 0.3, cpu, 1);
  }
  stepDynamic(model, 0.3, unpulled, kSteps);
  GpuDynamicSolver gpu(*context_, model);
  gpu.step(0.3, kSteps, pull);
  SimulationState device;
  gpu.state(device);
  EXPECT_GT(largestDistance(cpu.positions, unpulled.positions), 1e-2 * diagonal(model));
  EXPECT_LE(largestDistance(device.positions, cpu.positions), 1e-5 * diagonal(model));
}

// At 0% the flat development is at rest on the device exactly: the bars' rest lengths are
// measured there by the step's own expression, so no force rounds away from zero.
TEST_F(SimulationVk, AtZeroPercentTheFlatStateStaysExactlyFlat) {
  const BarHingeModel model = buildModel(miuraOri(5, 5, 0.021, 0.017, 0.007, 2.0));
  GpuDynamicSolver gpu(*context_, model);
  SimulationState start, device;
  gpu.state(start);  // the development as the device holds it, in float
  EXPECT_LE(largestDistance(start.positions, model.flatPositions), 1e-7 * diagonal(model));
  gpu.step(0.0, 300);
  gpu.state(device);
  for (std::size_t v = 0; v < model.vertexCount(); ++v) {
    EXPECT_EQ(device.positions[v], start.positions[v]) << "vertex " << v;
    EXPECT_EQ(device.positions[v].z, 0.0) << "vertex " << v;
    EXPECT_EQ(device.velocities[v], glm::dvec3(0.0)) << "vertex " << v;
  }
}

// A single straight crease folds to its share of the target within 0.5 degrees on the device,
// and the facets stay flat.
TEST_F(SimulationVk, SingleCreaseReachesItsShareOfTheTarget) {
  for (double target : {-120.0}) {  // one crease: thousands of steps on lavapipe take seconds
    const BarHingeModel model = buildModel(creasedSquare(6, 3, target, 0.2));
    GpuDynamicSolver gpu(*context_, model);
    constexpr double kAmount = 0.5;
    gpu.step(kAmount, 9000);  // 6000 before the crease's one-sided term lowered the stable step
    SimulationState device;
    gpu.state(device);
    for (std::size_t j = 0; j < model.hinges.size(); ++j) {
      const double expected = model.hingeCrease[j] ? target * kAmount : 0.0;
      EXPECT_NEAR(device.hingeAngles[j] * kDegrees, expected, 0.5) << target << " hinge " << j;
    }
  }
}

// The same input and step count give the same state bit for bit on one device, however the steps
// are split among calls.
TEST_F(SimulationVk, SameInputAndStepsGiveTheSameStateBitForBit) {
  const BarHingeModel model = buildModel(creasedSquare(16, 8, 100.0, 0.2));  // 289 vertices
  auto run = [&](std::vector<std::size_t> calls) {
    GpuDynamicSolver gpu(*context_, model);
    for (std::size_t steps : calls) gpu.step(0.8, steps);
    SimulationState state;
    gpu.state(state);
    return state;
  };
  const SimulationState once = run({300}), again = run({300}), split = run({120, 1, 179});
  const double moved = largestDistance(once.positions, model.flatPositions);
  EXPECT_GT(moved, 1e-4);
  for (const SimulationState* other : {&again, &split}) {
    EXPECT_EQ(other->positions, once.positions);
    EXPECT_EQ(other->velocities, once.velocities);
    EXPECT_EQ(other->hingeAngles, once.hingeAngles);
  }
}

// setState replaces the device's state: a CPU state handed over mid-fold continues on the device
// as it would have on the CPU.
TEST_F(SimulationVk, AStateHandedOverContinuesOnTheDevice) {
  const BarHingeModel model = buildModel(creasedSquare(12, 6, -90.0, 0.2));
  SimulationState cpu = flatState(model);
  stepDynamic(model, 0.7, cpu, 200);
  GpuDynamicSolver gpu(*context_, model);
  gpu.setState(cpu);
  EXPECT_EQ(gpu.steps(), 200u);
  gpu.step(0.7, 100);
  stepDynamic(model, 0.7, cpu, 100);
  SimulationState device;
  gpu.state(device);
  EXPECT_EQ(device.steps, 300u);
  EXPECT_LE(largestDistance(device.positions, cpu.positions), 1e-5 * diagonal(model));
}

// The live simulation on the device (the window's and the headset's "GPU" solver, issue 39, 4):
// a core given the GPU solver folds the sheet from flat toward the design and under a pull as a
// CPU core does, frame by frame within the paths' float tolerance (1e-5 of the sheet; the rigid
// placement does not amplify it), and the same frames on the device again give the same bits.
TEST_F(SimulationVk, TheLiveSimulationOnTheGpuFollowsTheCpus) {
  const Sheet cylinder = makeSurface("cylinder", {{"resolution", 8}});
  double size = 0.0;
  for (const glm::dvec3& p : cylinder.positions)
    size = std::max(size, glm::distance(p, cylinder.positions[0]));
  FoldSession cpuSession(cylinder), gpuSession(cylinder), againSession(cylinder);
  InteractionCore cpu(cpuSession, Pose{}), gpu(gpuSession, Pose{}), again(againSession, Pose{});
  gpu.setGpuSolver(desktop::gpuLiveSolver(*context_));
  again.setGpuSolver(desktop::gpuLiveSolver(*context_));
  // As the window asks: the device's solver still steps in turn (it shares the drawing queue), so
  // each frame shows its own steps, as the CPU core stepping in turn does.
  gpu.setSimulationOnWorker(true);
  const std::uint32_t steps = testing::kSanitized ? 20 : 60;
  InputFrame frame;
  double largest = 0.0, travel = 0.0;
  for (int i = 0; i < 16; ++i) {
    frame.time += 1.0 / 60.0;
    std::optional<SimulationPull> pull;
    if (i >= 10)  // a hand's few centimetres: a yank far past the sheet is chaotic in float
      pull = SimulationPull{0, cylinder.positions[0] + glm::dvec3(0.0, 0.01, 0.01) * double(i - 9)};
    frame.simulation = SimulationInput{std::min(100.0, 12.5 * i), steps, pull};
    cpu.process(frame);
    frame.simulation->solver = LiveSolverKind::Gpu;
    gpu.process(frame);
    again.process(frame);
    ASSERT_NE(gpu.simulation(), nullptr) << gpu.simulationProblem();
    EXPECT_EQ(gpu.simulation()->steps(), cpu.simulation()->steps());
    const std::vector<glm::dvec3>& shown = gpu.simulation()->sheet().positions;
    largest = std::max(largest, largestDistance(shown, cpu.simulation()->sheet().positions));
    EXPECT_EQ(shown, again.simulation()->sheet().positions) << "frame " << i;
    travel = std::max(travel, largestDistance(cpu.simulation()->state().positions,
                                              cpu.simulation()->model().flatPositions));
  }
  EXPECT_GT(travel, 0.05 * size);  // it folded: agreement at rest would say nothing
  EXPECT_LE(largest, 1e-5 * size);
  EXPECT_GT(largest, 0.0);  // float on the device: the CPU's bits would say the device never ran
}

// The OBJ's vertex positions ("v x y z" lines).
std::vector<glm::dvec3> objVertices(const std::string& text) {
  std::vector<glm::dvec3> vertices;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("v ", 0) == 0) {
      std::istringstream fields(line.substr(2));
      glm::dvec3 p;
      fields >> p.x >> p.y >> p.z;
      vertices.push_back(p);
    }
  return vertices;
}

using SimulateGpuCli = testing::CliTest;

// `simulate --gpu` takes the same steps on the Vulkan device: its state is the CPU's within the
// float tolerance above, and --gpu with --settle is refused in one line.
TEST_F(SimulateGpuCli, GpuStepsMatchTheCpuStepsAndSettleIsRefused) {
  const std::string pattern =
      std::string(CURVEFOLD_TEST_DATA) + "/crease_patterns/waterbomb_base.fold";
  const std::string common = "simulate " + pattern + " --percent 40 --steps 300 --obj ";
  const testing::CommandResult cpu = run(common + "cpu.obj");
  ASSERT_EQ(cpu.exitCode, 0) << cpu.err;
  const testing::CommandResult gpu = run(common + "gpu.obj --gpu", "CURVEFOLD_VK_VALIDATION=1");
  ASSERT_EQ(gpu.exitCode, 0) << gpu.err;
  EXPECT_NE(gpu.out.find("300 dynamic steps on the GPU"), std::string::npos) << gpu.out;
  const std::vector<glm::dvec3> a = objVertices(testing::slurp(path("cpu.obj")));
  const std::vector<glm::dvec3> b = objVertices(testing::slurp(path("gpu.obj")));
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 4u);
  double size = 0.0, moved = 0.0;
  for (std::size_t v = 0; v < a.size(); ++v) {
    size = std::max(size, glm::distance(a[v], a[0]));
    moved = std::max(moved, std::abs(a[v].z));
  }
  EXPECT_GT(moved, 0.05 * size);  // folded, not flat
  EXPECT_LE(largestDistance(a, b), 1e-5 * 2.0 * size);
  expectFailure(common + "settled.obj --gpu --settle", "--gpu", path("settled.obj"));
}

}  // namespace
}  // namespace curvefold
