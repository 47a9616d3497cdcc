#include "engine/fabrication/cutter_svg.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>
#include <stdexcept>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "engine/fabrication/colours.hpp"
#include "engine/fabrication/pattern_edges.hpp"
#include "engine/fabrication/units.hpp"
#include "engine/io/atomic_file.hpp"

namespace curvefold {
namespace {

constexpr double kMarginMm = 5.0;

// A crease runs on through a vertex where others meet if it turns by less than this there; a
// curved crease turns by a few degrees a vertex, creases crossing at a vertex by far more.
constexpr double kMaxRunOnTurnCos = 0.7071067811865476;  // 45 degrees

// Joins edges into polylines: through every vertex where exactly two meet, and through a vertex
// where more meet along the straightest pairs (so a crease crossed by another of its kind stays
// one line, and its perforation runs on across the crossing). Paths first from each end (an edge
// end with no partner), then what is left, closed loops.
std::vector<std::vector<VertexIndex>> chains(const std::vector<Edge>& edges,
                                             const std::vector<glm::dvec2>& at2d) {
  std::map<VertexIndex, std::vector<std::size_t>> at;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    at[edges[i].a].push_back(i);
    at[edges[i].b].push_back(i);
  }
  auto other = [&](std::size_t e, VertexIndex v) {
    return edges[e].a == v ? edges[e].b : edges[e].a;
  };
  // partner[{v, e}]: the edge that continues e through v.
  std::map<std::pair<VertexIndex, std::size_t>, std::size_t> partner;
  for (const auto& [v, incident] : at) {
    if (incident.size() == 2) {
      partner[{v, incident[0]}] = incident[1];
      partner[{v, incident[1]}] = incident[0];
      continue;
    }
    if (incident.size() < 3) continue;
    // Greedy pairing by straightness: the pair whose directions out of v are most opposed first.
    struct Pair {
      double cosine;
      std::size_t e, f;
    };
    std::vector<Pair> pairs;
    for (std::size_t i = 0; i < incident.size(); ++i)
      for (std::size_t j = i + 1; j < incident.size(); ++j) {
        const glm::dvec2 u = at2d[other(incident[i], v)] - at2d[v];
        const glm::dvec2 w = at2d[other(incident[j], v)] - at2d[v];
        const double lengths = glm::length(u) * glm::length(w);
        if (lengths > 0.0) pairs.push_back({glm::dot(u, w) / lengths, incident[i], incident[j]});
      }
    std::sort(pairs.begin(), pairs.end(),
              [](const Pair& x, const Pair& y) { return x.cosine < y.cosine; });
    for (const Pair& pair : pairs)
      if (-pair.cosine >= kMaxRunOnTurnCos && !partner.count({v, pair.e}) &&
          !partner.count({v, pair.f})) {
        partner[{v, pair.e}] = pair.f;
        partner[{v, pair.f}] = pair.e;
      }
  }
  std::vector<char> used(edges.size(), 0);
  std::vector<std::vector<VertexIndex>> result;
  auto walk = [&](VertexIndex start, std::size_t first) {
    std::vector<VertexIndex> chain{start};
    VertexIndex v = start;
    std::size_t e = first;
    while (true) {
      used[e] = 1;
      v = other(e, v);
      chain.push_back(v);
      const auto next = partner.find({v, e});
      if (next == partner.end() || used[next->second]) break;
      e = next->second;
    }
    result.push_back(std::move(chain));
  };
  for (const auto& [v, incident] : at)
    for (std::size_t e : incident)
      if (!used[e] && !partner.count({v, e})) walk(v, e);
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (!used[e]) walk(edges[e].a, e);
  return result;
}

// Dashes of `cut` with `gap` between along a polyline, the pattern running on across its
// vertices; each dash follows the line through the vertices it passes (a chord would cut across
// a curved crease's bends), and only the line's last dash may be shorter.
std::vector<std::vector<glm::dvec2>> perforate(const std::vector<glm::dvec2>& line,
                                               const Perforation& p) {
  std::vector<std::vector<glm::dvec2>> dashes;
  bool cutting = true;
  double left = p.cutMm;  // of the current dash or gap
  std::vector<glm::dvec2> dash{line.front()};
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
      if (left <= kDashRoundingMm) {
        if (cutting) {
          dash.push_back(end);
          dashes.push_back(std::move(dash));
        }
        cutting = !cutting;
        left = cutting ? p.cutMm : p.gapMm;
        dash = {end};
      }
    }
    // The dash bends here with the line (not at its very start, which is already in it).
    if (cutting && i + 2 < line.size() && glm::distance(dash.back(), b) > kSamePointMm)
      dash.push_back(b);
  }
  // A last, shorter dash where the line ends inside one.
  if (cutting && glm::distance(dash.front(), line.back()) > kSamePointMm) {
    if (glm::distance(dash.back(), line.back()) > kSamePointMm) dash.push_back(line.back());
    dashes.push_back(std::move(dash));
  }
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
  const std::vector<DrawnEdge> drawn = drawnEdges(sheet, buildEdgeTopology(sheet));
  const std::vector<Edge> cut = edgesOf(drawn, {Assignment::Boundary, Assignment::Cut});
  const std::vector<Edge> mountain = edgesOf(drawn, {Assignment::Mountain});
  const std::vector<Edge> valley = edgesOf(drawn, {Assignment::Valley});
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
  std::vector<glm::dvec2> mm(sheet.development.size());
  for (std::size_t v = 0; v < mm.size(); ++v) mm[v] = toMm(static_cast<std::uint32_t>(v));
  std::vector<CutterLayer> layers{{"cut", kCutterCutColour, {}},
                                  {"mountain score", kCutterMountainScoreColour, {}},
                                  {"valley score", kCutterValleyScoreColour, {}}};
  // Perforations are cuts: a layer of their own (issue 28, 3), so the machine cuts them through
  // rather than scoring them with the creases.
  if (perforation) layers.push_back({"perforation", kCutterPerforationColour, {}});
  const std::vector<Edge>* sources[3] = {&cut, &mountain, &valley};
  for (int k = 0; k < 3; ++k)
    for (const std::vector<VertexIndex>& chain : chains(*sources[k], mm)) {
      std::vector<glm::dvec2> line;
      for (VertexIndex v : chain) line.push_back(mm[v]);
      if (k > 0 && perforation) {
        for (std::vector<glm::dvec2>& dash : perforate(line, *perforation))
          layers[3].polylines.push_back(std::move(dash));
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
