// Creases: the tracked edges made by folds (docs/design.md 3), their signed fold angles and their
// assignment, and the crease curves (chains of crease edges between junctions).
#pragma once

#include <span>
#include <vector>

#include "engine/geometry/sheet.hpp"
#include "engine/geometry/topology.hpp"

namespace curvefold {

// FOLD's edge assignments.
enum class Assignment : char {
  Boundary = 'B',
  Mountain = 'M',
  Valley = 'V',
  Flat = 'F',  // an interior edge that only bends, or a crease unfolded flat again
  Cut = 'C',   // the slit of a tube or cone
};

// Signed dihedral angle between the front normals of the two triangles of an interior edge, in
// degrees in [-180, 180]: positive for a valley (the front faces turn toward each other),
// negative for a mountain (the FOLD convention). 0 for a boundary edge.
double foldAngleDegrees(const Sheet& sheet, const EdgeTopology::EdgeSides& sides);

Assignment assignmentOf(const Sheet& sheet, const EdgeTopology::EdgeSides& sides, double foldAngle);

struct CreaseEdge {
  Edge edge;
  double foldAngle = 0.0;  // degrees, FOLD convention
  Assignment assignment = Assignment::Flat;
};

// Every crease-tagged edge with its angle, in edge order.
std::vector<CreaseEdge> creaseEdges(const Sheet& sheet, const EdgeTopology& edges);

// A maximal chain of crease edges whose inner vertices touch exactly two crease edges.
struct CreaseCurve {
  std::vector<VertexIndex> vertices;  // in order; first == last when closed
  bool closed = false;
  double planarityError = 0.0;  // metres: largest distance of a vertex from the curve's plane
};

std::vector<CreaseCurve> creaseCurves(const Sheet& sheet, const EdgeTopology& edges);

// Largest distance of the points from a plane fitted through them (an upper bound on the best
// plane's, tight for the chains folds make). A straight chain is planar, and a nearly straight
// one is measured without the rounding of a cross product of nearly parallel vectors.
double planarityError(std::span<const glm::dvec3> points);

}  // namespace curvefold
