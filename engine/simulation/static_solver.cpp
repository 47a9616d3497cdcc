#include "engine/simulation/static_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "engine/simulation/central_differences.hpp"
#include "engine/simulation/contact_advance.hpp"
#include "engine/simulation/hinge_kernel.hpp"
#include "engine/simulation/hinge_unfolding.hpp"
#include "engine/simulation/layer_order.hpp"
#include "engine/simulation/rigid_placement.hpp"

namespace curvefold {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// The shifts tried where the exact Hessian is indefinite (StaticOptions::shiftIndefinite), as
// shares of its largest diagonal entry, from the smallest up by tens.
constexpr double kMinExactShift = 1e-12;
constexpr double kMaxExactShift = 1e-2;

// Self-contact: with edge pairs (ContactOptions::edgePairs), after this many iterations in a row
// whose step contactStepBound cut, the bound is advanced along the step (contact_advance.hpp; a
// longer step that makes a triangle pair cross is cut back). Without edge pairs it let edges pass
// through edges on the longer steps (contact19: crossings rose in 22 runs); with them no crossing
// rose in contact19's 126 runs (contact20, docs/performance.md).
constexpr std::size_t kAdvanceAfterCuts = 20;

// The Hessian's lower block triangle, laid out once: for each element, the value index of the
// first row of each of its 3x3 blocks' columns, so assembly adds into the matrix directly.
struct HessianLayout {
  SparseMatrix matrix;
  std::vector<int> barBlocks;    // per bar: 3 blocks x 3 columns
  std::vector<int> hingeBlocks;  // per hinge: 10 blocks x 3 columns
  std::vector<int> glueBlocks;   // per glue pair: 3 blocks x 3 columns
  std::vector<int> diagonal;     // per dof: the value index of its diagonal entry
  // Contact pairs the layout has room for (sorted; contact.hpp) and their blocks: 10 x 3 each.
  std::vector<ContactPair> contactPairs;
  std::vector<int> contactBlocks;
};

std::array<std::uint32_t, 4> pairVertices(const BarHingeModel& model, const ContactPair& pair) {
  return contactPairVertices(model, pair);
}

// The element's lower-triangle block pairs (p, q) with vertex[p] >= vertex[q] (or p == q).
template <std::size_t N>
void forLowerBlocks(const std::array<std::uint32_t, N>& vertices, auto&& visit) {
  for (std::size_t p = 0; p < N; ++p)
    for (std::size_t q = 0; q < N; ++q)
      if (p == q || vertices[p] > vertices[q]) visit(p, q);
}

int valueIndex(const SparseMatrix& matrix, int row, int column) {
  const int* begin = matrix.innerIndexPtr() + matrix.outerIndexPtr()[column];
  const int* end = matrix.innerIndexPtr() + matrix.outerIndexPtr()[column + 1];
  return static_cast<int>(std::lower_bound(begin, end, row) - matrix.innerIndexPtr());
}

std::array<std::uint32_t, 4> hingeVertices(const Hinge& h) {
  return {h.a, h.b, h.c, h.d};
}

HessianLayout buildLayout(const BarHingeModel& model, std::vector<ContactPair> contactPairs = {}) {
  const std::size_t n = model.vertexCount();
  const int dofs = static_cast<int>(3 * n);
  // The vertex pairs (row > column) that share an element, per column, sorted and unique; the
  // matrix's lower triangle is then written column by column with no triplets to sort.
  std::vector<std::vector<std::uint32_t>> below(n);
  auto addElement = [&](const auto& vertices) {
    for (std::uint32_t p : vertices)
      for (std::uint32_t q : vertices)
        if (p > q) below[q].push_back(p);
  };
  for (const auto& bar : model.bars) addElement(bar);
  for (const Hinge& h : model.hinges) addElement(hingeVertices(h));
  for (const auto& pair : model.glue) addElement(pair);
  for (const ContactPair& pair : contactPairs) addElement(pairVertices(model, pair));
  std::size_t nonZeros = 0;
  for (auto& rows : below) {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    nonZeros += 6 + 9 * rows.size();
  }

  HessianLayout layout;
  layout.matrix.resize(dofs, dofs);
  layout.matrix.resizeNonZeros(static_cast<Eigen::Index>(nonZeros));
  int* outer = layout.matrix.outerIndexPtr();
  int* inner = layout.matrix.innerIndexPtr();
  int next = 0;
  for (std::size_t q = 0; q < n; ++q)
    for (int c = 0; c < 3; ++c) {
      outer[3 * q + c] = next;
      for (int r = c; r < 3; ++r) inner[next++] = static_cast<int>(3 * q) + r;
      for (std::uint32_t p : below[q])
        for (int r = 0; r < 3; ++r) inner[next++] = static_cast<int>(3 * p) + r;
    }
  outer[dofs] = next;
  std::fill(layout.matrix.valuePtr(), layout.matrix.valuePtr() + nonZeros, 0.0);
  // A diagonal block keeps only its lower triangle, so its column c starts at row 3v + c.
  auto record = [&](std::vector<int>& out, const auto& vertices) {
    forLowerBlocks(vertices, [&](std::size_t p, std::size_t q) {
      for (int c = 0; c < 3; ++c)
        out.push_back(
            valueIndex(layout.matrix, 3 * vertices[p] + (p == q ? c : 0), 3 * vertices[q] + c));
    });
  };
  for (const auto& bar : model.bars) record(layout.barBlocks, bar);
  for (const Hinge& h : model.hinges) record(layout.hingeBlocks, hingeVertices(h));
  for (const auto& pair : model.glue) record(layout.glueBlocks, pair);
  for (const ContactPair& pair : contactPairs)
    record(layout.contactBlocks, pairVertices(model, pair));
  layout.contactPairs = std::move(contactPairs);
  layout.diagonal.resize(dofs);
  for (int d = 0; d < dofs; ++d) layout.diagonal[d] = valueIndex(layout.matrix, d, d);
  return layout;
}

// Adds the element's Hessian block (p, q) = coefficient x K into the matrix, skipping pinned
// vertices (their rows and columns stay identity).
template <std::size_t N>
void addElementBlocks(double* values, const int* blocks,
                      const std::array<std::uint32_t, N>& vertices,
                      const std::vector<std::uint8_t>& pinned, auto&& blockOf) {
  std::size_t block = 0;
  forLowerBlocks(vertices, [&](std::size_t p, std::size_t q) {
    const int* columns = blocks + 3 * block++;
    if (pinned[vertices[p]] || pinned[vertices[q]]) return;
    const glm::dmat3 k = blockOf(p, q);
    for (int c = 0; c < 3; ++c)
      for (int r = (p == q ? c : 0); r < 3; ++r)
        values[columns[c] + r - (p == q ? c : 0)] += k[c][r];
  });
}

// The hinge angle's second derivatives (12 x 12, symmetric: [p][q] the 3x3 block of vertices p
// and q), by central differences of its exact gradient (central_differences.hpp), steps of 1e-6
// of the hinge's edge: relative error about 1e-10.
std::array<std::array<glm::dmat3, 4>, 4> hingeAngleHessian(const std::array<glm::dvec3, 4>& x) {
  std::array<std::array<glm::dmat3, 4>, 4> out{};
  const double step = 1e-6 * glm::length(x[1] - x[0]);
  if (!(step > 0.0)) return out;
  centralDifferenceHessian(
      x, step,
      [](const std::array<glm::dvec3, 4>& p, std::array<glm::dvec3, 4>& g) {
        g = hingeAngleGradient(p[0], p[1], p[2], p[3]);
        return true;
      },
      out);
  for (int p = 0; p < 4; ++p)  // symmetric, as the true Hessian is
    for (int q = p; q < 4; ++q)
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) {
          const double mean = 0.5 * (out[p][q][c][r] + out[q][p][r][c]);
          out[p][q][c][r] = out[q][p][r][c] = mean;
        }
  return out;
}

