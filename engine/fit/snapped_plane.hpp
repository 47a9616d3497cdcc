// A plane read off a target's crease, moved onto the sheet vertices it all but passes through
// (issue 38, 1). A fold whose plane runs through a vertex of the sheet (a plane set through a
// vertex, or one the fold snapped onto it: reflection.hpp's plane shifts) leaves that vertex in its
// crease, and a crease read back carries rounding (about 1e-9 of the sheet's size): the read plane
// passes the vertex by a hair and cuts a sliver next to it, which the fold refuses where one shift
// cannot bring it through every such vertex at once (two vertices, or a vertex and a tilt).
//
// Known limits: the vertices within `reach` must lie in one plane; where they do not (a plane
// that grazes a curved sheet), nothing is returned.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/geometry/reflection.hpp"

namespace curvefold {

// `plane`: the plane read; `points`: the sheet's vertices as they lie; `reach`: how far from the
// plane a vertex may lie and be taken into it (metres); `size`: the sheet's size (a turn of the
// normal weighs as much as a move of the plane by it). Returns the plane nearest `plane` (least
// change of its unit normal and of its offset over `size`) through every point within `reach`,
// each then within `onPlane` of it; nullopt where no point lies within reach, or where no such
// plane holds them all within `onPlane`.
std::optional<ReflectionPlane> planeThroughNearPoints(const ReflectionPlane& plane,
                                                      const std::vector<glm::dvec3>& points,
                                                      double reach, double size, double onPlane);

}  // namespace curvefold
