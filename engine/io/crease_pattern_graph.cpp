#include "engine/io/crease_pattern_graph.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <queue>
#include <unordered_map>
#include <unordered_set>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include "engine/io/input_limits.hpp"
#include "engine/io/json_reader.hpp"

namespace curvefold {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  int region = -1;
  int triangle = -1;
};
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<
    Kernel, CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Constraints that cross throw (no point is ever constructed, so every vertex is one of ours); a
// constraint through a vertex is split there, and the pieces are found again by walking along it.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
    Kernel, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;

std::uint64_t pairKey(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(a) << 32) | b;
}

double cross(glm::dvec2 a, glm::dvec2 b) {
  return a.x * b.y - a.y * b.x;
}

// Which of two lines on the same place a repeated line keeps.
int strength(CreaseAssignment assignment) {
  switch (assignment) {
    case CreaseAssignment::Boundary:
      return 5;
    case CreaseAssignment::Cut:
      return 4;
    case CreaseAssignment::Mountain:
    case CreaseAssignment::Valley:
      return 3;
    case CreaseAssignment::Unassigned:
      return 2;
    case CreaseAssignment::Flat:
      return 1;
  }
  return 0;
}

std::string lineName(const CreaseDrawing& drawing, std::size_t line) {
  if (line < drawing.lineNames.size() && !drawing.lineNames[line].empty())
    return drawing.lineNames[line];
  return "edge " + std::to_string(line);
}

std::string point(glm::dvec2 p) {
  return "(" + shortestDouble(p.x) + ", " + shortestDouble(p.y) + ")";
}

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Points within `tolerance` of each other, found through a hash grid of that cell size.
class PointSnapper {
 public:
  PointSnapper(glm::dvec2 origin, double cell) : origin_(origin), cell_(cell) {}

  // The index of a kept point within tolerance of p, or keeps p under `index` and returns it.
  std::uint32_t snap(glm::dvec2 p, std::uint32_t index, std::vector<glm::dvec2>& kept) {
    const auto [ix, iy] = cellOf(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto found = cells_.find(key(ix + dx, iy + dy));
        if (found == cells_.end()) continue;
        for (std::uint32_t other : found->second) {
          const glm::dvec2 d = kept[other] - p;
          if (d.x * d.x + d.y * d.y <= cell_ * cell_) return other;
        }
      }
    cells_[key(ix, iy)].push_back(index);
    return index;
  }

