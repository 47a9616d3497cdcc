#include <cmath>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <random>
#include <sstream>
#include <utility>

#include <tbb/task_arena.h>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <chrono>
#include <filesystem>

#include "engine/fit/surface_distance.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/triangle_mesh.hpp"
#include "engine/io/crease_pattern_reader.hpp"
#include "engine/io/fold_crease_pattern.hpp"
#include "engine/io/svg_crease_pattern.hpp"
#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/central_differences.hpp"
#include "engine/simulation/contact.hpp"
#include "engine/simulation/design_input.hpp"
#include "engine/simulation/dynamic_solver.hpp"
#include "engine/simulation/folding_motion.hpp"
#include "engine/simulation/hinge_unfolding.hpp"
#include "engine/simulation/rigid_placement.hpp"
#include "engine/simulation/state_report.hpp"
#include "engine/simulation/static_solver.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "sanitizer_support.hpp"
#include "sim_input/player.hpp"
#include "sim_input/recording.hpp"
#include "test_paths.hpp"
#include "tests/simulation_test_support.hpp"

namespace curvefold {
namespace {

using testing::creasedSquare;
constexpr double kDegrees = 180.0 / std::numbers::pi;

// The judge's square twist (testing::squareTwistFold), with the crease's one-sided term this
// stiff.
BarHingeModel squareTwist(double wrongSideScale = ModelOptions{}.wrongSideScale) {
  ModelOptions options;
  options.wrongSideScale = wrongSideScale;
  return buildModel(readFoldCreasePatternText(testing::squareTwistFold(), "twist.fold"), options);
}

// `pattern` in metres as paper 0.1 mm thick, of the default modulus, with self-contact.
BarHingeModel paperModelOf(CreasePattern pattern) {
  scaleToMetres(pattern);
  ModelOptions paper;
  setPaperMode(paper, 0.1, kDefaultPaperModulusGpa, true);
  return buildModel(pattern, paper);
}

// Creases past flat to the other side of their targets, or past flat-folded (through the
// paper), by more than half a degree, at these angles.
std::size_t creasesOffTheirSide(const BarHingeModel& model, const std::vector<double>& angles) {
  std::size_t off = 0;
  for (std::size_t j = 0; j < model.hinges.size(); ++j) {
    if (!model.hingeCrease[j]) continue;
    const double along = (model.hingeTarget[j] > 0.0 ? 1.0 : -1.0) * angles[j] * kDegrees;
    if (along < -0.5 || along > 180.5) ++off;
  }
  return off;
}

TEST(Simulation, HingeGradientMatchesFiniteDifferences) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (int trial = 0; trial < 20; ++trial) {
    std::array<glm::dvec3, 4> p = {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0),
                                   glm::dvec3(0.4, 0.8, 0), glm::dvec3(0.6, -0.7, 0)};
    for (auto& q : p) q += glm::dvec3(jitter(random), jitter(random), jitter(random));
    const auto gradient = hingeAngleGradient(p[0], p[1], p[2], p[3]);
    const double h = 1e-6;
    for (int v = 0; v < 4; ++v)
      for (int c = 0; c < 3; ++c) {
        auto plus = p, minus = p;
        plus[v][c] += h;
        minus[v][c] -= h;
        const double numeric = (hingeAngle(plus[0], plus[1], plus[2], plus[3]) -
                                hingeAngle(minus[0], minus[1], minus[2], minus[3])) /
                               (2 * h);
        EXPECT_NEAR(gradient[v][c], numeric, 1e-6) << "vertex " << v << " coordinate " << c;
      }
  }
}

// The exact Hessian's central differences (central_differences.hpp) give the same second
// derivatives wherever the points lie: a hinge of 5 mm edges, as traditionalCrane's, at the origin
// and 1 m out (the angle and its derivatives are the same there). Divided by twice the step, not
// by the width the coordinate moved as rounded, entries 1 m out were off by up to ulp(1) / 2h =
// 2.2e-8 of their size (issue 39: the crane at 75% of 25:100:4, 0.13 m from the origin, stalled
// at residual 1.9e-7).
TEST(Simulation, CentralDifferenceHessianIsTheSameWhereverTheHingeLies) {
  const std::array<glm::dvec3, 4> hinge{glm::dvec3(0.0, 0.0, 0.0), glm::dvec3(0.005, 0.0, 0.0),
                                        glm::dvec3(0.0021, 0.0043, 0.0007),
                                        glm::dvec3(0.0032, -0.0029, 0.0021)};
  const auto gradientOf = [](const std::array<glm::dvec3, 4>& p, std::array<glm::dvec3, 4>& g) {
    g = hingeAngleGradient(p[0], p[1], p[2], p[3]);
    return true;
  };
  const double step = 1e-6 * glm::length(hinge[1] - hinge[0]);
  std::array<std::array<glm::dmat3, 4>, 4> here{}, there{};
  ASSERT_TRUE(centralDifferenceHessian(hinge, step, gradientOf, here));
  for (const glm::dvec3 offset : {glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.13, -0.09, 1.0)}) {
    std::array<glm::dvec3, 4> moved = hinge;
    for (glm::dvec3& p : moved) p += offset;
    ASSERT_TRUE(centralDifferenceHessian(moved, step, gradientOf, there));
    double largest = 0.0, apart = 0.0;
    for (int p = 0; p < 4; ++p)
      for (int q = 0; q < 4; ++q)
        for (int c = 0; c < 3; ++c)
          for (int r = 0; r < 3; ++r) {
            largest = std::max(largest, std::abs(here[p][q][c][r]));
            apart = std::max(apart, std::abs(there[p][q][c][r] - here[p][q][c][r]));
          }
    EXPECT_GT(largest, 1e3);  // 1 / (5 mm)^2 scale: a hinge that bends
    EXPECT_LT(apart / largest, 2e-9) << offset.x << " " << offset.y << " " << offset.z;
  }
}

// Two good triangles with a sliver between them (a 1e-6 edge beside 1-long ones, as reflection
// cuts leave): the sliver's own hinges are weakened to nothing, yet the sheet must resist bending
// across it as across any facet edge (a bridge hinge from one good triangle to the other), and
// the static solver must bring a sheet bent there back to the design (flat) from 30 degrees.
TEST(Simulation, SheetResistsBendingAcrossASliverAsAcrossAnyFacetEdge) {
  CreasePattern pattern;
  // A, B (1e-6 above A), C, P (below AC), Q (above BC).
  pattern.vertices = {{0.0, 0.0}, {0.0, 1e-6}, {1.0, 0.0}, {0.5, -0.5}, {0.5, 0.5}};
  pattern.triangles = {{0, 3, 2}, {0, 2, 1}, {1, 2, 4}};
  testing::addEdges(pattern, [](std::uint32_t a, std::uint32_t b) {
    return CreasePatternEdge{a, b, CreaseAssignment::Flat, 0.0};
  });
  const BarHingeModel model = buildModel(pattern);
  // Q turned 10 degrees about the line AC (B is within 1e-6 of it).
  std::vector<glm::dvec3> bent = model.flatPositions;
  const double turn = 10.0 / kDegrees;
  bent[4] = glm::dvec3(0.5, 0.5 * std::cos(turn), 0.5 * std::sin(turn));
  const double energy =
      modelEnergy(model, bent, hingeTargets(model, 1.0), hingeAngles(model, model.flatPositions));
  const double facetHinge = 0.5 * ModelOptions{}.facetStiffness * 1.0 * turn * turn;
  EXPECT_GE(energy, 0.5 * facetHinge) << "a facet hinge's energy " << facetHinge;

  SimulationState state = flatState(model);
  state.positions[4] = glm::dvec3(0.5, 0.5 * std::cos(3 * turn), 0.5 * std::sin(3 * turn));
  state.hingeAngles.clear();
  StaticOptions options;
  options.predictor = false;
  const StaticResult result = settle(model, 1.0, state, options);
  EXPECT_TRUE(result.converged);
  const double angle = hingeAngle(state.positions[0], state.positions[2], state.positions[3],
                                  state.positions[4]);  // T1 to T2 about AC
  EXPECT_NEAR(angle * kDegrees, 0.0, 0.1);
}

// A sliver (0.01 high over its unit edge AC) bridged from the triangle below AC to the one above
// its long edge AE, with a short edge CE (0.022) off the bridge's path that is a valley crease to
// a good triangle. Driven, that crease turned the sliver, whose plane is ill-defined, and in
// langCardinal.svg collapsed one in 3D to a height of 1e-10 m (its hinges' forces 3e6 each,
// cancelling to a residual of 5: NOT settled at 100%). The short edge, which the sliver does not
// weaken, is left to the bridge as the crossed edges are; the good triangles' own hinges keep
// their stiffness.
TEST(Simulation, TheShortEdgeOfABridgedSliverIsLeftToTheBridge) {
  CreasePattern pattern;
  // A, C, E (the sliver's far corner, 0.022 from C), P (below AC), Q (above AE), F (right of CE).
  pattern.vertices = {{0.0, 0.0}, {1.0, 0.0}, {0.98, 0.01}, {0.5, -0.5}, {0.5, 0.5}, {1.3, 0.3}};
  pattern.triangles = {{0, 3, 1}, {0, 1, 2}, {0, 2, 4}, {1, 5, 2}, {2, 5, 4}};
  testing::addEdges(pattern, [](std::uint32_t a, std::uint32_t b) {
    if (a == 1 && b == 2) return CreasePatternEdge{a, b, CreaseAssignment::Valley, 180.0};
    return CreasePatternEdge{a, b, CreaseAssignment::Flat, 0.0};
  });
  const BarHingeModel model = buildModel(pattern);
  std::size_t bridges = 0;
  for (std::size_t j = 0; j < model.hinges.size(); ++j) {
    if (model.bridgeKind(j) != 0) {
      ++bridges;
      EXPECT_GT(model.hingeStiffness[j], 0.0) << "the bridge";
      continue;
    }
    const auto& [left, right] = model.hingeTriangles[j];
    const bool onSliver = left == 1 || right == 1;
    const Hinge& h = model.hinges[j];
    if (onSliver)
      EXPECT_EQ(model.hingeStiffness[j], 0.0) << "hinge " << h.a << "-" << h.b << " of the sliver";
    else
      EXPECT_GT(model.hingeStiffness[j], 0.0) << "hinge " << h.a << "-" << h.b;
  }
  EXPECT_EQ(bridges, 1u);
}

