#include "engine/fabrication/pattern_edges.hpp"

#include <algorithm>

namespace curvefold {

std::vector<DrawnEdge> drawnEdges(const Sheet& sheet, const EdgeTopology& topology) {
  std::vector<DrawnEdge> drawn;
  for (const EdgeTopology::EdgeSides& sides : topology.edges) {
    const double angle = foldAngleDegrees(sheet, sides);
    const Assignment assignment = assignmentOf(sheet, sides, angle);
    if (assignment != Assignment::Flat) drawn.push_back({sides.edge, assignment, angle});
  }
  return drawn;
}

std::vector<Edge> edgesOf(const std::vector<DrawnEdge>& edges,
                          std::initializer_list<Assignment> assignments) {
  std::vector<Edge> result;
  for (const DrawnEdge& e : edges)
    if (std::find(assignments.begin(), assignments.end(), e.assignment) != assignments.end())
      result.push_back(e.edge);
  return result;
}

}  // namespace curvefold
