#include "engine/io/crease_pattern_reader.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>

#include "engine/io/crease_pattern_graph.hpp"
#include "engine/io/fold_crease_pattern.hpp"
#include "engine/io/input_limits.hpp"
#include "engine/io/svg_crease_pattern.hpp"

namespace curvefold {

CreasePattern readCreasePattern(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const std::string text = readWholeFile(path, kMaxCreasePatternBytes, "crease pattern");
  bool svg = extension == ".svg";
  if (extension != ".fold" && !svg) {
    const auto first =
        std::find_if(text.begin(), text.end(), [](unsigned char c) { return !std::isspace(c); });
    // A UTF-8 byte-order mark is how some editors start an SVG.
    const bool bom = text.rfind("\xEF\xBB\xBF", 0) == 0;
    const char start = bom && text.size() > 3 ? text[3] : (first == text.end() ? '\0' : *first);
    if (start != '{' && start != '<')
      throw CreasePatternError(path.string() + ": neither FOLD nor SVG (name it .fold or .svg)");
    svg = start == '<';
  }
  CreasePattern pattern = svg ? readSvgCreasePatternText(text, path.string())
                              : readFoldCreasePatternText(text, path.string());
  scaleToMetres(pattern);
  return pattern;
}

void scaleToMetres(CreasePattern& pattern) {
  if (pattern.metresPerUnit == 1.0) return;
  for (glm::dvec2& v : pattern.vertices) v *= pattern.metresPerUnit;
  pattern.metresPerUnit = 1.0;
}

void scaleToSize(CreasePattern& pattern, double largerSide) {
  if (pattern.vertices.empty()) return;
  glm::dvec2 low = pattern.vertices.front(), high = low;
  for (const glm::dvec2& v : pattern.vertices) {
    low = glm::min(low, v);
    high = glm::max(high, v);
  }
  const double side = std::max(high.x - low.x, high.y - low.y);
  if (!(side > 0.0)) return;
  for (glm::dvec2& v : pattern.vertices) v *= largerSide / side;
}

double sheetSizeMetres(double sizeMm) {
  if (!(sizeMm > 0.0 && sizeMm <= 1e6))
    throw std::invalid_argument("size: must be above 0 and at most 1000000 mm (1 km)");
  return sizeMm * 1e-3;
}

}  // namespace curvefold
