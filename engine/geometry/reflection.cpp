#include "engine/geometry/reflection.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

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

double cross2(const glm::dvec2& a, const glm::dvec2& b) {
  return a.x * b.y - a.y * b.x;
}

// Shape quality of a development triangle: twice its area over its longest edge squared.
double quality(const std::vector<glm::dvec2>& dev, VertexIndex a, VertexIndex b, VertexIndex c) {
  const glm::dvec2 ab = dev[b] - dev[a], bc = dev[c] - dev[b], ca = dev[a] - dev[c];
  const double longest = std::max({glm::dot(ab, ab), glm::dot(bc, bc), glm::dot(ca, ca)});
  return cross2(ab, dev[c] - dev[a]) / longest;
}

// Side of a vertex: -1 strictly behind the plane (the seed's side), 0 on it, +1 in front.
int sideOf(double d, double epsilon) {
  return d < -epsilon ? -1 : (d > epsilon ? 1 : 0);
}

}  // namespace

void ReflectionWorkspace::resize(std::size_t vertexCount, std::size_t triangleCount) {
  if (distance_.size() < vertexCount) {
    distance_.resize(vertexCount);
    distanceStamp_.resize(vertexCount, 0);
    vertexReached_.resize(vertexCount, 0);
  }
  if (triangleReached_.size() < triangleCount) triangleReached_.resize(triangleCount, 0);
  if (++stamp_ == 0) {  // wrapped: old stamps could alias the new one
    std::fill(distanceStamp_.begin(), distanceStamp_.end(), 0);
    std::fill(vertexReached_.begin(), vertexReached_.end(), 0);
    std::fill(triangleReached_.begin(), triangleReached_.end(), 0);
    stamp_ = 1;
  }
}

double ReflectionWorkspace::distanceOf(const Sheet& sheet, const ReflectionPlane& plane,
                                       VertexIndex v) {
  if (distanceStamp_[v] != stamp_) {
    distanceStamp_[v] = stamp_;
    distance_[v] = plane.signedDistance(sheet.positions[v]);
  }
  return distance_[v];
}

// Flood fill from the seed through strictly-negative vertices [MI 3.3]: a triangle is reached when
// it touches a reached vertex, and every strictly-negative vertex of a reached triangle is reached.
void ReflectionWorkspace::fill(const Sheet& sheet, const VertexTriangles& adjacency,
                               VertexIndex seed, const ReflectionPlane& plane, double epsilon) {
  reachedVertices_.clear();
  reachedTriangles_.clear();
  vertexReached_[seed] = stamp_;
  reachedVertices_.push_back(seed);
  for (std::size_t next = 0; next < reachedVertices_.size(); ++next) {
    for (TriangleIndex t : adjacency.of(reachedVertices_[next])) {
      if (triangleReached_[t] == stamp_) continue;
      triangleReached_[t] = stamp_;
      reachedTriangles_.push_back(t);
      for (VertexIndex w : sheet.triangles[t]) {
        if (vertexReached_[w] != stamp_ && distanceOf(sheet, plane, w) < -epsilon) {
          vertexReached_[w] = stamp_;
          reachedVertices_.push_back(w);
        }
      }
    }
  }
}

void ReflectionWorkspace::clear() {
  changes_ = ReflectionChanges{};
  splitEdges_.clear();
}

void ReflectionWorkspace::apply(const Sheet& sheet, const VertexTriangles& adjacency,
                                VertexIndex seed, const ReflectionPlane& plane, double epsilon,
                                Sheet& out) {
  clear();
  changes_.firstNewVertex = sheet.vertexCount();
  changes_.firstNewTriangle = sheet.triangleCount();
  resize(sheet.vertexCount(), sheet.triangleCount());
  if (!(distanceOf(sheet, plane, seed) < -epsilon)) return;  // nothing on the seed's side

  fill(sheet, adjacency, seed, plane, epsilon);

  for (VertexIndex v : reachedVertices_) out.positions[v] = plane.reflect(sheet.positions[v]);
  changes_.movedVertices = reachedVertices_;

  cuts_.clear();
  newTags_.clear();
  // The vertex where the plane cuts edge e, shared by both triangles of the edge. Interpolated
  // from the lower-numbered end so either triangle computes the same point; 3D and development
  // use the same parameter, which is exact because each triangle is congruent to its development.
  auto cutVertex = [&](VertexIndex u, VertexIndex w) {
    const Edge e = Edge::of(u, w);
    auto [it, inserted] =
        cuts_.try_emplace(edgeKey(e), static_cast<VertexIndex>(out.vertexCount()));
    if (inserted) {
      const double da = distance_[e.a], db = distance_[e.b];
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
    if (reflected) changes_.reflectedTriangles.push_back(index);
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

  for (TriangleIndex t : reachedTriangles_) {
    const Triangle tri = sheet.triangles[t];
    std::array<int, 3> side;
    bool crossed = false;
    int onPlane = 0;
    for (int i = 0; i < 3; ++i) {
      side[i] = sideOf(distance_[tri[i]], epsilon);
      crossed |= side[i] > 0;
      onPlane += side[i] == 0;
    }
    if (!crossed) {
      changes_.reflectedTriangles.push_back(t);
      // An existing edge lying in the plane between this reflected triangle and one outside the
      // reached part becomes a crease.
      if (onPlane == 2) {
        const int i = side[0] != 0 ? 1 : (side[1] != 0 ? 2 : 0);
        const VertexIndex u = tri[i], w = tri[(i + 1) % 3];
        for (TriangleIndex other : adjacency.of(u)) {
          if (other == t || triangleReached_[other] == stamp_) continue;
          const Triangle& o = sheet.triangles[other];
          if (o[0] == w || o[1] == w || o[2] == w) newTags_.push_back({Edge::of(u, w)});
        }
      }
      continue;
    }
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

  // Tags: the sheet's, less the edges that were split, plus the halves and the new creases.
  std::size_t creases = 0;
  for (const TaggedEdge& tag : newTags_) creases += tag.kind == EdgeKind::Crease;
  changes_.newCreaseCount = creases;
  out.tags.clear();
  std::sort(splitEdges_.begin(), splitEdges_.end());
  for (const TaggedEdge& tag : sheet.tags)
    if (!std::binary_search(splitEdges_.begin(), splitEdges_.end(), tag.edge))
      out.tags.push_back(tag);
  out.tags.insert(out.tags.end(), newTags_.begin(), newTags_.end());
  out.normalizeTags();
}

void ReflectionWorkspace::restore(const Sheet& sheet, Sheet& out) const {
  for (VertexIndex v : changes_.movedVertices) out.positions[v] = sheet.positions[v];
  for (TriangleIndex t : changes_.rewrittenTriangles) out.triangles[t] = sheet.triangles[t];
  out.positions.resize(sheet.vertexCount());
  out.development.resize(sheet.vertexCount());
  out.triangles.resize(sheet.triangleCount());
  out.tags = sheet.tags;
}

ReflectionResult reflect(const Sheet& sheet, const VertexTriangles& adjacency, VertexIndex seed,
                         const ReflectionPlane& plane, double epsilon) {
  ReflectionWorkspace workspace;
  ReflectionResult result{sheet, {}};
  workspace.apply(sheet, adjacency, seed, plane, epsilon, result.sheet);
  result.changes = workspace.changes();
  return result;
}

ReflectionResult reflect(const Sheet& sheet, VertexIndex seed, const ReflectionPlane& plane) {
  return reflect(sheet, buildVertexTriangles(sheet), seed, plane, sheetEpsilon(sheet));
}

}  // namespace curvefold
