// A coarser triangulation of the same surface, for drawing: planar regions of the sheet (a
// cylinder's strips between rulings, a flat outline, the pieces between creases) need only enough
// triangles to cover them. Greedy half-edge collapses [Hoppe et al., "Mesh Optimization",
// SIGGRAPH 1993] restricted to those that leave the surface where it was: each moved triangle stays
// in its plane and keeps its orientation, and the link condition [Dey et al., "Topology Preserving
// Edge Contraction", 1999] keeps the sheet manifold. The result is itself a valid sheet (validate()
// holds: its vertices are input vertices and each planar region is congruent to its development).
#pragma once

#include <vector>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

struct PlanarSimplificationOptions {
  // How far, relative to the sheet's size, a vertex may lie off a triangle's plane and still count
  // as in it; the isometry tolerance, far below a pixel.
  double relativePlaneTolerance = kRelativePlaneTolerance;
  // New triangles lower than this (relative to the sheet's size, in the development) are refused:
  // a sliver would make the next fold's cuts fragile.
  double relativeMinHeight = kRelativeSimplifiedMinHeight;
};

struct PlanarSimplification {
  Sheet sheet;
  std::vector<VertexIndex> originalVertex;  // sheet vertex -> input vertex
};

// Boundary loops, slits and creases keep their shape: a vertex on them goes only along a straight
// stretch of the same kind. A vertex on a non-manifold edge stays where it is.
PlanarSimplification simplifyPlanar(const Sheet& sheet,
                                    const PlanarSimplificationOptions& options = {});

}  // namespace curvefold
