#include "engine/simulation/fold_interpolation.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/rigid_placement.hpp"

namespace curvefold {
namespace {

// The weak pull of every vertex toward the straight blend, against about 6-12 on the diagonal:
// it only fixes each piece's place, not its shape.
constexpr double kAnchorWeight = 1e-6;

// |q . r| below this (rotations more than about 150 degrees apart): which sign of r goes with q
// is told by the hinge between them, where known (see the constructor).
constexpr double kAmbiguousTurn = 0.25;

// A right-handed frame of a triangle: its first edge's direction, the in-plane normal, the
// normal.
glm::dmat3 triangleFrame(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
  const glm::dvec3 u = glm::normalize(b - a);
  return glm::dmat3(u, glm::cross(n, u), n);
}

// q's unit axis and half its angle, the way q turns (q and -q turn opposite ways when their
// angle is not 0); the identity's axis is 0.
glm::dvec4 axisAndHalfAngle(const glm::dquat& q) {
  const glm::dvec3 axis(q.x, q.y, q.z);
  const double s = glm::length(axis);
  if (s == 0.0) return glm::dvec4(0.0);
  return glm::dvec4(axis / s, std::atan2(s, q.w));
}

// The rotation by `amount` of that angle about that axis (amount 1: q).
glm::dquat partOf(const glm::dvec4& turn, double amount) {
  const double half = amount * turn.w;
  const glm::dvec3 v = std::sin(half) * glm::dvec3(turn);
  return glm::dquat(std::cos(half), v.x, v.y, v.z);
}

}  // namespace

struct FoldInterpolation::Solver {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt;
};

FoldInterpolation::FoldInterpolation(const BarHingeModel& model,
                                     const std::vector<glm::dvec3>& folded)
    : FoldInterpolation(model.flatPositions, folded, model.triangles, &model) {}

FoldInterpolation::FoldInterpolation(const std::vector<glm::dvec3>& flat,
                                     const std::vector<glm::dvec3>& folded,
                                     const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                     const BarHingeModel* model)
    : flat_(flat), triangles_(triangles), solver_(std::make_unique<Solver>()) {
  if (flat.size() != folded.size())
    throw std::invalid_argument("fold interpolation: the flat and folded states differ in size");
  const std::size_t n = flat.size();
  for (const auto& triangle : triangles)
    for (std::uint32_t v : triangle)
      if (v >= n) throw std::invalid_argument("fold interpolation: a vertex out of range");
  folded_ = placed(bestRigidPlacement(folded, flat), folded);

  // Each triangle's rotation, its sign alike its neighbour's where it was reached from.
  std::vector<glm::dquat> rotations(triangles.size());
  flatFrames_.resize(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& [a, b, c] = triangles[t];
    const glm::dmat3 from = flatFrames_[t] = triangleFrame(flat_[a], flat_[b], flat_[c]);
    const glm::dmat3 to = triangleFrame(folded_[a], folded_[b], folded_[c]);
    rotations[t] = glm::normalize(glm::quat_cast(to * glm::transpose(from)));
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> byEdge;
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t p = triangles[t][k], q = triangles[t][(k + 1) % 3];
      byEdge[{std::min(p, q), std::max(p, q)}].push_back(t);
    }
  std::vector<std::vector<std::uint32_t>> neighbours(triangles.size());
  for (const auto& [edge, sharing] : byEdge)
    for (std::uint32_t t : sharing)
      for (std::uint32_t u : sharing)
        if (t != u) neighbours[t].push_back(u);
  // Where a model is given: its hinge between two triangles, which tells the way a flap folded
  // flat turns (its rotation's two signs are then about as near its neighbour's).
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> hingeOf;
  if (model)
    for (std::uint32_t j = 0; j < model->hinges.size(); ++j) {
      const auto& [left, right] = model->hingeTriangles[j];
      hingeOf[{std::min(left, right), std::max(left, right)}] = j;
    }
  std::vector<char> reached(triangles.size(), 0);
  for (std::uint32_t first = 0; first < triangles.size(); ++first) {
    if (reached[first]) continue;
    reached[first] = 1;
    if (rotations[first].w < 0.0) rotations[first] = -rotations[first];
    std::deque<std::uint32_t> queue{first};
    while (!queue.empty()) {
      const std::uint32_t t = queue.front();
      queue.pop_front();
      for (std::uint32_t u : neighbours[t]) {
        if (reached[u]) continue;
        reached[u] = 1;
        const double alike = glm::dot(rotations[u], rotations[t]);
        const auto hinge = hingeOf.find({std::min(t, u), std::max(t, u)});
        if (std::abs(alike) < kAmbiguousTurn && hinge != hingeOf.end()) {
          // Halfway, the hinge's angle with either sign of u, against half its target.
          const std::uint32_t j = hinge->second;
          const Hinge& h = model->hinges[j];
          const std::uint32_t left = model->hingeTriangles[j][0];  // a lambda cannot take a binding
          auto halfwayError = [&](const glm::dquat& qu) {
            const glm::dquat halfT = partOf(axisAndHalfAngle(rotations[t]), 0.5);
            const glm::dquat halfU = partOf(axisAndHalfAngle(qu), 0.5);
            const glm::dquat& l = left == t ? halfT : halfU;
            const glm::dquat& r = left == t ? halfU : halfT;
            const glm::dvec3 shift = l * flat_[h.a] - r * flat_[h.a];
            const double angle = hingeAngle(l * flat_[h.a], l * flat_[h.b], l * flat_[h.c],
                                            r * flat_[h.d] + shift, 0.5 * model->target(j, 1.0));
            return std::abs(angle - 0.5 * model->target(j, 1.0));
          };
          if (halfwayError(-rotations[u]) < halfwayError(rotations[u]))
            rotations[u] = -rotations[u];
        } else if (alike < 0.0) {
          rotations[u] = -rotations[u];
        }
        queue.push_back(u);
      }
    }
  }

  turns_.resize(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) turns_[t] = axisAndHalfAngle(rotations[t]);

  // The normal equations of the edge fit: a graph Laplacian over the triangles' edges.
  // Each edge weighted by 1 / its squared length: a relative error costs alike on every edge, as
  // a bar's stretch does, so sliver triangles' short edges are not the ones bent to fit.
  double meanSquare = 0.0;
  for (const auto& triangle : triangles)
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 e = flat_[triangle[(k + 1) % 3]] - flat_[triangle[k]];
      meanSquare += glm::dot(e, e);
    }
  meanSquare = triangles.empty() ? 1.0 : meanSquare / (3.0 * double(triangles.size()));
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(9 * triangles.size() + n);
  weights_.resize(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t p = triangles[t][k], q = triangles[t][(k + 1) % 3];
      const double length = glm::distance(flat_[p], flat_[q]);
      const double w = weights_[3 * t + k] = length > 0.0 ? meanSquare / (length * length) : 1.0;
      const int i = static_cast<int>(p), j = static_cast<int>(q);
      entries.emplace_back(i, i, w);
      entries.emplace_back(j, j, w);
      entries.emplace_back(std::max(i, j), std::min(i, j), -w);
    }
  for (std::size_t v = 0; v < n; ++v)
    entries.emplace_back(static_cast<int>(v), static_cast<int>(v), kAnchorWeight);
  Eigen::SparseMatrix<double> laplacian(static_cast<int>(n), static_cast<int>(n));
  laplacian.setFromTriplets(entries.begin(), entries.end());
  solver_->ldlt.compute(laplacian);
  if (solver_->ldlt.info() != Eigen::Success)
    throw std::invalid_argument("fold interpolation: the sheet's edge system cannot be solved");
}

