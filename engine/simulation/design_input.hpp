// A curvefold design as a crease pattern to simulate (docs/design.md, "Simulating the fold"): its
// development is the flat state; every interior edge carries its dihedral in the design (the FOLD
// sign of creases.hpp), creases as Mountain or Valley the way the printed pattern assigns them
// (assignmentOf, as engine/fabrication/pattern_edges does), every other edge as Flat with the
// initial surface's own bending at that edge; slits are Cut edges (boundaries).
//
// In design mode (bar_hinge_model.hpp) the model then drives every edge to the design, so 100%
// is the design itself; in paper mode only the creases are driven.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/geometry/sheet.hpp"
#include "engine/io/crease_pattern.hpp"

namespace curvefold {

struct DesignPattern {
  CreasePattern pattern;                    // vertices and triangles as the sheet numbers them
  std::vector<glm::dvec3> designPositions;  // the design's folded state
  // Vertex pairs on slits that meet in the design (within the sheet's tolerance): the seams a
  // maker glues (a tube's or cone's slit), each pair once, lower index first.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> seams;
};

// Throws InvalidSheet for a sheet whose edges have more than two triangles.
DesignPattern designPattern(const Sheet& sheet);

}  // namespace curvefold