// The energy's Hessian at the hinges' angles and targets. Gauss-Newton (exactHessian false): the
// bars' without their compressive part and the hinges' k grad grad^T, positive semidefinite.
// Exact (exactHessian): the bars' whole and the hinges' plus k (theta - target) Hess(theta); where
// targets cannot all be met (a curved crease driven to 180 degrees) the errors stay large at the
// equilibrium, and Gauss-Newton without that term converges only linearly there.
//
// A crease's one-sided term (hinge_kernel.hpp) adds its stiffness to k where the crease is past
// either bound (its second derivative there), and its moment to the exact term's torque.
void assemble(const BarHingeModel& model, const std::vector<glm::dvec3>& x, HessianLayout& layout,
              const std::vector<double>& angles, const std::vector<double>& targets,
              bool exactHessian) {
  double* values = layout.matrix.valuePtr();
  std::fill(values, values + layout.matrix.nonZeros(), 0.0);
  for (std::size_t i = 0; i < model.bars.size(); ++i) {
    const auto& bar = model.bars[i];
    const glm::dvec3 delta = x[bar[1]] - x[bar[0]];
    const double length = glm::length(delta);
    if (length == 0.0) continue;
    const glm::dvec3 u = delta / length;
    const double k = model.barStiffness[i];
    // Along the bar k; across it k (1 - L / l) (Gauss-Newton: dropped when compressed, where it
    // would make the matrix indefinite).
    const double across = exactHessian ? k * (1.0 - model.barLength[i] / length)
                                       : k * std::max(0.0, 1.0 - model.barLength[i] / length);
    const glm::dmat3 block = (k - across) * glm::outerProduct(u, u) + across * glm::dmat3(1.0);
    addElementBlocks(values, layout.barBlocks.data() + 9 * i, bar, model.pinned,
                     [&](std::size_t p, std::size_t q) { return p == q ? block : -block; });
  }
  for (std::size_t j = 0; j < model.hinges.size(); ++j) {
    const Hinge& h = model.hinges[j];
    const auto g = hingeAngleGradient(x[h.a], x[h.b], x[h.c], x[h.d]);
    const double wrongSide = model.hingeWrongSide[j];
    const double k =
        model.hingeStiffness[j] +
        (hinge_kernel::wrongSideExcess(angles[j], wrongSide) != 0.0 ? std::abs(wrongSide) : 0.0);
    const double torque =
        exactHessian
            ? hinge_kernel::hingeMoment(angles[j], targets[j], model.hingeStiffness[j], wrongSide)
            : 0.0;
    std::array<std::array<glm::dmat3, 4>, 4> second{};
    if (torque != 0.0) second = hingeAngleHessian({x[h.a], x[h.b], x[h.c], x[h.d]});
    addElementBlocks(values, layout.hingeBlocks.data() + 30 * j, hingeVertices(h), model.pinned,
                     [&](std::size_t p, std::size_t q) {
                       return k * glm::outerProduct(g[p], g[q]) + torque * second[p][q];
                     });
  }
  for (std::size_t i = 0; i < model.glue.size(); ++i) {
    const glm::dmat3 block = model.glueStiffness * glm::dmat3(1.0);
    addElementBlocks(values, layout.glueBlocks.data() + 9 * i, model.glue[i], model.pinned,
                     [&](std::size_t p, std::size_t q) { return p == q ? block : -block; });
  }
  // Contact: b'' grad(d) grad(d)^T, positive semidefinite; exact (exactHessian) also
  // b' Hess(d), by central differences of the distance's exact gradient (24 gradients a pair):
  // without it Newton's steps converge only linearly where a pair pushes at the equilibrium (a
  // glued folded cone: its residual halved each iteration and stalled at 2.5e-9).
  ContactTerm term, shifted;
  std::vector<glm::dvec3> moved;
  if (exactHessian && !layout.contactPairs.empty()) moved = x;
  const double shift = 1e-5 * model.contact.thickness;
  for (std::size_t i = 0; i < layout.contactPairs.size(); ++i) {
    if (!contactTerm(model, x, layout.contactPairs[i], term)) continue;
    std::array<std::array<glm::dmat3, 4>, 4> second{};
    bool exactTerm = exactHessian && term.slope != 0.0;
    if (exactTerm) {
      std::array<glm::dvec3, 4> corners;
      for (int q = 0; q < 4; ++q) corners[q] = x[term.vertices[q]];
      exactTerm = centralDifferenceHessian(
          corners, shift,
          [&](const std::array<glm::dvec3, 4>& p, std::array<glm::dvec3, 4>& g) {
            for (int q = 0; q < 4; ++q) moved[term.vertices[q]] = p[q];
            const bool defined = contactTerm(model, moved, layout.contactPairs[i], shifted);
            for (int q = 0; q < 4; ++q) moved[term.vertices[q]] = x[term.vertices[q]];
            g = shifted.gradient;
            return defined;
          },
          second);
    }
    if (!exactTerm) second = {};
    addElementBlocks(values, layout.contactBlocks.data() + 30 * i, term.vertices, model.pinned,
                     [&](std::size_t p, std::size_t q) {
                       return term.curvature *
                                  glm::outerProduct(term.gradient[p], term.gradient[q]) +
                              term.slope * second[p][q];
                     });
  }
  for (std::size_t v = 0; v < model.vertexCount(); ++v)
    if (model.pinned[v])
      for (int c = 0; c < 3; ++c) values[layout.diagonal[3 * v + c]] = 1.0;
}