TEST(Simulation, SingleStraightCreaseReachesItsShareOfTheTarget) {
  for (SimulationMode mode : {SimulationMode::Design, SimulationMode::Paper})
    for (double target : {90.0, -120.0})
      for (double percent : {25.0, 50.0, 100.0}) {
        const CreasePattern pattern = creasedSquare(6, 3, target, 0.2);
        ModelOptions options;
        options.mode = mode;
        const BarHingeModel model = buildModel(pattern, options);
        SimulationState state = flatState(model);
        const StaticResult result = settle(model, percent / 100.0, state);
        EXPECT_TRUE(result.converged);
        const std::vector<double> angles = hingeAngles(model, state.positions, state.hingeAngles);
        for (std::size_t j = 0; j < model.hinges.size(); ++j) {
          const double expected = model.hingeCrease[j] ? target * percent / 100.0 : 0.0;
          EXPECT_NEAR(angles[j] * kDegrees, expected, 0.5)
              << "percent " << percent << " hinge " << j;
        }
      }
}

// The rounding floor (static_solver.hpp): a tolerance far below what doubles resolve (1e-25 of the
// force scale) cannot be met, and the last stage stops where no step lowers the energy. There the
// state is settled at the rounding floor: every vertex's force within kRoundingFloorScale x its
// stiffness x its coordinates' last place, and the report says so. Without the floor it was "NOT
// settled" at a residual no representable move can lower.
TEST(Simulation, AToleranceBelowDoublePrecisionSettlesAtTheRoundingFloor) {
  const BarHingeModel model = buildModel(testing::miuraOri(4, 4, 1.0, 1.0, 0.5, 120.0 / kDegrees));
  StaticOptions options;
  options.tolerance = 1e-25;
  SimulationState state = flatState(model);
  const StaticResult result = settle(model, 0.6, state, options);
  EXPECT_TRUE(result.converged) << "residual " << result.residual;
  EXPECT_TRUE(result.atRoundingFloor);
  EXPECT_LT(result.iterations, options.maxIterations);  // stopped: no step lowered the energy
  EXPECT_GT(result.residual, options.tolerance);
  EXPECT_LE(result.residual, result.roundingFloor);
  EXPECT_LT(result.roundingFloor, 1e-12);  // a floor of doubles, not of the solver
  EXPECT_EQ(energyRises(result.history), 0u);
  EXPECT_EQ(settleSummary(result).rfind("settled at the rounding floor (residual ", 0), 0u)
      << settleSummary(result);
  // The stated tolerance, where doubles resolve it, decides alone.
  SimulationState plain = flatState(model);
  const StaticResult settled = settle(model, 0.6, plain);
  EXPECT_TRUE(settled.converged);
  EXPECT_FALSE(settled.atRoundingFloor);
  EXPECT_EQ(settled.roundingFloor, 0.0);
  EXPECT_EQ(settleSummary(settled).rfind("settled in ", 0), 0u) << settleSummary(settled);
}

// ... and a state short of equilibrium is not at the floor: the same Miura-ori cut after 21
// iterations, at a residual 2.5 times the tolerance (25,000 times the floor of the first test),
// is NOT settled, with the plain tolerance or one below doubles (a floor 1e7 times as lax called
// it settled).
TEST(Simulation, AStateShortOfEquilibriumIsNotAtTheRoundingFloor) {
  const BarHingeModel model = buildModel(testing::miuraOri(4, 4, 1.0, 1.0, 0.5, 120.0 / kDegrees));
  for (double tolerance : {StaticOptions{}.tolerance, 1e-25}) {
    StaticOptions options;
    options.tolerance = tolerance;
    options.maxIterations = 21;
    SimulationState state = flatState(model);
    const StaticResult result = settle(model, 0.6, state, options);
    // Near equilibrium, else this tests nothing: find the cut that is if the solver changes.
    EXPECT_GT(result.residual, StaticOptions{}.tolerance);
    EXPECT_LT(result.residual, 1e-8);
    EXPECT_FALSE(result.converged) << tolerance;
    EXPECT_FALSE(result.atRoundingFloor) << tolerance;
    EXPECT_EQ(settleSummary(result).rfind("NOT settled in 21 iterations", 0), 0u)
        << settleSummary(result);
  }
}

// The largest distance between corresponding vertices after the best rigid placement.
double placedDistance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  const std::vector<glm::dvec3> moved = placed(bestRigidPlacement(a, b), a);
  double largest = 0.0;
  for (std::size_t v = 0; v < a.size(); ++v)
    largest = std::max(largest, glm::distance(moved[v], b[v]));
  return largest;
}

TEST(Simulation, MiuraOriFollowsItsRigidFoldingMotion) {
  const double w = 1.0, h = 1.0, s = 0.5, side = std::min(h, std::hypot(w, s));
  const double full = 150.0 / kDegrees;  // zigzag fold angle at 100%
  const BarHingeModel model = buildModel(testing::miuraOri(6, 6, w, h, s, full));
  // The motion's state at zigzag angle rho: the closed form's angles placed across the hinges.
  auto motion = [&](double rho) {
    return unfoldedState(buildModel(testing::miuraOri(6, 6, w, h, s, rho)), 1.0).positions;
  };
  // The closed form is a motion: every hinge, not only the placement's tree, sits at its angle,
  // and every edge keeps its length.
  for (double rho : {0.4, 1.2, 2.4}) {
    const BarHingeModel exact = buildModel(testing::miuraOri(6, 6, w, h, s, rho));
    const SimulationState state = unfoldedState(exact, 1.0);
    for (std::size_t j = 0; j < exact.hinges.size(); ++j)
      ASSERT_NEAR(state.hingeAngles[j], exact.hingeTarget[j], 1e-9) << "rho " << rho;
    for (double strain : edgeStrain(exact, state.positions)) ASSERT_NEAR(strain, 0.0, 1e-12);
  }
  SimulationState state = flatState(model);
  for (double percent : {25.0, 50.0, 75.0}) {
    const StaticResult result = settle(model, percent / 100.0, state);
    EXPECT_TRUE(result.converged) << percent;
    // The nearest state of the motion: a fine scan of rho, then golden-section refinement.
    auto distance = [&](double rho) { return placedDistance(state.positions, motion(rho)); };
    double best = 0.0;
    for (double rho = 0.0; rho <= std::numbers::pi * 0.99; rho += 0.02)
      if (distance(rho) < distance(best)) best = rho;
    double low = std::max(0.0, best - 0.02), high = best + 0.02;
    for (int k = 0; k < 40; ++k) {
      const double m1 = low + (high - low) * 0.382, m2 = low + (high - low) * 0.618;
      (distance(m1) < distance(m2) ? high : low) = distance(m1) < distance(m2) ? m2 : m1;
    }
    const double nearest = distance(0.5 * (low + high));
    EXPECT_LE(nearest, 0.01 * side)
        << percent << "%: zigzag angle " << 0.5 * (low + high) * kDegrees;
    EXPECT_GT(0.5 * (low + high), 0.1) << "folded at all";
    std::fprintf(stderr,
                 "Miura %g%%: nearest motion state at zigzag %.2f degrees, %.2e of the side\n",
                 percent, 0.5 * (low + high) * kDegrees, nearest / side);
  }
}

TEST(Simulation, StaticSolverReachesItsResidualWithEnergyNeverRising) {
  const BarHingeModel model = buildModel(testing::miuraOri(4, 4, 1.0, 1.0, 0.5, 120.0 / kDegrees));
  SimulationState state = flatState(model);
  StaticOptions options;
  const StaticResult result = settle(model, 0.6, state, options);
  ASSERT_TRUE(result.converged);
  EXPECT_LE(result.residual, options.tolerance);
  EXPECT_LE(staticResidual(model, state.positions, 0.6, state.hingeAngles), options.tolerance);
  ASSERT_GT(result.history.size(), 3u);
  for (std::size_t k = 1; k < result.history.size(); ++k) {
    if (result.history[k].stage == result.history[k - 1].stage) {
      EXPECT_LE(result.history[k].energy, result.history[k - 1].energy) << "iteration " << k;
    }
  }
}

// Paper mode: the bars are as stiff as paper (E t, millions of times the creases here), and
// Newton steps from the flat sheet, straight lines in the narrow valley of the sheet's isometric
// motions, crawled: the square twist stalled near flat (mean crease error 140 of its 180 degrees
// after 400 iterations) and the curved pleat took 261 iterations. Folded with the bars softened to
// a hundred times the creases and stiffened at the goal (StaticOptions::softBarRatio), the twist
// leaves flat and the pleat's equilibrium takes a fifth of the iterations; unstretched at the end.
TEST(Simulation, PaperModeFoldsFromFlatWithTheBarsStiffenedAtTheGoal) {
  const std::filesystem::path data = std::filesystem::path(CURVEFOLD_TEST_DATA) / "crease_patterns";
  ModelOptions paper;
  paper.mode = SimulationMode::Paper;
  // In its user units as metres (readSvgCreasePattern, not readCreasePattern's 96 px to the
  // inch): a 100 m sheet, whose bars are the millions of times stiffer than its creases that this
  // test is about (at its stated 26 mm the twist barely folds in 0.1 mm paper).
  const BarHingeModel twist = buildModel(readSvgCreasePattern(data / "square_twist.svg"), paper);
  SimulationState state = flatState(twist);
  settle(twist, 1.0, state);
  double meanError = 0.0, meanTarget = 0.0;
  std::size_t creases = 0;
  const std::vector<double> error =
      creaseAngleError(twist, state.positions, 1.0, state.hingeAngles);
  for (std::size_t j = 0; j < twist.hinges.size(); ++j)
    if (twist.hingeCrease[j]) {
      meanError += std::abs(error[twist.hingeEdge[j]]);
      meanTarget += std::abs(twist.hingeTarget[j]) * kDegrees;
      ++creases;
    }
  ASSERT_GT(creases, 0u);
  meanError /= static_cast<double>(creases);
  meanTarget /= static_cast<double>(creases);
  EXPECT_LT(meanError, 0.5 * meanTarget);
  for (double strain : edgeStrain(twist, state.positions)) EXPECT_LT(std::abs(strain), 1e-5);

  const BarHingeModel pleat = buildModel(readCreasePattern(data / "curved_pleat.fold"), paper);
  state = flatState(pleat);
  const StaticResult result = settle(pleat, 1.0, state);
  EXPECT_LT(result.iterations, 130u);
  EXPECT_LT(result.residual, 1e-7);
  for (double strain : edgeStrain(pleat, state.positions)) EXPECT_LT(std::abs(strain), 1e-5);
}

