// Shared by the symmetry tests: a folded sheet that maps onto itself under a symmetry's element.
#pragma once

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/geometry/creases.hpp"
#include "engine/geometry/surface_point.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/topology.hpp"

namespace curvefold::testing {

// The folded surface maps onto itself under g: every vertex onto the surface, and every crease
// edge (its ends and middle) onto the creases, within the tolerance. Vertex for vertex where the
// triangulations agree; where two folds of a group cut the same triangles, in an order the
// symmetry does not keep, the triangles differ but the surface and its creases do not.
inline void expectMapsOntoItself(const Sheet& sheet, const Isometry& g, double tolerance) {
  auto onSurface = [&](const glm::dvec3& p) {
    for (const glm::dvec3& q : sheet.positions)
      if (glm::distance(p, q) <= tolerance) return true;
    return glm::distance(positionOf(sheet, closestSurfacePoint(sheet, p)), p) <= tolerance;
  };
  for (const glm::dvec3& p : sheet.positions) ASSERT_TRUE(onSurface(g.apply(p)));
  const std::vector<CreaseEdge> creases = creaseEdges(sheet, buildEdgeTopology(sheet));
  ASSERT_FALSE(creases.empty());
  auto onCrease = [&](const glm::dvec3& p) {
    for (const CreaseEdge& d : creases) {
      const glm::dvec3 a = sheet.positions[d.edge.a], b = sheet.positions[d.edge.b];
      const double t = glm::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
      if (glm::distance(a + t * (b - a), p) <= tolerance) return true;
    }
    return false;
  };
  for (const CreaseEdge& c : creases) {
    const glm::dvec3 a = g.apply(sheet.positions[c.edge.a]), b = g.apply(sheet.positions[c.edge.b]);
    ASSERT_TRUE(onCrease(a) && onCrease(b) && onCrease(0.5 * (a + b)));
  }
}

// Folds, on the default cylinder with 6-fold symmetry, a cap at the top rim centred 30 degrees
// from +x and 55 degrees wide (apart from its images): its image 240 degrees on is centred on the
// slit, so that image's part lies in two pieces.
inline void foldCapWhoseImageCrossesTheSlit(FoldSession& session) {
  session.setSymmetry(parseSymmetry("rotational:6", session.initial()));
  session.beginDragNear({0.038971, 0.105, 0.0225});
  session.updateDrag({0.030311, 0.103, 0.0175});
  ASSERT_TRUE(session.commit());
  ASSERT_EQ(session.foldCount(), 6u);
}

}  // namespace curvefold::testing
