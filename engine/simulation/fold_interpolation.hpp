// A folded state between the flat sheet and its design, made from the design alone: each
// triangle turns by the same fraction of its own rotation from flat to folded (quaternion slerp,
// signs chosen alike across neighbours so a flap folded flat turns one way), and the positions
// are those whose edges best fit the turned triangles' edges in the least-squares sense: the
// Poisson form (Xu, Zhang, Tai, Shum & Guo, "Poisson shape interpolation", SPM 2005) of
// Alexa, Cohen-Or & Levin's "As-rigid-as-possible shape interpolation" (SIGGRAPH 2000). The
// design is first placed rigidly onto the flat sheet, so only the folding turns the triangles.
// Relaxations are the local-global iterations of as-rigid-as-possible modelling (Sorkine &
// Alexa, "As-rigid-as-possible surface modeling", SGP 2007): each triangle's best rotation onto
// the positions, then the positions refitted, which takes the state toward an isometric one.
//
// Used by the live simulation while the fold-amount slider moves
// (interaction/live_simulation.hpp), by onward(): from the state as it is, each triangle's
// rotation turned on by its share of the change, partly pulled back toward the path's, and
// relaxed. For a curved design the hinge targets between 0 and 100% cannot all be met at once,
// so the breadth-first unfolding (hinge_unfolding.hpp) tears there and the dynamic solver creeps,
// while this state stays whole and nearly isometric, its hinges close to their share of the
// design's angles. At 0 it is the flat sheet and at 1 the design (up to the rigid placement and
// rounding).
//
// Cost: one sparse LDL^T factorization (Eigen) when made; each state a rotation per triangle and
// three back-substitutions per fit (a few milliseconds at 10k vertices; docs/performance.md).
// Deterministic: the per-triangle passes write only their own entries (forEachIndex), the sums
// and the solve are sequential; std::sin/cos/atan2 are libm's (as the predictor's).
//
// Known limits: the fit is to edge vectors (each weighted by 1 / its squared length), so the
// state is only nearly isometric between the ends (median strain up to 0.3% on the cones after
// the live slider's six relaxations a frame, 0.5% after two; a few percent on the worst sliver
// edges: more relaxations converge slowly, and projecting the edges onto their lengths
// position-based flipped sliver triangles, docs/performance.md); several pieces (a cut sheet) keep
// their places relative to each other by a weak pull toward the straight blend of flat and
// folded positions.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "engine/simulation/bar_hinge_model.hpp"

namespace curvefold {

class FoldInterpolation {
 public:
  // flat and folded: the same vertices' positions (the flat one in any plane); triangles
  // counter-clockwise in the flat sheet. Throws std::invalid_argument on mismatched sizes or
  // an index out of range.
  FoldInterpolation(const std::vector<glm::dvec3>& flat, const std::vector<glm::dvec3>& folded,
                    const std::vector<std::array<std::uint32_t, 3>>& triangles,
                    const BarHingeModel* model = nullptr);
  // The model's flat sheet and triangles; its hinges' targets at 100% tell which way a flap
  // folded flat (a rotation of 180 degrees, the same either way round) turns.
  FoldInterpolation(const BarHingeModel& model, const std::vector<glm::dvec3>& folded);
  ~FoldInterpolation();
  FoldInterpolation(FoldInterpolation&&) noexcept;
  FoldInterpolation& operator=(FoldInterpolation&&) noexcept;

  // The state at this fraction of the fold (0: flat, 1: folded; clamped), in the flat sheet's
  // frame, after `relaxations` local-global iterations (see above).
  std::vector<glm::dvec3> at(double amount, std::size_t relaxations = 0) const;
  // From a state at fromAmount (any positions of these vertices, in any frame) on to toAmount:
  // each triangle's best rotation now, turned on by its share of the change, then fitted and
  // relaxed as at().
  std::vector<glm::dvec3> onward(const std::vector<glm::dvec3>& positions, double fromAmount,
                                 double toAmount, std::size_t relaxations, double pull) const;

 private:
  struct Solver;
  // The global and local steps.
  std::vector<glm::dvec3> fit(std::vector<glm::dmat3>& turns, double amount,
                              std::size_t relaxations) const;
  void bestTurns(const std::vector<glm::dvec3>& positions, std::vector<glm::dmat3>& turns) const;
  std::vector<glm::dvec3> flat_, folded_;  // folded_: placed onto flat_
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  std::vector<glm::dvec4> turns_;       // per triangle, flat to folded: unit axis, half angle
  std::vector<glm::dmat3> flatFrames_;  // per triangle: triangleFrame of its flat corners
  std::vector<double> weights_;         // per triangle edge (3t + k: corner k to k + 1)
  std::unique_ptr<Solver> solver_;
};

}  // namespace curvefold