// A curved pleat drawn as Origami Simulator's files draw them: creases at full opacity, +-180
// degrees, which a curved crease cannot reach (it cannot fold flat), so at the equilibrium the
// creases stay far from their targets. Gauss-Newton steps (the hinges' k grad grad^T, without
// k (theta - target) Hess(theta)) converge only linearly there: the settle stopped with the
// residual at 2e-8, twenty times its tolerance, no step lowering the energy. With the exact Hessian
// where it is positive definite (StaticOptions::exactHessian) it reaches the tolerance; the energy
// never rises within a stage.
TEST(Simulation, PaperModeCurvedPleatAt180DegreesReachesTheStaticTolerance) {
  CreasePattern pattern = readSvgCreasePatternText(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 4 4">
      <rect width="4" height="4" stroke="black" fill="none"/>
      <path d="M0,1 C1.2,0.6 2.8,0.6 4,1" stroke="red" fill="none"/>
      <path d="M0,2 C1.2,1.6 2.8,1.6 4,2" stroke="blue" fill="none"/>
      <path d="M0,3 C1.2,2.6 2.8,2.6 4,3" stroke="red" fill="none"/></svg>)",
      "pleat.svg");
  scaleToMetres(pattern);
  ModelOptions paper;
  paper.mode = SimulationMode::Paper;
  const BarHingeModel model = buildModel(pattern, paper);
  SimulationState state = flatState(model);
  StaticOptions options;
  const StaticResult result = settle(model, 1.0, state, options);
  EXPECT_TRUE(result.converged);
  EXPECT_LE(result.residual, options.tolerance);
  EXPECT_LE(staticResidual(model, state.positions, 1.0, state.hingeAngles), options.tolerance);
  for (std::size_t k = 1; k < result.history.size(); ++k)
    if (result.history[k].stage == result.history[k - 1].stage) {
      EXPECT_LE(result.history[k].energy, result.history[k - 1].energy) << "iteration " << k;
    }
  // A 100 mm sheet whose creases pull toward 180 degrees stretches a little (about 6e-4).
  for (double strain : edgeStrain(model, state.positions)) EXPECT_LT(std::abs(strain), 2e-3);
  // Folded, not left flat: every crease at least halfway to its 180 degrees.
  const std::vector<double> error =
      creaseAngleError(model, state.positions, 1.0, state.hingeAngles);
  for (std::size_t j = 0; j < model.hinges.size(); ++j)
    if (model.hingeCrease[j]) {
      EXPECT_LT(std::abs(error[model.hingeEdge[j]]), 90.0) << j;
    }
}

// One circular valley at 90 degrees (an SVG <circle>, 64 segments) on a 60 mm square of 0.1 mm
// paper: a closed curved crease, which no isometric fold takes at a constant angle, so the
// equilibrium keeps large angle errors. Triangulated from the circle's own points, its inside was
// a fan of lenses that collapsed folded (a triangle 5e-14 m high, the residual at 1e5 to 1e8:
// NOT settled in 3200 iterations); with points added inside (crease_pattern_graph.cpp) it
// settles to the tolerance, the energy never rising, no triangle collapsed or crossing.
TEST(Simulation, PaperModeCircleCreaseFromAnSvgCircleSettles) {
  CreasePattern pattern = readSvgCreasePatternText(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="60mm" height="60mm" viewBox="0 0 60 60">
      <rect width="60" height="60" stroke="black" fill="none"/>
      <circle cx="30" cy="30" r="16.2" stroke="blue" stroke-opacity="0.5" fill="none"/></svg>)",
      "circle.svg");
  const BarHingeModel model = paperModelOf(std::move(pattern));
  SimulationState state = flatState(model);
  const StaticOptions options;
  const StaticResult result = settle(model, 1.0, state, options);
  EXPECT_TRUE(result.converged) << "residual " << result.residual;
  EXPECT_FALSE(result.atRoundingFloor);
  EXPECT_LE(result.residual, options.tolerance);
  EXPECT_LE(staticResidual(model, state.positions, 1.0, state.hingeAngles), options.tolerance);
  EXPECT_EQ(energyRises(result.history), 0u);
  EXPECT_EQ(crossingTrianglePairs(model, state.positions), 0u);
  // No triangle collapsed: each keeps at least a tenth of its flat height over its longest side.
  for (const auto& t : model.triangles) {
    const auto height = [&](const std::vector<glm::dvec3>& p) {
      const glm::dvec3 a = p[t[0]], b = p[t[1]], c = p[t[2]];
      const double longest =
          std::max({glm::distance(a, b), glm::distance(b, c), glm::distance(c, a)});
      return glm::length(glm::cross(b - a, c - a)) / longest;
    };
    EXPECT_GT(height(state.positions), 0.1 * height(model.flatPositions));
  }
  // Folded, not left flat: the crease turned at least 10 degrees on average.
  const std::vector<double> error =
      creaseAngleError(model, state.positions, 1.0, state.hingeAngles);
  double meanError = 0.0;
  std::size_t creases = 0;
  for (std::size_t j = 0; j < model.hinges.size(); ++j)
    if (model.hingeCrease[j]) {
      meanError += std::abs(error[model.hingeEdge[j]]);
      ++creases;
    }
  ASSERT_GT(creases, 0u);
  EXPECT_LT(meanError / static_cast<double>(creases), 80.0);
}

// Concentric curved pleats on an annulus as FOLD text: rings + 1 circles of `segments` points
// from radius 0.12 to 1 m, the inner and outer borders, the others alternating mountain and
// valley at 60 degrees, quads between them (bench/make_judge_patterns.py's annulus, coarser).
std::string annulusFold(int rings, int segments) {
  std::ostringstream coords, edges, assignments, angles, faces;
  const auto index = [&](int k, int s) { return k * segments + (s % segments); };
  const auto comma = [](std::ostringstream& list) -> std::ostringstream& {
    if (list.tellp() > 0) list << ',';
    return list;
  };
  coords.precision(17);
  for (int k = 0; k <= rings; ++k)
    for (int s = 0; s < segments; ++s) {
      const double r = 0.12 + 0.88 * k / rings, t = 2.0 * std::numbers::pi * s / segments;
      comma(coords) << '[' << r * std::cos(t) << ',' << r * std::sin(t) << ']';
    }
  for (int k = 0; k <= rings; ++k) {
    const bool border = k == 0 || k == rings;
    for (int s = 0; s < segments; ++s) {
      comma(edges) << '[' << index(k, s) << ',' << index(k, s + 1) << ']';
      comma(assignments) << (border ? "\"B\"" : (k % 2 ? "\"M\"" : "\"V\""));
      comma(angles) << (border ? 0 : (k % 2 ? -60 : 60));
    }
  }
  for (int k = 0; k < rings; ++k)
    for (int s = 0; s < segments; ++s) {
      comma(edges) << '[' << index(k, s) << ',' << index(k + 1, s) << ']';
      comma(assignments) << "\"F\"";
      comma(angles) << 0;
      comma(faces) << '[' << index(k, s) << ',' << index(k, s + 1) << ',' << index(k + 1, s + 1)
                   << ',' << index(k + 1, s) << ']';
    }
  std::ostringstream fold;
  fold << R"({"file_spec": 1.1, "vertices_coords": [)" << coords.str()
       << R"(], "edges_vertices": [)" << edges.str() << R"(], "edges_assignment": [)"
       << assignments.str() << R"(], "edges_foldAngle": [)" << angles.str()
       << R"(], "faces_vertices": [)" << faces.str() << "]}";
  return fold.str();
}

// ... folded at 100% in paper mode (0.1 mm, self-contact) within 400 iterations: with each soft
// stage cut at 30 iterations, the last stage, with the paper's bars, starts far from its
// equilibrium and needs 504 iterations in all; made again with the soft stages run to their
// tolerance it settles in 319 (issue 39: the judge's finer annulus crept 688 iterations to a
// residual of 1.2 and ran out at 800).
TEST(Simulation, PaperModeSoftStagesCutShortAreRunToTheirToleranceWhereTheSettleRunsOut) {
  CreasePattern pattern = readFoldCreasePatternText(annulusFold(6, 24), "annulus.fold");
  const BarHingeModel model = paperModelOf(std::move(pattern));
  StaticOptions options;
  options.maxIterations = 400;
  SimulationState state = flatState(model);
  const StaticResult result = settle(model, 1.0, state, options);
  EXPECT_TRUE(result.converged) << "residual " << result.residual;
  // Made again (so the settle with its stages cut ran out): else this tests nothing.
  EXPECT_TRUE(result.patientSoftStages);
  EXPECT_FALSE(result.atRoundingFloor);
  EXPECT_LE(result.residual, options.tolerance);
  EXPECT_LE(staticResidual(model, state.positions, 1.0, state.hingeAngles), options.tolerance);
  // Never rising, as the moves measure it (the sums of a step the residual rule took near
  // equilibrium can read a rounding above).
  EXPECT_EQ(energyRises(result.history), 0u);
  EXPECT_EQ(crossingTrianglePairs(model, state.positions), 0u);
}

// The waterbomb base's creases all at +-180 degrees, driven to half and three quarters: targets
// the sheet cannot take at once (its diagonals and midlines move in a fixed ratio), so the
// equilibrium keeps large hinge errors and the energy's last decreases fall below its rounding;
// the solver still reaches its tolerance, and agrees with the dynamic solver's rest state.
TEST(Simulation, StaticSolverReachesItsToleranceOnTheWaterbombBase) {
  const BarHingeModel model = buildModel(readFoldCreasePattern(
      std::filesystem::path(CURVEFOLD_TEST_DATA) / "crease_patterns/waterbomb_base.fold"));
  for (double amount : {0.5, 0.75}) {
    SimulationState state = flatState(model);
    StaticOptions options;
    const StaticResult result = settle(model, amount, state, options);
    EXPECT_TRUE(result.converged) << amount;
    EXPECT_LE(result.residual, options.tolerance) << amount;
    SimulationState moving = flatState(model);
    stepDynamic(model, amount, moving, 20000);
    for (std::size_t j = 0; j < model.hinges.size(); ++j)
      EXPECT_NEAR(state.hingeAngles[j], moving.hingeAngles[j], 1e-3) << amount << " hinge " << j;
  }
}

