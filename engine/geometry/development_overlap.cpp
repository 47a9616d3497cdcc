#include "engine/geometry/development_overlap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include <glm/geometric.hpp>

#include "engine/geometry/topology.hpp"

namespace curvefold {
namespace {

double cross(const glm::dvec2& a, const glm::dvec2& b) {
  return a.x * b.y - a.y * b.x;
}

// Whether segments pq and rs cross at a point inside both, each endpoint clearly (beyond
// `tolerance`, an area) on its own side of the other segment.
bool crossProperly(const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& r,
                   const glm::dvec2& s, double tolerance) {
  const double r1 = cross(q - p, r - p), r2 = cross(q - p, s - p);
  const double p1 = cross(s - r, p - r), p2 = cross(s - r, q - r);
  return ((r1 > tolerance && r2 < -tolerance) || (r1 < -tolerance && r2 > tolerance)) &&
         ((p1 > tolerance && p2 < -tolerance) || (p1 < -tolerance && p2 > tolerance));
}

}  // namespace

std::optional<EdgeCrossing> findDevelopmentCrossing(const Sheet& sheet) {
  const EdgeTopology topology = buildEdgeTopology(sheet);
  const auto& edges = topology.edges;
  if (edges.size() < 2) return std::nullopt;
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  double totalLength = 0.0;
  for (const auto& sides : edges) {
    const glm::dvec2 a = sheet.development[sides.edge.a], b = sheet.development[sides.edge.b];
    lo = glm::min(lo, glm::min(a, b));
    hi = glm::max(hi, glm::max(a, b));
    totalLength += glm::distance(a, b);
  }
  const glm::dvec2 extent = hi - lo;
  const double size = glm::length(extent);
  if (!(size > 0.0)) return std::nullopt;
  // Cells about the mean edge length, but no more cells than a few per edge.
  double cell = std::max(totalLength / double(edges.size()), size / 4096.0);
  const auto columns = static_cast<std::int64_t>(std::floor(extent.x / cell)) + 1;
  const auto rows = static_cast<std::int64_t>(std::floor(extent.y / cell)) + 1;
  auto cellOf = [&](const glm::dvec2& p) {
    return glm::i64vec2(std::clamp<std::int64_t>(std::int64_t((p.x - lo.x) / cell), 0, columns - 1),
                        std::clamp<std::int64_t>(std::int64_t((p.y - lo.y) / cell), 0, rows - 1));
  };
  const double tolerance = 1e-12 * size * size;
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> grid;
  grid.reserve(edges.size() * 2);
  for (std::uint32_t e = 0; e < edges.size(); ++e) {
    const Edge edge = edges[e].edge;
    const glm::dvec2 a = sheet.development[edge.a], b = sheet.development[edge.b];
    // The cells the segment passes through, walked from a to b (Amanatides and Woo), with the
    // cells beside each step, so that rounding at a cell corner loses none.
    std::vector<std::int64_t> cells;
    const glm::i64vec2 start = cellOf(a), end = cellOf(b);
    const glm::dvec2 d = b - a;
    glm::i64vec2 at = start;
    const glm::i64vec2 step(d.x > 0 ? 1 : -1, d.y > 0 ? 1 : -1);
    auto boundary = [&](int axis, std::int64_t index) {
      return lo[axis] + double(index + (step[axis] > 0 ? 1 : 0)) * cell;
    };
    glm::dvec2 next(d.x != 0 ? (boundary(0, at.x) - a.x) / d.x : 2.0,
                    d.y != 0 ? (boundary(1, at.y) - a.y) / d.y : 2.0);
    const glm::dvec2 delta(d.x != 0 ? cell / std::abs(d.x) : 2.0,
                           d.y != 0 ? cell / std::abs(d.y) : 2.0);
    for (int guard = 0; guard < 4 * (columns + rows) + 8; ++guard) {
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
          const std::int64_t x = at.x + dx, y = at.y + dy;
          if (x >= 0 && x < columns && y >= 0 && y < rows) cells.push_back(y * columns + x);
        }
      if (at == end || (next.x > 1.0 && next.y > 1.0)) break;
      if (next.x < next.y) {
        at.x += step.x;
        next.x += delta.x;
      } else {
        at.y += step.y;
        next.y += delta.y;
      }
      at = glm::clamp(at, glm::i64vec2(0), glm::i64vec2(columns - 1, rows - 1));
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    for (std::int64_t index : cells) {
      std::vector<std::uint32_t>& here = grid[index];
      for (std::uint32_t other : here) {
        const Edge o = edges[other].edge;
        if (o.a == edge.a || o.a == edge.b || o.b == edge.a || o.b == edge.b) continue;
        if (crossProperly(a, b, sheet.development[o.a], sheet.development[o.b], tolerance))
          return EdgeCrossing{o, edge};
      }
      here.push_back(e);
    }
  }
  return std::nullopt;
}

}  // namespace curvefold
