// The folding simulation (engine/simulation): one damped dynamic step at 10k and 100k vertices
// (targets 1 ms and 10 ms on 2 cores), and a 10k-vertex design from flat to settled at 100% by the
// static solver (target 2 s), and every bundled and showcase design from flat by the solvers alone
// (BM_DesignFromFlatBySolvers/NAME), and by the dynamic solver alone as the live window steps it
// (BM_DesignFromFlatLive/NAME/S; crease patterns: BM_PatternFromFlatLive/NAME/S), and through the
// live window's own path, predictor included (BM_DesignFromFlatLiveWindow/NAME). The patterns: a
// square grid with one crease through the middle; the design: the cylinder surface bent to its
// shape (design mode drives every edge to its dihedral).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>

#include <tbb/task_arena.h>

#include "bench/simulation_bench_support.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/geometry/triangle_mesh.hpp"
#include "engine/io/crease_pattern_reader.hpp"
#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/contact.hpp"
#include "engine/simulation/design_input.hpp"
#include "engine/simulation/dynamic_solver.hpp"
#include "engine/simulation/rigid_placement.hpp"
#include "engine/simulation/static_solver.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "interaction/live_simulation.hpp"
#include "sim_input/player.hpp"
#include "sim_input/recording.hpp"

namespace curvefold {
namespace {

void BM_DynamicStep(benchmark::State& bench) {
  simbench::timeCpuDynamicStep(bench);
}
// 100 x 100 cells: 10,201 vertices; 173 x 173: 30,276; 316 x 316: 100,489.
BENCHMARK(BM_DynamicStep)
    ->Arg(100)
    ->Arg(173)
    ->Arg(316)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The same step on one thread: its CPU time is the step's whole work, which a loaded machine does
// not inflate (the two-thread wall time above waits for a second core other jobs may hold).
void BM_DynamicStepOneThread(benchmark::State& bench) {
  tbb::task_arena arena(1);
  arena.execute([&] { BM_DynamicStep(bench); });
}
BENCHMARK(BM_DynamicStepOneThread)->Arg(100)->Arg(173)->Arg(316)->Unit(benchmark::kMillisecond);

// The dynamic step in paper mode (0.1 mm) with self-contact off (second argument 0) or on (1), on
// the grid 0.2 m a side with its right half folded over onto its left 1.9 thicknesses above it
// (third argument 1: every vertex of both halves within the barrier's reach of the other layer,
// which pushes it away: no rest state, the steps push the layers apart and the list is found
// again several times), or folded at rest (2: restingFold), or left flat (0: the contact's list is
// kept, no pair pushes); fourth argument 1: edge pairs too (what `simulate --paper` asks for,
// setPaperMode). Counters: pairs listed and pushing at the end, and the list's rebuilds (searches)
// and refits (searches that refitted the trees) in the timed steps alone.
//
// restingFold: the right half folded over onto the left with its layers thickness + activation
// (2 t) apart, where the barrier begins: the crease column at the fold's apex t above the lower
// layer, the two columns beside it leaning by asin(t / h) (h the cell) and every bar at its
// length, driven at the fold amount whose crease target is the angle it has (180 - 2 asin(t / h)
// degrees), so no element and no pair pushes: the steps time the list's forces as the live window
// meets a sheet folded flat, not its rebuilds.
std::vector<glm::dvec3> restingFold(const BarHingeModel& model, double side, double cell, double t,
                                    double& amount) {
  const double crease = 0.5 * side, lean = cell - std::sqrt(cell * cell - t * t);
  std::vector<glm::dvec3> x = model.flatPositions;
  for (glm::dvec3& p : x) {
    if (std::abs(p.x - crease) < 1e-9)
      p = {crease, p.y, t};
    else if (p.x < crease)
      p = {p.x + lean, p.y, 0.0};
    else
      p = {2.0 * crease - p.x + lean, p.y, 2.0 * t};
  }
  amount = (180.0 - 2.0 * std::asin(t / cell) * 180.0 / std::numbers::pi) / 180.0;
  return x;
}

void BM_DynamicStepPaper(benchmark::State& bench) {
  const int cells = static_cast<int>(bench.range(0));
  constexpr double kSide = 0.2, kThickness = 1e-4;
  ModelOptions options;
  options.mode = SimulationMode::Paper;
  options.paper.thickness = kThickness;
  options.contact.enabled = bench.range(1) == 1;
  options.contact.edgePairs = bench.range(3) == 1;
  const BarHingeModel model =
      buildModel(testing::creasedSquare(cells, cells / 2, 180.0, kSide), options);
  SimulationState state = flatState(model);
  double amount = 1.0;
  if (bench.range(2) == 1) {
    for (glm::dvec3& p : state.positions)
      if (p.x > 0.1 + 1e-9) p = {0.2 - p.x, p.y, 1.9e-4};
    state.hingeAngles = hingeAngles(model, state.positions);
  } else if (bench.range(2) == 2) {
    state.positions = restingFold(model, kSide, kSide / cells, kThickness, amount);
    state.hingeAngles = hingeAngles(model, state.positions);
  }
  stepDynamic(model, amount, state, 10);
  const std::size_t rebuildsBefore = state.contactPairs.rebuilds;
  const std::size_t refitsBefore = state.contactPairs.refits;
  for (auto _ : bench) {
    stepDynamic(model, amount, state, 1);
    benchmark::DoNotOptimize(state.positions.data());
  }
  std::size_t edgePairs = 0, pushing = 0;
  ContactTerm term;
  for (const ContactPair& pair : state.contactPairs.pairs) {
    edgePairs += pair.edges;
    pushing += contactTerm(model, state.positions, pair, term, true);
  }
  bench.counters["vertices"] = static_cast<double>(model.vertexCount());
  bench.counters["pairs"] = static_cast<double>(state.contactPairs.pairs.size());
  bench.counters["pushing"] = static_cast<double>(pushing);
  bench.counters["edge_pairs"] = static_cast<double>(edgePairs);
  bench.counters["rebuilds"] = static_cast<double>(state.contactPairs.rebuilds - rebuildsBefore);
  bench.counters["refits"] = static_cast<double>(state.contactPairs.refits - refitsBefore);
}
// 100 cells: 10,201 vertices; 316: 100,489 (the 1 ms and 10 ms).
void paperStepCases(benchmark::internal::Benchmark* bench) {
  // contact, folded, edge pairs
  constexpr std::int64_t kCases[][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 1},
                                        {1, 1, 1}, {0, 2, 0}, {1, 2, 0}, {1, 2, 1}};
  for (const std::int64_t cells : {100, 316})
    for (const auto& c : kCases) bench->Args({cells, c[0], c[1], c[2]});
}
BENCHMARK(BM_DynamicStepPaper)->Apply(paperStepCases)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same paper steps on one thread: CPU time, which a loaded machine does not inflate.
void BM_DynamicStepPaperOneThread(benchmark::State& bench) {
  tbb::task_arena arena(1);
  arena.execute([&] { BM_DynamicStepPaper(bench); });
}
BENCHMARK(BM_DynamicStepPaperOneThread)->Apply(paperStepCases)->Unit(benchmark::kMillisecond);

// Flat to settled at 100% (predictor on: the default) or by continuation alone (predictor off,
// the path a design takes when its targets are not reachable at once).
void settleDesignFromFlat(benchmark::State& bench, bool predictor) {
  const Sheet sheet =
      makeSurface("cylinder", {{"resolution", static_cast<double>(bench.range(0))}});
  const BarHingeModel model = buildModel(designPattern(sheet).pattern);
  StaticOptions options;
  options.predictor = predictor;
  bool converged = true;
  StaticResult result;
  for (auto _ : bench) {
    SimulationState state = flatState(model);
    result = settle(model, 1.0, state, options);
    converged = result.converged && converged;
    benchmark::DoNotOptimize(state.positions.data());
  }
  bench.counters["vertices"] = static_cast<double>(model.vertexCount());
  bench.counters["converged"] = converged ? 1 : 0;
  bench.counters["iterations"] = static_cast<double>(result.iterations);
  bench.counters["residual"] = result.residual;
}
void BM_SettleDesignFromFlat(benchmark::State& bench) {
  settleDesignFromFlat(bench, true);
}
void BM_SettleDesignFromFlatByContinuation(benchmark::State& bench) {
  settleDesignFromFlat(bench, false);
}
// Resolution 116: 10,092 vertices.
BENCHMARK(BM_SettleDesignFromFlat)->Arg(116)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SettleDesignFromFlatByContinuation)
    ->Arg(116)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

