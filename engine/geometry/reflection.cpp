#include "engine/geometry/reflection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtx/exterior_product.hpp>

#include "engine/geometry/validate.hpp"

namespace curvefold {

double ReflectionPlane::signedDistance(const glm::dvec3& x) const {
  return glm::dot(x - point, normal);
}

glm::dvec3 ReflectionPlane::reflect(const glm::dvec3& x) const {
  return x - (2.0 * signedDistance(x)) * normal;
}

ReflectionPlane bisectorPlane(const glm::dvec3& p0, const glm::dvec3& p1) {
  const glm::dvec3 delta = p1 - p0;
  return {0.5 * (p0 + p1), delta / glm::length(delta)};
}

namespace {

std::uint64_t edgeKey(Edge e) {
  return (std::uint64_t{e.a} << 32) | e.b;
}

// Shape quality of a development triangle: twice its area over its longest edge squared.
double quality(const std::vector<glm::dvec2>& dev, VertexIndex a, VertexIndex b, VertexIndex c) {
  const glm::dvec2 ab = dev[b] - dev[a], bc = dev[c] - dev[b], ca = dev[a] - dev[c];
  const double longest = std::max({glm::dot(ab, ab), glm::dot(bc, bc), glm::dot(ca, ca)});
  return glm::cross(ab, dev[c] - dev[a]) / longest;
}

// Side of a distance: -1 strictly behind the plane (the seed's side), 0 on it, +1 in front.
int sideOfDistance(double d, double epsilon) {
  return d < -epsilon ? -1 : (d > epsilon ? 1 : 0);
}

}  // namespace

int ReflectionWorkspace::sideOf(VertexIndex v, double epsilon) const {
  return reached(v) ? -1 : sideOfDistance(distances_[v], epsilon);
}

void ReflectionWorkspace::resize(std::size_t vertexCount, std::size_t triangleCount) {
  if (vertexMarks_.size() < vertexCount) {
    vertexMarks_.resize(vertexCount, 0);
    distances_.resize(vertexCount, 0.0);
  }
  if (triangleSeen_.size() < triangleCount) {
    triangleSeen_.resize(triangleCount, 0);
    triangleCrossed_.resize(triangleCount, 0);
  }
  if (++stamp_ == 0x80000000u) {  // vertex marks would wrap: old marks could alias new ones
    std::fill(vertexMarks_.begin(), vertexMarks_.end(), 0);
    std::fill(triangleSeen_.begin(), triangleSeen_.end(), 0);
    std::fill(triangleCrossed_.begin(), triangleCrossed_.end(), 0);
    stamp_ = 1;
  }
}

// Flood fill from the seed through strictly-negative vertices [MI 3.3]. Two strictly-negative
// vertices of one triangle always share an edge, so flooding over edges reaches exactly the
// vertices that the paper's triangle-to-triangle fill reaches. Reached vertices are reflected into
// `out` as they are found; the neighbours that stop the flood (on or beyond the plane) are kept,
// since every triangle to split or hinge touches one of them.
void ReflectionWorkspace::fill(const Sheet& sheet, const SheetAdjacency& adjacency,
                               VertexIndex seed, const ReflectionPlane& plane, double epsilon,
                               Sheet& out, std::span<const VertexIndex> moreSeeds) {
  std::vector<VertexIndex>& reached = changes_.movedVertices;
  reached.clear();
  boundaryVertices_.clear();
  reached.push_back(seed);
  out.positions[seed] = plane.reflect(sheet.positions[seed]);
  for (VertexIndex s : moreSeeds) {
    if (vertexMarks_[s] >= visitedMark() || !(plane.signedDistance(sheet.positions[s]) < -epsilon))
      continue;
    vertexMarks_[s] = reachedMark();
    reached.push_back(s);
    out.positions[s] = plane.reflect(sheet.positions[s]);
  }
  // Raw pointers: the compiler cannot tell that the writes below leave the vectors alone.
  std::uint32_t* const marks = vertexMarks_.data();
  double* const distances = distances_.data();
  const glm::dvec3* const positions = sheet.positions.data();
  glm::dvec3* const moved = out.positions.data();
  const std::uint32_t* const rowStart = adjacency.neighbors.offsets.data();
  const VertexIndex* const neighbors = adjacency.neighbors.vertices.data();
  const std::uint32_t visitedMark = this->visitedMark(), reachedMark = this->reachedMark();
  // On a big sheet every step waits on memory; the queue says which vertices come next, so their
  // rows and their neighbours' records are fetched a few steps ahead. A sheet whose per-vertex
  // arrays (about 90 bytes a vertex) fit in the caches only pays for the extra work (bench_drag:
  // about 10% slower at 50k vertices, 20% faster at 500k).
  constexpr std::size_t kRowsAhead = 32, kNeighborsAhead = 16;
  constexpr std::size_t kPrefetchFromVertices = 150'000;
  const bool prefetch = sheet.vertexCount() >= kPrefetchFromVertices;
  for (std::size_t next = 0; next < reached.size(); ++next) {
    if (prefetch && next + kRowsAhead < reached.size())
      __builtin_prefetch(neighbors + rowStart[reached[next + kRowsAhead]]);
    if (prefetch && next + kNeighborsAhead < reached.size()) {
      const VertexIndex ahead = reached[next + kNeighborsAhead];
      for (std::uint32_t i = rowStart[ahead]; i < rowStart[ahead + 1]; ++i) {
        __builtin_prefetch(marks + neighbors[i]);
        __builtin_prefetch(positions + neighbors[i]);
      }
    }
    const VertexIndex v = reached[next];
    for (std::uint32_t i = rowStart[v]; i < rowStart[v + 1]; ++i) {
      const VertexIndex w = neighbors[i];
      if (marks[w] >= visitedMark) continue;
      const double distance = plane.signedDistance(positions[w]);
      if (distance < -epsilon) {
        marks[w] = reachedMark;
        reached.push_back(w);
        moved[w] = plane.reflect(positions[w]);
      } else {
        marks[w] = visitedMark;
        distances[w] = distance;
        boundaryVertices_.push_back(w);
      }
    }
  }
}

// The reached triangles that need more than reflecting touch a boundary vertex: crossed ones (a
// vertex beyond the plane) are split; hinged ones (an edge in the plane) may gain a crease.
void ReflectionWorkspace::classifyBoundary(const Sheet& sheet, const SheetAdjacency& adjacency,
                                           double epsilon) {
  crossedTriangles_.clear();
  hingeTriangles_.clear();
  for (VertexIndex w : boundaryVertices_) {
    for (TriangleIndex t : adjacency.triangles.of(w)) {
      if (triangleSeen_[t] == stamp_) continue;
      triangleSeen_[t] = stamp_;
      // Every vertex of a triangle with a reached vertex was visited, so its distance is known.
      const Triangle& tri = sheet.triangles[t];
      if (!reached(tri[0]) && !reached(tri[1]) && !reached(tri[2])) continue;
      int positive = 0, onPlane = 0;
      for (VertexIndex v : tri) {
        const int side = sideOf(v, epsilon);
        positive += side > 0;
        onPlane += side == 0;
      }
      if (positive > 0) {
        crossedTriangles_.push_back(t);
        triangleCrossed_[t] = stamp_;
      } else if (onPlane == 2) {
        hingeTriangles_.push_back(t);
      }
    }
  }
}

const std::vector<TriangleIndex>& ReflectionWorkspace::reflectedTriangles(
    const SheetAdjacency& adjacency) {
  if (reflectedReady_) return reflected_;
  reflectedReady_ = true;
  reflected_.clear();
  if (triangleListed_.size() < changes_.firstNewTriangle)
    triangleListed_.resize(changes_.firstNewTriangle, 0);
  if (++listStamp_ == 0) {
    std::fill(triangleListed_.begin(), triangleListed_.end(), 0);
    listStamp_ = 1;
  }
  // Triangles around reached vertices are reflected whole, unless they were split: then only
  // their pieces on the reflected side are.
  for (VertexIndex v : changes_.movedVertices) {
    for (TriangleIndex t : adjacency.triangles.of(v)) {
      if (triangleListed_[t] == listStamp_) continue;
      triangleListed_[t] = listStamp_;
      if (triangleCrossed_[t] != stamp_) reflected_.push_back(t);
    }
  }
  reflected_.insert(reflected_.end(), reflectedPieces_.begin(), reflectedPieces_.end());
  return reflected_;
}

std::size_t ReflectionWorkspace::memoryBytes() const {
  const auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return bytes(vertexMarks_) + bytes(distances_) + bytes(previousMoved_) + bytes(triangleSeen_) +
         bytes(triangleCrossed_) + bytes(triangleListed_) + bytes(boundaryVertices_) +
         bytes(crossedTriangles_) + bytes(hingeTriangles_) + bytes(reflectedPieces_) +
         bytes(reflected_) + bytes(changes_.movedVertices) + bytes(changes_.rewrittenTriangles) +
         bytes(changes_.triangleOrigin);
}

// Empties every list but keeps its storage: a drag reuses it frame after frame.
void ReflectionWorkspace::clear() {
  changes_.movedVertices.clear();
  changes_.rewrittenTriangles.clear();
  changes_.triangleOrigin.clear();
  changes_.firstNewVertex = changes_.firstNewTriangle = changes_.newCreaseCount = 0;
  changes_.splitAny = false;
  changes_.planeShift = 0.0;
  changes_.thinnestCut = std::numeric_limits<double>::infinity();
  sliverSources_.clear();
  splitEdges_.clear();
  reflectedPieces_.clear();
  reflectedReady_ = false;
}

void ReflectionWorkspace::apply(const Sheet& sheet, const SheetAdjacency& adjacency,
                                VertexIndex seed, const ReflectionPlane& plane, double epsilon,
                                Sheet& out, std::span<const VertexIndex> moreSeeds) {
  // Both tolerances follow the sheet's size, which epsilon carries.
  const double feature = epsilon * (kRelativeCutFeatureSize / kRelativeEpsilon);
  const double maxShift = epsilon * (kRelativeMaxPlaneShift / kRelativeEpsilon);
  applyThrough(sheet, adjacency, seed, plane, epsilon, feature, out, moreSeeds);
  if (sliverSources_.empty()) return;

  // Planes through the vertices of the triangles cut too thin, nearest first; the seed must stay
  // strictly on its side. Each try may find other thin cuts, whose vertices join the candidates.
  const double seedDistance = plane.signedDistance(sheet.positions[seed]);
  auto shifted = [&](double shift) {
    return ReflectionPlane{plane.point + shift * plane.normal, plane.normal};
  };
  triedShifts_.assign(1, 0.0);
  double bestShift = 0.0, bestThinnest = changes_.thinnestCut;
  std::vector<double> candidates;
  for (int attempt = 1; attempt < kMaxPlaneShiftTries; ++attempt) {
    for (TriangleIndex t : sliverSources_)
      for (VertexIndex v : sheet.triangles[t]) {
        const double d = plane.signedDistance(sheet.positions[v]);
        if (std::abs(d) > maxShift || !(d > seedDistance + epsilon)) continue;
        if (std::find(triedShifts_.begin(), triedShifts_.end(), d) != triedShifts_.end()) continue;
        if (std::find(candidates.begin(), candidates.end(), d) == candidates.end())
          candidates.push_back(d);
      }
    if (candidates.empty()) break;
    const auto nearest =
        std::min_element(candidates.begin(), candidates.end(), [](double x, double y) {
          return std::abs(x) < std::abs(y) || (std::abs(x) == std::abs(y) && x < y);
        });
    const double shift = *nearest;
    candidates.erase(nearest);
    triedShifts_.push_back(shift);
    restore(sheet, out);
    applyThrough(sheet, adjacency, seed, shifted(shift), epsilon, feature, out, moreSeeds);
    changes_.planeShift = shift;
    if (sliverSources_.empty()) return;
    if (changes_.thinnestCut > bestThinnest) {
      bestThinnest = changes_.thinnestCut;
      bestShift = shift;
    }
  }
  if (changes_.planeShift != bestShift) {
    restore(sheet, out);
    applyThrough(sheet, adjacency, seed, shifted(bestShift), epsilon, feature, out, moreSeeds);
    changes_.planeShift = bestShift;
  }
}

void ReflectionWorkspace::applyThrough(const Sheet& sheet, const SheetAdjacency& adjacency,
                                       VertexIndex seed, const ReflectionPlane& plane,
                                       double epsilon, double feature, Sheet& out,
                                       std::span<const VertexIndex> moreSeeds) {
  clear();
  changes_.firstNewVertex = sheet.vertexCount();
  changes_.firstNewTriangle = sheet.triangleCount();
  resize(sheet.vertexCount(), sheet.triangleCount());
  const double seedDistance = plane.signedDistance(sheet.positions[seed]);
  if (!(seedDistance < -epsilon)) {  // nothing on the seed's side
    vertexMarks_[seed] = visitedMark();
    return;
  }
  vertexMarks_[seed] = reachedMark();

  fill(sheet, adjacency, seed, plane, epsilon, out, moreSeeds);
  classifyBoundary(sheet, adjacency, epsilon);

  cuts_.reset();
  cutMemory_.release();
  cuts_.emplace(2 * crossedTriangles_.size(), &cutMemory_);
  newTags_.clear();
  tagHingeEdges(sheet, adjacency, epsilon);
  splitCrossedTriangles(sheet, plane, epsilon, feature, out);
  mergeTags(sheet, out);
}

// Each triangle the plane crosses clipped by it, both sides kept as triangles in the vertex
// order (so the development stays CCW), with the cut vertices shared along each split edge and
// the chord a new crease.
void ReflectionWorkspace::splitCrossedTriangles(const Sheet& sheet, const ReflectionPlane& plane,
                                                double epsilon, double feature, Sheet& out) {
  // The vertex where the plane cuts edge e, shared by both triangles of the edge. Interpolated
  // from the lower-numbered end so either triangle computes the same point; 3D and development
  // use the same parameter, which is exact because each triangle is congruent to its development.
  auto cutVertex = [&](VertexIndex u, VertexIndex w) {
    const Edge e = Edge::of(u, w);
    auto [it, inserted] =
        cuts_->try_emplace(edgeKey(e), static_cast<VertexIndex>(out.vertexCount()));
    if (inserted) {
      // A reached vertex's distance was not kept; the same expression gives the same bits.
      auto distanceOf = [&](VertexIndex v) {
        return reached(v) ? plane.signedDistance(sheet.positions[v]) : distances_[v];
      };
      const double da = distanceOf(e.a), db = distanceOf(e.b);
      const double t = da / (da - db);
      out.positions.push_back(sheet.positions[e.a] +
                              t * (sheet.positions[e.b] - sheet.positions[e.a]));
      out.development.push_back(sheet.development[e.a] +
                                t * (sheet.development[e.b] - sheet.development[e.a]));
      if (const std::optional<EdgeKind> kind = sheet.edgeKind(e)) {
        splitEdges_.push_back(e);
        newTags_.push_back({Edge::of(e.a, it->second), *kind});
        newTags_.push_back({Edge::of(it->second, e.b), *kind});
      }
    }
    return it->second;
  };
  bool wroteOriginal = false;
  TriangleIndex original = kNoIndex;
  auto emit = [&](VertexIndex a, VertexIndex b, VertexIndex c, bool reflected) {
    TriangleIndex index;
    if (!wroteOriginal) {
      wroteOriginal = true;
      index = original;
      out.triangles[index] = {a, b, c};
      changes_.rewrittenTriangles.push_back(index);
    } else {
      index = static_cast<TriangleIndex>(out.triangleCount());
      out.triangles.push_back({a, b, c});
      changes_.triangleOrigin.push_back(original);
    }
    if (reflected) reflectedPieces_.push_back(index);
    const double height =
        smallestHeight(out.development[a], out.development[b], out.development[c]);
    changes_.thinnestCut = std::min(changes_.thinnestCut, height);
    if (height < feature && (sliverSources_.empty() || sliverSources_.back() != original))
      sliverSources_.push_back(original);
  };
  // A convex polygon of 3 or 4 vertices in the original's order, as 1 or 2 triangles; a quad takes
  // the diagonal that gives the better-shaped pair.
  auto emitPolygon = [&](const std::array<VertexIndex, 4>& p, int count, bool reflected) {
    if (count == 3) {
      emit(p[0], p[1], p[2], reflected);
      return;
    }
    const double viaFirst = std::min(quality(out.development, p[0], p[1], p[2]),
                                     quality(out.development, p[0], p[2], p[3]));
    const double viaSecond = std::min(quality(out.development, p[1], p[2], p[3]),
                                      quality(out.development, p[1], p[3], p[0]));
    if (viaSecond > viaFirst) {
      emit(p[1], p[2], p[3], reflected);
      emit(p[1], p[3], p[0], reflected);
    } else {
      emit(p[0], p[1], p[2], reflected);
      emit(p[0], p[2], p[3], reflected);
    }
  };

  for (TriangleIndex t : crossedTriangles_) {
    const Triangle tri = sheet.triangles[t];
    std::array<int, 3> side;
    for (int i = 0; i < 3; ++i) side[i] = sideOf(tri[i], epsilon);
    // Clip the triangle by the plane, keeping the vertex order (so the development stays CCW).
    std::array<VertexIndex, 4> negative{}, positive{};
    int negativeCount = 0, positiveCount = 0;
    std::array<VertexIndex, 2> chord{};
    int chordCount = 0;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      if (side[i] <= 0) negative[negativeCount++] = tri[i];
      if (side[i] >= 0) positive[positiveCount++] = tri[i];
      if (side[i] == 0) chord[chordCount++] = tri[i];
      if (side[i] * side[j] < 0) {
        const VertexIndex m = cutVertex(tri[i], tri[j]);
        negative[negativeCount++] = m;
        positive[positiveCount++] = m;
        chord[chordCount++] = m;
      }
    }
    changes_.splitAny = true;
    wroteOriginal = false;
    original = t;
    emitPolygon(negative, negativeCount, true);
    emitPolygon(positive, positiveCount, false);
    newTags_.push_back({Edge::of(chord[0], chord[1])});
  }
}

