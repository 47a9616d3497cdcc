// Connectivity derived from a sheet's triangle array: vertex-to-triangle references in compressed
// rows for constant-time neighbourhoods [Mitani & Igarashi 2011, Sec. 3.3], the edge list with the
// triangles on either side, and the boundary loops.
#pragma once

#include <span>
#include <vector>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

// Triangles incident to each vertex, as compressed rows: triangles[offsets[v] .. offsets[v+1]).
struct VertexTriangles {
  std::vector<std::uint32_t> offsets;
  std::vector<TriangleIndex> triangles;

  std::span<const TriangleIndex> of(VertexIndex v) const {
    return {triangles.data() + offsets[v], triangles.data() + offsets[v + 1]};
  }
};

VertexTriangles buildVertexTriangles(const Sheet& sheet);

// Vertices sharing an edge with each vertex, as compressed rows, sorted within each row.
struct VertexNeighbors {
  std::vector<std::uint32_t> offsets;
  std::vector<VertexIndex> vertices;

  std::span<const VertexIndex> of(VertexIndex v) const {
    return {vertices.data() + offsets[v], vertices.data() + offsets[v + 1]};
  }
};

// Both neighbourhoods of every vertex: what a flood fill over the sheet needs.
struct SheetAdjacency {
  VertexTriangles triangles;
  VertexNeighbors neighbors;
};

SheetAdjacency buildAdjacency(const Sheet& sheet);
std::size_t adjacencyBytes(const SheetAdjacency& adjacency);

// Every edge once, sorted; left is the triangle that runs a->b, right the one that runs b->a
// (kNoIndex when absent). A consistently oriented manifold has at most one of each.
struct EdgeTopology {
  struct EdgeSides {
    Edge edge;
    TriangleIndex left = kNoIndex;
    TriangleIndex right = kNoIndex;
    std::uint32_t triangleCount = 0;  // more than 2 means non-manifold

    bool isBoundary() const { return triangleCount == 1; }
  };
  std::vector<EdgeSides> edges;

  // Index into edges, or kNoIndex. O(log E).
  std::uint32_t find(Edge edge) const;
};

EdgeTopology buildEdgeTopology(const Sheet& sheet);

// Boundary loops as vertex cycles, each following the boundary edges in the triangles' direction.
// Throws InvalidSheet when the boundary is not a set of simple cycles.
std::vector<std::vector<VertexIndex>> boundaryLoops(const Sheet& sheet, const EdgeTopology& edges);

// Connected components of the triangle graph (through shared edges).
std::size_t connectedComponentCount(const Sheet& sheet, const EdgeTopology& edges);
// Each triangle's component, numbered 0, 1, ... in the order of their first triangles.
std::vector<std::uint32_t> connectedComponents(const Sheet& sheet, const EdgeTopology& edges);

}  // namespace curvefold
