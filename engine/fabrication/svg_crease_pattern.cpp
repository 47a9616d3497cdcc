#include "engine/fabrication/svg_crease_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <stdexcept>

#include <glm/common.hpp>

#include "engine/fabrication/colours.hpp"
#include "engine/fabrication/pattern_edges.hpp"
#include "engine/fabrication/units.hpp"
#include "engine/io/atomic_file.hpp"

namespace curvefold {

void writeSvgCreasePattern(const Sheet& sheet, const std::filesystem::path& path,
                           const SvgOptions& options) {
  if (!(options.marginMm >= 0.0)) throw std::invalid_argument("SVG margin must not be negative");
  if (!(options.strokeWidthMm > 0.0))
    throw std::invalid_argument("SVG stroke width must be positive");

  const DevelopmentBounds bounds = developmentBounds(sheet);
  const glm::dvec2 lo = bounds.low, hi = bounds.high;
  const double width = (hi.x - lo.x) * kMmPerMetre + 2.0 * options.marginMm;
  const double height = (hi.y - lo.y) * kMmPerMetre + 2.0 * options.marginMm;
  // SVG's y axis points down while the development's points up: flip y, or the print would be
  // the pattern's mirror image, which seen from the front swaps every mountain and valley.
  auto toSvg = [&](VertexIndex v) {
    const glm::dvec2& p = sheet.development[v];
    return glm::dvec2((p.x - lo.x) * kMmPerMetre + options.marginMm,
                      (hi.y - p.y) * kMmPerMetre + options.marginMm);
  };

  const std::vector<DrawnEdge> edges = drawnEdges(sheet, buildEdgeTopology(sheet));
  writeFileAtomically(path, [&](std::ostream& out) {
    out << std::fixed << std::setprecision(4);  // 0.1 um: far below what a printer resolves
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "mm\" height=\""
        << height << "mm\" viewBox=\"0 0 " << width << ' ' << height << "\">\n";
    // Lines are direct children of <svg>: Origami Simulator's importer ignores groups.
    for (const DrawnEdge& e : edges) {
      const bool folded =
          e.assignment == Assignment::Mountain || e.assignment == Assignment::Valley;
      const double opacity = folded ? std::min(std::abs(e.foldAngle) / 180.0, 1.0) : 1.0;
      const glm::dvec2 a = toSvg(e.edge.a);
      const glm::dvec2 b = toSvg(e.edge.b);
      out << "<line x1=\"" << a.x << "\" y1=\"" << a.y << "\" x2=\"" << b.x << "\" y2=\"" << b.y
          << "\" stroke=\"" << paperSvgColour(e.assignment) << "\" stroke-opacity=\"" << opacity
          << "\" stroke-width=\"" << options.strokeWidthMm << "\" stroke-linecap=\"round\"/>\n";
    }
    out << "</svg>\n";
  });
}

}  // namespace curvefold
