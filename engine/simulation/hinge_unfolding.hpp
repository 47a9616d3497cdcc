// A folded state made directly from the hinge targets, as a predictor for the static solver
// (static_solver.hpp): the triangles are placed breadth-first across hinges from each piece's
// first triangle (which keeps its flat place), each turned about the shared edge so that hinge
// sits exactly at its target for the fold amount. For targets the sheet can take all at once
// (a design's dihedrals at 0 and 100%, a single crease) the result is that state; otherwise the
// loops of triangles around a vertex do not close, each vertex takes its place from the first
// triangle that reaches it, and the solver then pulls the sheet together from there.
#pragma once

#include "engine/simulation/bar_hinge_model.hpp"

namespace curvefold {

// The state (at rest) with every hinge of the breadth-first tree at its target.
SimulationState unfoldedState(const BarHingeModel& model, double foldAmount);
// The same for explicit hinge targets (one per hinge, radians).
SimulationState unfoldedState(const BarHingeModel& model, const std::vector<double>& targets);

}  // namespace curvefold
