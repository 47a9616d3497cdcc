// The invariants of a design, as `curvefold check` prints them and the Python module returns them
// (docs/design.md 1): isometry, planar creases, the initial topology, a manifold, a development
// that does not overlap itself, no self-intersection (unless allowed), consistent orientation, no
// degenerate triangle and a stated symmetry the initial sheet has. One home for both.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "engine/geometry/sheet.hpp"
#include "engine/io/design_document.hpp"

namespace curvefold::session {

struct CheckLine {
  bool ok = true;
  std::string text;  // "isometry: max edge-length error ...", "manifold", ...
};

struct DesignCheck {
  std::string summary;  // "<name>: cylinder, 3 folds, 812 vertices, 1536 triangles"
  std::vector<CheckLine> lines;
  std::size_t selfIntersectingPairs = 0;
  std::size_t contactPairs = 0;  // layers that touch (allowed)
  double maxEdgeLengthError = 0.0;
  double lengthTolerance = 0.0;
  std::size_t mountainEdges = 0, valleyEdges = 0, creaseCurves = 0;
  bool passed() const;
  // The first failing line's text ("" when it passed).
  std::string firstFailure() const;
};

// The isometry tolerance for a design: 1e-9 of the size, or what an imported mesh brought with it
// (an OBJ carries about 6 digits, so its sheet starts with edge errors near 1e-7 that folds keep
// but never grow).
double isometryTolerance(const Sheet& initial);

// Checks `sheet`, the folded form of `design` (whose initial sheet is `initial`). A self-crossing
// fails unless allowed.
DesignCheck checkDesign(const Design& design, std::string_view name, const Sheet& initial,
                        const Sheet& sheet, bool allowSelfIntersection);

}  // namespace curvefold::session