 private:
  std::pair<std::int64_t, std::int64_t> cellOf(glm::dvec2 p) const {
    return {static_cast<std::int64_t>(std::floor((p.x - origin_.x) / cell_)),
            static_cast<std::int64_t>(std::floor((p.y - origin_.y) / cell_))};
  }
  static std::uint64_t key(std::int64_t x, std::int64_t y) {
    return (static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull) ^ static_cast<std::uint64_t>(y);
  }
  glm::dvec2 origin_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

// Far above any real pattern; they bound the work a hostile file can ask of the crossing search.
constexpr std::uint64_t kMaxCrossingCellVisits = 64ull << 20;
constexpr std::uint64_t kMaxCrossingPairTests = 256ull << 20;

struct Split {
  double t;
  std::uint32_t vertex;
};

// The region on a curve's concave side, bounded by that curve alone (the inside of an SVG circle
// or ellipse, drawn as 64 segments), is triangulated by the constrained Delaunay triangulation
// from the curve's own points: a fan of lenses, each a triangle on three points of the curve
// whose height is the curve's sagitta over two or three segments (0.2 mm on a 16 mm circle of
// 1.6 mm segments). Folded, the curve shortens by more than that height allows and such a
// triangle collapses flat in 3D (a height of 5e-14 m), its hinges' levers 1 / height: the static
// solver's residual stood at 1e5 to 1e8 (NOT settled). Every paper region that holds such a
// triangle (all three corners on one smooth chain of lines: degree-2 vertices whose lines keep
// their assignment and angle and turn by less than kSmoothTurnDegrees) gets a triangular lattice
// of points, kLatticeSpacing times its lines' median length apart (1 tripled the iterations'
// CPU for settled energies within 0.2 to 4%), none nearer than half a spacing to its lines,
// so its triangles reach across it. Regions without such a triangle are left as they are,
// bit for bit. Returns the points added (appended to vertices, numbered after them).
constexpr double kSmoothTurnDegrees = 30.0;
constexpr std::size_t kMaxAddedPoints = 200'000;
constexpr double kLatticeSpacing = 2.0;  // times the median length of the region's lines

std::size_t addPointsInsideCurves(Cdt& cdt, std::vector<glm::dvec2>& vertices,
                                  const std::vector<CreaseLine>& lines,
                                  const std::unordered_map<std::uint64_t, std::uint32_t>& lineOf,
                                  const std::vector<char>& paper) {
  // Constrained neighbours of each vertex, with their line.
  std::unordered_map<std::uint32_t, std::vector<std::pair<std::uint32_t, std::uint32_t>>> around;
  for (const auto& [key, line] : lineOf) {
    const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key);
    around[a].push_back({b, line});
    around[b].push_back({a, line});
  }
  const double cosTurn = std::cos(kSmoothTurnDegrees * std::numbers::pi / 180.0);
  std::unordered_set<std::uint32_t> smooth;
  for (const auto& [v, spokes] : around) {
    if (spokes.size() != 2) continue;
    const CreaseLine& p = lines[spokes[0].second];
    const CreaseLine& q = lines[spokes[1].second];
    if (p.assignment != q.assignment || p.foldAngleDegrees != q.foldAngleDegrees) continue;
    const glm::dvec2 in = vertices[v] - vertices[spokes[0].first];
    const glm::dvec2 out = vertices[spokes[1].first] - vertices[v];
    const double lengths = std::sqrt(glm::dot(in, in) * glm::dot(out, out));
    if (lengths > 0.0 && glm::dot(in, out) >= cosTurn * lengths) smooth.insert(v);
  }
  if (smooth.empty()) return 0;
  // Chains: smooth vertices joined by their lines.
  std::unordered_map<std::uint32_t, std::uint32_t> chain;
  for (std::uint32_t v : smooth) chain[v] = v;
  const auto root = [&](std::uint32_t v) {
    while (chain[v] != v) v = chain[v] = chain[chain[v]];
    return v;
  };
  for (std::uint32_t v : smooth)
    for (const auto& spoke : around[v])
      if (smooth.count(spoke.first)) {
        const std::uint32_t a = root(v), b = root(spoke.first);
        if (a != b) chain[std::max(a, b)] = std::min(a, b);
      }
  std::vector<char> refine(paper.size(), 0);
  for (Cdt::Face_handle face : cdt.finite_face_handles()) {
    if (!paper[face->info().region]) continue;
    bool lens = true;
    for (int k = 0; k < 3 && lens; ++k) lens = smooth.count(face->vertex(k)->info()) > 0;
    if (lens)
      lens = root(face->vertex(0)->info()) == root(face->vertex(1)->info()) &&
             root(face->vertex(0)->info()) == root(face->vertex(2)->info());
    if (lens) refine[face->info().region] = 1;
  }
  // Each such region's lines (as segments), bounding box and a face, in the faces' order.
  struct Region {
    std::vector<std::pair<glm::dvec2, glm::dvec2>> sides;
    glm::dvec2 low{INFINITY}, high{-INFINITY};
    Cdt::Face_handle inside;
  };
  std::map<int, Region> regions;
  for (Cdt::Face_handle face : cdt.finite_face_handles()) {
    if (!refine[face->info().region]) continue;
    Region& r = regions[face->info().region];
    r.inside = face;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec2 p = vertices[face->vertex(k)->info()];
      r.low = glm::min(r.low, p);
      r.high = glm::max(r.high, p);
      if (cdt.is_constrained({face, k}))
        r.sides.push_back({vertices[face->vertex(Cdt::ccw(k))->info()],
                           vertices[face->vertex(Cdt::cw(k))->info()]});
    }
  }
  std::size_t added = 0;
  for (auto& [region, r] : regions) {
    const auto& sides = r.sides;
    const glm::dvec2 low = r.low, high = r.high;
    const Cdt::Face_handle inside = r.inside;
    if (sides.empty()) continue;
    std::vector<double> lengths;
    for (const auto& [a, b] : sides) lengths.push_back(glm::distance(a, b));
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    double spacing = kLatticeSpacing * lengths[lengths.size() / 2];
    const glm::dvec2 size = high - low;
    // Within the budget of points (a region far larger than its lines' spacing).
    const double rows = size.y / (spacing * 0.8660254037844386);
    if (!(spacing > 0.0) || !std::isfinite(rows)) continue;
    const double wanted = (size.x / spacing + 1.0) * (rows + 1.0);
    const double budget = static_cast<double>(kMaxAddedPoints - std::min(added, kMaxAddedPoints));
    if (wanted > budget) spacing *= std::sqrt(wanted / std::max(budget, 1.0));
    // Sides bucketed by cells of the spacing, each in the cells its box (grown by half a spacing)
    // meets, for the clearance test.
    const double cell = spacing;
    const auto columns = static_cast<std::int64_t>(std::floor(size.x / cell)) + 1;
    std::unordered_map<std::int64_t, std::vector<std::uint32_t>> buckets;
    const auto cellOf = [&](double x, double y) {
      const auto i = static_cast<std::int64_t>(std::floor((x - low.x) / cell));
      const auto j = static_cast<std::int64_t>(std::floor((y - low.y) / cell));
      return std::pair{i, j};
    };
    for (std::uint32_t s = 0; s < sides.size(); ++s) {
      const auto [a, b] = sides[s];
      const auto [i0, j0] =
          cellOf(std::min(a.x, b.x) - 0.5 * spacing, std::min(a.y, b.y) - 0.5 * spacing);
      const auto [i1, j1] =
          cellOf(std::max(a.x, b.x) + 0.5 * spacing, std::max(a.y, b.y) + 0.5 * spacing);
      for (std::int64_t j = j0; j <= j1; ++j)
        for (std::int64_t i = i0; i <= i1; ++i) buckets[j * (columns + 2) + i].push_back(s);
    }
    const auto clear = [&](glm::dvec2 p) {
      const auto [i, j] = cellOf(p.x, p.y);
      const auto found = buckets.find(j * (columns + 2) + i);
      if (found == buckets.end()) return true;
      for (std::uint32_t s : found->second) {
        const auto [a, b] = sides[s];
        const glm::dvec2 ab = b - a;
        const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
        if (glm::distance(p, a + t * ab) < 0.5 * spacing) return false;
      }
      return true;
    };
    const double rise = spacing * 0.8660254037844386;
    Cdt::Face_handle hint = inside;
    for (std::int64_t j = 1; low.y + j * rise < high.y; ++j)
      for (std::int64_t i = 0; low.x + (i + 0.5 * (j % 2)) * spacing < high.x; ++i) {
        if (added >= kMaxAddedPoints) return added;
        const glm::dvec2 p(
            low.x + (static_cast<double>(i) + 0.5 * static_cast<double>(j % 2)) * spacing,
            low.y + static_cast<double>(j) * rise);
        const Kernel::Point_2 point(p.x, p.y);
        Cdt::Locate_type type;
        int index = 0;
        const Cdt::Face_handle face = cdt.locate(point, type, index, hint);
        if (type != Cdt::FACE || cdt.is_infinite(face) || face->info().region != region ||
            !clear(p))
          continue;
        const Cdt::Vertex_handle handle = cdt.insert(point, face);
        handle->info() = static_cast<std::uint32_t>(vertices.size());
        vertices.push_back(p);
        // The new faces belong to the region (classify() numbers them again after).
        auto incident = cdt.incident_faces(handle), done = incident;
        do {
          incident->info().region = region;
        } while (++incident != done);
        hint = handle->face();
        ++added;
      }
  }
  return added;
}

}  // namespace

