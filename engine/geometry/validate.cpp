#include "engine/geometry/validate.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/gtx/exterior_product.hpp>

#include "engine/geometry/topology.hpp"

namespace curvefold {
namespace {

std::string describe(const glm::dvec3& p) {
  std::ostringstream out;
  out.precision(17);
  out << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return out.str();
}

// Twice the signed area of a development triangle.
double doubledArea(const Sheet& sheet, const Triangle& t) {
  const glm::dvec2& a = sheet.development[t[0]];
  return glm::cross(sheet.development[t[1]] - a, sheet.development[t[2]] - a);
}

double smallestHeightOf(const Sheet& sheet, const Triangle& t) {
  return smallestHeight(sheet.development[t[0]], sheet.development[t[1]], sheet.development[t[2]]);
}

void checkArrays(const Sheet& sheet) {
  if (sheet.positions.size() != sheet.development.size())
    throw InvalidSheet("sheet has " + std::to_string(sheet.positions.size()) +
                       " 3D positions but " + std::to_string(sheet.development.size()) +
                       " development positions");
  if (sheet.triangles.empty()) throw InvalidSheet("sheet has no triangles");
  for (VertexIndex v = 0; v < sheet.vertexCount(); ++v) {
    const glm::dvec3& p = sheet.positions[v];
    const glm::dvec2& q = sheet.development[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(q.x) ||
        !std::isfinite(q.y))
      throw InvalidSheet("vertex " + std::to_string(v) + " has a non-finite coordinate");
  }
  std::vector<bool> used(sheet.vertexCount(), false);
  for (TriangleIndex t = 0; t < sheet.triangleCount(); ++t) {
    const Triangle& tri = sheet.triangles[t];
    for (VertexIndex v : tri) {
      if (v >= sheet.vertexCount())
        throw InvalidSheet("triangle " + std::to_string(t) + " refers to vertex " +
                           std::to_string(v) + " of " + std::to_string(sheet.vertexCount()));
      used[v] = true;
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      throw InvalidSheet("triangle " + std::to_string(t) + " repeats a vertex");
  }
  for (VertexIndex v = 0; v < used.size(); ++v)
    if (!used[v]) throw InvalidSheet("vertex " + std::to_string(v) + " belongs to no triangle");
}

void checkEdges(const Sheet& sheet, const EdgeTopology& edges) {
  for (const auto& sides : edges.edges) {
    const std::string name =
        "edge (" + std::to_string(sides.edge.a) + ", " + std::to_string(sides.edge.b) + ")";
    if (sides.triangleCount > 2)
      throw InvalidSheet(name + " is not manifold: it has " + std::to_string(sides.triangleCount) +
                         " triangles");
    if (sides.triangleCount == 2 && (sides.left == kNoIndex || sides.right == kNoIndex))
      throw InvalidSheet(name + " is inconsistently oriented: both triangles run the same way");
  }
  for (const TaggedEdge& tag : sheet.tags) {
    const std::uint32_t e = edges.find(tag.edge);
    const std::string name =
        "tagged edge (" + std::to_string(tag.edge.a) + ", " + std::to_string(tag.edge.b) + ")";
    if (e == kNoIndex) throw InvalidSheet(name + " is not an edge of the mesh");
    if (tag.kind == EdgeKind::Slit && !edges.edges[e].isBoundary())
      throw InvalidSheet(name + " is a slit but not a boundary edge");
    if (tag.kind == EdgeKind::Crease && edges.edges[e].isBoundary())
      throw InvalidSheet(name + " is a crease on the boundary");
  }
  if (!std::is_sorted(sheet.tags.begin(), sheet.tags.end()))
    throw InvalidSheet("edge tags are not sorted");
}

// The triangles around each vertex must form a single fan (no pinched "bow-tie" vertices). Each
// triangle is joined to its neighbours across its two edges through the vertex (found in the
// edge table), so the cost is O(corners log E), not the square of a vertex's valence. Runs after
// checkEdges: every edge has at most two triangles.
void checkVertexFans(const Sheet& sheet, const EdgeTopology& edges) {
  const VertexTriangles around = buildVertexTriangles(sheet);
  std::vector<std::uint32_t> parent;
  for (VertexIndex v = 0; v < sheet.vertexCount(); ++v) {
    const auto fan = around.of(v);  // ascending triangle indices
    parent.resize(fan.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&](std::uint32_t x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    std::size_t groups = fan.size();
    for (std::uint32_t i = 0; i < fan.size(); ++i) {
      const Triangle& tri = sheet.triangles[fan[i]];
      const int corner = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
      for (int step : {1, 2}) {
        const std::uint32_t e = edges.find(Edge::of(v, tri[(corner + step) % 3]));
        if (e == kNoIndex) continue;
        const EdgeTopology::EdgeSides& sides = edges.edges[e];
        const TriangleIndex other = sides.left == fan[i] ? sides.right : sides.left;
        if (other == kNoIndex || other == fan[i]) continue;
        const auto at = std::lower_bound(fan.begin(), fan.end(), other);
        if (at == fan.end() || *at != other) continue;
        const std::uint32_t j = static_cast<std::uint32_t>(at - fan.begin());
        if (root(i) != root(j)) {
          parent[root(i)] = root(j);
          --groups;
        }
      }
    }
    if (groups != 1)
      throw InvalidSheet("vertex " + std::to_string(v) + " is not manifold: its triangles form " +
                         std::to_string(groups) + " separate fans");
  }
}

void checkTriangle(const Sheet& sheet, TriangleIndex t, double minHeight) {
  const Triangle& tri = sheet.triangles[t];
  if (doubledArea(sheet, tri) <= 0.0)
    throw InvalidSheet("triangle " + std::to_string(t) +
                       " is not counter-clockwise in the development");
  const double height = smallestHeightOf(sheet, tri);
  if (height < minHeight) {
    std::ostringstream out;
    out.precision(3);
    out << "triangle " << t << " is degenerate: height " << height << " m (the floor is "
        << minHeight << " m)";
    throw InvalidSheet(out.str());
  }
}

void checkTriangles(const Sheet& sheet, double minHeight) {
  for (TriangleIndex t = 0; t < sheet.triangleCount(); ++t) checkTriangle(sheet, t, minHeight);
}

double maxEdgeLengthError(const Sheet& sheet, const EdgeTopology& edges, Edge* worst) {
  double largest = 0.0;
  for (const auto& sides : edges.edges) {
    const Edge e = sides.edge;
    const double error = std::abs(glm::distance(sheet.positions[e.a], sheet.positions[e.b]) -
                                  glm::distance(sheet.development[e.a], sheet.development[e.b]));
    if (error > largest || std::isnan(error)) {
      largest = error;
      if (worst) *worst = e;
    }
  }
  return largest;
}

}  // namespace

double smallestHeight(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  const double longest = std::max({glm::distance(a, b), glm::distance(b, c), glm::distance(c, a)});
  return longest > 0.0 ? std::abs(glm::cross(b - a, c - a)) / longest : 0.0;
}

void validate(const Sheet& sheet, const ValidationOptions& options) {
  checkArrays(sheet);
  const EdgeTopology edges = buildEdgeTopology(sheet);
  checkEdges(sheet, edges);
  checkVertexFans(sheet, edges);
  boundaryLoops(sheet, edges);  // throws on a non-simple boundary
  const double size = sheetSize(sheet);
  checkTriangles(sheet, options.relativeDegenerateHeight * size);
  Edge worst;
  const double error = maxEdgeLengthError(sheet, edges, &worst);
  if (error > options.relativeLengthTolerance * size) {
    // Lengths with three significant digits: "0.000001 m" said nothing about 1.4e-7 m.
    std::ostringstream out;
    out.precision(3);
    out << "edge (" << worst.a << ", " << worst.b << ") is not isometric: its length in 3D "
        << "differs from its development's by " << error << " m (the limit is "
        << options.relativeLengthTolerance * size << " m, " << options.relativeLengthTolerance
        << " of the size): the mesh is not developable to that tolerance; 3D "
        << describe(sheet.positions[worst.a]) << "-" << describe(sheet.positions[worst.b]);
    throw InvalidSheet(out.str());
  }
}

void validateTriangles(const Sheet& sheet, std::span<const TriangleIndex> triangles,
                       double sheetSize, const ValidationOptions& options) {
  for (TriangleIndex t : triangles)
    checkTriangle(sheet, t, options.relativeDegenerateHeight * sheetSize);
}

SheetReport measure(const Sheet& sheet, const ValidationOptions& options) {
  SheetReport report;
  report.vertexCount = sheet.vertexCount();
  report.triangleCount = sheet.triangleCount();
  report.size = sheetSize(sheet);
  try {
    validate(sheet, options);
  } catch (const InvalidSheet& error) {
    report.firstProblem = error.what();
  }
  // Index errors make the rest meaningless; report only what is safe to compute.
  for (const Triangle& t : sheet.triangles)
    for (VertexIndex v : t)
      if (v >= sheet.vertexCount()) return report;
  if (sheet.positions.size() != sheet.development.size()) return report;

  const EdgeTopology edges = buildEdgeTopology(sheet);
  report.edgeCount = edges.edges.size();
  report.eulerCharacteristic = static_cast<long>(report.vertexCount) -
                               static_cast<long>(report.edgeCount) +
                               static_cast<long>(report.triangleCount);
  report.manifold = std::all_of(edges.edges.begin(), edges.edges.end(),
                                [](const auto& s) { return s.triangleCount <= 2; });
  report.consistentlyOriented =
      std::all_of(edges.edges.begin(), edges.edges.end(), [](const auto& s) {
        return s.triangleCount != 2 || (s.left != kNoIndex && s.right != kNoIndex);
      });
  report.developmentCounterClockwise = true;
  report.minRelativeHeight = std::numeric_limits<double>::infinity();
  for (const Triangle& t : sheet.triangles) {
    report.developmentCounterClockwise &= doubledArea(sheet, t) > 0.0;
    report.minRelativeHeight =
        std::min(report.minRelativeHeight, smallestHeightOf(sheet, t) / report.size);
  }
  report.maxEdgeLengthError = maxEdgeLengthError(sheet, edges, nullptr);
  report.componentCount = connectedComponentCount(sheet, edges);
  try {
    report.boundaryLoopCount = boundaryLoops(sheet, edges).size();
  } catch (const InvalidSheet&) {
    report.manifold = false;
  }
  return report;
}

}  // namespace curvefold