// What the live predictor costs a frame (LiveSimulation, interaction/live_simulation.hpp): a
// frame with no dynamic steps (the rigid placement alone) on a cylinder design of 10k vertices,
// with the slider held (second argument 0), moving a percent a frame between 50 and 90% (1: not
// tried while it moves), or coming to rest at a new amount every second frame (2: tried, and
// taken, every second frame; the time is per frame); 3: moving as 1 with the frame's
// liveStepsPerFrame steps, as the window steps it (the fold path's update in their place).
void BM_LiveFramePredictor(benchmark::State& bench) {
  const Sheet sheet =
      makeSurface("cylinder", {{"resolution", static_cast<double>(bench.range(0))}});
  LiveSimulation live(sheet);
  const long mode = bench.range(1);
  int frame = 0;
  for (auto _ : bench) {
    ++frame;
    const double percent = mode == 0                ? 70.0
                           : mode == 1 || mode == 3 ? 50.0 + frame % 40
                                                    : 50.0 + (frame / 2) % 40;
    SimulationInput input = liveSimulationInput(percent, sheet);
    if (mode != 3) input.steps = 0;
    live.advance(input);
    benchmark::DoNotOptimize(live.sheet().positions.data());
  }
  bench.counters["vertices"] = static_cast<double>(sheet.vertexCount());
  bench.counters["predictions"] = static_cast<double>(live.predictions());
}
BENCHMARK(BM_LiveFramePredictor)
    ->Args({116, 0})
    ->Args({116, 1})
    ->Args({116, 2})
    ->Args({116, 3})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Every bundled and showcase design (the final sheet of each recording in examples/recordings and
// examples/showcase/recordings) from flat to 100% in design mode by the solvers alone (no
// predictor), then compared with the design after the best rigid placement: the two-sided
// Hausdorff distance over the diagonal (check: <= 0.5%) and the worst edge strain (<= 0.1%).
void designFromFlatBySolvers(benchmark::State& bench, const std::filesystem::path& recording) {
  const Sheet sheet = replayRecording(readRecording(recording)).sheet;
  const BarHingeModel model = buildModel(designPattern(sheet).pattern);
  StaticOptions options;
  options.predictor = false;
  StaticResult result;
  SimulationState state;
  for (auto _ : bench) {
    state = flatState(model);
    result = settle(model, 1.0, state, options);
    benchmark::DoNotOptimize(state.positions.data());
  }
  Sheet simulated = sheet;
  simulated.positions =
      placed(bestRigidPlacement(state.positions, sheet.positions), state.positions);
  double worstStrain = 0.0;
  for (double strain : edgeStrain(model, state.positions))
    worstStrain = std::max(worstStrain, std::abs(strain));
  bench.counters["vertices"] = static_cast<double>(model.vertexCount());
  bench.counters["converged"] = result.converged ? 1 : 0;
  bench.counters["iterations"] = static_cast<double>(result.iterations);
  bench.counters["hausdorff_pct"] =
      100.0 * surfaceDistance(meshOf(simulated), meshOf(sheet)).relativeHausdorff();
  bench.counters["strain_pct"] = 100.0 * worstStrain;
}

// Every bundled and showcase design folded from flat as the live window folds it: the dynamic
// solver alone (no predictor, no static solve), liveStepsPerFrame steps a frame, the fold slider
// moved from 0 to 100% over the first kSliderFrames frames and then held. Counts the frames until
// the state (after the best rigid placement) is within 0.5% of the design's diagonal (two-sided
// Hausdorff, checked every kCheckEvery frames), up to kMaxFrames. The second argument picks the
// stiffnesses: 0 the project's design-mode defaults, 1 Origami Simulator's published ones (axial
// 20, crease 0.7, facet 0.2; its damping ratio 0.45 is the solver's default either way), 2 the
// defaults with facets 200 times softer than creases (the static solver's "creases first").
constexpr std::size_t kSliderFrames = 30, kCheckEvery = 10;
// $CURVEFOLD_BENCH_MAX_FRAMES, else 3000 (100 s at 30 frames a second).
const std::size_t kMaxFrames = [] {
  const char* text = std::getenv("CURVEFOLD_BENCH_MAX_FRAMES");
  return text ? std::size_t(std::max(1L, std::atol(text))) : std::size_t(3000);
}();

void designFromFlatLive(benchmark::State& bench, const std::filesystem::path& recording,
                        int stiffness) {
  const Sheet sheet = replayRecording(readRecording(recording)).sheet;
  ModelOptions modelOptions;
  if (stiffness == 1) modelOptions = simulatorModelOptions();
  if (stiffness == 2) modelOptions.facetStiffness = modelOptions.creaseStiffness / 200.0;
  const BarHingeModel model = buildModel(designPattern(sheet).pattern, modelOptions);
  const std::uint32_t steps = liveStepsPerFrame(model.vertexCount());
  std::size_t frames = 0;
  double distance = 1.0;
  SimulationState state;
  // $CURVEFOLD_BENCH_VELOCITY_DAMPING: the share of every velocity lost per step (default 0.01).
  DynamicOptions dynamic;
  if (const char* text = std::getenv("CURVEFOLD_BENCH_VELOCITY_DAMPING"))
    dynamic.velocityDamping = std::atof(text);
  for (auto _ : bench) {
    state = flatState(model);
    for (frames = 1; frames <= kMaxFrames; ++frames) {
      const double amount = std::min(1.0, double(frames) / kSliderFrames);
      stepDynamic(model, amount, state, steps, dynamic);
      if (frames % kCheckEvery != 0) continue;
      Sheet simulated = sheet;
      simulated.positions =
          placed(bestRigidPlacement(state.positions, sheet.positions), state.positions);
      distance = surfaceDistance(meshOf(simulated), meshOf(sheet)).relativeHausdorff();
      if (!std::isfinite(distance) || distance <= 0.005) break;
    }
  }
  // $CURVEFOLD_BENCH_POLISH: then the static solver (no predictor) from the dynamic state.
  if (std::getenv("CURVEFOLD_BENCH_POLISH") && distance > 0.005) {
    StaticOptions options;
    options.predictor = false;
    const StaticResult result = settle(model, 1.0, state, options);
    Sheet simulated = sheet;
    simulated.positions =
        placed(bestRigidPlacement(state.positions, sheet.positions), state.positions);
    bench.counters["static_iterations"] = static_cast<double>(result.iterations);
    bench.counters["static_hausdorff_pct"] =
        100.0 * surfaceDistance(meshOf(simulated), meshOf(sheet)).relativeHausdorff();
  }
  double worstStrain = 0.0;
  for (double strain : edgeStrain(model, state.positions))
    worstStrain = std::max(worstStrain, std::abs(strain));
  bench.counters["vertices"] = static_cast<double>(model.vertexCount());
  bench.counters["steps_per_frame"] = steps;
  bench.counters["frames"] = static_cast<double>(std::min(frames, kMaxFrames));
  bench.counters["reached"] = distance <= 0.005 ? 1 : 0;
  bench.counters["hausdorff_pct"] = 100.0 * distance;
  bench.counters["strain_pct"] = 100.0 * worstStrain;
}

// The same through the live window's own path (interaction/live_simulation.hpp, as the window's
// fold-amount slider drives it: liveSimulationInput, liveStepsPerFrame steps a frame, the
// predictor whenever the amount changes; the project's design-mode stiffnesses): the slider moved
// from 0 to 100% over the first kSliderFrames frames and then held; counts the frames until the
// shown sheet is within 0.5% of the design's diagonal (two-sided Hausdorff), checked every frame
// from the slider's last frame for ten frames, then every kCheckEvery, up to kMaxFrames.
void designFromFlatLiveWindow(benchmark::State& bench, const std::filesystem::path& recording) {
  const Sheet sheet = replayRecording(readRecording(recording)).sheet;
  std::size_t frames = 0, predictions = 0;
  double distance = 1.0, worstStrain = 0.0;
  for (auto _ : bench) {
    LiveSimulation live(sheet);
    for (frames = 1; frames <= kMaxFrames; ++frames) {
      live.advance(liveSimulationInput(
          100.0 * std::min(1.0, double(frames) / double(kSliderFrames)), sheet));
      if (frames < kSliderFrames || (frames >= kSliderFrames + 10 && frames % kCheckEvery != 0))
        continue;
      distance = surfaceDistance(meshOf(live.sheet()), meshOf(sheet)).relativeHausdorff();
      if (!std::isfinite(distance) || distance <= 0.005) break;
    }
    worstStrain = 0.0;
    for (double strain : edgeStrain(live.model(), live.state().positions))
      worstStrain = std::max(worstStrain, std::abs(strain));
    predictions = live.predictions();
  }
  bench.counters["vertices"] = static_cast<double>(sheet.vertexCount());
  bench.counters["steps_per_frame"] = liveStepsPerFrame(sheet.vertexCount());
  bench.counters["frames"] = static_cast<double>(std::min(frames, kMaxFrames));
  bench.counters["reached"] = distance <= 0.005 ? 1 : 0;
  bench.counters["hausdorff_pct"] = 100.0 * distance;
  bench.counters["strain_pct"] = 100.0 * worstStrain;
  bench.counters["predictions"] = static_cast<double>(predictions);
}

// The live slider's ramp (issue 39, 4: "the sheet folds from flat to the design and back as it
// moves"): the live window's path (LiveSimulation, liveStepsPerFrame steps a frame) with the
// slider moved from 0 to 100% over kRampFrames frames and then held for kRestFrames. Counters:
// the crease hinges' mean |angle - target| at the frame's amount (degrees), its mean over the
// ramp's frames (lag_mean_deg) and its largest (lag_max_deg); the worst crease's error at
// mid-ramp (worst_mid_deg); the largest edge strain over the ramp (ramp_strain_pct); the largest
// move of any shown vertex in one frame during the ramp (ramp_step_pct) and while the slider
// rests at 100% (rest_jump_pct, rest_jump_m), in % of the design's diagonal or metres.
constexpr std::size_t kRampFrames = 60, kRestFrames = 10;

void liveSliderRamp(benchmark::State& bench, const std::filesystem::path& recording) {
  const Sheet sheet = replayRecording(readRecording(recording)).sheet;
  glm::dvec3 low(1e300), high(-1e300);
  for (const glm::dvec3& p : sheet.positions) low = glm::min(low, p), high = glm::max(high, p);
  const double diagonal = glm::distance(low, high);
  double lagSum = 0.0, lagMax = 0.0, worstMid = 0.0, rampStrain = 0.0, rampStep = 0.0,
         restJump = 0.0, rampStrainMedian = 0.0, rampStrain99 = 0.0;
  for (auto _ : bench) {
    LiveSimulation live(sheet);
    lagSum = lagMax = worstMid = rampStrain = rampStep = restJump = 0.0;
    rampStrainMedian = rampStrain99 = 0.0;
    std::vector<glm::dvec3> before = live.sheet().positions;
    for (std::size_t frame = 1; frame <= kRampFrames + kRestFrames; ++frame) {
      const double amount = std::min(1.0, double(frame) / double(kRampFrames));
      live.advance(liveSimulationInput(100.0 * amount, sheet));
      double move = 0.0;
      for (std::size_t v = 0; v < before.size(); ++v)
        move = std::max(move, glm::distance(before[v], live.sheet().positions[v]));
      before = live.sheet().positions;
      if (frame >= kRampFrames) {
        restJump = std::max(restJump, move);
        continue;
      }
      rampStep = std::max(rampStep, move);
      const BarHingeModel& model = live.model();
      const std::vector<double> angles =
          hingeAngles(model, live.state().positions, live.state().hingeAngles);
      double sum = 0.0, worst = 0.0;
      std::size_t creases = 0;
      for (std::size_t j = 0; j < model.hinges.size(); ++j) {
        if (!model.hingeCrease[j]) continue;
        const double error = std::abs(angles[j] - model.target(j, amount)) * 180.0 / M_PI;
        sum += error, worst = std::max(worst, error), ++creases;
      }
      const double lag = creases ? sum / double(creases) : 0.0;
      lagSum += lag, lagMax = std::max(lagMax, lag);
      if (frame == kRampFrames / 2) worstMid = worst;
      std::vector<double> strains = edgeStrain(model, live.state().positions);
      for (double& strain : strains) strain = std::abs(strain);
      std::sort(strains.begin(), strains.end());
      if (!strains.empty()) {
        rampStrain = std::max(rampStrain, strains.back());
        rampStrainMedian = std::max(rampStrainMedian, strains[strains.size() / 2]);
        rampStrain99 = std::max(rampStrain99, strains[strains.size() * 99 / 100]);
      }
    }
  }
  bench.counters["vertices"] = static_cast<double>(sheet.vertexCount());
  bench.counters["lag_mean_deg"] = lagSum / double(kRampFrames - 1);
  bench.counters["lag_max_deg"] = lagMax;
  bench.counters["worst_mid_deg"] = worstMid;
  bench.counters["ramp_strain_pct"] = 100.0 * rampStrain;
  bench.counters["ramp_strain_median_pct"] = 100.0 * rampStrainMedian;
  bench.counters["ramp_strain_p99_pct"] = 100.0 * rampStrain99;
  bench.counters["ramp_step_pct"] = 100.0 * rampStep / diagonal;
  bench.counters["rest_jump_pct"] = 100.0 * restJump / diagonal;
  bench.counters["rest_jump_m"] = restJump;
}

// Crease patterns (tests/data/crease_patterns, and every .fold and .svg in the folder
// $CURVEFOLD_BENCH_PATTERNS when set, e.g. Origami Simulator's assets) folded from flat the same
// way, in design mode: frames until every crease is within 0.5 degrees of its 100% angle, up to
// kMaxFrames (then the largest error left). Second argument as above.
void patternFromFlatLive(benchmark::State& bench, const std::filesystem::path& file,
                         bool simulatorStiffness) {
  ModelOptions modelOptions;
  if (simulatorStiffness) modelOptions = simulatorModelOptions();
  const BarHingeModel model = buildModel(readCreasePattern(file), modelOptions);
  const std::uint32_t steps = liveStepsPerFrame(model.vertexCount());
  std::size_t frames = 0;
  double worstError = 180.0;
  SimulationState state;
  for (auto _ : bench) {
    state = flatState(model);
    for (frames = 1; frames <= kMaxFrames; ++frames) {
      const double amount = std::min(1.0, double(frames) / kSliderFrames);
      stepDynamic(model, amount, state, steps);
      if (frames % kCheckEvery != 0 || amount < 1.0) continue;
      worstError = 0.0;
      for (double error : creaseAngleError(model, state.positions, 1.0, state.hingeAngles))
        worstError = std::max(worstError, std::abs(error));
      if (!std::isfinite(worstError) || worstError <= 0.5) break;
    }
  }
  double worstStrain = 0.0;
  for (double strain : edgeStrain(model, state.positions))
    worstStrain = std::max(worstStrain, std::abs(strain));
  bench.counters["vertices"] = static_cast<double>(model.vertexCount());
  bench.counters["steps_per_frame"] = steps;
  bench.counters["frames"] = static_cast<double>(std::min(frames, kMaxFrames));
  bench.counters["reached"] = worstError <= 0.5 ? 1 : 0;
  bench.counters["crease_error_deg"] = worstError;
  bench.counters["strain_pct"] = 100.0 * worstStrain;
}

// Crease patterns settled from flat at 100% in paper mode (0.1 mm, 4 GPa: `simulate P --percent
// 100 --settle --paper 0.1`), the static solver's last stage with Gauss-Newton steps (0) or the
// exact Hessian (1, StaticOptions::exactHessian): iterations, final residual, converged, largest
// and mean crease angle error (degrees), largest strain. contact: 0 off, 1 vertex-triangle pairs
// only, 2 the command line's (setPaperMode: edge pairs too).
void patternPaperSettle(benchmark::State& bench, const std::filesystem::path& file, bool exact,
                        int contact = 0) {
  ModelOptions modelOptions;
  setPaperMode(modelOptions, 0.1, kDefaultPaperModulusGpa, contact > 0);
  modelOptions.contact.edgePairs = contact == 2;
  const BarHingeModel model = buildModel(readCreasePattern(file), modelOptions);
  StaticOptions options;
  options.exactHessian = exact;
  StaticResult result;
  SimulationState state;
  for (auto _ : bench) {
    state = flatState(model);
    result = settle(model, 1.0, state, options);
  }
  double largest = 0.0, sum = 0.0, strain = 0.0;
  std::size_t creases = 0;
  const std::vector<double> error =
      creaseAngleError(model, state.positions, 1.0, state.hingeAngles);
  for (std::size_t j = 0; j < model.hinges.size(); ++j)
    if (model.hingeCrease[j]) {
      largest = std::max(largest, std::abs(error[model.hingeEdge[j]]));
      sum += std::abs(error[model.hingeEdge[j]]);
      ++creases;
    }
  for (double e : edgeStrain(model, state.positions)) strain = std::max(strain, std::abs(e));
  bench.counters["vertices"] = static_cast<double>(model.vertexCount());
  bench.counters["iterations"] = static_cast<double>(result.iterations);
  bench.counters["residual"] = result.residual;
  bench.counters["converged"] = result.converged ? 1 : 0;
  bench.counters["error_max_deg"] = largest;
  bench.counters["error_mean_deg"] = creases ? sum / static_cast<double>(creases) : 0.0;
  bench.counters["strain"] = strain;
  bench.counters["crossing_pairs"] =
      static_cast<double>(crossingTrianglePairs(model, state.positions));
  bench.counters["nearest_layers_mm"] =
      1e3 * smallestLayerDistance(model, state.positions, 1e-4, 1e-2);
}

void registerPatterns() {
  std::vector<std::filesystem::path> folders = {CURVEFOLD_SOURCE_DIR "/tests/data/crease_patterns"};
  if (const char* more = std::getenv("CURVEFOLD_BENCH_PATTERNS")) folders.emplace_back(more);
  for (const auto& folder : folders) {
    std::vector<std::filesystem::path> paths;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
      if (entry.path().extension() == ".fold" || entry.path().extension() == ".svg")
        paths.push_back(entry.path());
    std::sort(paths.begin(), paths.end());
    // Self-contact off (0: as before it was built), vertex-triangle pairs only (1) or with edge
    // pairs (2: `simulate --paper`'s), exact Hessian.
    for (const auto& path : paths)
      for (int contact : {0, 1, 2})
        benchmark::RegisterBenchmark(
            ("BM_PatternPaperContact/" + path.stem().string() + "/" + std::to_string(contact))
                .c_str(),
            [path, contact](benchmark::State& bench) {
              try {
                patternPaperSettle(bench, path, true, contact);
              } catch (const std::exception& e) {
                bench.SkipWithError(e.what());
              }
            })
            ->Unit(benchmark::kMillisecond)
            ->Iterations(1)
            ->UseRealTime();
    for (const auto& path : paths)
      for (int exact : {0, 1})
        benchmark::RegisterBenchmark(
            ("BM_PatternPaperSettle/" + path.stem().string() + "/" + std::to_string(exact)).c_str(),
            [path, exact](benchmark::State& bench) {
              try {
                patternPaperSettle(bench, path, exact == 1);
              } catch (const std::exception& e) {
                bench.SkipWithError(e.what());
              }
            })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime()
            ->Iterations(1);
    for (const auto& path : paths)
      for (int simulator : {0, 1})
        benchmark::RegisterBenchmark(
            ("BM_PatternFromFlatLive/" + path.stem().string() + "/" + std::to_string(simulator))
                .c_str(),
            [path, simulator](benchmark::State& bench) {
              try {
                patternFromFlatLive(bench, path, simulator == 1);
              } catch (const std::exception& e) {
                bench.SkipWithError(e.what());
              }
            })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime()
            ->Iterations(1);
  }
}

void registerDesigns() {
  for (const char* folder : {"/examples/recordings", "/examples/showcase/recordings"}) {
    std::vector<std::filesystem::path> paths;
    for (const auto& entry :
         std::filesystem::directory_iterator(CURVEFOLD_SOURCE_DIR + std::string(folder)))
      if (entry.path().extension() == ".jsonl") paths.push_back(entry.path());
    std::sort(paths.begin(), paths.end());
    for (const auto& path : paths)
      benchmark::RegisterBenchmark(
          ("BM_DesignFromFlatBySolvers/" + path.stem().string()).c_str(),
          [path](benchmark::State& bench) { designFromFlatBySolvers(bench, path); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(1);
    for (const auto& path : paths)
      benchmark::RegisterBenchmark(
          ("BM_DesignFromFlatLiveWindow/" + path.stem().string()).c_str(),
          [path](benchmark::State& bench) { designFromFlatLiveWindow(bench, path); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(1);
    for (const auto& path : paths)
      benchmark::RegisterBenchmark(("BM_LiveSliderRamp/" + path.stem().string()).c_str(),
                                   [path](benchmark::State& bench) { liveSliderRamp(bench, path); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(1);
    for (const auto& path : paths)
      for (int stiffness : {0, 1, 2})
        benchmark::RegisterBenchmark(
            ("BM_DesignFromFlatLive/" + path.stem().string() + "/" + std::to_string(stiffness))
                .c_str(),
            [path, stiffness](benchmark::State& bench) {
              designFromFlatLive(bench, path, stiffness);
            })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime()
            ->Iterations(1);
  }
}

}  // namespace
}  // namespace curvefold

int main(int argc, char** argv) {
  curvefold::registerDesigns();
  curvefold::registerPatterns();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
