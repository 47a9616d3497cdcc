#include "engine/geometry/surface_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include <glm/geometric.hpp>

#include "engine/geometry/validate.hpp"

namespace curvefold {
namespace {

// Closest point of triangle abc to p, as barycentric coordinates (Ericson, Real-Time Collision
// Detection, 5.1.5: Voronoi regions of the vertices, then the edges, then the face).
glm::dvec3 closestBarycentric(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                              const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1, 0, 0};
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denominator = 1.0 / (va + vb + vc);
  const double v = vb * denominator, w = vc * denominator;
  return {1 - v - w, v, w};
}

glm::dvec3 lift(const glm::dvec2& q) {
  return {q.x, q.y, 0.0};
}

std::string describe(const glm::dvec2& q) {
  std::ostringstream out;
  out.precision(17);
  out << "(" << q.x << ", " << q.y << ")";
  return out.str();
}

// Distance from q to segment uv and the parameter of its foot, clamped to [0, 1].
std::pair<double, double> segmentDistance(const glm::dvec2& q, const glm::dvec2& u,
                                          const glm::dvec2& v) {
  const glm::dvec2 d = v - u;
  const double t = std::clamp(glm::dot(q - u, d) / glm::dot(d, d), 0.0, 1.0);
  return {glm::distance(q, u + t * d), t};
}

}  // namespace

glm::dvec3 positionOf(const Sheet& sheet, const SurfacePoint& point) {
  const Triangle& t = sheet.triangles[point.triangle];
  return point.barycentric.x * sheet.positions[t[0]] + point.barycentric.y * sheet.positions[t[1]] +
         point.barycentric.z * sheet.positions[t[2]];
}

glm::dvec2 developmentOf(const Sheet& sheet, const SurfacePoint& point) {
  const Triangle& t = sheet.triangles[point.triangle];
  return point.barycentric.x * sheet.development[t[0]] +
         point.barycentric.y * sheet.development[t[1]] +
         point.barycentric.z * sheet.development[t[2]];
}

SurfacePoint closestPointOnTriangle(const Sheet& sheet, TriangleIndex triangle,
                                    const glm::dvec3& p) {
  const Triangle& tri = sheet.triangles[triangle];
  return {triangle, closestBarycentric(p, sheet.positions[tri[0]], sheet.positions[tri[1]],
                                       sheet.positions[tri[2]])};
}

bool withinReach(const glm::dvec3& p, const glm::dvec3& from, double sheetSize) {
  // Each coordinate first, so that no squared distance can overflow (NaN is out of reach too).
  const double reach = kRelativeMaxReach * sheetSize;
  const glm::dvec3 offset = glm::abs(p - from);
  return std::max({offset.x, offset.y, offset.z}) <= reach / 2.0 && glm::length(p - from) <= reach;
}

void checkWithinReach(const glm::dvec3& p, const glm::dvec3& from, double sheetSize,
                      const char* what) {
  const double reach = kRelativeMaxReach * sheetSize;
  if (withinReach(p, from, sheetSize)) return;
  std::ostringstream message;
  message.precision(6);
  message << what << " (" << p.x << ", " << p.y << ", " << p.z << ")";
  // A NaN lies nowhere: "too far" would name the wrong problem.
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    message << " is not a point: its coordinates must be finite numbers";
  else
    message << " lies too far from the sheet (more than " << reach
            << " m, a million times the sheet's size)";
  throw InvalidSheet(message.str());
}

SurfacePoint closestSurfacePoint(const Sheet& sheet, const glm::dvec3& p) {
  if (sheet.triangles.empty()) throw InvalidSheet("the sheet has no triangles to grab");
  checkWithinReach(p, sheet.positions[sheet.triangles[0][0]], sheetSize(sheet), "point");
  SurfacePoint best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (TriangleIndex t = 0; t < sheet.triangleCount(); ++t) {
    const Triangle& tri = sheet.triangles[t];
    const glm::dvec3 bary = closestBarycentric(p, sheet.positions[tri[0]], sheet.positions[tri[1]],
                                               sheet.positions[tri[2]]);
    const SurfacePoint candidate{t, bary};
    const glm::dvec3 offset = positionOf(sheet, candidate) - p;
    const double distance = glm::dot(offset, offset);
    if (distance < bestDistance) {
      bestDistance = distance;
      best = candidate;
    }
  }
  if (best.triangle == kNoIndex)
    throw InvalidSheet("no surface point is nearest (a NaN position?)");
  return best;
}

