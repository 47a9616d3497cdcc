#include "engine/fit/target_unfolding.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <glm/geometric.hpp>

#include "engine/fit/crease_planes.hpp"
#include "engine/fit/surface_distance.hpp"

namespace curvefold {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct MeshEdge {
  std::uint32_t a = 0, b = 0;
  std::uint32_t faces[2] = {0, 0};
};

// The mesh's connectivity, which unfolding never changes.
struct Connectivity {
  std::vector<MeshEdge> interior;                      // edges with exactly two faces
  std::vector<std::vector<std::uint32_t>> neighbours;  // per vertex
};

Connectivity connectivityOf(const TriangleMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> faces;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = mesh.triangles[t][i], v = mesh.triangles[t][(i + 1) % 3];
      faces[{std::min(u, v), std::max(u, v)}].push_back(t);
    }
  Connectivity c;
  c.neighbours.resize(mesh.positions.size());
  for (const auto& [edge, around] : faces) {
    c.neighbours[edge.first].push_back(edge.second);
    c.neighbours[edge.second].push_back(edge.first);
    if (around.size() == 2) c.interior.push_back({edge.first, edge.second, {around[0], around[1]}});
  }
  return c;
}

glm::dvec3 faceNormal(const std::vector<glm::dvec3>& p, const std::array<std::uint32_t, 3>& t) {
  const glm::dvec3 n = glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
  const double length = glm::length(n);
  return length > 0.0 ? n / length : glm::dvec3(0.0);
}

// Total length of the edges whose faces turn by more than the threshold.
double sharpLength(const TriangleMesh& mesh, const Connectivity& c,
                   const std::vector<glm::dvec3>& positions, double cosThreshold) {
  std::vector<glm::dvec3> normals(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    normals[t] = faceNormal(positions, mesh.triangles[t]);
  double total = 0.0;
  for (const MeshEdge& e : c.interior)
    if (glm::dot(normals[e.faces[0]], normals[e.faces[1]]) < cosThreshold)
      total += glm::distance(positions[e.a], positions[e.b]);
  return total;
}

struct Candidate {
  ReflectionPlane plane;
  std::vector<std::uint32_t> part;
  double sharpAfter = 0.0;
  std::size_t anchored = 0;
};

}  // namespace

namespace {

struct Unfolder {
  const TriangleMesh& target;
  const Connectivity connectivity;
  const double diagonal, onPlane, onSheet, cosThreshold, minDihedralDegrees;
  const SurfaceDistanceQuery& sheetSurface;
  std::size_t maxFolds;
  std::size_t leaves = 0;  // unfoldings finished, to bound the branching

  // Where the unfolded target lies off the sheet, on average: the right unfolding lies on it.
  double offSheet(const std::vector<glm::dvec3>& positions) const {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t v = 0; v < positions.size(); v += 1 + positions.size() / 500, ++count)
      sum += sheetSurface.distance(positions[v]);
    return count ? sum / static_cast<double>(count) : 0.0;
  }

  std::vector<Candidate> candidatesAt(const std::vector<glm::dvec3>& positions) const {
    TriangleMesh current{positions, target.triangles};
    CreasePlaneOptions options;
    options.minDihedralDegrees = minDihedralDegrees;
    options.maxPlanes = 8;
    const std::vector<CreasePlane> planes = findCreasePlanes(current, options);
    std::vector<char> anchored(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v)
      anchored[v] =
          !connectivity.neighbours[v].empty() && sheetSurface.distance(positions[v]) <= onSheet;
    std::vector<Candidate> candidates;
    std::vector<int> component(positions.size());
    for (const CreasePlane& crease : planes) {
      const ReflectionPlane& plane = crease.plane;
      std::vector<double> d(positions.size());
      for (std::size_t v = 0; v < positions.size(); ++v) d[v] = plane.signedDistance(positions[v]);
      std::fill(component.begin(), component.end(), -1);
      // The pieces next to the crease: grown from each vertex of a face on a sharp edge in the
      // plane, through vertices on its side.
      for (const MeshEdge& e : connectivity.interior) {
        if (std::abs(d[e.a]) > onPlane || std::abs(d[e.b]) > onPlane) continue;
        const glm::dvec3 n0 = faceNormal(positions, target.triangles[e.faces[0]]);
        const glm::dvec3 n1 = faceNormal(positions, target.triangles[e.faces[1]]);
        if (glm::dot(n0, n1) >= cosThreshold) continue;
        for (std::uint32_t face : e.faces)
          for (std::uint32_t seed : target.triangles[face]) {
            if (std::abs(d[seed]) <= onPlane || component[seed] >= 0) continue;
            Candidate candidate;
            candidate.plane = plane;
            const bool positive = d[seed] > 0.0;
            std::vector<std::uint32_t> stack{seed};
            component[seed] = 1;
            while (!stack.empty()) {
              const std::uint32_t v = stack.back();
              stack.pop_back();
              candidate.part.push_back(v);
              candidate.anchored += anchored[v];
              for (std::uint32_t w : connectivity.neighbours[v])
                if (component[w] < 0 && std::abs(d[w]) > onPlane && (d[w] > 0.0) == positive) {
                  component[w] = 1;
                  stack.push_back(w);
                }
            }
            std::vector<glm::dvec3> moved = positions;
            for (std::uint32_t v : candidate.part) moved[v] = plane.reflect(moved[v]);
            candidate.sharpAfter = sharpLength(target, connectivity, moved, cosThreshold);
            candidates.push_back(std::move(candidate));
          }
      }
    }
    return candidates;
  }

