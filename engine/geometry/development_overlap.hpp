// Whether a development overlaps itself: two of its edges cross in the plane. A development that
// does (an OBJ of a cone sweeping twice around, unfolded) cannot be cut from one sheet of paper:
// its crease pattern crosses itself. Folds never change the development, so this is checked where
// a development is made (OBJ import) and by `check`, not after every fold.
//
// Edges go into a uniform grid of cells about the mean edge length, and each edge is tested only
// against the edges sharing a cell: near-linear in the number of edges for real meshes.
#pragma once

#include <optional>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

struct EdgeCrossing {
  Edge first, second;
};

// The first pair of edges (of the development) that cross properly, or nothing. Edges sharing a
// vertex never count; crossings are decided with a tolerance of 1e-12 of the size squared, so
// edges that only touch within rounding do not count either.
std::optional<EdgeCrossing> findDevelopmentCrossing(const Sheet& sheet);

}  // namespace curvefold