std::optional<SurfacePoint> locateDevelopmentPoint(const Sheet& sheet, const glm::dvec2& q,
                                                   double tolerance) {
  std::optional<SurfacePoint> best;
  double bestDistance = std::numeric_limits<double>::infinity();
  double bestInterior = -std::numeric_limits<double>::infinity();
  const glm::dvec3 target = lift(q);
  for (TriangleIndex t = 0; t < sheet.triangleCount(); ++t) {
    const Triangle& tri = sheet.triangles[t];
    const glm::dvec3 a = lift(sheet.development[tri[0]]), b = lift(sheet.development[tri[1]]),
                     c = lift(sheet.development[tri[2]]);
    const glm::dvec3 bary = closestBarycentric(target, a, b, c);
    const double distance = glm::distance(bary.x * a + bary.y * b + bary.z * c, target);
    if (distance > tolerance || distance > bestDistance) continue;
    // Among triangles containing q, prefer the one where q is farthest from the edges.
    const double interior = std::min({bary.x, bary.y, bary.z});
    if (distance < bestDistance || interior > bestInterior) {
      bestDistance = distance;
      bestInterior = interior;
      best = SurfacePoint{t, bary};
    }
  }
  return best;
}

std::vector<VertexIndex> verticesAtDevelopment(const Sheet& sheet,
                                               const std::vector<glm::dvec2>& points) {
  const double snap = kRelativeGrabSnap * sheetSize(sheet);
  std::vector<VertexIndex> found;
  for (const glm::dvec2& q : points) {
    VertexIndex nearest = kNoIndex;
    if (const std::optional<SurfacePoint> at = locateDevelopmentPoint(sheet, q, snap)) {
      double nearestDistance = snap;
      for (VertexIndex v : sheet.triangles[at->triangle]) {
        const double d = glm::distance(sheet.development[v], q);
        if (d <= nearestDistance) {
          nearest = v;
          nearestDistance = d;
        }
      }
    }
    if (nearest == kNoIndex)
      throw InvalidSheet("development point " + describe(q) + " is no vertex of the sheet");
    found.push_back(nearest);
  }
  return found;
}