char foldLetter(CreaseAssignment assignment) {
  constexpr char letters[] = {'B', 'M', 'V', 'F', 'U', 'C'};
  return letters[static_cast<int>(assignment)];
}

const char* assignmentName(CreaseAssignment assignment) {
  constexpr const char* names[] = {"boundary", "mountain", "valley", "flat", "unassigned", "cut"};
  return names[static_cast<int>(assignment)];
}

void planarize(CreaseDrawing& drawing, const PlanarizeOptions& options) {
  auto& vertices = drawing.vertices;
  const std::size_t vertexCount = vertices.size();
  for (std::size_t i = 0; i < drawing.lines.size(); ++i) {
    const CreaseLine& line = drawing.lines[i];
    if (line.a >= vertexCount || line.b >= vertexCount)
      throw CreasePatternError(lineName(drawing, i) + ": vertex index out of range");
  }
  if (drawing.lines.empty()) throw CreasePatternError("no lines: the pattern is empty");
  glm::dvec2 low(INFINITY), high(-INFINITY);
  for (const CreaseLine& line : drawing.lines)
    for (std::uint32_t v : {line.a, line.b}) {
      if (!std::isfinite(vertices[v].x) || !std::isfinite(vertices[v].y))
        throw CreasePatternError("vertex " + std::to_string(v) + " is not a finite point");
      low = glm::min(low, vertices[v]);
      high = glm::max(high, vertices[v]);
    }
  const glm::dvec2 size = high - low;
  const double diagonal = std::sqrt(size.x * size.x + size.y * size.y);
  if (!(diagonal > 0.0) || !std::isfinite(diagonal))
    throw CreasePatternError(diagonal > 0.0
                                 ? "coordinates too large to measure (over 1e308)"
                                 : "the pattern has no extent: every line has length zero");
  // The floor keeps the snapping grid's cell count within 64-bit keys.
  const double tolerance = std::max(options.relativeSnap, 1e-12) * diagonal;

  // 1. One point for points within the tolerance; a note says how many merged.
  std::vector<std::uint32_t> snapped(vertexCount, UINT32_MAX);
  PointSnapper snapper(low, tolerance);
  std::size_t merged = 0;
  const double noteFloor = options.noteCoincidentPoints ? -1.0 : 1e-9 * diagonal;
  for (CreaseLine& line : drawing.lines)
    for (std::uint32_t* v : {&line.a, &line.b}) {
      if (snapped[*v] == UINT32_MAX) {
        snapped[*v] = snapper.snap(vertices[*v], *v, vertices);
        const glm::dvec2 moved = vertices[snapped[*v]] - vertices[*v];
        merged += snapped[*v] != *v && std::hypot(moved.x, moved.y) > noteFloor;
      }
      *v = snapped[*v];
    }
  for (auto& face : drawing.faces) {
    for (std::uint32_t& v : face) {
      if (v >= vertexCount) throw CreasePatternError("a face's vertex index is out of range");
      if (snapped[v] == UINT32_MAX) snapped[v] = snapper.snap(vertices[v], v, vertices);
      v = snapped[v];
    }
    face.erase(std::unique(face.begin(), face.end()), face.end());
    while (face.size() > 1 && face.front() == face.back()) face.pop_back();
  }
  if (merged > 0)
    drawing.notes.push_back(std::to_string(merged) + " vertices within " +
                            shortestDouble(tolerance) + " of another were merged with it");

  // 2. Crossings and touches, found among the lines that share a cell of a grid, and the lines
  // split there. A crossing snapped to a nearby vertex bends its lines a little, which can make
  // new crossings within the tolerance of that vertex: rounds repeat until none is left.
  std::size_t zeroLength = 0, repeated = 0, conflicting = 0, crossingVertices = 0;
  for (int round = 0;; ++round) {
    std::vector<std::vector<Split>> splits(drawing.lines.size());
    std::size_t splitCount = 0;
    const std::size_t lineCount = drawing.lines.size();
    const double cell =
        std::max(diagonal / std::ceil(std::sqrt(static_cast<double>(lineCount))), 4.0 * tolerance);
    const auto cellsOf = [&](const CreaseLine& line, std::vector<std::uint64_t>& keys) {
      // Samples every half cell, each with its 3 x 3 neighbourhood: two lines within the tolerance
      // of each other have samples less than a cell apart, so they share a cell.
      keys.clear();
      const glm::dvec2 p = vertices[line.a], q = vertices[line.b];
      const double length = std::hypot(q.x - p.x, q.y - p.y);
      const std::size_t samples = static_cast<std::size_t>(std::ceil(length / (0.5 * cell))) + 1;
      for (std::size_t s = 0; s <= samples; ++s) {
        const glm::dvec2 at = p + (q - p) * (static_cast<double>(s) / static_cast<double>(samples));
        const auto ix = static_cast<std::int64_t>(std::floor((at.x - low.x) / cell));
        const auto iy = static_cast<std::int64_t>(std::floor((at.y - low.y) / cell));
        for (std::int64_t dx = -1; dx <= 1; ++dx)
          for (std::int64_t dy = -1; dy <= 1; ++dy)
            keys.push_back((static_cast<std::uint64_t>(ix + dx + 1) << 32) |
                           static_cast<std::uint32_t>(iy + dy + 1));
      }
      std::sort(keys.begin(), keys.end());
      keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    };
    std::vector<std::pair<std::uint64_t, std::uint32_t>> registry;
    std::vector<std::uint64_t> keys;
    for (std::uint32_t i = 0; i < lineCount; ++i) {
      if (drawing.lines[i].a == drawing.lines[i].b) continue;
      cellsOf(drawing.lines[i], keys);
      if (registry.size() + keys.size() > kMaxCrossingCellVisits)
        throw CreasePatternError("too many long lines to check for crossings (more than " +
                                 std::to_string(kMaxCrossingCellVisits >> 20) + "M grid cells)");
      for (std::uint64_t key : keys) registry.emplace_back(key, i);
    }
    std::sort(registry.begin(), registry.end());
    std::vector<std::uint32_t> testedWith(lineCount, UINT32_MAX);
    std::uint64_t pairTests = 0;
    // Where point p lies on segment (s, e): its parameter, or a negative number when it is not
    // within the tolerance of the segment's inside.
    const auto onInside = [&](glm::dvec2 p, glm::dvec2 s, glm::dvec2 e) {
      const glm::dvec2 d = e - s;
      const double length2 = d.x * d.x + d.y * d.y;
      const double t = ((p.x - s.x) * d.x + (p.y - s.y) * d.y) / length2;
      const double length = std::sqrt(length2);
      if (t * length <= tolerance || (1.0 - t) * length <= tolerance) return -1.0;
      const glm::dvec2 foot = s + d * t;
      return std::hypot(p.x - foot.x, p.y - foot.y) <= tolerance ? t : -1.0;
    };
    for (std::uint32_t i = 0; i < lineCount; ++i) {
      const CreaseLine li = drawing.lines[i];
      if (li.a == li.b) continue;
      cellsOf(li, keys);
      for (std::uint64_t key : keys) {
        auto it = std::lower_bound(registry.begin(), registry.end(), std::make_pair(key, 0u));
        for (; it != registry.end() && it->first == key; ++it) {
          const std::uint32_t j = it->second;
          if (j <= i || testedWith[j] == i) continue;
          testedWith[j] = i;
          if (++pairTests > kMaxCrossingPairTests)
            throw CreasePatternError("too many lines meet in one place to check for crossings");
          const CreaseLine lj = drawing.lines[j];
          const glm::dvec2 p0 = vertices[li.a], p1 = vertices[li.b];
          const glm::dvec2 q0 = vertices[lj.a], q1 = vertices[lj.b];
          bool touched = false;
          // An end of one line on the inside of the other.
          const std::pair<std::uint32_t, std::uint32_t> ends[] = {
              {li.a, j}, {li.b, j}, {lj.a, i}, {lj.b, i}};
          for (const auto& [vertex, other] : ends) {
            const CreaseLine& lo = drawing.lines[other];
            if (vertex == lo.a || vertex == lo.b) continue;
            const double t = onInside(vertices[vertex], vertices[lo.a], vertices[lo.b]);
            if (t < 0.0) continue;
            touched = true;
            if (options.strict)
              throw CreasePatternError(lineName(drawing, other) + " passes through vertex " +
                                       std::to_string(vertex) + " " + point(vertices[vertex]) +
                                       " without ending there");
            splits[other].push_back({t, vertex});
            ++splitCount;
          }
          if (touched || li.a == lj.a || li.a == lj.b || li.b == lj.a || li.b == lj.b) continue;
          const double d1 = cross(p1 - p0, q0 - p0), d2 = cross(p1 - p0, q1 - p0);
          const double d3 = cross(q1 - q0, p0 - q0), d4 = cross(q1 - q0, p1 - q0);
          if (!((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0))) continue;
          if (!((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) continue;
          const double t = d3 / (d3 - d4), u = d1 / (d1 - d2);
          const glm::dvec2 at = p0 + (p1 - p0) * t;
          if (options.strict)
            throw CreasePatternError(lineName(drawing, i) + " and " + lineName(drawing, j) +
                                     " cross at " + point(at) + " without a vertex");
          const auto index = static_cast<std::uint32_t>(vertices.size());
          vertices.push_back(at);
          const std::uint32_t vertex = snapper.snap(at, index, vertices);
          if (vertex != index)
            vertices.pop_back();
          else
            ++crossingVertices;
          splits[i].push_back({t, vertex});
          splits[j].push_back({u, vertex});
          splitCount += 2;
        }
      }
      if (crossingVertices > kMaxCreasePatternVertices)
        throw CreasePatternError("more than " + std::to_string(kMaxCreasePatternVertices) +
                                 " crossings of lines");
    }

    // 3. Lines cut at their splits; zero-length pieces dropped, repeats merged.
    std::vector<CreaseLine> lines;
    std::vector<std::string> names;
    std::unordered_map<std::uint64_t, std::uint32_t> byEnds;
    // `whole`: the line as the file gave it. A piece of zero length between two splits at one
    // vertex (lines crossing where a third ends) is the splitting's own, and dropped silently.
    const auto add = [&](CreaseLine line, std::size_t source, bool whole) {
      if (line.a == line.b) {
        if (whole && round == 0) ++zeroLength;
        return;
      }
      if (line.a > line.b) std::swap(line.a, line.b);
      const auto [found, inserted] = byEnds.try_emplace(pairKey(line.a, line.b), lines.size());
      if (!inserted) {
        ++repeated;
        CreaseLine& kept = lines[found->second];
        if (kept.assignment != line.assignment || kept.foldAngleDegrees != line.foldAngleDegrees)
          ++conflicting;
        if (strength(line.assignment) > strength(kept.assignment)) kept = line;
        return;
      }
      if (lines.size() >= kMaxCreasePatternEdges)
        throw CreasePatternError("more than " + std::to_string(kMaxCreasePatternEdges) +
                                 " edges after splitting lines where they cross");
      lines.push_back(line);
      if (!drawing.lineNames.empty()) names.push_back(lineName(drawing, source));
    };
    for (std::size_t i = 0; i < lineCount; ++i) {
      auto& cuts = splits[i];
      std::sort(cuts.begin(), cuts.end(), [](const Split& x, const Split& y) { return x.t < y.t; });
      CreaseLine piece = drawing.lines[i];
      std::uint32_t from = piece.a;
      for (const Split& cut : cuts) {
        piece.a = from;
        piece.b = cut.vertex;
        add(piece, i, false);
        from = cut.vertex;
      }
      piece.a = from;
      piece.b = drawing.lines[i].b;
      add(piece, i, cuts.empty());
    }
    drawing.lines = std::move(lines);
    drawing.lineNames = std::move(names);
    if (splitCount == 0 || options.strict) break;
    if (round == 8) throw CreasePatternError("lines still cross after 8 rounds of splitting them");
  }
  if (zeroLength > 0)
    drawing.notes.push_back(std::to_string(zeroLength) + " lines of length zero were dropped");
  if (repeated > 0)
    drawing.notes.push_back(std::to_string(repeated) + " repeated lines were merged" +
                            (conflicting > 0 ? " (" + std::to_string(conflicting) +
                                                   " disagreed; the stronger assignment kept)"
                                             : ""));
  if (drawing.lines.empty()) throw CreasePatternError("no lines: every line has length zero");
}

CreasePattern triangulateCreaseDrawing(const CreaseDrawing& drawing,
                                       const TriangulateOptions& options) {
  CreasePattern pattern;
  pattern.notes = drawing.notes;
  // A copy: points added inside curves' regions (below) are appended.
  std::vector<glm::dvec2> vertices = drawing.vertices;
  std::vector<char> used(vertices.size(), 0);
  for (const CreaseLine& line : drawing.lines) used[line.a] = used[line.b] = 1;
  for (const auto& face : drawing.faces)
    for (std::uint32_t v : face) used.at(v) = 1;

  // Points in a spatially coherent order, each located from the last. The order decides the
  // triangulation where Delaunay is not unique (four points on a circle), so it must not vary:
  // spatial_sort shuffles with a fixed-seed rand48 of its own, the same on every call.
  std::vector<std::uint32_t> order;
  for (std::uint32_t v = 0; v < vertices.size(); ++v)
    if (used[v]) order.push_back(v);
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles(vertices.size());
  {
    std::vector<Kernel::Point_2> points;
    points.reserve(order.size());
    for (std::uint32_t v : order) points.emplace_back(vertices[v].x, vertices[v].y);
    std::vector<std::size_t> sorted(order.size());
    std::iota(sorted.begin(), sorted.end(), std::size_t{0});
    using SortTraits =
        CGAL::Spatial_sort_traits_adapter_2<Kernel,
                                            CGAL::Pointer_property_map<Kernel::Point_2>::type>;
    CGAL::spatial_sort(sorted.begin(), sorted.end(), SortTraits(CGAL::make_property_map(points)));
    Cdt::Face_handle hint;
    for (std::size_t k : sorted) {
      const std::size_t before = cdt.number_of_vertices();
      const Cdt::Vertex_handle handle = cdt.insert(points[k], hint);
      if (cdt.number_of_vertices() == before)
        throw CreasePatternError("vertices " + std::to_string(handle->info()) + " and " +
                                 std::to_string(order[k]) + " are at the same place");
      handle->info() = order[k];
      handles[order[k]] = handle;
      hint = handle->face();
    }
  }
  std::unordered_map<std::uint64_t, std::uint32_t> lineOf;
  for (std::uint32_t i = 0; i < drawing.lines.size(); ++i) {
    const CreaseLine& line = drawing.lines[i];
    try {
      cdt.insert_constraint(handles[line.a], handles[line.b]);
    } catch (const Cdt::Intersection_of_constraints_exception&) {
      throw CreasePatternError(lineName(drawing, i) +
                               " crosses another edge without a vertex (or nearly)");
    }
    lineOf.emplace(pairKey(line.a, line.b), i);
  }
  // A line through other vertices: its pieces, walked from a to b along constrained edges.
  std::vector<CreaseLine> lines = drawing.lines;
  std::vector<std::string> names = drawing.lineNames;
  std::size_t throughVertices = 0;
  for (std::uint32_t i = 0, count = static_cast<std::uint32_t>(lines.size()); i < count; ++i) {
    const CreaseLine line = lines[i];
    if (cdt.is_edge(handles[line.a], handles[line.b])) continue;
    ++throughVertices;
    lineOf.erase(pairKey(line.a, line.b));
    const Kernel::Point_2 a = handles[line.a]->point(), b = handles[line.b]->point();
    Cdt::Vertex_handle at = handles[line.a];
    CreaseLine piece = line;
    bool first = true;
    while (at != handles[line.b]) {
      Cdt::Vertex_handle step;
      auto around = cdt.incident_vertices(at), done = around;
      do {
        if (!cdt.is_infinite(around) && CGAL::collinear(a, b, around->point()) &&
            (around == handles[line.b] ||
             CGAL::collinear_are_strictly_ordered_along_line(at->point(), around->point(), b))) {
          step = around;
          break;
        }
      } while (++around != done);
      if (step == Cdt::Vertex_handle())
        throw CreasePatternError(lineName(drawing, i) + " passes through another vertex");
      piece.a = at->info();
      piece.b = step->info();
      const std::uint32_t index = first ? i : static_cast<std::uint32_t>(lines.size());
      if (first) {
        lines[i] = piece;
      } else {
        lines.push_back(piece);
        if (!names.empty()) names.push_back(lineName(drawing, i));
      }
      first = false;
      lineOf.emplace(pairKey(piece.a, piece.b), index);
      at = step;
    }
  }
  if (throughVertices > 0)
    pattern.notes.push_back(std::to_string(throughVertices) +
                            " lines through other vertices were split there");

  if (cdt.dimension() < 2)
    throw CreasePatternError("no paper: every line lies on one straight line");
  const auto lineAt = [&](Cdt::Face_handle face, int k) {
    return lineOf.at(pairKey(face->vertex(Cdt::ccw(k))->info(), face->vertex(Cdt::cw(k))->info()));
  };
  // Regions: faces joined across unconstrained edges; region 0 holds the outside. Which are
  // paper (found again after points are added inside: classify() is deterministic).
  int regionCount = 0;
  std::vector<char> paper;
  const auto classify = [&] {
    regionCount = 0;
    for (Cdt::Face_handle face : cdt.all_face_handles()) face->info().region = -1;
    {
      std::vector<Cdt::Face_handle> stack;
      const auto flood = [&](Cdt::Face_handle start) {
        start->info().region = regionCount;
        stack.push_back(start);
        while (!stack.empty()) {
          const Cdt::Face_handle face = stack.back();
          stack.pop_back();
          for (int k = 0; k < 3; ++k) {
            const Cdt::Face_handle next = face->neighbor(k);
            if (next->info().region >= 0 || cdt.is_constrained({face, k})) continue;
            next->info().region = regionCount;
            stack.push_back(next);
          }
        }
        ++regionCount;
      };
      flood(cdt.infinite_face());
      for (Cdt::Face_handle face : cdt.all_face_handles())
        if (face->info().region < 0) flood(face);
    }
    // Which regions are paper.
    paper.assign(regionCount, 0);
    if (!drawing.faces.empty()) {
      for (std::size_t f = 0; f < drawing.faces.size(); ++f) {
        const auto& face = drawing.faces[f];
        if (face.size() < 3)
          throw CreasePatternError("face " + std::to_string(f) + " has fewer than 3 corners");
        double area = 0.0;
        for (std::size_t k = 0; k < face.size(); ++k)
          area += cross(vertices[face[k]], vertices[face[(k + 1) % face.size()]]);
        if (area == 0.0) throw CreasePatternError("face " + std::to_string(f) + " has no area");
        for (std::size_t k = 0; k < face.size(); ++k) {
          const std::uint32_t u = face[k], v = face[(k + 1) % face.size()];
          Cdt::Face_handle side;
          int index = 0;
          if (!cdt.is_edge(handles[u], handles[v], side, index) ||
              !cdt.is_constrained({side, index}))
            throw CreasePatternError("face " + std::to_string(f) + ": its side " +
                                     std::to_string(u) + "-" + std::to_string(v) +
                                     " is not an edge");
          // side lies left of ccw(index) -> cw(index); the face lies left of u -> v when its
          // corners run counter-clockwise.
          const bool sideLeftOfUv = side->vertex(Cdt::ccw(index)) == handles[u];
          const Cdt::Face_handle inside = sideLeftOfUv == (area > 0) ? side : side->neighbor(index);
          if (cdt.is_infinite(inside) || inside->info().region == 0)
            throw CreasePatternError("face " + std::to_string(f) +
                                     " is not a face of the edges (it encloses others or crosses "
                                     "the outside)");
          paper[inside->info().region] = 1;
        }
      }
    } else {
      // As Origami Simulator (removeBorderFaces): a region bounded only by border lines is a hole,
      // unless it touches the outside (a plain sheet).
      std::vector<char> touchesOutside(regionCount, 0), onlyBorder(regionCount, 1);
      for (Cdt::Face_handle face : cdt.all_face_handles())
        for (int k = 0; k < 3; ++k) {
          if (!cdt.is_constrained({face, k})) continue;
          const int region = face->info().region, other = face->neighbor(k)->info().region;
          if (other == 0) touchesOutside[region] = 1;
          if (lines[lineAt(face, k)].assignment != CreaseAssignment::Boundary)
            onlyBorder[region] = 0;
        }
      for (int r = 1; r < regionCount; ++r) paper[r] = touchesOutside[r] || !onlyBorder[r];
    }
    paper[0] = 0;
  };
  classify();
  if (const std::size_t added = addPointsInsideCurves(cdt, vertices, lines, lineOf, paper);
      added > 0) {
    classify();
    pattern.notes.push_back(std::to_string(added) +
                            " points added inside regions bounded by one curve's own points");
  }

  // Each line: paper on which sides.
  std::vector<char> opened(lines.size(), 0);
  std::size_t creasesOnBorder = 0, bordersInside = 0, withoutFace = 0;
  for (std::uint32_t i = 0; i < lines.size(); ++i) {
    Cdt::Face_handle side;
    int index = 0;
    cdt.is_edge(handles[lines[i].a], handles[lines[i].b], side, index);
    const bool left = paper[side->info().region],
               right = paper[side->neighbor(index)->info().region];
    CreaseLine& line = lines[i];
    if (!left && !right) {
      if (!options.dropLinesWithoutFace)
        throw CreasePatternError((i < names.size() ? names[i] : "edge " + std::to_string(i)) +
                                 " has no face (it lies outside the paper)");
      ++withoutFace;
      continue;
    }
    if (left != right) {
      if (line.assignment != CreaseAssignment::Boundary &&
          line.assignment != CreaseAssignment::Cut) {
        ++creasesOnBorder;
        line.assignment = CreaseAssignment::Boundary;
        line.foldAngleDegrees = 0.0;
      }
    } else if (line.assignment == CreaseAssignment::Cut) {
      opened[i] = 1;
    } else if (line.assignment == CreaseAssignment::Boundary) {
      ++bordersInside;
      if (options.innerBorderAsHinge)
        line.assignment = CreaseAssignment::Unassigned;
      else
        opened[i] = 1;
    }
  }
  if (withoutFace > 0)
    pattern.notes.push_back(std::to_string(withoutFace) +
                            " lines outside the paper (in no face) were dropped");
  if (creasesOnBorder > 0)
    pattern.notes.push_back(std::to_string(creasesOnBorder) +
                            " creases on the paper's border were read as border edges");
  if (bordersInside > 0)
    pattern.notes.push_back(
        std::to_string(bordersInside) + " border edges with paper on both sides were " +
        (options.innerBorderAsHinge ? "read as unassigned (free) hinges" : "opened as cuts"));

  // Triangles of the paper, then corners joined across every edge that is not opened.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Cdt::Face_handle> faces;
  for (Cdt::Face_handle face : cdt.finite_face_handles())
    if (paper[face->info().region]) {
      face->info().triangle = static_cast<int>(triangles.size());
      faces.push_back(face);
      triangles.push_back(
          {face->vertex(0)->info(), face->vertex(1)->info(), face->vertex(2)->info()});
    }
  if (triangles.empty())
    throw CreasePatternError("no paper: the lines enclose no face (is the border closed?)");
  UnionFind corners(3 * triangles.size());
  for (std::size_t t = 0; t < faces.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Cdt::Face_handle other = faces[t]->neighbor(k);
      if (cdt.is_infinite(other) || !paper[other->info().region]) continue;
      if (other->info().triangle < static_cast<int>(t)) continue;
      if (cdt.is_constrained({faces[t], k}) && opened[lineAt(faces[t], k)]) continue;
      for (int end : {Cdt::ccw(k), Cdt::cw(k)}) {
        const int there = other->index(faces[t]->vertex(end));
        corners.unite(static_cast<std::uint32_t>(3 * t + end),
                      static_cast<std::uint32_t>(3 * other->info().triangle + there));
      }
    }
  // New vertex numbers in the order of the old ones.
  std::vector<std::uint32_t> cornerOrder(3 * triangles.size());
  std::iota(cornerOrder.begin(), cornerOrder.end(), 0u);
  std::stable_sort(cornerOrder.begin(), cornerOrder.end(), [&](std::uint32_t x, std::uint32_t y) {
    return triangles[x / 3][x % 3] < triangles[y / 3][y % 3];
  });
  std::vector<std::uint32_t> newVertex(3 * triangles.size(), UINT32_MAX);
  for (std::uint32_t corner : cornerOrder) {
    const std::uint32_t root = corners.find(corner);
    if (newVertex[root] == UINT32_MAX) {
      newVertex[root] = static_cast<std::uint32_t>(pattern.vertices.size());
      pattern.vertices.push_back(vertices[triangles[corner / 3][corner % 3]]);
    }
    newVertex[corner] = newVertex[root];
  }
  std::vector<char> inTriangle(vertices.size(), 0);
  for (const auto& triangle : triangles)
    for (std::uint32_t v : triangle) inTriangle[v] = 1;
  const auto kept = static_cast<std::size_t>(std::count(inTriangle.begin(), inTriangle.end(), 1));
  if (pattern.vertices.size() > kept)
    pattern.notes.push_back("cuts opened: " + std::to_string(pattern.vertices.size() - kept) +
                            " vertices doubled");
  std::unordered_set<std::uint64_t> listed;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    pattern.triangles.push_back({newVertex[3 * t], newVertex[3 * t + 1], newVertex[3 * t + 2]});
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = newVertex[3 * t + Cdt::ccw(k)], b = newVertex[3 * t + Cdt::cw(k)];
      if (!listed.insert(pairKey(a, b)).second) continue;
      CreasePatternEdge edge;
      edge.a = std::min(a, b);
      edge.b = std::max(a, b);
      const auto line = lineOf.find(pairKey(triangles[t][Cdt::ccw(k)], triangles[t][Cdt::cw(k)]));
      if (line != lineOf.end()) {
        edge.assignment = lines[line->second].assignment;
        edge.foldAngleDegrees = lines[line->second].foldAngleDegrees;
      }
      pattern.edges.push_back(edge);
    }
  }
  // A cut that cannot open: one edge whose both ends stay single vertices (a slit with both
  // ends inside the paper, no vertex on its way to double). A triangle mesh cannot hold it open
  // without a non-manifold edge, so the paper stays joined there as a free hinge.
  std::unordered_map<std::uint64_t, int> uses;
  for (const auto& triangle : pattern.triangles)
    for (int k = 0; k < 3; ++k) ++uses[pairKey(triangle[k], triangle[(k + 1) % 3])];
  std::size_t closedCuts = 0;
  for (CreasePatternEdge& edge : pattern.edges)
    if ((edge.assignment == CreaseAssignment::Cut ||
         edge.assignment == CreaseAssignment::Boundary) &&
        uses[pairKey(edge.a, edge.b)] == 2) {
      ++closedCuts;
      edge.assignment = CreaseAssignment::Unassigned;
      edge.foldAngleDegrees = 0.0;
    }
  if (closedCuts > 0)
    pattern.notes.push_back(std::to_string(closedCuts) +
                            " cut edges with both ends inside the paper cannot open; read as "
                            "unassigned (free) hinges");
  return pattern;
}

