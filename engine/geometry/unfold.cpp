#include "engine/geometry/unfold.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <numbers>
#include <sstream>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/gtx/exterior_product.hpp>

namespace curvefold {
namespace {

std::uint64_t directedKey(VertexIndex from, VertexIndex to) {
  return (static_cast<std::uint64_t>(from) << 32) | to;
}

// Angle at corner a of triangle (a, b, c); atan2 stays accurate near 0 and pi.
double cornerAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 u = b - a, v = c - a;
  return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

double boundingDiagonal(const std::vector<glm::dvec3>& positions) {
  if (positions.empty()) return 0.0;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const glm::dvec3& p : positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

// The third corner of a triangle on the left of the directed edge a->b, from its 3D distances.
glm::dvec2 placeLeft(const glm::dvec2& a, const glm::dvec2& b, double toA, double toB) {
  const double length = glm::distance(a, b);
  if (length == 0.0) return a;
  const glm::dvec2 along = (b - a) / length;
  const glm::dvec2 left(-along.y, along.x);
  const double x = (toA * toA - toB * toB + length * length) / (2.0 * length);
  const double h = std::sqrt(std::max(0.0, toA * toA - x * x));
  return a + x * along + h * left;
}

std::string describeDefect(const AngleDefect& defect) {
  std::ostringstream out;
  out.precision(6);
  out << "largest angle defect " << defect.radians * 180.0 / std::numbers::pi << " degrees ("
      << defect.radians << " rad) at vertex " << defect.vertex;
  return out.str();
}

}  // namespace

std::vector<double> angleDefects(const std::vector<glm::dvec3>& positions,
                                 const std::vector<Triangle>& triangles) {
  // A vertex is interior when each of its directed edges has a twin running the other way.
  std::unordered_map<std::uint64_t, std::uint32_t> directed;
  directed.reserve(triangles.size() * 3);
  for (const Triangle& t : triangles)
    for (int i = 0; i < 3; ++i) ++directed[directedKey(t[i], t[(i + 1) % 3])];
  std::vector<bool> boundary(positions.size(), false);
  for (const auto& [key, count] : directed) {
    const VertexIndex from = static_cast<VertexIndex>(key >> 32);
    const VertexIndex to = static_cast<VertexIndex>(key & 0xffffffffu);
    if (count != 1 || directed.find(directedKey(to, from)) == directed.end())
      boundary[from] = boundary[to] = true;
  }
  std::vector<double> angleSum(positions.size(), 0.0);
  std::vector<bool> used(positions.size(), false);
  for (const Triangle& t : triangles) {
    for (int i = 0; i < 3; ++i) {
      const VertexIndex v = t[i];
      angleSum[v] +=
          cornerAngle(positions[v], positions[t[(i + 1) % 3]], positions[t[(i + 2) % 3]]);
      used[v] = true;
    }
  }
  std::vector<double> defects(positions.size(), std::numeric_limits<double>::quiet_NaN());
  for (VertexIndex v = 0; v < positions.size(); ++v)
    if (used[v] && !boundary[v]) defects[v] = 2.0 * std::numbers::pi - angleSum[v];
  return defects;
}

AngleDefect largestAngleDefect(const std::vector<glm::dvec3>& positions,
                               const std::vector<Triangle>& triangles) {
  const std::vector<double> defects = angleDefects(positions, triangles);
  AngleDefect largest;
  for (VertexIndex v = 0; v < defects.size(); ++v) {
    if (std::isnan(defects[v])) continue;
    if (largest.vertex == kNoIndex || std::abs(defects[v]) > std::abs(largest.radians))
      largest = {v, defects[v]};
  }
  return largest;
}

std::vector<glm::dvec2> unfoldDevelopment(const std::vector<glm::dvec3>& positions,
                                          const std::vector<Triangle>& triangles,
                                          double relativeTolerance) {
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (VertexIndex v : triangles[t])
      if (v >= positions.size())
        throw NotDevelopable("triangle " + std::to_string(t) + " refers to vertex " +
                             std::to_string(v) + " of " + std::to_string(positions.size()));

  // Directed edge -> the triangle running along it; its twin is the neighbour across the edge.
  std::unordered_map<std::uint64_t, TriangleIndex> halfEdges;
  halfEdges.reserve(triangles.size() * 3);
  for (TriangleIndex t = 0; t < triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const VertexIndex u = triangles[t][i], v = triangles[t][(i + 1) % 3];
      if (!halfEdges.emplace(directedKey(u, v), t).second)
        throw NotDevelopable("edge (" + std::to_string(u) + ", " + std::to_string(v) +
                             ") is not manifold or not consistently oriented");
    }
  }

