// The static solver of the bar-and-hinge model (bar_hinge_model.hpp): the equilibrium at a fold
// amount, for exports and tests. A damped Gauss-Newton (Levenberg-Marquardt) iteration: each
// step solves (H + mu diag(H)) dx = -g with Eigen's sparse LDL^T, where H is the model's
// Gauss-Newton Hessian (bars: their exact Hessian with the compressive part dropped; hinges
// k grad(theta) grad(theta)^T; glue exact), then a backtracking line search (Armijo) takes the
// longest step of 1, 1/2, 1/4, .. that lowers the energy, so the energy never rises between
// iterations (near equilibrium, where a decrease falls below the rounding of the energy's sum,
// a step that leaves the energy equal, never above, is taken if it lowers the residual).
// Large angle changes are reached by continuation: the hinge targets go from the state's angles
// to the goal in stages of at most maxStageDegrees, each solved loosely, the last
// to the tolerance; in design mode the stages run with the bent facets as soft as the creases
// and one more stage at the goal restores them (StaticOptions::foldingFacetScale); in paper mode
// they run with the bars softened to a hundred times the creases and stiffening stages at the goal
// restore paper's (StaticOptions::softBarRatio). The last stage steps with the energy's exact
// Hessian where it is positive definite (StaticOptions::exactHessian), shifted until it is where
// it is not (a saddle: StaticOptions::shiftIndefinite), and so does an earlier stage after
// exactAfterIterations (a stage that crosses a snap). Before all that,
// a predictor (StaticOptions::predictor) places the triangles across the hinges at their goal
// angles and starts from there if that is lower in energy than the state.
//
// Residual (the stated convergence test): the largest force on a free vertex divided by
// forceScale(model), the force a hinge exerts at one radian of error through a lever of its own
// edge's length (the largest over hinges). Converged when it is at most `tolerance`.
//
// The rounding floor: positions are doubles, so a vertex's force cannot be brought below what
// moving it and its neighbours by their last place makes (its stiffness times that place), and a
// tolerance below it is no tolerance. Where the last stage stops above the tolerance (no step
// lowers the energy, or the iterations run out), the state counts as settled at the rounding
// floor when every free vertex whose force is above the tolerance is within its floor,
// kRoundingFloorScale x the trace of its 3x3 diagonal block of the (Gauss-Newton) Hessian x the
// unit in the last place of the largest coordinate of it and the vertices its bars join
// (StaticResult::atRoundingFloor, roundingFloor). Only at that stop: a state that reaches the
// tolerance settles exactly as without the floor, bit for bit. A stall short of the floor (or in
// an earlier stage) is first tried again once from the stage's first damping, which by then can
// stand at 1e10 to 1e14 of the diagonal.
//
// Deterministic: sequential assembly and a sequential factorization; the forces are the
// element-per-slot kernels of bar_hinge_model.hpp.
//
// Self-contact (paper mode, contact.hpp): the energy, forces and residual include the barrier
// between layers, the Hessian its b'' grad(d) grad(d)^T (and b' Hess(d) where the last stage is
// exact) for the pairs near enough to push (the sparse pattern laid out again when a pair it
// lacks begins to push), each step is shortened so that no vertex can pass through a layer
// along it, and the predictor's state is taken only when it does not pass the sheet through
// itself. Layers that start in touch (a design's flat folds) are first moved apart to the sides
// their folds give (layer_order.hpp), on each predictor guess and on a start the predictor did
// not replace.
//
// Known limits: a state between two stable equilibria may settle in either (the solver takes the
// one downhill of its start, or the predictor's when that is lower); each iteration is a
// sequential sparse factorization (about 0.6 s of CPU at 10k vertices).
#pragma once

#include <cstddef>
#include <vector>

#include "engine/simulation/bar_hinge_model.hpp"