// Every free vertex's total force: the elements' (elementForces, gatherForces) and the contact's.
void totalForces(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                 const std::vector<double>& targets, const std::vector<double>& previous,
                 std::vector<double>& angles, std::vector<glm::dvec3>& slots,
                 std::vector<glm::dvec3>& forces) {
  elementForces(model, positions, targets, previous, angles, slots);
  gatherForces(model, slots, forces);
  addContactForces(model, positions, forces);
}

double maxForce(const std::vector<glm::dvec3>& forces) {
  double largest = 0.0;
  for (const glm::dvec3& f : forces) largest = std::max(largest, glm::length(f));
  return largest;
}

// The factor that brings the bars' median stiffness (k L^2, per radian-equivalent) down to
// softBarRatio times the creases' median hinge stiffness, or 1 when they are already no stiffer
// than that, outside paper mode, or with the option off.
double paperBarScale(const BarHingeModel& model, const StaticOptions& options) {
  if (model.mode != SimulationMode::Paper || !(options.softBarRatio > 0.0)) return 1.0;
  std::vector<double> bars, creases;
  for (std::size_t i = 0; i < model.bars.size(); ++i)
    bars.push_back(model.barStiffness[i] * model.barLength[i] * model.barLength[i]);
  for (std::size_t j = 0; j < model.hinges.size(); ++j)
    if (model.hingeCrease[j] && model.hingeStiffness[j] > 0.0)
      creases.push_back(model.hingeStiffness[j]);
  if (bars.empty() || creases.empty()) return 1.0;
  const auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  const double bar = median(bars), crease = median(creases);
  return std::min(1.0, options.softBarRatio * crease / bar);
}

}  // namespace

double forceScale(const BarHingeModel& model) {
  double scale = 0.0;
  for (std::size_t j = 0; j < model.hinges.size(); ++j)
    scale = std::max(scale, model.hingeStiffness[j] / model.barLength[model.hingeEdge[j]]);
  if (scale == 0.0)
    for (std::size_t i = 0; i < model.bars.size(); ++i)
      scale = std::max(scale, model.barStiffness[i] * model.barLength[i]);
  return scale > 0.0 ? scale : 1.0;
}

double staticResidual(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                      double foldAmount, const std::vector<double>& previousAngles) {
  std::vector<double> angles;
  std::vector<glm::dvec3> slots, forces;
  totalForces(model, positions, hingeTargets(model, foldAmount), previousAngles, angles, slots,
              forces);
  return maxForce(forces) / forceScale(model);
}

