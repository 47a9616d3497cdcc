// Steps the test targets' random folds share (random_fold_target.cpp, fold_target_generators.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <glm/vec3.hpp>

#include "engine/fit/unit_draw.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/self_intersection.hpp"

namespace curvefold {

// A direction uniform on the sphere (two draws).
inline glm::dvec3 uniformDirection(std::mt19937_64& random) {
  const double z = 2.0 * unit(random) - 1.0, phi = 2.0 * std::numbers::pi * unit(random);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// Commits the fold being dragged and keeps it unless the sheet then passes through itself
// (undone): whether it was kept.
inline bool commitUnlessSelfIntersecting(FoldSession& session) {
  if (!session.commit()) return false;
  if (!findSelfIntersections(session.fixed()).intersections.empty()) {
    session.undo();
    return false;
  }
  return true;
}

}  // namespace curvefold
