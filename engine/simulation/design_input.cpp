#include "engine/simulation/design_input.hpp"

#include <algorithm>
#include <string>

#include <glm/geometric.hpp>

#include "engine/geometry/creases.hpp"
#include "engine/geometry/topology.hpp"

namespace curvefold {

DesignPattern designPattern(const Sheet& sheet) {
  DesignPattern result;
  CreasePattern& pattern = result.pattern;
  pattern.vertices = sheet.development;
  pattern.triangles.reserve(sheet.triangleCount());
  for (const Triangle& t : sheet.triangles) pattern.triangles.push_back({t[0], t[1], t[2]});
  result.designPositions = sheet.positions;

  const EdgeTopology topology = buildEdgeTopology(sheet);
  std::vector<std::uint32_t> slitVertices;
  for (const EdgeTopology::EdgeSides& sides : topology.edges) {
    if (sides.triangleCount > 2)
      throw InvalidSheet("edge " + std::to_string(sides.edge.a) + "-" +
                         std::to_string(sides.edge.b) + " has more than two triangles");
    const double angle = foldAngleDegrees(sheet, sides);
    CreasePatternEdge edge{sides.edge.a, sides.edge.b, CreaseAssignment::Flat, angle};
    switch (assignmentOf(sheet, sides, angle)) {
      case Assignment::Boundary:
        edge.assignment = CreaseAssignment::Boundary;
        break;
      case Assignment::Cut:
        edge.assignment = CreaseAssignment::Cut;
        slitVertices.push_back(sides.edge.a);
        slitVertices.push_back(sides.edge.b);
        break;
      case Assignment::Mountain:
        edge.assignment = CreaseAssignment::Mountain;
        break;
      case Assignment::Valley:
        edge.assignment = CreaseAssignment::Valley;
        break;
      case Assignment::Flat:
        edge.assignment = CreaseAssignment::Flat;
        break;
    }
    if (sides.isBoundary()) edge.foldAngleDegrees = 0.0;
    pattern.edges.push_back(edge);
  }

  // Slit vertices that coincide in the design: the two sides of a seam.
  std::sort(slitVertices.begin(), slitVertices.end());
  slitVertices.erase(std::unique(slitVertices.begin(), slitVertices.end()), slitVertices.end());
  const double tolerance = sheetEpsilon(sheet);
  for (std::size_t i = 0; i < slitVertices.size(); ++i)
    for (std::size_t j = i + 1; j < slitVertices.size(); ++j) {
      const std::uint32_t u = slitVertices[i], v = slitVertices[j];
      if (glm::distance(sheet.positions[u], sheet.positions[v]) <= tolerance &&
          glm::distance(sheet.development[u], sheet.development[v]) > tolerance)
        result.seams.emplace_back(u, v);
    }
  return result;
}

}  // namespace curvefold