namespace curvefold {

// The floor's factor c: each coordinate of a vertex and of its neighbours at best within half a
// unit in the last place u of the equilibrium's, a bar's length is off by at most
// |dw - dv| <= sqrt(3) u, so its pull by k sqrt(3) u; summed over the vertex's bars, whose
// stiffnesses k sum to at most the trace of its diagonal block, c = sqrt(3).
inline constexpr double kRoundingFloorScale = 1.7320508075688772;

struct StaticOptions {
  double tolerance = 1e-9;        // residual the last stage must reach
  double stageTolerance = 1e-4;   // residual each earlier stage stops at
  double maxStageDegrees = 20.0;  // largest change of any hinge's target in one stage
  // Over all stages. 400 cut langHoneycomb.svg at 100% (each stage converging, the last falling
  // steadily from energy 18.5 to 3.4 through its snap) 12 iterations short from flat, 41 from 75%.
  // 800 cut two of Origami Simulator's examples in paper mode at 100% (settle26): the waterbomb
  // tessellation's soft-bar settle, its last stage falling from energy 38 to 0.099 when it ran
  // out (it settles in 1164), and brochurefold's settle with the paper's bars, in its 8th stage
  // of 9 (it settles in 875).
  std::size_t maxIterations = 1600;
  // Start from unfoldedState at the fold amount (hinge_unfolding.hpp), rigidly placed onto the
  // state, when its energy at the goal is lower than the state's: for targets the sheet can take
  // all at once (a design at 100% in design mode, a single crease) that is the equilibrium itself,
  // and no continuation is needed.
  bool predictor = true;
  // Design mode, far from the goal: the continuation's stages run with every hinge that is not a
  // crease and has a target (the design's own bending; flat facets stay stiff) this much softer,
  // then a last stage at the goal with the model's stiffnesses (0 or 1: off). Creases first, as a
  // hand folds them: the facets follow the creases' branch.
  double foldingFacetScale = 1.0 / 200.0;
  std::size_t maxSoftStageIterations = 30;  // each such stage stops there if not converged
  // Paper mode: the folding stages run with the bars at most this many times as stiff as the
  // creases (median k L^2 against the median crease hinge), then stiffening stages multiply them
  // by barStiffening until the model's own (0: off). Each such stage stops at
  // maxSoftStageIterations.
  double softBarRatio = 100.0;
  double barStiffening = 100.0;
  // Paper mode, where that settle ends NOT settled: it is made again from the start with each
  // soft-bar stage allowed this many iterations (run to stageTolerance, not cut), and kept where
  // it settles (StaticResult::patientSoftStages; iterations count both). 0: off.
  std::size_t patientSoftStageIterations = 200;
  // ... except from a predicted start no edge of which is strained above this (the sheet shaped as
  // drawn with its glued seams met, a straight crease at its goal): that start is already on the
  // paper's valley floor, and the settle runs with the paper's own bars from it.
  double isometricStrain = 1e-6;
  // The last stage: Newton's step with the energy's exact Hessian (the hinges' k (theta - target)
  // Hess(theta), by differences of their exact gradients, and the bars' compressive part) wherever
  // it is positive definite, Gauss-Newton's elsewhere. False: Gauss-Newton's always, which
  // converges only linearly where the hinges' errors stay large at the equilibrium (targets the
  // sheet cannot take together, as a curved crease's 180 degrees in paper mode).
  bool exactHessian = true;
  // Where the last stage's exact Hessian is indefinite (a saddle), step with it shifted by a
  // multiple of its largest diagonal until positive definite instead of with Gauss-Newton's, so
  // the step follows the negative curvature off the saddle.
  bool shiftIndefinite = true;
  // An earlier stage steps with the exact Hessian too once it has taken this many iterations.
  std::size_t exactAfterIterations = 30;
};

struct StaticIteration {
  std::size_t stage = 0;  // from 1; the last stage has the goal's targets
  double energy = 0.0;    // at that stage's targets, after the iteration
  double residual = 0.0;
  // The energy's change in the iteration that ended here, from the vertices' moves
  // (modelEnergyChange: accurate where the difference of two energy sums is rounding); 0 at a
  // stage's start (its targets differ from the last stage's). Above 0 only for a step the line
  // search took on the residual rule with the sums equal: a rise within their rounding.
  double energyChange = 0.0;
};

// Iterations whose energy rose by more than double precision can tell: a change (from the moves)
// above 1e-12 of the energy. Issue 39's "never rises", as `simulate --settle` reports it; a
// step the residual rule took near equilibrium may change it by a few units of 1e-20 either way.
std::size_t energyRises(const std::vector<StaticIteration>& history);

struct StaticResult {
  bool converged = false;  // the residual within the tolerance, or at the rounding floor
  // Settled at the rounding floor (above): converged, with a residual above the tolerance that no
  // representable move can lower; roundingFloor is the largest floor of a vertex above the
  // tolerance, in the residual's units (0 when the tolerance decided).
  bool atRoundingFloor = false;
  double roundingFloor = 0.0;
  std::size_t iterations = 0;
  std::size_t stages = 0;
  bool predicted = false;  // started from the predictor (StaticOptions::predictor)
  // Paper mode: the soft-bar stages ended above the start's energy (a triangle turned inside
  // out), or short of equilibrium (a residual above stageTolerance) where the paper's own bars
  // came nearer, so the settle was made again with those (iterations count both).
  bool softBarsUndone = false;
  // Paper mode: settled only when made again with the soft stages run to their tolerance
  // (StaticOptions::patientSoftStageIterations).
  bool patientSoftStages = false;
  double energy = 0.0;                   // at the goal's targets
  double residual = 0.0;                 // at the end
  std::vector<StaticIteration> history;  // one entry per iteration, and one for each stage's start
};

// The force a hinge exerts at one radian of error through a lever of its edge's length, the
// largest over hinges (the stiffest bar's k times its length when there is no hinge).
double forceScale(const BarHingeModel& model);

// The residual of a state: the largest force on a free vertex / forceScale(model).
double staticResidual(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                      double foldAmount, const std::vector<double>& previousAngles);

// The rounding floor's verdict on a state (above), with the forces already computed on it (the
// free vertices' totals, contact included). Output: the largest floor of a vertex whose force is
// above toleranceForce, in newtons; 0 when no vertex is above it; -1 when one is above both.
// Cost: one assembly of the Hessian (its layout built for the pushing contact pairs).
double roundingFloorForce(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                          const std::vector<double>& angles, const std::vector<double>& targets,
                          const std::vector<glm::dvec3>& forces, double toleranceForce);

// Moves the state to equilibrium at the fold amount (0..1). Velocities are zeroed; hinge angles
// are updated.
StaticResult settle(const BarHingeModel& model, double foldAmount, SimulationState& state,
                    const StaticOptions& options = {});

// The same toward explicit hinge targets (one per hinge, radians) instead of a fold amount's.
StaticResult settleToTargets(const BarHingeModel& model, const std::vector<double>& targets,
                             SimulationState& state, const StaticOptions& options = {});

}  // namespace curvefold