// Along its folding motion (folding_motion.hpp) the waterbomb base reaches its targets at every
// fold amount, every crease within 0.5 degrees, unstretched, P% of the way along (with the
// targets scaled linearly it settled 44 degrees off at 50%: no state has them all).
TEST(Simulation, WaterbombBaseFollowsItsFoldingMotionToEveryTarget) {
  BarHingeModel model = buildModel(readFoldCreasePattern(
      std::filesystem::path(CURVEFOLD_TEST_DATA) / "crease_patterns/waterbomb_base.fold"));
  const FoldingMotion motion = foldingMotion(model);
  // Its four-fold symmetric motion ends with the diagonals folded flat (four flaps, midlines at
  // -90 degrees) at about 79%: from there to the base one pair of flaps must go first.
  EXPECT_FALSE(motion.reachedFull);
  ASSERT_GE(motion.amounts.size(), 3u);
  EXPECT_GE(motion.amounts[motion.amounts.size() - 2], 0.75);
  setFoldingMotion(model, motion);
  SimulationState state = flatState(model);
  for (double percent : {25.0, 50.0, 75.0, 100.0}) {
    const double amount = percent / 100.0;
    const StaticResult result = settle(model, amount, state);
    EXPECT_TRUE(result.converged) << percent;
    double worstError = 0.0, worstStrain = 0.0;
    for (double error : creaseAngleError(model, state.positions, amount, state.hingeAngles))
      worstError = std::max(worstError, std::abs(error));
    for (double strain : edgeStrain(model, state.positions))
      worstStrain = std::max(worstStrain, std::abs(strain));
    EXPECT_LE(worstError, 0.5) << percent << "%";
    EXPECT_LE(worstStrain, 1e-3) << percent << "%";
    EXPECT_NEAR(foldProgress(model, state.hingeAngles), amount, 0.01) << percent << "%";
    // Every crease folds its own way, the midlines too (the linear compromise left them at half
    // the diagonals' angle).
    for (std::size_t j = 0; j < model.hinges.size(); ++j)
      EXPECT_GT(state.hingeAngles[j] * model.hingeTarget[j], 0.0) << percent << "% hinge " << j;
    std::fprintf(stderr, "waterbomb %g%%: worst crease error %.3f degrees, strain %.1e, angles",
                 percent, worstError, worstStrain);
    for (double angle : state.hingeAngles) std::fprintf(stderr, " %.1f", angle * kDegrees);
    std::fprintf(stderr, "\n");
  }
}

// The waterbomb base as it is folded (six creases: testing::waterbombBase) folds flat along its
// motion: the pursuit reaches the 100% angles, and the settled states at 25 to 100% keep every
// crease within 0.5 degrees of its target, unstretched; at 100% every crease is at +-180.
TEST(Simulation, WaterbombBaseFoldsFlatAlongItsMotion) {
  for (bool quarterTurn : {false, true}) {
    BarHingeModel model = buildModel(testing::waterbombBase(quarterTurn));
    const FoldingMotion motion = foldingMotion(model);
    EXPECT_TRUE(motion.reachedFull)
        << quarterTurn << ": followed to " << motion.amounts[motion.amounts.size() - 2];
    setFoldingMotion(model, motion);
    SimulationState state = flatState(model);
    for (double percent : {25.0, 50.0, 75.0, 100.0}) {
      const double amount = percent / 100.0;
      EXPECT_TRUE(settle(model, amount, state).converged) << percent;
      double worstError = 0.0, worstStrain = 0.0;
      for (double error : creaseAngleError(model, state.positions, amount, state.hingeAngles))
        worstError = std::max(worstError, std::abs(error));
      for (double strain : edgeStrain(model, state.positions))
        worstStrain = std::max(worstStrain, std::abs(strain));
      EXPECT_LE(worstError, 0.5) << quarterTurn << " " << percent << "%";
      EXPECT_LE(worstStrain, 1e-3) << quarterTurn << " " << percent << "%";
      std::fprintf(stderr, "waterbomb (6 creases) %g%%: worst crease error %.3f degrees, angles",
                   percent, worstError);
      for (double angle : state.hingeAngles) std::fprintf(stderr, " %.1f", angle * kDegrees);
      std::fprintf(stderr, "\n");
    }
    for (std::size_t j = 0; j < model.hinges.size(); ++j)
      if (model.hingeCrease[j]) {
        EXPECT_NEAR(std::abs(state.hingeAngles[j]) * kDegrees, 180.0, 0.5) << "hinge " << j;
      }
  }
}

// The dynamic solver alone, as the live window steps it (60 steps a frame, the slider from 0 to
// 100% over 30 frames), folds the waterbomb base flat from the flat sheet, every crease within
// 0.5 degrees of +-180, unstretched, within 60 frames (bench_simulation's BM_PatternFromFlatLive
// measures 30 to 40 frames; Origami Simulator's own waterbombBase.svg the same).
TEST(Simulation, DynamicSolverAloneFoldsTheWaterbombBaseFlatFromFlat) {
  const BarHingeModel model = buildModel(testing::waterbombBase());
  SimulationState state = flatState(model);
  double worstError = 180.0;
  std::size_t frame = 1;
  for (; frame <= 60 && worstError > 0.5; ++frame) {
    const double amount = std::min(1.0, frame / 30.0);
    stepDynamic(model, amount, state, 60);
    if (amount < 1.0) continue;
    worstError = 0.0;
    for (double error : creaseAngleError(model, state.positions, 1.0, state.hingeAngles))
      worstError = std::max(worstError, std::abs(error));
  }
  EXPECT_LE(worstError, 0.5) << "after " << frame - 1 << " frames";
  double worstStrain = 0.0;
  for (double strain : edgeStrain(model, state.positions))
    worstStrain = std::max(worstStrain, std::abs(strain));
  EXPECT_LE(worstStrain, 1e-3);
  for (std::size_t j = 0; j < model.hinges.size(); ++j)
    if (model.hingeCrease[j]) {
      EXPECT_NEAR(std::abs(state.hingeAngles[j]) * kDegrees, 180.0, 0.5) << "hinge " << j;
    }
  std::fprintf(stderr, "waterbomb (6 creases), dynamic: %zu frames, worst crease error %.3f\n",
               frame - 1, worstError);
}

// The largest crease angle error (degrees) of the settled states at 25, 50 and 75%.
double worstCreaseErrorAlong(const BarHingeModel& model) {
  SimulationState state = flatState(model);
  double worst = 0.0;
  for (double amount : {0.25, 0.5, 0.75}) {
    EXPECT_TRUE(settle(model, amount, state).converged) << amount;
    for (double error : creaseAngleError(model, state.positions, amount, state.hingeAngles))
      worst = std::max(worst, std::abs(error));
  }
  return worst;
}

// Patterns whose targets do scale together keep their linear targets on the motion (a straight
// crease: P% of its angle); the Miura-ori, whose vertical creases fold non-linearly in the zigzag
// angle, reaches every target of its motion (a degree or more off with linear targets).
TEST(Simulation, FoldingMotionKeepsLinearTargetsAndMakesTheMiuraOrisReachable) {
  BarHingeModel crease = buildModel(creasedSquare(6, 3, 120.0, 0.2));
  setFoldingMotion(crease, foldingMotion(crease));
  for (std::size_t j = 0; j < crease.hinges.size(); ++j)
    EXPECT_NEAR(crease.target(j, 0.5), 0.5 * crease.hingeTarget[j], 0.5 / kDegrees) << j;
  EXPECT_LE(worstCreaseErrorAlong(crease), 0.5);

  BarHingeModel miura = buildModel(testing::miuraOri(4, 4, 1.0, 1.0, 0.5, 150.0 / kDegrees));
  const double linear = worstCreaseErrorAlong(miura);
  const FoldingMotion motion = foldingMotion(miura);
  EXPECT_TRUE(motion.reachedFull);
  setFoldingMotion(miura, motion);
  const double along = worstCreaseErrorAlong(miura);
  EXPECT_LE(along, 0.5);
  std::fprintf(stderr,
               "Miura-ori worst crease error at 25-75%%: linear %.2f, motion %.3f degrees\n",
               linear, along);
}

TEST(Simulation, SameInputAndStepsGiveTheSameStateBitForBit) {
  const BarHingeModel model = buildModel(creasedSquare(32, 16, 100.0, 0.2));  // 1089 vertices
  auto run = [&](int threads) {
    tbb::task_arena arena(threads);
    SimulationState state = flatState(model);
    arena.execute([&] { stepDynamic(model, 0.8, state, 300); });
    return state;
  };
  const SimulationState one = run(1), two = run(2), again = run(2);
  ASSERT_EQ(one.positions.size(), two.positions.size());
  EXPECT_EQ(0, std::memcmp(one.positions.data(), two.positions.data(),
                           one.positions.size() * sizeof(glm::dvec3)));
  EXPECT_EQ(0, std::memcmp(two.positions.data(), again.positions.data(),
                           two.positions.size() * sizeof(glm::dvec3)));
  EXPECT_EQ(0, std::memcmp(one.velocities.data(), two.velocities.data(),
                           one.velocities.size() * sizeof(glm::dvec3)));
  // It moved: the test compares folding states, not two copies of the flat one.
  EXPECT_GT(std::abs(one.positions[30].z - one.positions[0].z) + std::abs(one.positions[60].z),
            1e-6);
  SimulationState a = flatState(model), b = flatState(model);
  settle(model, 0.5, a);
  settle(model, 0.5, b);
  EXPECT_EQ(0, std::memcmp(a.positions.data(), b.positions.data(),
                           a.positions.size() * sizeof(glm::dvec3)));
}

