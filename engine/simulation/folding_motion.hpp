// A folding motion for a crease pattern whose targets the sheet cannot take all at once along the
// straight line from flat (the waterbomb base: its diagonals and midlines fold in a fixed,
// non-linear ratio, so "every crease at P% of its angle" is no state of the sheet and the
// equilibrium there is a compromise tens of degrees off). Scaling the targets with the fold
// amount is what Origami Simulator does (Ghassaei, Demaine & Gershenfeld, 7OSME 2018: every
// crease's target is its angle times the fold percent); this follows instead the sheet's own
// motion, by pursuit in the manner of Tachi's rigid origami simulator ("Simulation of Rigid
// Origami", 4OSME 2009: the motion projected onto the configuration space's tangent): from the
// flat sheet, each step moves every driven hinge's target a few degrees from the sheet's present
// angles toward its angle at 100% and solves the equilibrium (static_solver.hpp); the stiff bars
// and facets keep the equilibrium on the sheet's motion, so its angles are targets the sheet can
// take together. The motion's states are recorded at their progress, the angles' weighted
// projection onto the 100% angles (sum k theta T / sum k T^2 over driven hinges), so a lone
// crease or any pattern whose targets do scale together gets the linear targets back.
//
// Inputs: a model (design or paper mode). Output: the amounts (0, increasing, 1) and every hinge's
// target at each; setFoldingMotion makes the model's targets follow it (BarHingeModel::target).
// Known limits: a static solve per step (tens for a pattern folded flat): meant for crease
// patterns of up to some thousands of vertices, not for live use on large designs; where the
// pursuit stalls (no equilibrium closer to the 100% angles) the motion ends there and its last
// stretch to 100% is linear (FoldingMotion::reachedFull says so).
#pragma once

#include <cstddef>
#include <vector>

#include "engine/simulation/bar_hinge_model.hpp"

namespace curvefold {

struct FoldingMotionOptions {
  double stepDegrees = 5.0;    // largest move of any hinge's target in one step
  std::size_t maxSteps = 400;  // static solves
};

struct FoldingMotion {
  std::vector<double> amounts;  // 0 first, 1 last, increasing
  std::vector<double> targets;  // amounts.size() rows of model.hinges.size()
  bool reachedFull = false;     // the pursuit reached the 100% angles (else the last row is linear)
  std::size_t steps = 0;
};

// The progress of hinge angles along the model's linear targets: sum k theta T / sum k T^2 over
// driven hinges (T their target at 100%); 0 when no driven hinge has a target.
double foldProgress(const BarHingeModel& model, const std::vector<double>& angles);

FoldingMotion foldingMotion(const BarHingeModel& model, const FoldingMotionOptions& options = {});

// The model's targets follow the motion from now on (BarHingeModel::target).
void setFoldingMotion(BarHingeModel& model, const FoldingMotion& motion);

}  // namespace curvefold
