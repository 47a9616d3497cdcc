#include "tests/support/random_fold_target.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "engine/geometry/self_intersection.hpp"
#include "tests/support/fold_steps.hpp"

namespace curvefold {
RandomFoldTarget makeRandomFoldTarget(const std::string& surface,
                                      const SurfaceParameters& parameters, std::size_t folds,
                                      std::uint64_t seed) {
  RandomFoldTarget target;
  target.initial = makeSurface(surface, parameters);
  FoldSession session(target.initial);
  const double size = sheetSize(target.initial);
  std::mt19937_64 random(seed);
  constexpr int kTries = 2000;
  for (std::size_t k = 0; k < folds; ++k) {
    bool made = false;
    for (int attempt = 0; attempt < kTries && !made; ++attempt) {
      const Sheet& fixed = session.fixed();
      const VertexIndex v = static_cast<VertexIndex>(
          std::min<std::size_t>(fixed.vertexCount() - 1, unit(random) * fixed.vertexCount()));
      // A direction uniform on the sphere, a drag of 15% to 60% of the size.
      const glm::dvec3 direction = uniformDirection(random);
      const double length = size * (0.15 + 0.45 * unit(random));
      const glm::dvec3 grab = session.beginDragAtDevelopment(fixed.development[v]);
      session.updateDrag(grab + length * direction);
      const std::size_t vertices = session.fixed().vertexCount();
      const ReflectionChanges& changes = session.lastChanges();
      const double moved = static_cast<double>(changes.movedVertices.size()) / vertices;
      if (!session.hasPlane() || changes.newCreaseCount == 0 || moved < 0.1 || moved > 0.9) {
        session.cancel();
        continue;
      }
      made = commitUnlessSelfIntersecting(session);
    }
    if (!made)
      throw std::runtime_error("no random fold of " + surface + " met the rules in " +
                               std::to_string(kTries) + " tries");
  }
  target.folds.assign(session.folds().begin(), session.folds().begin() + session.foldCount());
  target.sheet = session.fixed();
  return target;
}

}  // namespace curvefold