std::optional<std::string> validateCreasePattern(const CreasePattern& pattern) {
  const std::size_t n = pattern.vertices.size();
  for (std::size_t v = 0; v < n; ++v)
    if (!std::isfinite(pattern.vertices[v].x) || !std::isfinite(pattern.vertices[v].y))
      return "vertex " + std::to_string(v) + " is not finite";
  std::unordered_map<std::uint64_t, int> uses;
  for (std::size_t t = 0; t < pattern.triangles.size(); ++t) {
    const auto& tri = pattern.triangles[t];
    for (std::uint32_t v : tri)
      if (v >= n) return "triangle " + std::to_string(t) + " has a vertex out of range";
    const glm::dvec2 a = pattern.vertices[tri[0]], b = pattern.vertices[tri[1]],
                     c = pattern.vertices[tri[2]];
    if (!(cross(b - a, c - a) > 0.0))
      return "triangle " + std::to_string(t) + " is not counter-clockwise with area";
    for (int k = 0; k < 3; ++k) ++uses[pairKey(tri[k], tri[(k + 1) % 3])];
  }
  std::unordered_set<std::uint64_t> listed;
  for (std::size_t e = 0; e < pattern.edges.size(); ++e) {
    const CreasePatternEdge& edge = pattern.edges[e];
    const std::string name = "edge " + std::to_string(e);
    if (edge.a >= edge.b || edge.b >= n) return name + " is not a < b within range";
    if (!listed.insert(pairKey(edge.a, edge.b)).second) return name + " is listed twice";
    const auto found = uses.find(pairKey(edge.a, edge.b));
    if (found == uses.end()) return name + " is in no triangle";
    if (found->second > 2) return name + " is in more than two triangles";
    if (found->second == 2 &&
        (edge.assignment == CreaseAssignment::Cut || edge.assignment == CreaseAssignment::Boundary))
      return name + " is a " + assignmentName(edge.assignment) + " edge inside the paper";
    if (found->second == 1 && edge.assignment != CreaseAssignment::Cut &&
        edge.assignment != CreaseAssignment::Boundary)
      return name + " is a " + assignmentName(edge.assignment) + " edge on the border";
    if (!std::isfinite(edge.foldAngleDegrees) || std::abs(edge.foldAngleDegrees) > 180.0)
      return name + " has a fold angle outside [-180, 180]";
  }
  if (listed.size() != uses.size()) return "a triangle edge is not listed in edges";
  return std::nullopt;
}

}  // namespace curvefold