namespace {

// Whether q lies inside triangle t farther than `margin` from each of its edges.
bool deepInside(const Sheet& sheet, TriangleIndex t, const glm::dvec2& q, double margin) {
  if (t >= sheet.triangleCount()) return false;
  const Triangle& tri = sheet.triangles[t];
  for (int i = 0; i < 3; ++i) {
    const glm::dvec2 u = sheet.development[tri[i]], w = sheet.development[tri[(i + 1) % 3]];
    const glm::dvec2 d = w - u;
    const double length = glm::length(d);
    // Counter-clockwise: the inside is on the left of each edge.
    if (length == 0.0 || (d.x * (q - u).y - d.y * (q - u).x) / length <= margin) return false;
  }
  return true;
}

// The triangle holding q: the hint when q lies deep inside it, else the located one.
TriangleIndex triangleHolding(const Sheet& sheet, const glm::dvec2& q, const InsertionHints& hints,
                              double snap) {
  if (deepInside(sheet, hints.triangle, q, snap)) return hints.triangle;
  const std::optional<SurfacePoint> located = locateDevelopmentPoint(sheet, q, snap);
  if (!located) throw InvalidSheet("development point " + describe(q) + " lies outside the sheet");
  return located->triangle;
}

// A corner of tri within snap distance of q (the nearest), else kNoIndex.
VertexIndex cornerWithin(const Sheet& sheet, const Triangle& tri, const glm::dvec2& q,
                         double snap) {
  VertexIndex nearest = kNoIndex;
  double nearestDistance = snap;
  for (VertexIndex v : tri) {
    const double d = glm::distance(sheet.development[v], q);
    if (d <= nearestDistance) {
      nearestDistance = d;
      nearest = v;
    }
  }
  return nearest;
}

void rewriteTriangle(Sheet& sheet, TriangleIndex k, const Triangle& replacement,
                     InsertionUndo* undo) {
  if (undo) undo->rewritten.emplace_back(k, sheet.triangles[k]);
  sheet.triangles[k] = replacement;
}

// A triangle holding an edge, the edge's direction in it and its third corner.
struct EdgeSplit {
  TriangleIndex triangle;
  VertexIndex from, to, apex;
};

// Each triangle holding the edge (u, w) in either direction: among the triangles around u when
// known (ascending, as the scan would meet them), else among every triangle.
std::vector<EdgeSplit> trianglesOnEdge(const Sheet& sheet, VertexIndex u, VertexIndex w,
                                       const InsertionHints& hints) {
  std::vector<TriangleIndex> candidates;
  if (hints.around) {
    const auto aroundU = hints.around->of(u);
    candidates.assign(aroundU.begin(), aroundU.end());
  } else {
    candidates.resize(sheet.triangleCount());
    std::iota(candidates.begin(), candidates.end(), TriangleIndex{0});
  }
  std::vector<EdgeSplit> splits;
  for (TriangleIndex k : candidates) {
    const Triangle& o = sheet.triangles[k];
    for (int j = 0; j < 3; ++j)
      if (Edge::of(o[j], o[(j + 1) % 3]) == Edge::of(u, w))
        splits.push_back({k, o[j], o[(j + 1) % 3], o[(j + 2) % 3]});
  }
  return splits;
}

// The tag of edge (u, w), if any, carried onto its halves (u, m) and (m, w).
void splitEdgeTag(Sheet& sheet, VertexIndex u, VertexIndex w, VertexIndex m, InsertionUndo* undo) {
  const std::optional<EdgeKind> kind = sheet.edgeKind(Edge::of(u, w));
  if (!kind) return;
  if (undo) {
    undo->tags = sheet.tags;
    undo->tagsChanged = true;
  }
  std::erase_if(sheet.tags, [&](const TaggedEdge& tag) { return tag.edge == Edge::of(u, w); });
  sheet.tags.push_back({Edge::of(u, m), *kind});
  sheet.tags.push_back({Edge::of(m, w), *kind});
  sheet.normalizeTags();
}

// An edge of tri within snap distance of q: split, and both of its triangles, at the point of it
// nearest q (or that point's nearer end, when a split would be thinner than `thinnest`); nothing
// when no edge is that near.
std::optional<VertexIndex> splitEdgeNear(Sheet& sheet, const Triangle& tri, const glm::dvec2& q,
                                         const InsertionHints& hints, double snap, double thinnest,
                                         InsertionUndo* undo) {
  const auto m = static_cast<VertexIndex>(sheet.vertexCount());
  for (int i = 0; i < 3; ++i) {
    const VertexIndex u = tri[i], w = tri[(i + 1) % 3];
    const auto [distance, s] = segmentDistance(q, sheet.development[u], sheet.development[w]);
    if (distance > snap) continue;
    const glm::dvec3 position = sheet.positions[u] + s * (sheet.positions[w] - sheet.positions[u]);
    const glm::dvec2 flat =
        sheet.development[u] + s * (sheet.development[w] - sheet.development[u]);
    // Each triangle holding the edge (u, w) in either direction becomes two.
    const std::vector<EdgeSplit> splits = trianglesOnEdge(sheet, u, w, hints);
    for (const EdgeSplit& split : splits) {
      const glm::dvec2 apex = sheet.development[split.apex];
      if (smallestHeight(sheet.development[split.from], flat, apex) < thinnest ||
          smallestHeight(flat, sheet.development[split.to], apex) < thinnest)
        return glm::distance(q, sheet.development[u]) <= glm::distance(q, sheet.development[w]) ? u
                                                                                                : w;
    }
    sheet.positions.push_back(position);
    sheet.development.push_back(flat);
    for (const EdgeSplit& split : splits) {
      rewriteTriangle(sheet, split.triangle, {split.from, m, split.apex}, undo);
      sheet.triangles.push_back({m, split.to, split.apex});
    }
    splitEdgeTag(sheet, u, w, m, undo);
    return m;
  }
  return std::nullopt;
}

// Inside triangle t (tri): three triangles around the new vertex, with barycentric coordinates
// from the development so the 3D point is the same point of the paper; the nearest corner when
// one of them would be thinner than `thinnest`.
VertexIndex splitTriangleAt(Sheet& sheet, TriangleIndex t, const Triangle& tri, const glm::dvec2& q,
                            double thinnest, InsertionUndo* undo) {
  const glm::dvec2 a = sheet.development[tri[0]], b = sheet.development[tri[1]],
                   c = sheet.development[tri[2]];
  if (smallestHeight(a, b, q) < thinnest || smallestHeight(b, c, q) < thinnest ||
      smallestHeight(c, a, q) < thinnest) {
    VertexIndex best = tri[0];
    for (VertexIndex v : tri)
      if (glm::distance(sheet.development[v], q) < glm::distance(sheet.development[best], q))
        best = v;
    return best;
  }
  const auto m = static_cast<VertexIndex>(sheet.vertexCount());
  const double area = (b - a).x * (c - a).y - (b - a).y * (c - a).x;
  const double wb = ((q - a).x * (c - a).y - (q - a).y * (c - a).x) / area;
  const double wc = ((b - a).x * (q - a).y - (b - a).y * (q - a).x) / area;
  const double wa = 1.0 - wb - wc;
  sheet.positions.push_back(wa * sheet.positions[tri[0]] + wb * sheet.positions[tri[1]] +
                            wc * sheet.positions[tri[2]]);
  sheet.development.push_back(q);
  rewriteTriangle(sheet, t, {tri[0], tri[1], m}, undo);
  sheet.triangles.push_back({tri[1], tri[2], m});
  sheet.triangles.push_back({tri[2], tri[0], m});
  return m;
}

}  // namespace