// The hinge kernel (hinge_kernel.hpp: the sine from det(e, u, w) |e|, one reciprocal for the
// gradient's three divisions, atan2 reduced in one division without branches) against the
// plain formulas: normals' sine by a cross product over |e|, std::atan2, a division each; over
// random hinges at every angle (each of atan2's three reductions, both signs, near +-pi).
TEST(Simulation, HingeKernelMatchesThePlainFormulas) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  double worstAngle = 0.0, worstGradient = 0.0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double scale = std::pow(10.0, 4.0 * unit(random));  // 1e-4 .. 1e4
    const glm::dvec3 a = scale * glm::dvec3(unit(random), unit(random), unit(random));
    const glm::dvec3 b = scale * glm::dvec3(unit(random), unit(random), unit(random));
    const glm::dvec3 c = scale * glm::dvec3(unit(random), unit(random), unit(random));
    const glm::dvec3 d = scale * glm::dvec3(unit(random), unit(random), unit(random));
    const glm::dvec3 edge = b - a;
    const glm::dvec3 n1 = glm::cross(edge, c - a), n2 = glm::cross(a - b, d - b);
    const double ee = glm::dot(edge, edge), length = std::sqrt(ee);
    const double expected =
        std::atan2(-glm::dot(glm::cross(n1, n2), edge) / length, glm::dot(n1, n2));
    const glm::dvec3 gc = n1 * (length / glm::dot(n1, n1));
    const glm::dvec3 gd = n2 * (length / glm::dot(n2, n2));
    const double tc = glm::dot(c - a, edge) / ee, td = glm::dot(d - a, edge) / ee;
    const glm::dvec3 expectedGradient[4] = {-(1.0 - tc) * gc - (1.0 - td) * gd, -tc * gc - td * gd,
                                            gc, gd};
    // Previous within pi of the angle, so no wrap: the kernel's angle is the raw one.
    std::array<glm::dvec3, 4> gradient;
    const double angle = hingeAngleWithGradient(a, b, c, d, expected * 0.5, gradient);
    worstAngle = std::max(worstAngle, std::abs(angle - expected));
    EXPECT_EQ(angle, hingeAngle(a, b, c, d, expected * 0.5));
    double size = 0.0;
    for (const glm::dvec3& g : expectedGradient) size = std::max(size, glm::length(g));
    for (int k = 0; k < 4; ++k)
      worstGradient =
          std::max(worstGradient, glm::length(gradient[k] - expectedGradient[k]) / size);
  }
  EXPECT_LT(worstAngle, 1e-12);
  EXPECT_LT(worstGradient, 1e-12);
  // The wrap: an angle near pi tracked from just below -pi comes back within pi of it.
  const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0.5, 1, 0), d(0.5, 1, 1e-3);
  const double nearPi = hingeAngle(a, b, c, d, 0.0);
  EXPECT_GT(std::abs(nearPi), 3.1);
  std::array<glm::dvec3, 4> gradient;
  EXPECT_NEAR(hingeAngleWithGradient(a, b, c, d, nearPi - 2.0 * std::numbers::pi, gradient),
              nearPi - 2.0 * std::numbers::pi, 1e-12);
}

// The dynamic step writes each element's forces where each vertex reads them, in gather order
// (BarHingeModel::scatterSlots), and sums them in one run; the slot layout it replaced
// (elementForces into a slot per element end, gatherForces through gatherSlots, then the same
// semi-implicit Euler) is the reference, and the two must give the same state bit for bit, pins,
// glue and two threads included.
TEST(Simulation, DynamicStepGivesTheBitsOfTheSlotScatterAndGather) {
  ModelOptions pinnedAndGlued;
  pinnedAndGlued.pins = {0, 1};
  pinnedAndGlued.glue = {{6, 20}};
  // The Miura-ori with pins and glue, and a grid large enough (1681 vertices, 9.8k elements) that
  // the passes split into several tasks.
  const BarHingeModel models[] = {
      buildModel(testing::miuraOri(6, 4, 0.02, 0.02, 0.006, 2.0), pinnedAndGlued),
      buildModel(creasedSquare(40, 20, 90.0, 0.2)), squareTwist()};
  for (const BarHingeModel& model : models) {
    const DynamicOptions options;
    // Enough steps that each folded (the one-sided crease term lowers the stable step: 300 no
    // longer moved the grid 1e-3 of its size); the square twist's creases then press on it.
    const std::size_t kSteps = model.vertexCount() < 100 ? 3000 : 500;
    constexpr double kAmount = 0.6;
    tbb::task_arena arena(2);
    SimulationState fast = flatState(model);
    arena.execute([&] { stepDynamic(model, kAmount, fast, kSteps, options); });

    SimulationState reference = flatState(model);
    const std::vector<double> targets = hingeTargets(model, kAmount);
    std::vector<glm::dvec3> slots, forces;
    arena.execute([&] {
      for (std::size_t step = 0; step < kSteps; ++step) {
        elementForces(model, reference.positions, targets, reference.hingeAngles,
                      reference.hingeAngles, slots, reference.velocities.data(),
                      options.dampingRatio);
        gatherForces(model, slots, forces);
        for (std::size_t v = 0; v < model.vertexCount(); ++v) {
          if (model.pinned[v]) continue;
          reference.velocities[v] =
              (reference.velocities[v] + (model.timeStep / model.mass[v]) * forces[v]) *
              (1.0 - options.velocityDamping);
          reference.positions[v] += model.timeStep * reference.velocities[v];
        }
      }
    });
    // It folded: equal states at rest would say nothing.
    double travel = 0.0, size = 0.0;
    for (std::size_t v = 0; v < model.vertexCount(); ++v) {
      travel = std::max(travel, glm::distance(fast.positions[v], model.flatPositions[v]));
      size = std::max(size, glm::distance(model.flatPositions[v], model.flatPositions[0]));
    }
    EXPECT_GT(travel, 1e-3 * size);
    ASSERT_EQ(fast.positions.size(), reference.positions.size());
    EXPECT_EQ(0, std::memcmp(fast.positions.data(), reference.positions.data(),
                             fast.positions.size() * sizeof(glm::dvec3)));
    EXPECT_EQ(0, std::memcmp(fast.velocities.data(), reference.velocities.data(),
                             fast.velocities.size() * sizeof(glm::dvec3)));
    ASSERT_EQ(fast.hingeAngles.size(), reference.hingeAngles.size());
    EXPECT_EQ(0, std::memcmp(fast.hingeAngles.data(), reference.hingeAngles.data(),
                             fast.hingeAngles.size() * sizeof(double)));
  }
}

// Bundled designs: the final sheet of each named example recording (examples/recordings and
// examples/showcase/recordings), or of every one when `names` is empty.
std::vector<std::pair<std::string, Sheet>> exampleDesigns(const std::vector<std::string>& names) {
  std::vector<std::pair<std::string, Sheet>> designs;
  for (const char* folder : {"/examples/recordings", "/examples/showcase/recordings"}) {
    std::vector<std::filesystem::path> paths;
    for (const auto& entry :
         std::filesystem::directory_iterator(CURVEFOLD_SOURCE_DIR + std::string(folder)))
      if (entry.path().extension() == ".jsonl") paths.push_back(entry.path());
    std::sort(paths.begin(), paths.end());
    for (const auto& path : paths)
      if (names.empty() ||
          std::find(names.begin(), names.end(), path.stem().string()) != names.end())
        designs.emplace_back(path.stem().string(), replayRecording(readRecording(path)).sheet);
  }
  return designs;
}

Sheet withPositions(Sheet sheet, std::vector<glm::dvec3> positions) {
  sheet.positions = std::move(positions);
  return sheet;
}

// From the flat development (exactly the flat state at 0%) to 100% in design mode by the static
// solver alone, then compared with the design after the best rigid placement.
void expectDesignModeReachesTheDesign(const std::vector<std::string>& names,
                                      const StaticOptions& options = {}) {
  const auto designs = exampleDesigns(names);
  if (!names.empty()) {
    ASSERT_EQ(designs.size(), names.size());
  }
  for (const auto& [name, sheet] : designs) {
    const DesignPattern input = designPattern(sheet);
    const BarHingeModel model = buildModel(input.pattern);
    SimulationState state = flatState(model);

    // 0%: the flat development, exactly.
    settle(model, 0.0, state, options);
    for (std::size_t v = 0; v < sheet.vertexCount(); ++v)
      ASSERT_EQ(state.positions[v], glm::dvec3(sheet.development[v], 0.0))
          << name << " vertex " << v;

    const auto start = std::chrono::steady_clock::now();
    const StaticResult result = settle(model, 1.0, state, options);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_TRUE(result.converged) << name << " residual " << result.residual;
    EXPECT_EQ(result.predicted, options.predictor) << name;
    const Sheet simulated = withPositions(
        sheet, placed(bestRigidPlacement(state.positions, sheet.positions), state.positions));
    const SurfaceDistance distance = surfaceDistance(meshOf(simulated), meshOf(sheet));
    EXPECT_LE(distance.relativeHausdorff(), 0.005) << name;
    double worstStrain = 0.0;
    for (double strain : edgeStrain(model, state.positions))
      worstStrain = std::max(worstStrain, std::abs(strain));
    EXPECT_LE(worstStrain, 0.001) << name;
    std::fprintf(stderr,
                 "%-24s %6zu vertices  %3zu stages %3zu iterations %.2f s  hausdorff %.2e of "
                 "diagonal  strain %.1e\n",
                 name.c_str(), sheet.vertexCount(), result.stages, result.iterations, seconds,
                 distance.relativeHausdorff(), worstStrain);
  }
}

// Every bundled and showcase design (the cone alone under the sanitizers, which replay the
// recordings many times slower). The predictor places the triangles at the design's dihedrals.
TEST(Simulation, DesignModeFoldsEveryExampleDesignFromItsDevelopmentToTheDesign) {
  if (testing::kSanitized)
    expectDesignModeReachesTheDesign({"cone"});
  else
    expectDesignModeReachesTheDesign({});
}

// The static solver's own path, without the predictor: continuation over the hinge targets from
// the flat sheet, creases first (the smallest design, 142 iterations; every bundled and showcase
// design passes, in 87 to 293: bench_simulation's BM_DesignFromFlatBySolvers, too long for ctest).
TEST(Simulation, DesignModeByContinuationAloneFoldsASmallDesign) {
  // 46 s under the sanitizers; the predictor's path (the other design-mode tests) runs there.
  if (testing::kSanitized) GTEST_SKIP() << "the Release run checks the continuation (46 s here)";
  StaticOptions options;
  options.predictor = false;
  expectDesignModeReachesTheDesign({"crown_vessel"}, options);
}

