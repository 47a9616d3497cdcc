// The vertex nearest a point, by brute force (a linear scan: the callers ask a few times a step of
// sheets of a few thousand vertices; a kd-tree would cost more to build than it saves).
//
// Input: positions (non-empty) and a point. Output: the index of the nearest position, the first
// of equals; 0 for empty positions.
#pragma once

#include <cstdint>
#include <span>

#include <glm/vec3.hpp>

namespace curvefold {

std::uint32_t nearestVertex(std::span<const glm::dvec3> positions, const glm::dvec3& point);

}  // namespace curvefold