VertexIndex insertVertexInPlace(Sheet& sheet, const glm::dvec2& q, InsertionUndo* undo,
                                const InsertionHints& hints) {
  const double size = hints.sheetSize > 0.0 ? hints.sheetSize : sheetSize(sheet);
  const double snap = kRelativeGrabSnap * size;
  // Nothing thinner than this is made: a point that would make it grabs the triangle's nearest
  // corner instead (a point inside a thin triangle, next to one of its sharp corners).
  const double thinnest = kRelativeCutFeatureSize * size;
  const TriangleIndex t = triangleHolding(sheet, q, hints, snap);
  const Triangle tri = sheet.triangles[t];
  if (undo) *undo = {sheet.vertexCount(), sheet.triangleCount(), {}, {}, false};
  // An existing vertex within snap distance, else an edge within it, else inside the triangle.
  if (const VertexIndex corner = cornerWithin(sheet, tri, q, snap); corner != kNoIndex)
    return corner;
  if (const std::optional<VertexIndex> onEdge =
          splitEdgeNear(sheet, tri, q, hints, snap, thinnest, undo))
    return *onEdge;
  return splitTriangleAt(sheet, t, tri, q, thinnest, undo);
}

void undoInsertion(Sheet& sheet, const InsertionUndo& undo) {
  for (auto it = undo.rewritten.rbegin(); it != undo.rewritten.rend(); ++it)
    sheet.triangles[it->first] = it->second;
  sheet.positions.resize(undo.vertexCount);
  sheet.development.resize(undo.vertexCount);
  sheet.triangles.resize(undo.triangleCount);
  if (undo.tagsChanged) sheet.tags = undo.tags;
}

