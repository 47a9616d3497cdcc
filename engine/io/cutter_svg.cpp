#include "engine/io/cutter_svg.hpp"

#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "engine/geometry/creases.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/io/atomic_file.hpp"

namespace curvefold {
namespace {

constexpr double kMmPerMetre = 1000.0;
constexpr double kMarginMm = 5.0;

// Joins edges into polylines through vertices where exactly two of them meet: paths first from
// each end (a vertex where one or three or more meet), then what is left, closed loops.
std::vector<std::vector<VertexIndex>> chains(const std::vector<Edge>& edges) {
  std::map<VertexIndex, std::vector<std::size_t>> at;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    at[edges[i].a].push_back(i);
    at[edges[i].b].push_back(i);
  }
  std::vector<char> used(edges.size(), 0);
  std::vector<std::vector<VertexIndex>> result;
  auto walk = [&](VertexIndex start, std::size_t first) {
    std::vector<VertexIndex> chain{start};
    VertexIndex v = start;
    std::size_t e = first;
    while (true) {
      used[e] = 1;
      v = edges[e].a == v ? edges[e].b : edges[e].a;
      chain.push_back(v);
      const std::vector<std::size_t>& next = at[v];
      if (next.size() != 2) break;
      const std::size_t other = next[0] == e ? next[1] : next[0];
      if (used[other]) break;
      e = other;
    }
    result.push_back(std::move(chain));
  };
  for (const auto& [v, incident] : at)
    if (incident.size() != 2)
      for (std::size_t e : incident)
        if (!used[e]) walk(v, e);
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (!used[e]) walk(edges[e].a, e);
  return result;
}

// Dashes of `cut` with `gap` between along a polyline, continuing across its vertices.
std::vector<std::vector<glm::dvec2>> perforate(const std::vector<glm::dvec2>& line,
                                               const Perforation& p) {
  std::vector<std::vector<glm::dvec2>> dashes;
  bool cutting = true;
  double left = p.cutMm;  // of the current dash or gap
  glm::dvec2 dashStart = line.front();
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    glm::dvec2 a = line[i];
    const glm::dvec2 b = line[i + 1];
    double length = glm::distance(a, b);
    while (length > 0.0) {
      const double step = std::min(left, length);
      const glm::dvec2 end = a + (b - a) * (step / length);
      left -= step;
      length -= step;
      a = end;
      if (left <= 1e-12) {
        if (cutting) dashes.push_back({dashStart, end});
        cutting = !cutting;
        left = cutting ? p.cutMm : p.gapMm;
        dashStart = end;
      }
    }
  }
  // A last, shorter dash where the line ends inside one.
  if (cutting && glm::distance(dashStart, line.back()) > 1e-9)
    dashes.push_back({dashStart, line.back()});
  return dashes;
}

}  // namespace

std::vector<CutterLayer> cutterLayers(const Sheet& sheet,
                                      const std::optional<Perforation>& perforation) {
  if (perforation &&
      (!(perforation->cutMm >= kMinPerforationMm) || !(perforation->gapMm >= kMinPerforationMm) ||
       !std::isfinite(perforation->cutMm) || !std::isfinite(perforation->gapMm)))
    throw std::invalid_argument("perforation: cut and gap must be finite and at least " +
                                std::to_string(kMinPerforationMm).substr(0, 3) + " mm");
  const DevelopmentBounds bounds = developmentBounds(sheet);
  const glm::dvec2 lo = bounds.low, hi = bounds.high;
  // Millimetres, y down (as in the SVG crease pattern: else the print is the mirror image).
  auto toMm = [&](VertexIndex v) {
    const glm::dvec2& p = sheet.development[v];
    return glm::dvec2((p.x - lo.x) * kMmPerMetre + kMarginMm,
                      (hi.y - p.y) * kMmPerMetre + kMarginMm);
  };
  std::vector<Edge> cut, mountain, valley;
  for (const EdgeTopology::EdgeSides& sides : buildEdgeTopology(sheet).edges) {
    const Assignment assignment = assignmentOf(sheet, sides, foldAngleDegrees(sheet, sides));
    if (assignment == Assignment::Boundary || assignment == Assignment::Cut)
      cut.push_back(sides.edge);
    else if (assignment == Assignment::Mountain)
      mountain.push_back(sides.edge);
    else if (assignment == Assignment::Valley)
      valley.push_back(sides.edge);
  }
  // The dashes are counted before any is made: fine dashes over long creases would fill memory.
  if (perforation) {
    double scoreMm = 0.0;
    for (const std::vector<Edge>* edges : {&mountain, &valley})
      for (const Edge& e : *edges) scoreMm += glm::distance(toMm(e.a), toMm(e.b));
    const double dashes = scoreMm / (perforation->cutMm + perforation->gapMm);
    if (dashes > kMaxPerforationDashes)
      throw std::invalid_argument("perforation: " + std::to_string(std::llround(dashes)) +
                                  " dashes over " + std::to_string(std::llround(scoreMm)) +
                                  " mm of creases, more than " +
                                  std::to_string(std::llround(kMaxPerforationDashes)));
  }
  std::vector<CutterLayer> layers{
      {"cut", "#ff0000", {}}, {"mountain score", "#0000ff", {}}, {"valley score", "#00ff00", {}}};
  const std::vector<Edge>* sources[3] = {&cut, &mountain, &valley};
  for (int k = 0; k < 3; ++k)
    for (const std::vector<VertexIndex>& chain : chains(*sources[k])) {
      std::vector<glm::dvec2> line;
      for (VertexIndex v : chain) line.push_back(toMm(v));
      if (k > 0 && perforation) {
        for (std::vector<glm::dvec2>& dash : perforate(line, *perforation))
          layers[k].polylines.push_back(std::move(dash));
      } else {
        layers[k].polylines.push_back(std::move(line));
      }
    }
  return layers;
}

void writeCutterSvg(const Sheet& sheet, const std::filesystem::path& path,
                    const std::optional<Perforation>& perforation) {
  const std::vector<CutterLayer> layers = cutterLayers(sheet, perforation);
  const DevelopmentBounds bounds = developmentBounds(sheet);
  const glm::dvec2 lo = bounds.low, hi = bounds.high;
  const double width = (hi.x - lo.x) * kMmPerMetre + 2.0 * kMarginMm;
  const double height = (hi.y - lo.y) * kMmPerMetre + 2.0 * kMarginMm;
  writeFileAtomically(path, [&](std::ostream& out) {
    out << std::fixed << std::setprecision(4);
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" "
           "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\""
        << width << "mm\" height=\"" << height << "mm\" viewBox=\"0 0 " << width << ' ' << height
        << "\">\n";
    for (const CutterLayer& layer : layers) {
      std::string id = layer.name;
      for (char& c : id)
        if (c == ' ') c = '-';
      out << "<g inkscape:groupmode=\"layer\" id=\"" << id << "\" inkscape:label=\"" << layer.name
          << "\" fill=\"none\" stroke=\"" << layer.colour << "\" stroke-width=\"" << kHairlineMm
          << "\">\n";
      for (const std::vector<glm::dvec2>& line : layer.polylines) {
        out << "<path d=\"M";
        for (std::size_t i = 0; i < line.size(); ++i)
          out << (i == 0 ? " " : " L ") << line[i].x << ' ' << line[i].y;
        out << "\"/>\n";
      }
      out << "</g>\n";
    }
    out << "</svg>\n";
  });
}

}  // namespace curvefold