// An existing edge lying in the plane between a reflected triangle and one outside the reached
// part becomes a crease.
void ReflectionWorkspace::tagHingeEdges(const Sheet& sheet, const SheetAdjacency& adjacency,
                                        double epsilon) {
  for (TriangleIndex t : hingeTriangles_) {
    const Triangle& tri = sheet.triangles[t];
    int i = 0;
    while (sideOf(tri[i], epsilon) == 0) ++i;  // the one vertex off the plane
    const VertexIndex u = tri[(i + 1) % 3], w = tri[(i + 2) % 3];
    for (TriangleIndex other : adjacency.triangles.of(u)) {
      if (other == t) continue;
      const Triangle& o = sheet.triangles[other];
      if (o[0] != w && o[1] != w && o[2] != w) continue;
      if (!reached(o[0]) && !reached(o[1]) && !reached(o[2])) newTags_.push_back({Edge::of(u, w)});
    }
  }
}

// The result's tags: the sheet's, less the edges that were split, plus the halves and the new
// creases.
void ReflectionWorkspace::mergeTags(const Sheet& sheet, Sheet& out) {
  std::size_t creases = 0;
  for (const TaggedEdge& tag : newTags_) creases += tag.kind == EdgeKind::Crease;
  changes_.newCreaseCount = creases;
  // Both lists sorted, so a merge keeps the result sorted in linear time; for an edge in both, the
  // sheet's entry comes first and survives.
  std::sort(splitEdges_.begin(), splitEdges_.end());
  keptTags_.clear();
  for (const TaggedEdge& tag : sheet.tags)
    if (!std::binary_search(splitEdges_.begin(), splitEdges_.end(), tag.edge))
      keptTags_.push_back(tag);
  auto byEdge = [](const TaggedEdge& x, const TaggedEdge& y) { return x.edge < y.edge; };
  std::stable_sort(newTags_.begin(), newTags_.end(), byEdge);
  out.tags.clear();
  std::merge(keptTags_.begin(), keptTags_.end(), newTags_.begin(), newTags_.end(),
             std::back_inserter(out.tags), byEdge);
  out.tags.erase(
      std::unique(out.tags.begin(), out.tags.end(),
                  [](const TaggedEdge& x, const TaggedEdge& y) { return x.edge == y.edge; }),
      out.tags.end());
}