namespace {

// Compressed rows from `old` with some rows replaced (`rows`, ascending by vertex; every vertex
// at or past the old row count among them): unchanged runs are copied whole, their offsets moved.
template <typename Value>
void patchRows(const std::vector<std::uint32_t>& oldOffsets, const std::vector<Value>& oldValues,
               std::size_t rowCount,
               const std::vector<std::pair<VertexIndex, std::vector<Value>>>& rows,
               std::vector<std::uint32_t>& offsets, std::vector<Value>& values) {
  offsets.resize(rowCount + 1);
  offsets[0] = 0;
  values.clear();
  values.reserve(oldValues.size() + 16 * rows.size());
  auto copyRun = [&](VertexIndex from, VertexIndex to) {  // rows [from, to), all old ones
    if (from >= to) return;
    const std::uint32_t start = oldOffsets[from];
    const std::int64_t shift = static_cast<std::int64_t>(values.size()) - start;
    values.insert(values.end(), oldValues.begin() + start, oldValues.begin() + oldOffsets[to]);
    for (VertexIndex v = from; v < to; ++v)
      offsets[v + 1] = static_cast<std::uint32_t>(oldOffsets[v + 1] + shift);
  };
  VertexIndex next = 0;
  for (const auto& [v, row] : rows) {
    copyRun(next, v);
    values.insert(values.end(), row.begin(), row.end());
    offsets[v + 1] = static_cast<std::uint32_t>(values.size());
    next = v + 1;
  }
  copyRun(next, static_cast<VertexIndex>(rowCount));
}

}  // namespace

void adjacencyAfterInsertion(const SheetAdjacency& before, const Sheet& sheet,
                             const InsertionUndo& undo, SheetAdjacency& out) {
  // Touched: every corner of a rewritten triangle, before and after, and of a new triangle.
  std::vector<VertexIndex> touched;
  std::vector<TriangleIndex> changed;
  for (const auto& [t, old] : undo.rewritten) {
    changed.push_back(t);
    touched.insert(touched.end(), old.begin(), old.end());
    touched.insert(touched.end(), sheet.triangles[t].begin(), sheet.triangles[t].end());
  }
  for (std::size_t t = undo.triangleCount; t < sheet.triangleCount(); ++t) {
    changed.push_back(static_cast<TriangleIndex>(t));
    touched.insert(touched.end(), sheet.triangles[t].begin(), sheet.triangles[t].end());
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());

  std::vector<std::pair<VertexIndex, std::vector<TriangleIndex>>> triangleRows;
  std::vector<std::pair<VertexIndex, std::vector<VertexIndex>>> neighborRows;
  for (VertexIndex v : touched) {
    std::vector<TriangleIndex> row;
    if (v < undo.vertexCount) {
      const auto old = before.triangles.of(v);
      row.assign(old.begin(), old.end());
    }
    row.insert(row.end(), changed.begin(), changed.end());
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    std::erase_if(row, [&](TriangleIndex t) {
      const Triangle& tri = sheet.triangles[t];
      return tri[0] != v && tri[1] != v && tri[2] != v;
    });
    std::vector<VertexIndex> neighbors;
    for (TriangleIndex t : row)
      for (VertexIndex w : sheet.triangles[t])
        if (w != v) neighbors.push_back(w);
    std::sort(neighbors.begin(), neighbors.end());
    neighbors.erase(std::unique(neighbors.begin(), neighbors.end()), neighbors.end());
    triangleRows.emplace_back(v, std::move(row));
    neighborRows.emplace_back(v, std::move(neighbors));
  }
  patchRows(before.triangles.offsets, before.triangles.triangles, sheet.vertexCount(), triangleRows,
            out.triangles.offsets, out.triangles.triangles);
  patchRows(before.neighbors.offsets, before.neighbors.vertices, sheet.vertexCount(), neighborRows,
            out.neighbors.offsets, out.neighbors.vertices);
}

VertexInsertion insertVertexAt(const Sheet& sheet, const glm::dvec2& q) {
  VertexInsertion result{sheet, kNoIndex};
  result.vertex = insertVertexInPlace(result.sheet, q, nullptr);
  return result;
}

}  // namespace curvefold