// The catalogue's cone (resolution 12, docs/cli.md's sim-cone) in 0.1 mm paper with its slit
// glued, as the paper's authors glued theirs. From the flat sheet the glue pulls only in the
// sheet's plane, so Newton's steps never left it: the slit closed by stretching (64% strain,
// residual 4.6e4 after 400 iterations), and where the sheet was shaped first, the contact barrier
// pushed the glued seam's own vertices apart (residual 2.6e5). Started shaped as drawn, with the
// seam's neighbours excluded from contact, it rolls up unstretched.
TEST(Simulation, PaperModeGluedSlitConeSettlesUnstretched) {
  const DesignPattern input = designPattern(makeSurface("cone", {{"resolution", 12.0}}));
  ASSERT_FALSE(input.seams.empty());
  ModelOptions paper;
  paper.mode = SimulationMode::Paper;
  paper.contact.enabled = true;
  paper.glue = input.seams;
  const BarHingeModel model = buildModel(input.pattern, paper);
  SimulationState state = flatState(model);
  const StaticOptions options;
  const StaticResult result = settle(model, 1.0, state, options);
  // To the stated tolerance (relative: forceScale's hinge force), not stopped short of it.
  EXPECT_TRUE(result.converged);
  EXPECT_LE(result.residual, options.tolerance);
  EXPECT_LE(staticResidual(model, state.positions, 1.0, state.hingeAngles), options.tolerance);
  for (std::size_t k = 1; k < result.history.size(); ++k) {
    if (result.history[k].stage == result.history[k - 1].stage) {
      EXPECT_LE(result.history[k].energy, result.history[k - 1].energy) << "iteration " << k;
    }
  }
  double strain = 0.0;
  for (double e : edgeStrain(model, state.positions)) strain = std::max(strain, std::abs(e));
  EXPECT_LT(strain, 1e-3);
  for (const auto& [a, b] : input.seams) {
    EXPECT_LT(glm::distance(state.positions[a], state.positions[b]), 1e-4) << a << " " << b;
  }
  EXPECT_EQ(crossingTrianglePairs(model, state.positions), 0u);
}

// The same cone with one fold (its lower band turned up, a crease all round, not flat), glued:
// the predictor starts from the design itself, unstretched, and the settle runs with the paper's
// own bars. With soft-bar stages from there the sheet is let out of shape first (the recorded cone
// glued: 25% strain, then the whole settle made again with the paper's bars, twice the iterations).
TEST(Simulation, PaperModeGluedFoldedConeSettlesFromItsShapeWithThePapersBars) {
  FoldSession session(makeSurface("cone", {{"resolution", 12.0}}));
  session.beginDragNear({0.0, -0.06, 0.08});
  session.updateDrag({0.0, -0.03, 0.08});
  ASSERT_TRUE(session.commit());
  const DesignPattern input = designPattern(session.fixed());
  ASSERT_FALSE(input.seams.empty());
  ModelOptions paper;
  paper.mode = SimulationMode::Paper;
  paper.glue = input.seams;
  const BarHingeModel model = buildModel(input.pattern, paper);
  SimulationState state = flatState(model);
  const StaticOptions options;
  const StaticResult result = settle(model, 1.0, state, options);
  EXPECT_TRUE(result.predicted);
  EXPECT_TRUE(result.converged);
  EXPECT_LE(result.residual, options.tolerance);
  EXPECT_FALSE(result.softBarsUndone);
  // The continuation's stages only (the facets' targets from the design's bending to flat), no
  // soft-bar stage and no stiffening stage after them.
  EXPECT_LE(result.stages, 2u);
  double strain = 0.0;
  for (double e : edgeStrain(model, state.positions)) strain = std::max(strain, std::abs(e));
  EXPECT_LT(strain, 1e-3);
}

// A Huffman-style tower (bench/make_judge_patterns.py's): cols x rows cells of side `cell`,
// horizontals valley, verticals mountain, each cell's diagonal valley (alternating by row), as
// FOLD with M/V and no angles (so +-180 degrees at 100%), no faces.
std::string towerFold(int cols, int rows, double cell) {
  std::string vertices, edges, assignment;
  const auto id = [&](int i, int j) { return j * (cols + 1) + i; };
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= cols; ++i)
      vertices += (vertices.empty() ? "[" : ",[") + std::to_string(i * cell) + "," +
                  std::to_string(j * cell) + "]";
  const auto edge = [&](int a, int b, char kind) {
    edges += (edges.empty() ? "[" : ",[") + std::to_string(a) + "," + std::to_string(b) + "]";
    assignment += std::string(assignment.empty() ? "\"" : ",\"") + kind + "\"";
  };
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i < cols; ++i) edge(id(i, j), id(i + 1, j), j == 0 || j == rows ? 'B' : 'V');
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i <= cols; ++i) edge(id(i, j), id(i, j + 1), i == 0 || i == cols ? 'B' : 'M');
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i)
      if (j % 2 == 0)
        edge(id(i, j), id(i + 1, j + 1), 'V');
      else
        edge(id(i + 1, j), id(i, j + 1), 'V');
  return R"({"file_spec":1.1,"frame_unit":"m","vertices_coords":[)" + vertices +
         R"(],"edges_vertices":[)" + edges + R"(],"edges_assignment":[)" + assignment + "]}";
}

// A crease never passes through flat to the other side of its target (a real paper crease would
// not): the square twist, whose creases cannot all fold with rigid faces, folded a mountain as a
// valley (7 creases on the wrong side at 25% and 50% settled, and from 5% on in the dynamic
// path), as the symmetric crease energy allowed. With the one-sided term the sheet bends its
// facets instead: every state, settled and dynamic, keeps each crease on its side.
TEST(Simulation, SquareTwistKeepsEveryCreaseOnItsSideOfFlat) {
  const BarHingeModel model = squareTwist();
  SimulationState settled = flatState(model);
  for (const double amount : {0.25, 0.5, 0.75, 1.0}) {
    settle(model, amount, settled);
    EXPECT_EQ(creasesOffTheirSide(model, settled.hingeAngles), 0u) << "settled at " << amount;
  }
  SimulationState moving = flatState(model);
  for (int percent = 5; percent <= 100; percent += 5) {
    stepDynamic(model, percent / 100.0, moving, 2000);
    EXPECT_EQ(creasesOffTheirSide(model, moving.hingeAngles), 0u) << "dynamic at " << percent;
  }
  // The symmetric energy alone (the term off) does fold creases the wrong way here.
  const BarHingeModel symmetric = squareTwist(0.0);
  SimulationState loose = flatState(symmetric);
  settle(symmetric, 0.25, loose);
  EXPECT_GT(creasesOffTheirSide(symmetric, loose.hingeAngles), 0u);
}

// The one-sided term is one energy in every CPU kernel: a valley crease turned to the wrong side
// (-30 degrees for +90) and one turned past flat-folded (200 degrees): the energy exceeds the
// symmetric model's by 1/2 kw q^2 (q the angle past the bound), the forces are its negative
// gradient (central differences), and the energy's change from the moves matches the difference
// of the sums across the bound. (The dynamic step's bits are elementForces', tested below with
// the square twist, whose creases press on the bound.)
TEST(Simulation, WrongSideTermIsTheSameEnergyInEveryKernel) {
  const CreasePattern pattern = creasedSquare(4, 2, 90.0, 1.0);
  ModelOptions symmetricOptions;
  symmetricOptions.wrongSideScale = 0.0;
  const BarHingeModel model = buildModel(pattern),
                      symmetric = buildModel(pattern, symmetricOptions);
  std::size_t crease = model.hinges.size();
  double creaseWrongSide = 0.0;  // the crease's hinges' one-sided stiffnesses, summed
  for (std::size_t j = 0; j < model.hinges.size(); ++j)
    if (model.hingeCrease[j]) {
      crease = j;
      creaseWrongSide += std::abs(model.hingeWrongSide[j]);
    }
  ASSERT_LT(crease, model.hinges.size());
  for (const double wantedDegrees : {-30.0, 200.0}) {
    // The right half turned about the crease (x = 0.5) by the angle that gives the wanted one.
    std::vector<glm::dvec3> positions = model.flatPositions;
    std::vector<double> angles;
    for (const double sense : {1.0, -1.0}) {
      const double turn = sense * wantedDegrees / kDegrees;
      positions = model.flatPositions;
      for (glm::dvec3& p : positions)
        if (p.x > 0.5 + 1e-9) {
          const double r = p.x - 0.5;
          p = glm::dvec3(0.5 + r * std::cos(turn), p.y, r * std::sin(turn));
        }
      // Unwrapped through the turn: tracked from flat in small steps.
      angles.assign(model.hinges.size(), 0.0);
      for (int k = 1; k <= 20; ++k) {
        std::vector<glm::dvec3> partial = model.flatPositions;
        const double part = turn * k / 20.0;
        for (glm::dvec3& p : partial)
          if (p.x > 0.5 + 1e-9) {
            const double r = p.x - 0.5;
            p = glm::dvec3(0.5 + r * std::cos(part), p.y, r * std::sin(part));
          }
        angles = hingeAngles(model, partial, angles);
      }
      if (std::abs(angles[crease] * kDegrees - wantedDegrees) < 1e-6) break;
    }
    ASSERT_NEAR(angles[crease] * kDegrees, wantedDegrees, 1e-6);
    const std::vector<double> targets = hingeTargets(model, 0.5);
    const double past = (wantedDegrees < 0.0 ? wantedDegrees : wantedDegrees - 180.0) / kDegrees;
    EXPECT_NEAR(modelEnergy(model, positions, targets, angles) -
                    modelEnergy(symmetric, positions, targets, angles),
                0.5 * creaseWrongSide * past * past, 1e-9);
    std::vector<double> forceAngles;
    std::vector<glm::dvec3> slots, forces;
    elementForces(model, positions, targets, angles, forceAngles, slots);
    gatherForces(model, slots, forces);
    const double h = 1e-7;
    double worst = 0.0, size = 0.0;
    for (std::size_t v = 0; v < positions.size(); ++v)
      for (int c = 0; c < 3; ++c) {
        std::vector<glm::dvec3> plus = positions, minus = positions;
        plus[v][c] += h;
        minus[v][c] -= h;
        const double numeric = -(modelEnergy(model, plus, targets, angles) -
                                 modelEnergy(model, minus, targets, angles)) /
                               (2 * h);
        worst = std::max(worst, std::abs(forces[v][c] - numeric));
        size = std::max(size, std::abs(numeric));
      }
    EXPECT_LT(worst, 1e-5 * size) << wantedDegrees;
    // A move that brings the crease back across its bound: the change from the moves is the
    // difference of the sums (the change within a piece is tested on the tower above).
    std::vector<glm::dvec3> moved = positions;
    for (std::size_t v = 0; v < moved.size(); ++v) moved[v] += 2e-1 * forces[v] / (size + 1e-30);
    const std::vector<double> movedAngles = hingeAngles(model, moved, angles);
    EXPECT_NEAR(modelEnergyChange(model, positions, moved, targets, angles),
                modelEnergy(model, moved, targets, movedAngles) -
                    modelEnergy(model, positions, targets, angles),
                1e-9 * modelEnergy(model, positions, targets, angles));
  }
}

