#include "app/session/design_check.hpp"

#include <algorithm>
#include <cstdio>

#include "app/session/document.hpp"
#include "engine/geometry/creases.hpp"
#include "engine/geometry/development_overlap.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/tolerances.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/geometry/validate.hpp"

namespace curvefold::session {

bool DesignCheck::passed() const {
  return std::all_of(lines.begin(), lines.end(), [](const CheckLine& line) { return line.ok; });
}

std::string DesignCheck::firstFailure() const {
  for (const CheckLine& line : lines)
    if (!line.ok) return line.text;
  return "";
}

double isometryTolerance(const Sheet& initial) {
  const SheetReport report = measure(initial);
  return std::max(kRelativeIsometryTolerance * report.size, 1.5 * report.maxEdgeLengthError);
}

DesignCheck checkDesign(const Design& design, std::string_view name, const Sheet& initial,
                        const Sheet& sheet, bool allowSelfIntersection) {
  const double tolerance = isometryTolerance(initial);
  ValidationOptions options;
  options.relativeLengthTolerance = tolerance / sheetSize(sheet);
  const SheetReport now = measure(sheet, options);
  const SheetReport before = measure(initial, options);
  const EdgeTopology edges = buildEdgeTopology(sheet);
  const std::vector<CreaseEdge> creases = creaseEdges(sheet, edges);
  const std::vector<CreaseCurve> curves = creaseCurves(sheet, edges);

  DesignCheck check;
  check.maxEdgeLengthError = now.maxEdgeLengthError;
  check.lengthTolerance = tolerance;
  auto line = [&](bool ok, const std::string& text) { check.lines.push_back({ok, text}); };
  char buffer[256];
  check.summary = std::string(name) + ": " + surfaceName(design) + ", " +
                  std::to_string(design.folds.size()) + " folds, " +
                  std::to_string(now.vertexCount) + " vertices, " +
                  std::to_string(now.triangleCount) + " triangles";
  std::snprintf(buffer, sizeof buffer,
                "isometry: max edge-length error %.3g m (%.3g of the size; limit %.3g m)",
                now.maxEdgeLengthError, now.maxEdgeLengthError / now.size, tolerance);
  line(now.maxEdgeLengthError <= tolerance, buffer);
  double worstPlanarity = 0.0;
  for (const CreaseCurve& curve : curves)
    worstPlanarity = std::max(worstPlanarity, curve.planarityError);
  std::size_t mountains = 0, valleys = 0;
  for (const CreaseEdge& crease : creases) {
    mountains += crease.assignment == Assignment::Mountain;
    valleys += crease.assignment == Assignment::Valley;
  }
  check.mountainEdges = mountains;
  check.valleyEdges = valleys;
  check.creaseCurves = curves.size();
  std::snprintf(buffer, sizeof buffer,
                "creases: %zu curves, %zu edges (%zu mountain, %zu valley); max planarity "
                "error %.3g m",
                curves.size(), creases.size(), mountains, valleys, worstPlanarity);
  line(worstPlanarity <= kRelativePlaneTolerance * now.size, buffer);
  for (std::size_t i = 0; i < curves.size(); ++i) {
    std::snprintf(buffer, sizeof buffer, "crease %zu: %zu vertices%s, planarity error %.3g m",
                  i + 1, curves[i].vertices.size(), curves[i].closed ? " (closed)" : "",
                  curves[i].planarityError);
    line(curves[i].planarityError <= kRelativePlaneTolerance * now.size, buffer);
  }
  line(now.eulerCharacteristic == before.eulerCharacteristic,
       "Euler characteristic " + std::to_string(now.eulerCharacteristic) + " (initial " +
           std::to_string(before.eulerCharacteristic) + ")");
  line(now.boundaryLoopCount == before.boundaryLoopCount,
       "boundary loops " + std::to_string(now.boundaryLoopCount) + " (initial " +
           std::to_string(before.boundaryLoopCount) + ")");
  line(now.componentCount == before.componentCount,
       "components " + std::to_string(now.componentCount) + " (initial " +
           std::to_string(before.componentCount) + ")");
  line(now.manifold, now.manifold ? "manifold" : "not manifold");
  // Folds never change the development, but a design may embed one that overlaps itself.
  if (const std::optional<EdgeCrossing> crossing = findDevelopmentCrossing(sheet))
    line(false, "development overlaps itself: edges (" + std::to_string(crossing->first.a) + ", " +
                    std::to_string(crossing->first.b) + ") and (" +
                    std::to_string(crossing->second.a) + ", " + std::to_string(crossing->second.b) +
                    ") cross");
  else if (const std::optional<PieceOverlap> overlap = findPieceOverlap(sheet))
    line(false, "development overlaps itself: the piece of triangle " +
                    std::to_string(overlap->inner) + " lies on the piece of triangle " +
                    std::to_string(overlap->outer));
  else
    line(true, "development: no edges cross, no piece lies on another");
  // Paper cannot pass through itself (issue 17); layers that only touch are contact.
  const SelfIntersectionReport crossings = findSelfIntersections(sheet);
  check.selfIntersectingPairs = crossings.intersections.size();
  check.contactPairs = crossings.contacts.size();
  if (crossings.intersections.empty()) {
    line(true, "self-intersection: none");
  } else {
    const auto [s, t] = crossings.intersections.front();
    std::snprintf(buffer, sizeof buffer,
                  "self-intersection: %zu triangle pairs (first: triangles %u and %u, at "
                  "(%.6g, %.6g, %.6g))%s",
                  crossings.intersections.size(), s.value, t.value, crossings.firstPoint.x,
                  crossings.firstPoint.y, crossings.firstPoint.z,
                  allowSelfIntersection ? ", allowed" : "");
    line(allowSelfIntersection, buffer);
  }
  line(true, "contact: " + std::to_string(crossings.contacts.size()) +
                 " triangle pairs (layers that touch, allowed)");
  line(now.consistentlyOriented && now.developmentCounterClockwise,
       now.consistentlyOriented && now.developmentCounterClockwise
           ? "consistently oriented (development counter-clockwise)"
           : "orientation is inconsistent");
  std::snprintf(buffer, sizeof buffer, "smallest triangle height %.3g of the size",
                now.minRelativeHeight);
  line(now.minRelativeHeight >= options.relativeDegenerateHeight, buffer);
  line(now.firstProblem.empty(),
       now.firstProblem.empty() ? "validate: passed" : "validate: " + now.firstProblem);
  // A stated symmetry the initial sheet lacks makes opening or replaying the design fail.
  if (!design.symmetry.empty()) {
    try {
      line(true, "symmetry: " + parseSymmetry(design.symmetry, initial).name());
    } catch (const InvalidSymmetry& e) {
      line(false, "symmetry: " + session::symmetryProblem(e));
    }
  }
  return check;
}

}  // namespace curvefold::session