FoldInterpolation::~FoldInterpolation() = default;
FoldInterpolation::FoldInterpolation(FoldInterpolation&&) noexcept = default;
FoldInterpolation& FoldInterpolation::operator=(FoldInterpolation&&) noexcept = default;

std::vector<glm::dvec3> FoldInterpolation::at(double amount, std::size_t relaxations) const {
  amount = std::clamp(amount, 0.0, 1.0);
  std::vector<glm::dmat3> turns(triangles_.size());
  forEachIndex(triangles_.size(),
               [&](std::size_t t) { turns[t] = glm::mat3_cast(partOf(turns_[t], amount)); });
  return fit(turns, amount, relaxations);
}

std::vector<glm::dvec3> FoldInterpolation::onward(const std::vector<glm::dvec3>& positions,
                                                  double fromAmount, double toAmount,
                                                  std::size_t relaxations, double pull) const {
  if (positions.size() != flat_.size())
    throw std::invalid_argument("fold interpolation: the state differs in size");
  fromAmount = std::clamp(fromAmount, 0.0, 1.0);
  toAmount = std::clamp(toAmount, 0.0, 1.0);
  pull = std::clamp(pull, 0.0, 1.0);
  std::vector<glm::dmat3> turns(triangles_.size());
  bestTurns(positions, turns);
  // The state's own rigid motion away from the path's frame: the mean of each triangle's
  // rotation against its rotation on the path (quaternions of one sign, summed in order).
  std::vector<glm::dquat> fitted(triangles_.size()), off(triangles_.size());
  forEachIndex(triangles_.size(), [&](std::size_t t) {
    fitted[t] = glm::quat_cast(turns[t]);
    off[t] = fitted[t] * glm::conjugate(partOf(turns_[t], fromAmount));
  });
  glm::dquat sum(0.0, 0.0, 0.0, 0.0);
  for (std::size_t t = 0; t < triangles_.size(); ++t)
    sum += glm::dot(off[t], sum) < 0.0 || (t == 0 && off[t].w < 0.0) ? -off[t] : off[t];
  const glm::dquat back =
      glm::length(sum) > 0.0 ? glm::conjugate(glm::normalize(sum)) : glm::dquat(1, 0, 0, 0);
  // Each triangle turns on about its own axis by its share of the change (in the flat frame),
  // and `pull` of the way back toward its rotation on the path (normalized linear blend).
  forEachIndex(triangles_.size(), [&](std::size_t t) {
    const glm::dquat on = back * fitted[t] * partOf(turns_[t], toAmount - fromAmount);
    glm::dquat path = partOf(turns_[t], toAmount);
    if (glm::dot(on, path) < 0.0) path = -path;
    turns[t] = glm::mat3_cast(glm::normalize((1.0 - pull) * on + pull * path));
  });
  return fit(turns, toAmount, relaxations);
}