double roundingFloorForce(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                          const std::vector<double>& angles, const std::vector<double>& targets,
                          const std::vector<glm::dvec3>& forces, double toleranceForce) {
  const std::size_t n = model.vertexCount();
  // The unit in the last place of the largest coordinate of each vertex and its bars' others.
  std::vector<double> largest(n, 0.0), place(n, 0.0);
  for (std::size_t v = 0; v < n; ++v)
    for (int c = 0; c < 3; ++c) largest[v] = std::max(largest[v], std::abs(positions[v][c]));
  for (std::size_t v = 0; v < n; ++v) place[v] = largest[v];
  for (const auto& bar : model.bars) {
    place[bar[0]] = std::max(place[bar[0]], largest[bar[1]]);
    place[bar[1]] = std::max(place[bar[1]], largest[bar[0]]);
  }
  HessianLayout layout;
  bool assembled = false;
  double floor = 0.0;
  for (std::size_t v = 0; v < n; ++v) {
    const double force = glm::length(forces[v]);
    if (model.pinned[v] || force <= toleranceForce) continue;
    if (!assembled) {  // Gauss-Newton's: each element's stiffness, positive on the diagonal
      layout = buildLayout(model, model.contact.enabled
                                      ? findContactPairs(model, positions, model.contact.activation)
                                      : std::vector<ContactPair>{});
      assemble(model, positions, layout, angles, targets, false);
      assembled = true;
    }
    const double* values = layout.matrix.valuePtr();
    double trace = 0.0;
    for (int c = 0; c < 3; ++c) trace += values[layout.diagonal[3 * v + c]];
    const double ulp = std::nextafter(place[v], std::numeric_limits<double>::infinity()) - place[v];
    const double vertexFloor = kRoundingFloorScale * trace * ulp;
    if (!(force <= vertexFloor)) return -1.0;
    floor = std::max(floor, vertexFloor);
  }
  return floor;
}

namespace {
// The stages of settleToTargets (below), with the options as given.
StaticResult settleInStages(const BarHingeModel& model, const std::vector<double>& goal,
                            SimulationState& state, const StaticOptions& options,
                            bool* softBarsSkipped = nullptr, bool* softStageCut = nullptr);
// The settle with the paper's own bars from the start state (settleWithSoftBars' fallback) and
// the state it ended at, kept for the patient retry (settleToTargets), whose own would be the
// same bits: its options differ only in the soft stages' iterations, which it has none of.
struct StiffSettle {
  bool made = false;
  StaticResult result;
  SimulationState state;
};
// settleToTargets' settle in paper mode with the bars softened (below). softStageCut: set where a
// soft stage stopped at maxSoftStageIterations short of its tolerance. stiffSettle: the fallback
// with the paper's bars, made (and kept there) unless already made.
StaticResult settleWithSoftBars(const BarHingeModel& model, const std::vector<double>& goal,
                                SimulationState& state, const StaticOptions& options,
                                bool& softStageCut, StiffSettle& stiffSettle);
}  // namespace

StaticResult settle(const BarHingeModel& model, double foldAmount, SimulationState& state,
                    const StaticOptions& options) {
  return settleToTargets(model, hingeTargets(model, foldAmount), state, options);
}

StaticResult settleToTargets(const BarHingeModel& model, const std::vector<double>& goal,
                             SimulationState& state, const StaticOptions& options) {
  if (paperBarScale(model, options) == 1.0) return settleInStages(model, goal, state, options);
  const SimulationState before = state;
  bool softStageCut = false;
  StiffSettle stiff;
  StaticResult result = settleWithSoftBars(model, goal, state, options, softStageCut, stiff);
  // Not settled (with the paper's bars too where those were tried): a soft stage cut at
  // maxSoftStageIterations far from its equilibrium leaves the next, with bars a hundred times
  // stiffer, to crawl along the narrow valley they make (the curved-pleats annulus at 100%: its
  // last stage began at residual 29 and ran out of iterations at 1.2). Made again from the start
  // with every soft stage run to its tolerance; kept where that settles, else the first result
  // stands, bit for bit. Only here, so every state that settled before settles as it did.
  const std::size_t patientIterations = options.patientSoftStageIterations;
  if (result.converged || !softStageCut || patientIterations <= options.maxSoftStageIterations)
    return result;
  const SimulationState cut = state;
  state = before;
  StaticOptions patient = options;
  patient.maxSoftStageIterations = patientIterations;
  StaticResult retried = settleWithSoftBars(model, goal, state, patient, softStageCut, stiff);
  if (retried.converged) {
    retried.iterations += result.iterations;
    retried.patientSoftStages = true;
    return retried;
  }
  state = cut;
  result.iterations += retried.iterations;
  return result;
}