// modelEnergyChange is the energy's change from the vertices' moves: for a move large enough,
// the difference of the two sums; for a move of 1e-13 m, where that difference is
// lost in the sums' rounding, the first-order change -F . dx (the forces at the start; the
// second-order term is 1e-7 of it). A difference of sums fails the second (its rounding, about
// 1e-16 of the energy, is 1e-3 of the change).
TEST(Simulation, EnergyChangeFromTheMovesIsAccurateWhereSumsRoundAway) {
  const BarHingeModel model =
      buildModel(readFoldCreasePatternText(towerFold(4, 2, 0.05), "t.fold"));
  SimulationState state = flatState(model);
  stepDynamic(model, 0.5, state, 300);
  const std::vector<double> targets = hingeTargets(model, 0.5);
  std::vector<double> angles;
  std::vector<glm::dvec3> slots, forces;
  elementForces(model, state.positions, targets, state.hingeAngles, angles, slots);
  gatherForces(model, slots, forces);
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  std::vector<glm::dvec3> direction(model.vertexCount());
  for (glm::dvec3& d : direction) d = glm::dvec3(normal(random), normal(random), normal(random));
  const double energy = modelEnergy(model, state.positions, targets, angles);
  for (const double size : {1e-3, 1e-13}) {
    std::vector<glm::dvec3> moved = state.positions;
    double firstOrder = 0.0;
    for (std::size_t v = 0; v < moved.size(); ++v) {
      moved[v] += size * direction[v];
      firstOrder -= glm::dot(forces[v], moved[v] - state.positions[v]);
    }
    const double change = modelEnergyChange(model, state.positions, moved, targets, angles);
    if (size > 1e-6) {
      EXPECT_NEAR(change, modelEnergy(model, moved, targets, angles) - energy,
                  1e-9 * std::abs(energy));
    } else {
      ASSERT_GT(std::abs(firstOrder), 1e-15 * energy);  // below the sums' rounding: a real test
      EXPECT_NEAR(change, firstOrder, 1e-5 * std::abs(firstOrder)) << "energy " << energy;
    }
  }
}

// The Huffman-style tower at 50% (targets +-90 degrees, which the sheet cannot take together, so
// its equilibrium keeps large hinge errors): the static solver stalled at a residual of 5e-7
// when it compared energy sums alone (bench/make_judge_patterns.py's fold_tower.fold: NOT settled
// in 130 iterations), every trial a rounding above a start whose sum had rounded low. It settles,
// and no iteration raises the energy (measured from the moves).
// The judge's Huffman-style tower (bench/make_judge_patterns.py's fold_tower.fold) as written (its
// vertex and edge order: the stalls depend on the path), faces_vertices left out.
BarHingeModel judgesTower() {
  static const char* tower =
      R"({"file_spec":1.1,"frame_unit":"m","vertices_coords":[[0.0,0.0],[0.05,0.0],[0.1,0.0],)"
      R"([0.15000000000000002,0.0],[0.2,0.0],[0.25,0.0],[0.30000000000000004,0.0],)"
      R"([0.35000000000000003,0.0],[0.4,0.0],[0.0,0.05],[0.05,0.05],[0.1,0.05],)"
      R"([0.15000000000000002,0.05],[0.2,0.05],[0.25,0.05],[0.30000000000000004,0.05],)"
      R"([0.35000000000000003,0.05],[0.4,0.05],[0.0,0.1],[0.05,0.1],[0.1,0.1],[0.15000000000000002,)"
      R"(0.1],[0.2,0.1],[0.25,0.1],[0.30000000000000004,0.1],[0.35000000000000003,0.1],[0.4,0.1],)"
      R"([0.0,0.15000000000000002],[0.05,0.15000000000000002],[0.1,0.15000000000000002],)"
      R"([0.15000000000000002,0.15000000000000002],[0.2,0.15000000000000002],[0.25,)"
      R"(0.15000000000000002],[0.30000000000000004,0.15000000000000002],[0.35000000000000003,)"
      R"(0.15000000000000002],[0.4,0.15000000000000002]],"edges_vertices":[[0,1],[1,2],[2,3],[3,4],)"
      R"([4,5],[5,6],[6,7],[7,8],[9,10],[10,11],[11,12],[12,13],[13,14],[14,15],[15,16],[16,17],)"
      R"([18,19],[19,20],[20,21],[21,22],[22,23],[23,24],[24,25],[25,26],[27,28],[28,29],[29,30],)"
      R"([30,31],[31,32],[32,33],[33,34],[34,35],[0,9],[9,18],[18,27],[8,17],[17,26],[26,35],[1,)"
      R"(10],[2,11],[3,12],[4,13],[5,14],[6,15],[7,16],[0,10],[1,11],[2,12],[3,13],[4,14],[5,15],)"
      R"([6,16],[7,17],[10,19],[11,20],[12,21],[13,22],[14,23],[15,24],[16,25],[10,18],[11,19],[12,)"
      R"(20],[13,21],[14,22],[15,23],[16,24],[17,25],[19,28],[20,29],[21,30],[22,31],[23,32],[24,)"
      R"(33],[25,34],[18,28],[19,29],[20,30],[21,31],[22,32],[23,33],[24,34],[25,35]],)"
      R"("edges_assignment":["B","B","B","B","B","B","B","B","V","V","V","V","V","V","V","V","V",)"
      R"("V","V","V","V","V","V","V","B","B","B","B","B","B","B","B","B","B","B","B","B","B","M",)"
      R"("M","M","M","M","M","M","V","V","V","V","V","V","V","V","M","M","M","M","M","M","M","V",)"
      R"("V","V","V","V","V","V","V","M","M","M","M","M","M","M","V","V","V","V","V","V","V","V"]})";
  return buildModel(readFoldCreasePatternText(tower, "fold_tower.fold"));
}

TEST(Simulation, HuffmanTowerAtHalfSettlesWithTheEnergyNeverRising) {
  const BarHingeModel model = judgesTower();
  SimulationState state = flatState(model);
  const StaticResult result = settle(model, 0.5, state);
  EXPECT_TRUE(result.converged) << result.iterations << " iterations, residual " << result.residual;
  // No rise by more than double precision can tell (1e-12 of the energy; a real rise is far
  // larger).
  for (const StaticIteration& it : result.history)
    EXPECT_LE(it.energyChange, 1e-12 * std::abs(it.energy));
}

// At 75% (+-135 degrees, which the sheet cannot take together) the continuation's sixth stage of
// seven crosses a snap: with Gauss-Newton's steps it crept 228 iterations, the energy falling 1e-6
// an iteration, and the settle ran out of its 400 (NOT settled, residual 5.5e-3). An earlier
// stage steps with the exact Hessian once it has taken StaticOptions::exactAfterIterations.
TEST(Simulation, HuffmanTowerAtThreeQuartersSettlesWithTheEnergyNeverRising) {
  const BarHingeModel model = judgesTower();
  SimulationState state = flatState(model);
  const StaticResult result = settle(model, 0.75, state);
  EXPECT_TRUE(result.converged) << result.iterations << " iterations, residual " << result.residual;
  EXPECT_LE(result.residual, StaticOptions{}.tolerance);
  for (const StaticIteration& it : result.history)
    EXPECT_LE(it.energyChange, 1e-12 * std::abs(it.energy));
}

// A square base with its centre sunk open (a 40 cm square, its centre square and corner
// diagonals mountains, the centre's diagonals valleys, the vertical midline valley outside the
// centre square and mountain inside), folded 25%, 50%, 75% as `simulate --percent 25:100:4`
// folds it, each amount from the last. At 75% Gauss-Newton's steps (where the exact Hessian is
// indefinite) met the tolerance on a saddle, energy 4.71948, from which any nudge falls to
// 4.71748; the exact Hessian shifted until positive definite (StaticOptions::shiftIndefinite)
// steps off it along the negative curvature.
TEST(Simulation, ASettledStateIsAMinimumNotASaddle) {
  const char* sink =
      R"({"file_spec":1.1,"frame_unit":"m","vertices_coords":[[0,0],[0.4,0],[0.4,0.4],[0,0.4],)"
      R"([0.1,0.1],[0.3,0.1],[0.3,0.3],[0.1,0.3],[0.2,0],[0.2,0.1],[0.2,0.3],[0.2,0.4],)"
      R"([0.2,0.2]],"edges_vertices":[[0,8],[8,1],[1,2],[2,11],[11,3],[3,0],[4,9],[9,5],[5,6],)"
      R"([6,10],[10,7],[7,4],[0,4],[1,5],[2,6],[3,7],[7,12],[12,5],[4,12],[12,6],[8,9],[9,12],)"
      R"([12,10],[10,11]],"edges_assignment":["B","B","B","B","B","B","M","M","M","M","M","M",)"
      R"("M","M","M","M","V","V","V","V","V","M","M","V"]})";
  const BarHingeModel model = buildModel(readFoldCreasePatternText(sink, "sink.fold"));
  SimulationState state = flatState(model);
  StaticResult result;
  for (double amount : {0.25, 0.5, 0.75}) {
    result = settle(model, amount, state);
    ASSERT_TRUE(result.converged) << amount << ": residual " << result.residual;
  }
  // Nudged by up to 0.1 mm and settled again, a minimum comes back to its energy; a saddle falls.
  std::mt19937 random(41);
  std::uniform_real_distribution<double> nudge(-1e-4, 1e-4);
  SimulationState nudged = state;
  for (glm::dvec3& p : nudged.positions)
    p += glm::dvec3(nudge(random), nudge(random), nudge(random));
  const StaticResult again = settle(model, 0.75, nudged);
  ASSERT_TRUE(again.converged) << again.residual;
  EXPECT_GE(again.energy, result.energy - 1e-9 * result.energy)
      << "settled at " << result.energy << ", nudged to " << again.energy;
  for (const StaticIteration& it : result.history)
    EXPECT_LE(it.energyChange, 1e-12 * std::abs(it.energy));
}