  std::vector<glm::dvec2> development(positions.size(), glm::dvec2(0.0));
  std::vector<bool> placed(positions.size(), false);
  std::vector<bool> reached(triangles.size(), false);
  std::deque<TriangleIndex> queue;
  double componentOffset = 0.0;  // components are laid side by side along x
  // Measured once: per component it made separate pieces cost O(pieces x vertices).
  const double size = boundingDiagonal(positions);
  auto dist = [&](VertexIndex a, VertexIndex b) {
    return glm::distance(positions[a], positions[b]);
  };

  for (TriangleIndex seed = 0; seed < triangles.size(); ++seed) {
    if (reached[seed]) continue;
    const Triangle& s = triangles[seed];
    // A component's vertices are all unplaced here, so the seed can be laid freely.
    development[s[0]] = glm::dvec2(componentOffset, 0.0);
    development[s[1]] = glm::dvec2(componentOffset + dist(s[0], s[1]), 0.0);
    development[s[2]] =
        placeLeft(development[s[0]], development[s[1]], dist(s[2], s[0]), dist(s[2], s[1]));
    for (VertexIndex v : s) placed[v] = true;
    reached[seed] = true;
    queue.push_back(seed);
    double rightmost = componentOffset;
    while (!queue.empty()) {
      const Triangle& t = triangles[queue.front()];
      queue.pop_front();
      for (VertexIndex v : t) rightmost = std::max(rightmost, development[v].x);
      for (int i = 0; i < 3; ++i) {
        const VertexIndex u = t[i], v = t[(i + 1) % 3];
        auto twin = halfEdges.find(directedKey(v, u));
        if (twin == halfEdges.end() || reached[twin->second]) continue;
        const TriangleIndex n = twin->second;
        reached[n] = true;
        const Triangle& nt = triangles[n];
        // The neighbour runs v->u; its third corner lies on the left of that edge.
        int k = 0;
        while (nt[k] == u || nt[k] == v) ++k;
        const VertexIndex w = nt[k];
        if (!placed[w]) {
          development[w] = placeLeft(development[v], development[u], dist(w, v), dist(w, u));
          placed[w] = true;
        }
        queue.push_back(n);
      }
    }
    componentOffset = rightmost + 0.1 * size;
  }

  // Every edge and orientation must agree; closing a loop around a curved vertex or a tube does
  // not.
  const double tolerance = relativeTolerance * size;
  for (TriangleIndex t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    const double area = glm::cross(development[tri[1]] - development[tri[0]],
                                   development[tri[2]] - development[tri[0]]);
    std::string problem;
    for (int i = 0; i < 3 && problem.empty(); ++i) {
      const VertexIndex u = tri[i], v = tri[(i + 1) % 3];
      const double error = std::abs(glm::distance(development[u], development[v]) - dist(u, v));
      if (error > tolerance) {
        std::ostringstream out;
        out.precision(6);
        out << "edge (" << u << ", " << v << ") unfolds " << error << " m away from its length";
        problem = out.str();
      }
    }
    if (problem.empty() && area <= 0.0)
      problem = "triangle " + std::to_string(t) + " unfolds flipped or degenerate";
    if (problem.empty()) continue;
    const AngleDefect defect = largestAngleDefect(positions, triangles);
    if (defect.vertex != kNoIndex && std::abs(defect.radians) > relativeTolerance)
      throw NotDevelopable("mesh is not developable: " + describeDefect(defect) + "; " + problem);
    throw NotDevelopable("mesh does not develop without a cut: " + problem +
                         " although every angle defect is within tolerance");
  }
  return development;
}

}  // namespace curvefold