namespace {

StaticResult settleWithSoftBars(const BarHingeModel& model, const std::vector<double>& goal,
                                SimulationState& state, const StaticOptions& options,
                                bool& softStageCut, StiffSettle& stiffSettle) {
  // Soft bars can let a triangle turn inside out on the way; stiffened again it cannot turn
  // back, and the sheet ends strained far above where it began (one of Origami Simulator's
  // examples, Crossing_curves: 33%). Then the settle is made again with the paper's own bars.
  const SimulationState before = state;
  const double startEnergy = modelEnergy(model, before.positions, goal,
                                         before.hingeAngles.size() == model.hinges.size()
                                             ? before.hingeAngles
                                             : hingeAngles(model, before.positions));
  bool skipped = false;
  StaticResult soft = settleInStages(model, goal, state, options, &skipped, &softStageCut);
  if (skipped) return soft;  // settled with the paper's own bars already
  const bool softUsable = std::isfinite(soft.energy) && soft.energy <= startEnergy;
  // Left stretched and far from any equilibrium (strain above 0.1%, a residual above the stages'
  // tolerance), the soft stages tangled the sheet without raising its energy past the start's
  // (whirlpool at its stated size: strain 11%, residual 4e9; wavy_pleats 1%, 7e7): the paper's
  // own bars are tried too, and the state nearer equilibrium kept. (Unstretched and short of
  // equilibrium, the soft result stays: stiff bars from flat crawl, and their smaller residual
  // there is the flat sheet's.)
  double softStrain = 0.0;
  for (double strain : edgeStrain(model, state.positions))
    softStrain = std::max(softStrain, std::abs(strain));
  if (softUsable &&
      (soft.converged || soft.residual <= options.stageTolerance || softStrain <= 1e-3))
    return soft;
  const SimulationState softState = state;
  const bool made = stiffSettle.made;
  if (!made) {
    stiffSettle.state = before;
    StaticOptions stiff = options;
    stiff.softBarRatio = 0.0;
    stiffSettle.result = settleInStages(model, goal, stiffSettle.state, stiff);
    stiffSettle.made = true;
  }
  state = stiffSettle.state;
  StaticResult result = stiffSettle.result;
  if (made) result.iterations = 0;  // counted where it was made
  if (softUsable && !(result.residual < soft.residual)) {
    state = softState;
    soft.iterations += result.iterations;
    return soft;
  }
  result.iterations += soft.iterations;
  result.softBarsUndone = true;
  return result;
}

StaticResult settleInStages(const BarHingeModel& model, const std::vector<double>& goal,
                            SimulationState& state, const StaticOptions& options,
                            bool* softBarsSkipped, bool* softStageCut) {
  StaticResult result;
  const std::size_t n = model.vertexCount();
  state.velocities.assign(n, glm::dvec3(0.0));
  if (state.hingeAngles.size() != model.hinges.size())
    state.hingeAngles = hingeAngles(model, state.positions);
  const double scale = forceScale(model);
  double predictedStrain = 0.0;  // the predictor's start, as shaped
  if (options.predictor && !model.hinges.empty()) {
    bool anyPinned = false;
    for (std::uint8_t p : model.pinned) anyPinned = anyPinned || p;
    // Paper mode with glue: also the sheet shaped as drawn (facets at their design bending,
    // creases at the goal), where the glued seams meet. From the flat sheet the glue pulls only
    // in its plane, so Newton's steps never leave it and the slit is closed by stretching
    // (a glued cone: 14% strain, NOT settled); the paper's authors shaped the cone and glued it.
    std::vector<std::vector<double>> candidates{goal};
    if (model.mode == SimulationMode::Paper && !model.glue.empty() &&
        model.hingeShape.size() == goal.size()) {
      std::vector<double> shaped = goal;
      bool differs = false;
      for (std::size_t j = 0; j < goal.size(); ++j)
        if (!model.hingeCrease[j] && model.hingeShape[j] != 0.0) {
          shaped[j] = model.hingeShape[j];
          differs = true;
        }
      if (differs) candidates.push_back(std::move(shaped));
    }
    double energy = modelEnergy(model, state.positions, goal, state.hingeAngles);
    for (const std::vector<double>& targets : candidates) {
      SimulationState guess = unfoldedState(model, targets);
      // In the state's frame (pins already hold the guess where they hold the state).
      if (!anyPinned)
        guess.positions =
            placed(bestRigidPlacement(guess.positions, state.positions), guess.positions);
      // Its strain as shaped, before its layers are given the paper's thickness (below).
      double guessStrain = 0.0;
      for (double strain : edgeStrain(model, guess.positions))
        guessStrain = std::max(guessStrain, std::abs(strain));
      // A design folds flaps flat onto the sheet, layers in touch: each is moved to its side of
      // the layer it lies on, as the folds between them order them (layer_order.hpp). Where
      // that passes the sheet through itself (a side the path's folds chose wrongly: xr_studio's
      // 3 pairs in touch became 3 crossing pairs, and the settle from the soft bars ended with
      // 550), the pairs there take their other side, and where that crosses too the guess stays
      // as shaped (separateLayersUnlessCrossing).
      if (model.contact.enabled &&
          separateLayersUnlessCrossing(model, guess.positions, guess.hingeAngles))
        guess.hingeAngles = hingeAngles(model, guess.positions, guess.hingeAngles);
      // With contact, a guess that passes the sheet through itself is no start: the barrier
      // cannot tell which side of a layer a vertex belongs on.
      const double guessEnergy = modelEnergy(model, guess.positions, goal, guess.hingeAngles);
      if (guessEnergy < energy &&
          (!model.contact.enabled || crossingTrianglePairs(model, guess.positions) == 0)) {
        state.positions.swap(guess.positions);
        state.hingeAngles.swap(guess.hingeAngles);
        energy = guessEnergy;
        result.predicted = true;
        predictedStrain = guessStrain;
      }
    }
  }
  if (model.contact.enabled && !result.predicted &&
      separateLayers(model, state.positions, state.hingeAngles).pairs > 0)
    state.hingeAngles = hingeAngles(model, state.positions, state.hingeAngles);
  const std::vector<double> start = state.hingeAngles;
  // A bridge's target is the sum of the targets it crosses (bar_hinge_model.cpp), each of which
  // the stages already limit: counted too, a bridge over two valleys of 180 degrees (360)
  // doubled the stages (langKnlDragon: 19 from flat, NOT settled in 400 iterations).
  double largestChange = 0.0;
  for (std::size_t j = 0; j < goal.size(); ++j)
    if (model.bridgeKind(j) == 0)
      largestChange = std::max(largestChange, std::abs(goal[j] - start[j]));
  const double stageRadians = options.maxStageDegrees * std::numbers::pi / 180.0;
  const std::size_t stages =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(largestChange / stageRadians)));
  // Design mode from a state the goal is far from: the stages run first with the bent facets as
  // soft as the creases (their stiffness x options.foldingFacetScale), then one more stage at the
  // goal with the model's own. With facets 200 times stiffer, a curved crease whose targets lag
  // the facets' is held on the wrong branch (wave_chevrons: a crease at -18.6 degrees of its
  // -145.8, behind facets already at their shape); driven by its crease first, the sheet takes
  // the design's branch, and at the goal, which the sheet can take, the stiffnesses' ratio no
  // longer matters.
  bool softFacets = options.foldingFacetScale > 0.0 && options.foldingFacetScale < 1.0 &&
                    model.mode == SimulationMode::Design && largestChange > stageRadians;
  BarHingeModel softModel;
  if (softFacets) {
    softModel = model;
    softFacets = false;  // unless some facet bends (a crease pattern's flat facets stay stiff)
    // A bridge across slivers that crosses a crease holds the crease's angle: it is driven with
    // the creases, not softened with the facets (a crease pattern's bridges made every stage of
    // langKnlDragon soft, each cut at maxSoftStageIterations short of its tolerance).
    for (std::size_t j = 0; j < model.hinges.size(); ++j)
      if (!model.hingeCrease[j] && model.bridgeKind(j) != 2 && model.hingeTarget[j] != 0.0) {
        softModel.hingeStiffness[j] *= options.foldingFacetScale;
        softFacets = true;
      }
  }
  // Paper mode: bars far stiffer than the creases (paper is nearly inextensible) make the energy a
  // narrow curved valley around the sheet's isometric motions, and Newton steps along straight
  // lines in it crawl from the flat sheet (a curved pleat ended 160 degrees short after 400
  // iterations). The folding stages run with the bars softened to softBarRatio times the creases
  // (as Origami Simulator's stiffnesses are), then stiffening stages at the goal multiply them by
  // barStiffening each until the model's own: each starts near its valley's floor.
  // From a predicted start the sheet already takes unstretched (the sheet shaped as drawn, glued
  // shut; a straight crease at its goal) there is no valley to cross: soft bars only let it spring
  // out of shape (the recorded cone glued: its flaps' contact pushed the softened sheet 25% out of
  // length, the stiffening stages never pulled it back, and the whole settle was made again with
  // the paper's bars, which reached the same state in half the iterations).
  // (As shaped: a start whose layers were then moved a thickness apart is still on that floor.)
  const bool isometricStart = result.predicted && predictedStrain <= options.isometricStrain;
  if (isometricStart && softBarsSkipped) *softBarsSkipped = true;
  std::vector<double> barScales;  // one per stage
  const double softBars = isometricStart ? 1.0 : paperBarScale(model, options);
  if (softBars < 1.0 && options.barStiffening > 1.0) {
    barScales.assign(stages, softBars);
    for (double s = softBars * options.barStiffening; s < 1.0; s *= options.barStiffening)
      barScales.push_back(s);
    barScales.push_back(1.0);
  }
  BarHingeModel barModel;
  if (!barScales.empty()) barModel = model;
  const std::size_t allStages =
      barScales.empty() ? stages + (softFacets ? 1 : 0) : barScales.size();
  result.stages = allStages;

  // Laid out and analysed once per call, and only when an iteration needs it (a predicted state
  // that already meets the tolerance needs none).
  HessianLayout layout;
  bool analysed = false;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> solver;
  Eigen::VectorXd gradient(3 * n), step(3 * n);
  std::vector<glm::dvec3> forces, trial(n), trialSlots, trialForces, stepVectors(n);
  std::vector<double> targets(goal.size()), trialAngles, diagonal(3 * n);

  for (std::size_t stage = 1; stage <= allStages; ++stage) {
    const bool last = stage == allStages;
    if (!barScales.empty())
      for (std::size_t i = 0; i < model.bars.size(); ++i)
        barModel.barStiffness[i] = model.barStiffness[i] * barScales[stage - 1];
    // Glue is as stiff as the stiffest bar: softened with them, or a glued slit, pulled shut
    // from the flat sheet's gap by glue 1e4 times stiffer than the softened bars, crushes them.
    if (!barScales.empty()) barModel.glueStiffness = model.glueStiffness * barScales[stage - 1];
    const BarHingeModel& m =
        !barScales.empty() && !last ? barModel : (softFacets && !last ? softModel : model);
    const double t = std::min(1.0, static_cast<double>(stage) / static_cast<double>(stages));
    for (std::size_t j = 0; j < goal.size(); ++j)
      targets[j] = t == 1.0 ? goal[j] : start[j] + (goal[j] - start[j]) * t;
    if (last) {
      // A (nearly) flat fold reached from the other side, a few degrees short (a mountain at
      // -176 degrees whose target is a valley at 180), is within those degrees of the goal's
      // sheet but counted a turn away; counted the near way, the last stage closes it instead of
      // unfolding it back through flat. (No self-contact: the flap passes the layer it lies on.)
      for (std::size_t j = 0; j < goal.size(); ++j) {
        const double away = state.hingeAngles[j] - goal[j];
        const double near = std::remainder(away, 2.0 * std::numbers::pi);
        if (std::abs(away) > std::numbers::pi && std::abs(near) < std::numbers::pi / 6.0)
          state.hingeAngles[j] = goal[j] + near;
      }
    }
    const double tolerance =
        last ? options.tolerance : std::max(options.tolerance, options.stageTolerance);
    double energy = modelEnergy(m, state.positions, targets, state.hingeAngles);
    double damping = 1e-6;  // mu, relative to the Hessian's diagonal
    const std::size_t stageStart = result.iterations;
    double lastChange = 0.0;     // the energy's change in the last iteration (0: the stage's start)
    bool movesMeasured = false;  // the line search's second pass (below) for the rest of the stage
    double exactShift =
        0.0;  // of the largest diagonal, added where the exact Hessian is indefinite
    std::size_t boundCuts = 0;  // iterations in a row whose step the contact bound cut
    bool dampingReset = false;  // since the last accepted step (below)
    // Stopped above the tolerance at the goal: settled if no representable move can do better
    // (the rounding floor, static_solver.hpp), from the forces of the state stopped at.
    const auto judgeRoundingFloor = [&](double toleranceForce) {
      const double floor = roundingFloorForce(model, state.positions, state.hingeAngles, targets,
                                              forces, toleranceForce);
      if (floor <= 0.0) return;
      result.converged = result.atRoundingFloor = true;
      result.roundingFloor = floor / scale;
    };
    while (true) {
      totalForces(m, state.positions, targets, state.hingeAngles, state.hingeAngles,
                  state.slotForces, forces);
      const double residual = maxForce(forces) / scale;
      result.history.push_back({stage, energy, residual, lastChange});
      result.residual = residual;
      if (residual <= tolerance) break;
      // A soft stage only has to bring the sheet onto the creases' branch, not to equilibrium.
      if ((softFacets || !barScales.empty()) && !last &&
          result.iterations - stageStart >= options.maxSoftStageIterations) {
        if (softStageCut && !barScales.empty()) *softStageCut = true;
        break;
      }
      if (result.iterations >= options.maxIterations) {
        if (last) judgeRoundingFloor(tolerance * scale);
        result.energy = modelEnergy(model, state.positions, goal, state.hingeAngles);
        return result;
      }

      for (std::size_t v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c) gradient[3 * v + c] = -forces[v][c];
      // With contact the pattern has a block for each pair near enough to push, and is laid out
      // again (with twice the activation gap's pairs, so it lasts) when one it lacks pushes.
      std::vector<ContactPair> pushing;
      if (model.contact.enabled) {
        pushing = findContactPairs(model, state.positions, model.contact.activation);
        if (analysed && !std::includes(layout.contactPairs.begin(), layout.contactPairs.end(),
                                       pushing.begin(), pushing.end()))
          analysed = false;
      }
      if (!analysed) {
        layout = buildLayout(
            model, model.contact.enabled
                       ? findContactPairs(model, state.positions, 2.0 * model.contact.activation)
                       : std::vector<ContactPair>{});
        solver.analyzePattern(layout.matrix);
        analysed = true;
      }
      // The exact Hessian where it is positive definite (near a minimum: quadratic convergence),
      // else Gauss-Newton's (StaticOptions::exactHessian).
      // An earlier stage that has not converged in exactAfterIterations (a continuation step
      // that crosses a snap: the judge's Huffman tower at 75% crept 228 iterations in its sixth
      // stage of seven, the energy falling 1e-6 an iteration, and ran out) steps so too.
      bool exact = options.exactHessian &&
                   (last || result.iterations - stageStart >= options.exactAfterIterations);
      double* values = layout.matrix.valuePtr();
      double largestDiagonal = 0.0;
      const auto assembleHessian = [&] {
        assemble(m, state.positions, layout, state.hingeAngles, targets, exact);
        largestDiagonal = 0.0;
        for (std::size_t d = 0; d < 3 * n; ++d) {
          diagonal[d] = values[layout.diagonal[d]];
          largestDiagonal = std::max(largestDiagonal, diagonal[d]);
        }
      };
      assembleHessian();
      bool accepted = false;
      // Two passes: the energy's sums alone, then, only where no step lowered them, the
      // change measured from the moves too (below), from the same damping; once the sums have
      // failed so, the rest of the stage measures the moves from its first attempt.
      const double passDamping = damping;
      for (int attempt = movesMeasured ? 10 : 0; attempt < 20 && !accepted; ++attempt) {
        if (attempt == 10 && !movesMeasured) {
          movesMeasured = true;
          damping = passDamping;
        }
        // The tiny absolute term keeps rigid motions (no stiffness at all) solvable.
        const double shift = exact ? exactShift : 0.0;
        for (std::size_t d = 0; d < 3 * n; ++d)
          values[layout.diagonal[d]] =
              diagonal[d] * (1.0 + damping) + (1e-12 + shift) * largestDiagonal;
        solver.factorize(layout.matrix);
        if (exact && (solver.info() != Eigen::Success || (solver.vectorD().array() <= 0.0).any())) {
          // Indefinite here (a saddle, or a state between two equilibria): the exact Hessian
          // shifted until it is positive definite, which steps along the negative curvature
          // (Gauss-Newton's steps leave a saddle only as fast as its instability grows: the
          // open sink base at 75% crept down 2e-10 an iteration for 350 iterations); past
          // kMaxExactShift of the largest diagonal, Gauss-Newton's, positive semidefinite.
          if (options.shiftIndefinite && exactShift < kMaxExactShift) {
            exactShift = exactShift == 0.0 ? kMinExactShift : exactShift * 10.0;
          } else {
            exact = false;
            exactShift = 0.0;
            assembleHessian();
          }
          --attempt;
          continue;
        }
        if (solver.info() != Eigen::Success) {
          damping = std::max(damping * 10.0, 1e-6);
          continue;
        }
        step = solver.solve(-gradient);
        const double slope = gradient.dot(step);
        // No longer than lets a vertex pass through a layer (contact.hpp).
        double alpha = 1.0, oneShot = 1.0;
        bool advanced = false;
        if (model.contact.enabled) {
          for (std::size_t v = 0; v < n; ++v)
            stepVectors[v] = glm::dvec3(step[3 * v], step[3 * v + 1], step[3 * v + 2]);
          alpha = oneShot = contactStepBound(model, state.positions, stepVectors);
          // The one-shot bound takes a vertex's whole motion against a triangle as closing on
          // it: a flap's tip sliding over a layer at a steady gap (vertex6_s2: 2 um of closing
          // along a step of 9 mm) was cut to 0.5% for 600 iterations. Once it has cut that
          // many in a row, the bound is advanced along the step (contact_advance.hpp).
          if (model.contact.edgePairs && oneShot < 1.0 && boundCuts >= kAdvanceAfterCuts) {
            alpha = advancedContactStepBound(model, state.positions, stepVectors);
            advanced = alpha > oneShot;
          }
        }
        // The barrier's edge pairs keep edges from passing through edges only where they push:
        // a longer step that makes more triangle pairs cross is cut back to the one-shot bound.
        const std::size_t crossingsBefore =
            advanced ? crossingTrianglePairs(model, state.positions) : 0;
        const double longest = alpha;
        for (int halving = 0; halving < 30 && slope < 0.0 && !accepted; ++halving) {
          for (std::size_t v = 0; v < n; ++v)
            trial[v] = state.positions[v] +
                       alpha * glm::dvec3(step[3 * v], step[3 * v + 1], step[3 * v + 2]);
          const double trialEnergy = modelEnergy(m, trial, targets, state.hingeAngles);
          bool lower = trialEnergy < energy && trialEnergy <= energy + 1e-4 * alpha * slope;
          // Near equilibrium the decrease (about residual^2 / stiffness) falls below the
          // rounding of the energy's sum: a step that leaves the energy where it was (not
          // above) is then taken if it lowers the residual. The sum's rounding can also read a
          // true decrease as a rise (the Huffman tower at 50% stalled at residual 4.9e-7, every
          // trial a rounding above a sum that had rounded low): where no step passed so, the
          // second pass measures the change from the moves (modelEnergyChange) instead.
          const bool level =
              movesMeasured
                  ? std::abs(energy - trialEnergy) <= 1e-12 * std::abs(energy) &&
                        modelEnergyChange(m, state.positions, trial, targets, state.hingeAngles) <=
                            0.0
                  : trialEnergy <= energy && energy - trialEnergy <= 1e-12 * std::abs(energy);
          if (!lower && level) {
            totalForces(m, trial, targets, state.hingeAngles, trialAngles, trialSlots, trialForces);
            lower = maxForce(trialForces) < maxForce(forces);
          }
          if (lower && advanced && alpha > oneShot &&
              crossingTrianglePairs(model, trial) > crossingsBefore) {
            lower = false;
            alpha = 2.0 * oneShot;  // halved below to the one-shot bound
            advanced = false;
          }
          if (lower) {
            // What the step changed, measured from the moves (modelEnergyChange, accurate where
            // the sums above are rounding): StaticIteration::energyChange, `simulate --verbose`.
            lastChange = modelEnergyChange(m, state.positions, trial, targets, state.hingeAngles);
            trialAngles = hingeAngles(model, trial, state.hingeAngles);
            state.positions.swap(trial);
            state.hingeAngles.swap(trialAngles);
            energy = trialEnergy;
            accepted = true;
          } else {
            alpha *= 0.5;
          }
        }
        if (accepted) boundCuts = oneShot < 1.0 ? boundCuts + 1 : 0;
        if (accepted) {
          damping = alpha == longest ? std::max(1e-9, damping / 4.0) : damping * 2.0;
          // The next iteration tries a tenth of the shift first (none once it is that small).
          exactShift = exactShift <= kMinExactShift ? 0.0 : exactShift / 10.0;
        } else
          damping = std::max(damping * 10.0, 1e-4);
      }
      for (std::size_t d = 0; d < 3 * n; ++d) values[layout.diagonal[d]] = diagonal[d];
      ++result.iterations;
      if (accepted) dampingReset = false;
      if (!accepted) {  // no step lowers the energy: as close as double precision gets
        if (last) judgeRoundingFloor(tolerance * scale);
        // Short of that floor: the damping grows with every short step and tenfold with every
        // refused attempt, and at a stall it can stand at 1e10 to 1e14 of the diagonal, its steps
        // too short to move a coordinate (the curved-pleats annulus at 25%: residual 1.8e-9,
        // twice its floor, at damping 8e11). One iteration tries again from the stage's first.
        if (!result.atRoundingFloor && !dampingReset) {
          dampingReset = true;
          damping = 1e-6;
          lastChange = 0.0;  // no move
          continue;
        }
        result.energy = modelEnergy(model, state.positions, goal, state.hingeAngles);
        return result;
      }
    }
  }
  result.converged = true;
  result.energy = modelEnergy(model, state.positions, goal, state.hingeAngles);
  return result;
}

}  // namespace

std::size_t energyRises(const std::vector<StaticIteration>& history) {
  std::size_t rises = 0;
  for (const StaticIteration& it : history)
    if (it.energyChange > 1e-12 * std::abs(it.energy)) ++rises;
  return rises;
}

}  // namespace curvefold