// What restore() and reapply() both put back: the rewritten triangles and the arrays' lengths.
void ReflectionWorkspace::restoreTopology(const Sheet& sheet, Sheet& out) const {
  for (TriangleIndex t : changes_.rewrittenTriangles) out.triangles[t] = sheet.triangles[t];
  out.positions.resize(sheet.vertexCount());
  out.development.resize(sheet.vertexCount());
  out.triangles.resize(sheet.triangleCount());
}

void ReflectionWorkspace::restore(const Sheet& sheet, Sheet& out) const {
  for (VertexIndex v : changes_.movedVertices) out.positions[v] = sheet.positions[v];
  restoreTopology(sheet, out);
  out.tags = sheet.tags;
}

void ReflectionWorkspace::reapply(const Sheet& sheet, const SheetAdjacency& adjacency,
                                  VertexIndex seed, const ReflectionPlane& plane, double epsilon,
                                  Sheet& out) {
  restoreTopology(sheet, out);
  previousMoved_.swap(changes_.movedVertices);
  apply(sheet, adjacency, seed, plane, epsilon, out);
  for (VertexIndex v : previousMoved_)
    if (!reached(v)) out.positions[v] = sheet.positions[v];
  if (!reached(seed)) out.tags = sheet.tags;  // apply() rebuilt them otherwise
}

ReflectionResult reflect(const Sheet& sheet, const SheetAdjacency& adjacency, VertexIndex seed,
                         const ReflectionPlane& plane, double epsilon,
                         std::span<const VertexIndex> moreSeeds) {
  ReflectionWorkspace workspace;
  ReflectionResult result{sheet, {}, {}};
  workspace.apply(sheet, adjacency, seed, plane, epsilon, result.sheet, moreSeeds);
  result.changes = workspace.changes();
  result.reflectedTriangles = workspace.reflectedTriangles(adjacency);
  return result;
}

ReflectionResult reflect(const Sheet& sheet, VertexIndex seed, const ReflectionPlane& plane) {
  return reflect(sheet, buildAdjacency(sheet), seed, plane, sheetEpsilon(sheet));
}

}  // namespace curvefold
