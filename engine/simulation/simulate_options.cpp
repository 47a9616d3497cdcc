#include "engine/simulation/simulate_options.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "engine/text/decimal.hpp"
#include "engine/text/excerpt.hpp"

namespace curvefold {

void setStiffnessPreset(ModelOptions& options, std::string_view name, bool paperMode) {
  const ModelOptions preset =
      name == "origami-simulator" ? simulatorModelOptions() : ModelOptions{};
  if (name != "origami-simulator" && name != "curvefold")
    throw std::invalid_argument("stiffness: expected curvefold or origami-simulator, got " +
                                quotedExcerpt(name));
  if (paperMode)
    throw std::invalid_argument(
        "stiffness: sets design mode's stiffnesses; paper mode takes paper's, name one");
  options.axialStiffness = preset.axialStiffness;
  options.facetStiffness = preset.facetStiffness;
  options.creaseStiffness = preset.creaseStiffness;
}

glm::dvec2 parseSheetPoint(std::string_view text, std::string_view name) {
  const std::size_t comma = text.find(',');
  glm::dvec2 p;
  if (comma == std::string_view::npos || !readDecimal(text.substr(0, comma), p.x) ||
      !readDecimal(text.substr(comma + 1), p.y) || !std::isfinite(p.x) || !std::isfinite(p.y))
    throw std::invalid_argument(std::string(name) +
                                ": expected X,Y on the flat sheet in metres, got " +
                                quotedExcerpt(text));
  return p;
}

std::uint32_t sheetVertexNear(const CreasePattern& pattern, glm::dvec2 p, std::string_view name) {
  const std::string option(name);
  char line[320];
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
    std::snprintf(line, sizeof line, "%s: expected X,Y on the flat sheet in metres, got (%g, %g)",
                  option.c_str(), p.x, p.y);
    throw std::invalid_argument(line);
  }
  glm::dvec2 low(std::numeric_limits<double>::infinity());
  glm::dvec2 high(-std::numeric_limits<double>::infinity());
  for (const glm::dvec2& v : pattern.vertices) {
    low = glm::min(low, v);
    high = glm::max(high, v);
  }
  const double margin = 0.01 * glm::distance(low, high);
  if (pattern.vertices.empty() || p.x < low.x - margin || p.y < low.y - margin ||
      p.x > high.x + margin || p.y > high.y + margin) {
    std::snprintf(line, sizeof line,
                  "%s: (%g, %g) is off the flat sheet, which spans x %g to %g and y %g to %g "
                  "(metres)",
                  option.c_str(), p.x, p.y, low.x, high.x, low.y, high.y);
    throw std::invalid_argument(line);
  }
  std::uint32_t best = 0;
  for (std::uint32_t v = 1; v < pattern.vertices.size(); ++v)
    if (glm::distance(pattern.vertices[v], p) < glm::distance(pattern.vertices[best], p)) best = v;
  return best;
}

void addPin(ModelOptions& options, const CreasePattern& pattern, glm::dvec2 p) {
  options.pins.push_back(sheetVertexNear(pattern, p, "pin"));
}

void addGlue(ModelOptions& options, const CreasePattern& pattern, glm::dvec2 a, glm::dvec2 b) {
  const std::uint32_t i = sheetVertexNear(pattern, a, "glue");
  const std::uint32_t j = sheetVertexNear(pattern, b, "glue");
  if (i == j) throw std::invalid_argument("glue: both points are nearest the same vertex");
  options.glue.emplace_back(i, j);
}

void glueSlits(ModelOptions& options,
               const std::vector<std::pair<std::uint32_t, std::uint32_t>>& seams) {
  if (seams.empty()) throw std::invalid_argument("glue slits: the design has no slit");
  options.glue.insert(options.glue.end(), seams.begin(), seams.end());
}

void addGlueText(ModelOptions& options, const CreasePattern& pattern,
                 const std::vector<std::pair<std::uint32_t, std::uint32_t>>& seams,
                 std::string_view text) {
  if (text == "slits") return glueSlits(options, seams);
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos)
    throw std::invalid_argument("glue: expected X1,Y1:X2,Y2 or slits, got " + quotedExcerpt(text));
  addGlue(options, pattern, parseSheetPoint(text.substr(0, colon), "glue"),
          parseSheetPoint(text.substr(colon + 1), "glue"));
}

FoldingMotion followFoldingMotion(BarHingeModel& model) {
  if (model.vertexCount() > kMaxMotionVertices)
    throw std::invalid_argument("motion: the pattern has " + std::to_string(model.vertexCount()) +
                                " vertices; the motion is found for at most " +
                                std::to_string(kMaxMotionVertices));
  FoldingMotion motion = foldingMotion(model);
  setFoldingMotion(model, motion);
  return motion;
}

}  // namespace curvefold
