#include "engine/geometry/topology.hpp"

#include <algorithm>
#include <numeric>
#include <string>

namespace curvefold {

VertexTriangles buildVertexTriangles(const Sheet& sheet) {
  VertexTriangles result;
  const std::size_t vertexCount = sheet.vertexCount();
  result.offsets.assign(vertexCount + 1, 0);
  for (const Triangle& t : sheet.triangles)
    for (VertexIndex v : t) ++result.offsets[v + 1];
  std::partial_sum(result.offsets.begin(), result.offsets.end(), result.offsets.begin());
  result.triangles.resize(result.offsets.back());
  std::vector<std::uint32_t> cursor(result.offsets.begin(), result.offsets.end() - 1);
  for (TriangleIndex t = 0; t < sheet.triangles.size(); ++t)
    for (VertexIndex v : sheet.triangles[t]) result.triangles[cursor[v]++] = t;
  return result;
}

SheetAdjacency buildAdjacency(const Sheet& sheet) {
  SheetAdjacency result{buildVertexTriangles(sheet), {}};
  VertexNeighbors& neighbors = result.neighbors;
  const std::size_t vertexCount = sheet.vertexCount();
  neighbors.offsets.assign(vertexCount + 1, 0);
  neighbors.vertices.reserve(result.triangles.triangles.size() + vertexCount);
  std::vector<VertexIndex> row;
  for (VertexIndex v = 0; v < vertexCount; ++v) {
    row.clear();
    for (TriangleIndex t : result.triangles.of(v))
      for (VertexIndex w : sheet.triangles[t])
        if (w != v) row.push_back(w);
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    neighbors.vertices.insert(neighbors.vertices.end(), row.begin(), row.end());
    neighbors.offsets[v + 1] = static_cast<std::uint32_t>(neighbors.vertices.size());
  }
  return result;
}

std::size_t adjacencyBytes(const SheetAdjacency& adjacency) {
  return sizeof(std::uint32_t) *
         (adjacency.triangles.offsets.capacity() + adjacency.triangles.triangles.capacity() +
          adjacency.neighbors.offsets.capacity() + adjacency.neighbors.vertices.capacity());
}

std::uint32_t EdgeTopology::find(Edge edge) const {
  auto it = std::lower_bound(edges.begin(), edges.end(), edge,
                             [](const EdgeSides& s, const Edge& e) { return s.edge < e; });
  if (it == edges.end() || it->edge != edge) return kNoIndex;
  return static_cast<std::uint32_t>(it - edges.begin());
}

EdgeTopology buildEdgeTopology(const Sheet& sheet) {
  struct HalfEdge {
    Edge edge;
    TriangleIndex triangle;
    bool forward;  // runs a->b
  };
  std::vector<HalfEdge> halves;
  halves.reserve(sheet.triangles.size() * 3);
  for (TriangleIndex t = 0; t < sheet.triangles.size(); ++t) {
    const Triangle& tri = sheet.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const VertexIndex u = tri[i], v = tri[(i + 1) % 3];
      halves.push_back({Edge::of(u, v), t, u < v});
    }
  }
  std::sort(halves.begin(), halves.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.edge != y.edge ? x.edge < y.edge : x.triangle < y.triangle;
  });
  EdgeTopology result;
  for (const HalfEdge& h : halves) {
    if (result.edges.empty() || result.edges.back().edge != h.edge)
      result.edges.push_back({h.edge, kNoIndex, kNoIndex, 0});
    EdgeTopology::EdgeSides& sides = result.edges.back();
    ++sides.triangleCount;
    TriangleIndex& slot = h.forward ? sides.left : sides.right;
    if (slot == kNoIndex) slot = h.triangle;
  }
  return result;
}

std::vector<std::vector<VertexIndex>> boundaryLoops(const Sheet& sheet, const EdgeTopology& edges) {
  // Directed boundary edges, following the orientation of their single triangle.
  std::vector<VertexIndex> next(sheet.vertexCount(), kNoIndex);
  std::size_t boundaryEdgeCount = 0;
  for (const auto& sides : edges.edges) {
    if (!sides.isBoundary()) continue;
    ++boundaryEdgeCount;
    const bool forward = sides.left != kNoIndex;
    const VertexIndex from = forward ? sides.edge.a : sides.edge.b;
    const VertexIndex to = forward ? sides.edge.b : sides.edge.a;
    if (next[from] != kNoIndex)
      throw InvalidSheet("boundary is not simple: vertex " + std::to_string(from) +
                         " starts two boundary edges");
    next[from] = to;
  }
  std::vector<std::vector<VertexIndex>> loops;
  std::vector<bool> visited(sheet.vertexCount(), false);
  std::size_t walked = 0;
  for (VertexIndex start = 0; start < next.size(); ++start) {
    if (next[start] == kNoIndex || visited[start]) continue;
    std::vector<VertexIndex> loop;
    VertexIndex v = start;
    while (!visited[v]) {
      visited[v] = true;
      loop.push_back(v);
      v = next[v];
      if (v == kNoIndex)
        throw InvalidSheet("boundary is not closed at vertex " + std::to_string(loop.back()));
    }
    if (v != start) throw InvalidSheet("boundary loops touch at vertex " + std::to_string(v));
    walked += loop.size();
    loops.push_back(std::move(loop));
  }
  if (walked != boundaryEdgeCount) throw InvalidSheet("boundary edges do not form loops");
  return loops;
}

std::vector<std::uint32_t> connectedComponents(const Sheet& sheet, const EdgeTopology& edges) {
  std::vector<std::uint32_t> parent(sheet.triangleCount());
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& sides : edges.edges)
    if (sides.left != kNoIndex && sides.right != kNoIndex)
      parent[root(sides.left)] = root(sides.right);
  std::vector<std::uint32_t> component(parent.size());
  std::vector<std::uint32_t> number(parent.size(), kNoIndex);
  std::uint32_t count = 0;
  for (std::uint32_t t = 0; t < parent.size(); ++t) {
    std::uint32_t& n = number[root(t)];
    if (n == kNoIndex) n = count++;
    component[t] = n;
  }
  return component;
}

std::size_t connectedComponentCount(const Sheet& sheet, const EdgeTopology& edges) {
  const std::vector<std::uint32_t> component = connectedComponents(sheet, edges);
  return component.empty() ? 0 : *std::max_element(component.begin(), component.end()) + 1;
}

}  // namespace curvefold
