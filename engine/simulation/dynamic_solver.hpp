// The damped dynamic solver of the bar-and-hinge model (bar_hinge_model.hpp), for live use:
// explicit integration at a fixed step, as Origami Simulator does on the GPU (Ghassaei, Demaine &
// Gershenfeld, 7OSME 2018): each step computes every element's forces into its own slots, each
// slot stored where its vertex reads it (BarHingeModel::scatterSlots: gather order), then each
// vertex sums its run of slots and moves (semi-implicit Euler: v += dt F / m, x += dt v). The
// same bits as elementForces then gatherForces; two parallel passes a step, no allocation. Bars are
// damped along their length (damping ratio of Origami Simulator's form, 2 zeta sqrt(k m)); every
// velocity also loses a small fraction per step so bending modes settle.
//
// Deterministic: the same model, fold amount, state and step count give the same state bit for
// bit, whatever the thread count (no atomics, no reductions whose order depends on scheduling).
//
// Self-contact (paper mode, contact.hpp): each step adds the barrier's force from a list of
// pairs kept in the state (found again when a vertex has moved half its skin).
//
// Known limits: the step is set by the stiffest element (stableTimeStep), so paper mode's very
// stiff bars take many steps to settle; for equilibrium use the static solver (static_solver.hpp).
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/simulation/bar_hinge_model.hpp"

namespace curvefold {

struct DynamicOptions {
  double timeStep = 0.0;          // 0: stableTimeStep(model)
  double dampingRatio = 0.45;     // of each bar, as in Origami Simulator
  double velocityDamping = 0.01;  // fraction of every velocity lost per step
};

// A step the integrator is stable at: a Gershgorin bound on the stiffest vertex's frequency at the
// flat state (bars, hinges and glue), with a safety factor of 2. buildModel stores it in
// BarHingeModel::timeStep, which stepDynamic uses (recompute it after changing a stiffness).
double stableTimeStep(const BarHingeModel& model);

// Advances the state by `steps` fixed steps toward the fold amount (0..1).
void stepDynamic(const BarHingeModel& model, double foldAmount, SimulationState& state,
                 std::size_t steps, const DynamicOptions& options = {});

}  // namespace curvefold
