// The dynamic contact list's point-triangle distance, a vertex-triangle pair a lane (eight lanes;
// the loop runs on local arrays so that it vectorizes; AVX2 clone by lane_clones.hpp; the source
// compiled without errno on math calls, traps or contraction: CMakeLists.txt). Inputs: the
// positions `x` and per lane its pair's four vertices (p, then the triangle's corners a, b, c);
// `count` (1..kContactLanes) lanes in use (the last one's pair fills the others). Each lane's
// results are nearestTriangleWeights' bits (contact.hpp), so a step is the same whichever way a
// list is cut into lanes.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

namespace curvefold {

constexpr std::size_t kContactLanes = 8;

// Per lane nearestTriangleWeights(p, a, b, c) (out[4..6]), p minus the nearest point
// (out[0..2]) and its length (out[3]), as contactTerm computes them. Every Voronoi region's test
// is made and the first that holds is taken, in nearestTriangleWeights' order and with its
// expressions; the divisions take their operands by that choice (two a lane, the face's, where
// contact22's lanes made one for each region: five).
void triangleDistanceLanes(const glm::dvec3* x, const std::array<std::uint32_t, 4>* pairs,
                           std::size_t count, double (&out)[7][kContactLanes]);

}  // namespace curvefold
