// The one walk over a sheet's edges by assignment that every writer of paper and machine files
// shares (crease-pattern SVG, cutter SVG, PDF): each edge that is drawn, with its assignment and
// fold angle. Bending edges and creases unfolded flat (Assignment::Flat) are not drawn.
#pragma once

#include <initializer_list>
#include <vector>

#include "engine/geometry/creases.hpp"
#include "engine/geometry/sheet.hpp"
#include "engine/geometry/topology.hpp"

namespace curvefold {

struct DrawnEdge {
  Edge edge;
  Assignment assignment = Assignment::Boundary;  // never Flat
  double foldAngle = 0.0;                        // degrees, FOLD convention
};

// The drawn edges in the topology's edge order (so every file lists them alike).
std::vector<DrawnEdge> drawnEdges(const Sheet& sheet, const EdgeTopology& topology);

// Those of the given assignments, in the same order.
std::vector<Edge> edgesOf(const std::vector<DrawnEdge>& edges,
                          std::initializer_list<Assignment> assignments);

}  // namespace curvefold