  // Unfolds from `positions` (folds found so far in `backwards`); returns the best unfolding.
  TargetUnfolding unfold(std::vector<glm::dvec3> positions, std::vector<UnfoldedFold> backwards,
                         double sharp) {
    std::vector<Candidate> candidates;
    if (backwards.size() < maxFolds) candidates = candidatesAt(positions);
    double least = kInfinitySharp;
    for (const Candidate& c : candidates) least = std::min(least, c.sharpAfter);
    // Unfolding must take a crease away, not trade one for another.
    if (candidates.empty() || !(least < sharp - 0.02 * diagonal)) {
      ++leaves;
      TargetUnfolding result;
      result.folds.assign(backwards.rbegin(), backwards.rend());
      result.sharpLengthLeft = sharp;
      result.unfolded = std::move(positions);
      return result;
    }
    // The sides of the crease that unfold it alike, the one holding more of the sheet last (the
    // side that never moved stays where the sheet is): both are followed, while fewer than
    // kMaxUnfoldings have ended (their unfoldings differ by a reflection of the whole), and the
    // one that ends on the sheet wins.
    std::vector<const Candidate*> sides;
    for (const Candidate& c : candidates)
      if (c.sharpAfter <= least + 1e-6 * diagonal) sides.push_back(&c);
    std::stable_sort(sides.begin(), sides.end(), [](const Candidate* a, const Candidate* b) {
      return a->anchored != b->anchored ? a->anchored < b->anchored
                                        : a->part.size() < b->part.size();
    });
    const std::size_t tries = leaves >= kMaxUnfoldings ? 1 : std::min<std::size_t>(2, sides.size());
    TargetUnfolding best;
    double bestOff = kInfinitySharp;
    for (std::size_t k = 0; k < tries; ++k) {
      const Candidate& chosen = *sides[k];
      std::vector<glm::dvec3> next = positions;
      UnfoldedFold fold;
      fold.plane = chosen.plane;
      double deepest = -1.0;
      for (std::uint32_t v : chosen.part) {
        next[v] = chosen.plane.reflect(next[v]);
        const double depth = std::abs(chosen.plane.signedDistance(next[v]));
        if (depth > deepest) {
          deepest = depth;
          fold.seedBefore = next[v];
        }
      }
      std::vector<UnfoldedFold> more = backwards;
      more.push_back(fold);
      TargetUnfolding result = unfold(std::move(next), std::move(more), chosen.sharpAfter);
      const double off = tries > 1 ? offSheet(result.unfolded) : 0.0;
      // The unfolding that takes away more creases, then the one that ends on the sheet.
      if (k == 0 || result.sharpLengthLeft < best.sharpLengthLeft - 0.02 * diagonal ||
          (result.sharpLengthLeft <= best.sharpLengthLeft + 0.02 * diagonal && off < bestOff)) {
        best = std::move(result);
        bestOff = off;
      }
    }
    return best;
  }

  static constexpr double kInfinitySharp = 1e300;
  static constexpr std::size_t kMaxUnfoldings = 8;
};

}  // namespace

TargetUnfolding unfoldTarget(const TriangleMesh& target, const TriangleMesh& sheet,
                             double minDihedralDegrees, std::size_t maxFolds) {
  const double diagonal = boundingDiagonal(target);
  const SurfaceDistanceQuery sheetSurface(sheet, "sheet");
  Unfolder unfolder{target,
                    connectivityOf(target),
                    diagonal,
                    1e-5 * diagonal,  // a crease's vertices, to the digits a file keeps
                    1e-4 * diagonal,
                    std::cos(minDihedralDegrees * kPi / 180.0),
                    minDihedralDegrees,
                    sheetSurface,
                    maxFolds};
  const double sharp =
      sharpLength(target, unfolder.connectivity, target.positions, unfolder.cosThreshold);
  return unfolder.unfold(target.positions, {}, sharp);
}

}  // namespace curvefold