// Two valleys 1.1 degrees apart from a boundary vertex, a sliver between them (0.02 of its edge
// high), which the model bridges (bar_hinge_model.cpp): the bridge holds both creases' angles,
// a target of 180 + 180 = 360 degrees at 100%. Its one-sided term held it at flat-folded, half a
// turn short at every amount past half (settled at 75% with energy 1.23, at 100% 4.93: a crease
// left flat), its 360 degrees made twice the stages the creases need, and as a hinge with a target
// that is not a crease it was softened with facets in stages cut short (langKnlDragon: NOT settled
// at 100%). Each amount from the last, as `simulate --percent 25:100:4 --settle` folds it, and from
// flat by the continuation alone.
TEST(Simulation, ABridgeOverTwoFlatFoldedValleysWindsAFullTurn) {
  const char* pattern =
      R"({"file_spec":1.1,"frame_unit":"m","vertices_coords":[[0,0],[0.5,0],[1,0],[1,1],)"
      R"([0.52,1],[0.5,1],[0,1]],"edges_vertices":[[0,1],[1,2],[2,3],[3,4],[4,5],[5,6],[6,0],)"
      R"([1,5],[1,4]],"edges_assignment":["B","B","B","B","B","B","B","V","V"]})";
  const BarHingeModel model = buildModel(readFoldCreasePatternText(pattern, "valleys.fold"));
  std::size_t bridges = 0;
  for (std::size_t j = 0; j < model.hinges.size(); ++j)
    if (model.bridgeKind(j) == 2) {
      ++bridges;
      EXPECT_NEAR(std::abs(model.hingeTarget[j]), 2.0 * std::numbers::pi, 1e-9);
    }
  ASSERT_EQ(bridges, 1u);
  const auto expectAtTargets = [&](const SimulationState& state, double amount,
                                   const StaticResult& result) {
    EXPECT_TRUE(result.converged) << amount << ": residual " << result.residual;
    EXPECT_LT(result.energy, 1e-12) << amount;
    EXPECT_EQ(energyRises(result.history), 0u) << amount;
    for (double error : creaseAngleError(model, state.positions, amount, state.hingeAngles))
      EXPECT_LT(std::abs(error), 0.5) << amount;
  };
  SimulationState state = flatState(model);
  for (double amount : {0.25, 0.5, 0.75, 1.0}) {
    const StaticResult result = settle(model, amount, state);
    expectAtTargets(state, amount, result);
  }
  // By the continuation alone: 180 / 20 degrees, nine stages, none of them soft.
  StaticOptions continuation;
  continuation.predictor = false;
  SimulationState fromFlat = flatState(model);
  const StaticResult result = settle(model, 1.0, fromFlat, continuation);
  expectAtTargets(fromFlat, 1.0, result);
  EXPECT_EQ(result.stages, 9u);
}

// A Yoshimura pattern (cols x rows bands of triangles of base `base` and height `height`, user
// units of a 96-per-inch SVG): horizontal valleys at 0.8 opacity (144 degrees), zigzag mountains
// at 180, colours from a <style> rule, as another tool would draw it.
std::string yoshimuraSvg(int cols, int rows, double base, double height) {
  const double width = cols * base, tall = rows * height;
  const auto number = [](double v) { return std::to_string(v); };
  std::string svg = R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 )" + number(width) +
                    " " + number(tall) +
                    R"("><style>.m{stroke:#ff0000} .v{stroke:#0000ff;stroke-opacity:0.8}</style>)" +
                    R"(<polygon fill="none" stroke="#000" points="0,0 )" + number(width) + ",0 " +
                    number(width) + "," + number(tall) + " 0," + number(tall) + R"("/>)";
  for (int j = 1; j < rows; ++j)
    svg += R"(<polyline class="v" fill="none" points="0,)" + number(j * height) + " " +
           number(width) + "," + number(j * height) + R"("/>)";
  for (int j = 0; j < rows; ++j) {
    // The zigzag between lines j and j + 1, odd bands shifted half a base.
    std::string points;
    for (int k = 0; k <= 2 * cols + 1; ++k) {
      const double x = -(j % 2) * base / 2 + k * base / 2;
      if (x < 0.0 || x > width) continue;
      points += number(x) + "," + number((j + k % 2) * height) + " ";
    }
    svg += R"(<polyline class="m" fill="none" points=")" + points + R"("/>)";
  }
  return svg + "</svg>";
}

// The static solver's iteration budget (StaticOptions::maxIterations, raised from 400 to 800
// for langHoneycomb.svg). A Yoshimura pattern whose valleys want 144 degrees and mountains 180
// (no rigid folding takes both: its facets stretch about 0.1%) settles from flat at 100% in
// over 400 iterations (537 when this was written; each stage converging, the last falling
// slowly): within the budget it settles to the tolerance, with 400 it stops NOT settled.
TEST(Simulation, IterationBudgetSettlesAYoshimuraPastFourHundredIterations) {
  CreasePattern pattern = readSvgCreasePatternText(yoshimuraSvg(12, 4, 30.0, 14.0), "y.svg");
  scaleToMetres(pattern);
  const BarHingeModel model = buildModel(pattern);
  SimulationState state = flatState(model);
  const StaticOptions options;
  const StaticResult result = settle(model, 1.0, state, options);
  EXPECT_TRUE(result.converged) << "residual " << result.residual;
  EXPECT_LE(result.residual, options.tolerance);
  // Fewer would no longer test the budget: find a harder pattern then.
  EXPECT_GT(result.iterations, 400u);
  EXPECT_LE(result.iterations, options.maxIterations);
  EXPECT_EQ(energyRises(result.history), 0u);

  StaticOptions oldBudget = options;
  oldBudget.maxIterations = 400;
  SimulationState cut = flatState(model);
  const StaticResult stopped = settle(model, 1.0, cut, oldBudget);
  EXPECT_FALSE(stopped.converged);
  EXPECT_EQ(stopped.iterations, 400u);
  EXPECT_GT(stopped.residual, options.tolerance);
}

// A 240 x 160 mm map fold (four panels, three valleys across, the midline valley and mountain in
// turn): in paper mode at 100% from flat with a budget it cannot settle in, the soft-bar settle
// falls back to the paper's bars and the patient retry falls back to them again, from the same
// start with the same options, so the same bits. Made once and kept: three settles of the budget,
// not four (brochurefold at 100% made 3200 iterations, 800 of them a repeat).
TEST(Simulation, PaperModeSettleWithThePapersBarsIsMadeOnceForThePatientRetry) {
  std::string svg =
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="240mm" height="160mm" )"
      R"(viewBox="0 0 240 160"><rect x="0" y="0" width="240" height="160" fill="none" )"
      R"(stroke="#000000"/>)";
  const auto line = [&](int x1, int y1, int x2, int y2, const char* colour) {
    svg += "<line x1=\"" + std::to_string(x1) + "\" y1=\"" + std::to_string(y1) + "\" x2=\"" +
           std::to_string(x2) + "\" y2=\"" + std::to_string(y2) + "\" stroke=\"" + colour + "\"/>";
  };
  for (int i = 1; i < 4; ++i) line(60 * i, 0, 60 * i, 160, "#0000FF");
  for (int i = 0; i < 4; ++i) line(60 * i, 80, 60 * (i + 1), 80, i % 2 ? "#FF0000" : "#0000FF");
  svg += "</svg>";
  CreasePattern pattern = readSvgCreasePatternText(svg, "map.svg");
  const BarHingeModel model = paperModelOf(std::move(pattern));
  StaticOptions options;
  options.maxIterations = 100;
  SimulationState state = flatState(model);
  const StaticResult result = settle(model, 1.0, state, options);
  // Through every fallback: NOT settled, its soft stages cut, the paper's bars tried.
  EXPECT_FALSE(result.converged);
  EXPECT_FALSE(result.patientSoftStages);
  EXPECT_EQ(result.iterations, 3 * options.maxIterations);
  EXPECT_EQ(energyRises(result.history), 0u);
  // With the budget it settles (the pattern is no harder than that).
  SimulationState full = flatState(model);
  const StaticResult settled = settle(model, 1.0, full);
  EXPECT_TRUE(settled.converged) << "residual " << settled.residual;
  EXPECT_EQ(crossingTrianglePairs(model, full.positions), 0u);
}

// Origami Simulator's examples (github.com/amandaghassaei/OrigamiSimulator, assets/; not in this
// repository: their licence) that the budget of 800 cut in paper mode (0.1 mm, self-contact) at
// 100% from flat: the waterbomb tessellation's soft-bar settle ran out in its last stage, falling
// from energy 38 to 0.099 (it settles in 1164), and brochurefold's settle with the paper's bars
// in its 8th stage of 9 (875). Set CURVEFOLD_ORIGAMI_SIMULATOR_ASSETS to a checkout's assets
// folder; skipped without it. About 15 s.
TEST(SimulationExternal, OrigamiSimulatorWaterbombAndBrochureSettleInPaperModeAtFull) {
  const char* root = std::getenv("CURVEFOLD_ORIGAMI_SIMULATOR_ASSETS");
  if (!root) GTEST_SKIP() << "CURVEFOLD_ORIGAMI_SIMULATOR_ASSETS is not set";
  for (const char* file : {"SimpleFolds/brochurefold.svg", "Tessellations/waterbomb.svg"}) {
    CreasePattern pattern = readSvgCreasePattern(std::filesystem::path(root) / file);
    const BarHingeModel model = paperModelOf(std::move(pattern));
    SimulationState state = flatState(model);
    const StaticResult result = settle(model, 1.0, state);
    EXPECT_TRUE(result.converged) << file << ": residual " << result.residual;
    EXPECT_LE(result.residual, StaticOptions{}.tolerance) << file;
    EXPECT_EQ(energyRises(result.history), 0u) << file;
    EXPECT_EQ(crossingTrianglePairs(model, state.positions), 0u) << file;
  }
}
}  // namespace
}  // namespace curvefold
