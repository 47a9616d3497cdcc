// The geometry contract of every sheet (docs/design.md 1-2): a manifold, consistently oriented disk
// (possibly with holes) whose triangles are non-degenerate, counter-clockwise in the development
// and congruent to it in 3D.
#pragma once

#include <span>

#include <cstddef>
#include <string>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

struct ValidationOptions {
  // Largest allowed |3D edge length - 2D edge length|, relative to the sheet's size.
  double relativeLengthTolerance = kRelativeIsometryTolerance;
  // A triangle whose smallest height (in the development) is below this, relative to the sheet's
  // size, is degenerate: the minimum feature size.
  double relativeDegenerateHeight = kRelativeFeatureSize;
};

// Smallest height of the triangle abc (twice its area over its longest side); 0 for a point.
double smallestHeight(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c);

// Throws InvalidSheet naming the first problem found (the vertex, edge or triangle and by how
// much).
void validate(const Sheet& sheet, const ValidationOptions& options = {});

// validate()'s triangle rules (counter-clockwise, not degenerate) on some triangles only: what a
// fold made, checked before it is committed, at the cost of those triangles.
void validateTriangles(const Sheet& sheet, std::span<const TriangleIndex> triangles,
                       double sheetSize, const ValidationOptions& options = {});

// The invariants as numbers, for `curvefold check` and for tests that compare with a reference.
struct SheetReport {
  std::size_t vertexCount = 0;
  std::size_t edgeCount = 0;
  std::size_t triangleCount = 0;
  std::size_t boundaryLoopCount = 0;
  std::size_t componentCount = 0;
  long eulerCharacteristic = 0;  // V - E + F
  double size = 0.0;
  double maxEdgeLengthError = 0.0;  // metres, |3D length - 2D length| over all edges
  double minRelativeHeight = 0.0;   // smallest triangle height / size, in the development
  bool manifold = false;
  bool consistentlyOriented = false;
  bool developmentCounterClockwise = false;
  std::string firstProblem;  // empty when validate() would pass
};

SheetReport measure(const Sheet& sheet, const ValidationOptions& options = {});

}  // namespace curvefold
