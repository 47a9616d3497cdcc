// A plain mesh's boundary: its edges with one triangle (a sheet's rim, a slit's two sides, a
// scan's holes). Unlike boundaryLoops (topology.hpp) it needs no Sheet and no simple cycles: a
// fit's target and its unfolding are plain meshes.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {

// The edges with one triangle, lower vertex first, sorted (edgeFaces' order).
std::vector<std::pair<std::uint32_t, std::uint32_t>> boundaryEdges(const TriangleMesh& mesh);

// Whether each vertex lies on such an edge (1) or not (0), indexed as the mesh's positions.
std::vector<char> boundaryVertexFlags(const TriangleMesh& mesh);

// The vertices on such edges, each once, in the order a walk along them meets them: each loop
// from its lowest vertex on, the lowest unvisited neighbour next where a vertex has several
// (a pinched rim). Every k-th of them is then spread along the whole rim, each side of a sheet's
// grid sampled, where every k-th in index order may keep to one side (a grid's rows alias k).
// Cost: one pass over the edges (edgeFaces) and one over the boundary.
std::vector<std::uint32_t> boundaryVerticesAlong(const TriangleMesh& mesh);

}  // namespace curvefold