void FoldInterpolation::bestTurns(const std::vector<glm::dvec3>& positions,
                                  std::vector<glm::dmat3>& turns) const {
  // Each triangle's rotation that best takes its flat edges onto its edges now (least squares,
  // each edge weighted as in the fit). Both triangles are planar, so the best rotation takes the
  // flat plane onto the triangle's plane and is a plane rotation there, in closed form (the
  // 2D Procrustes angle). Each triangle writes only its own; a degenerate one keeps its turn.
  forEachIndex(triangles_.size(), [&](std::size_t t) {
    const auto& [a, b, c] = triangles_[t];
    const glm::dvec3 normal = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
    const double area = glm::length(normal);
    const double side = glm::distance(positions[a], positions[b]);
    if (!(area > 1e-12 * side * side) || !(side > 0.0)) return;
    const glm::dmat3 to = triangleFrame(positions[a], positions[b], positions[c]);
    const glm::dmat3& from = flatFrames_[t];
    double cosine = 0.0, sine = 0.0;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = triangles_[t][k], j = triangles_[t][(k + 1) % 3];
      const glm::dvec3 p = flat_[j] - flat_[i], q = positions[j] - positions[i];
      const double px = glm::dot(p, from[0]), py = glm::dot(p, from[1]);
      const double qx = glm::dot(q, to[0]), qy = glm::dot(q, to[1]);
      const double w = weights_[3 * t + k];
      cosine += w * (px * qx + py * qy);
      sine += w * (px * qy - py * qx);
    }
    const double length = std::sqrt(cosine * cosine + sine * sine);
    if (!(length > 0.0)) return;
    cosine /= length, sine /= length;
    const glm::dmat3 turn(glm::dvec3(cosine, sine, 0.0), glm::dvec3(-sine, cosine, 0.0),
                          glm::dvec3(0.0, 0.0, 1.0));
    turns[t] = to * turn * glm::transpose(from);
  });
}

std::vector<glm::dvec3> FoldInterpolation::fit(std::vector<glm::dmat3>& turns, double amount,
                                               std::size_t relaxations) const {
  const std::size_t n = flat_.size();
  std::vector<glm::dvec3> positions(n), edges(3 * triangles_.size());
  Eigen::MatrixX3d rhs(static_cast<Eigen::Index>(n), 3);
  for (std::size_t pass = 0;; ++pass) {
    // The global step: the positions whose edges best fit the triangles' turned flat edges.
    for (std::size_t v = 0; v < n; ++v) {
      const glm::dvec3 blend = kAnchorWeight * ((1.0 - amount) * flat_[v] + amount * folded_[v]);
      rhs.row(static_cast<Eigen::Index>(v)) << blend.x, blend.y, blend.z;
    }
    forEachIndex(triangles_.size(), [&](std::size_t t) {
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t i = triangles_[t][k], j = triangles_[t][(k + 1) % 3];
        edges[3 * t + k] = weights_[3 * t + k] * (turns[t] * (flat_[j] - flat_[i]));
      }
    });
    for (std::size_t t = 0; t < triangles_.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const auto i = static_cast<Eigen::Index>(triangles_[t][k]);
        const auto j = static_cast<Eigen::Index>(triangles_[t][(k + 1) % 3]);
        const glm::dvec3& edge = edges[3 * t + k];
        for (int axis = 0; axis < 3; ++axis) {
          rhs(j, axis) += edge[axis];
          rhs(i, axis) -= edge[axis];
        }
      }
    const Eigen::MatrixX3d x = solver_->ldlt.solve(rhs);
    for (std::size_t v = 0; v < n; ++v) {
      const auto row = static_cast<Eigen::Index>(v);
      positions[v] = glm::dvec3(x(row, 0), x(row, 1), x(row, 2));
    }
    if (pass == relaxations) return positions;
    bestTurns(positions, turns);  // the local step
  }
}

}  // namespace curvefold
