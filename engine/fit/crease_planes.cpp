#include "engine/fit/crease_planes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <random>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "engine/fit/unit_draw.hpp"

namespace curvefold {
namespace {

struct SharpEdge {
  glm::dvec3 a{0.0}, b{0.0};
  glm::dvec3 na{0.0}, nb{0.0};  // the two faces' unit normals
  double length = 0.0;
};

// Each edge with exactly two faces, with the angle its faces turn by (degrees).
template <typename Visit>
void forEachInteriorEdge(const TriangleMesh& mesh, Visit visit) {
  for (const auto& [edge, around] : edgeFaces(mesh)) {
    if (around.size() != 2) continue;
    const glm::dvec3 n1 = faceNormal(mesh.positions, mesh.triangles[around[0]]);
    const glm::dvec3 n2 = faceNormal(mesh.positions, mesh.triangles[around[1]]);
    if (n1 == glm::dvec3(0.0) || n2 == glm::dvec3(0.0)) continue;
    // Two faces that share an edge the same way up have the same normal when flat.
    const double degrees =
        std::acos(std::clamp(glm::dot(n1, n2), -1.0, 1.0)) * 180.0 / std::numbers::pi;
    visit(edge.first, edge.second, n1, n2, degrees);
  }
}

// The normal of the plane through a sharp edge (direction `along`) that mirrors its faces: the
// faces' normals are one another's mirror images reversed, so their sum lies along it and their
// difference in it. Whichever is longer is read: at a fold of 180 degrees the sum vanishes (the
// plane stands across the two layers), at a shallow one the difference does.
glm::dvec3 mirroringNormal(const SharpEdge& e, const glm::dvec3& along) {
  const glm::dvec3 sum = e.na + e.nb, difference = e.na - e.nb;
  const glm::dvec3 n = glm::length(sum) >= glm::length(difference)
                           ? sum - glm::dot(sum, along) * along
                           : glm::cross(along, difference);
  const double length = glm::length(n);
  return length > 0.0 ? n / length : glm::dvec3(0.0);
}

// A straight crease: the line its sharp edges lie along and the normal of the plane through it
// that mirrors their faces.
struct CreaseLine {
  glm::dvec3 point{0.0}, along{0.0}, normal{0.0};
};

// The line of least squares through `edges` (each a uniform segment, weighted by its length): their
// centroid and the principal direction of their second moments (power iteration from the
// farthest point).
std::optional<CreaseLine> lineThrough(const std::vector<SharpEdge>& sharp,
                                      const std::vector<std::size_t>& edges) {
  double total = 0.0;
  glm::dvec3 centroid(0.0);
  for (std::size_t i : edges) {
    total += sharp[i].length;
    centroid += sharp[i].length * 0.5 * (sharp[i].a + sharp[i].b);
  }
  if (!(total > 0.0)) return std::nullopt;
  centroid /= total;
  glm::dmat3 moments(0.0);
  glm::dvec3 along(0.0);
  for (std::size_t i : edges) {
    const glm::dvec3 a = sharp[i].a - centroid, b = sharp[i].b - centroid;
    moments += sharp[i].length * ((glm::outerProduct(a, a) + glm::outerProduct(b, b)) / 3.0 +
                                  (glm::outerProduct(a, b) + glm::outerProduct(b, a)) / 6.0);
    for (const glm::dvec3& p : {a, b})
      if (glm::length(p) > glm::length(along)) along = p;
  }
  for (int k = 0; k < 20 && glm::length(along) > 0.0; ++k) along = glm::normalize(moments * along);
  if (!(glm::length(along) > 0.5)) return std::nullopt;
  return CreaseLine{centroid, along, glm::dvec3(0.0)};
}

double offLine(const CreaseLine& line, const glm::dvec3& p) {
  const glm::dvec3 d = p - line.point;
  return glm::length(d - glm::dot(d, line.along) * line.along);
}

// The crease line of `edges` when nearly all of them (by length) lie along one line within
// `tolerance`: fitted to all of them, far more exact than one short edge's direction, then again
// to those on it (not the stub of a crease that meets it); and the mirroring normal averaged over
// them by length, those more than half a degree off the first average left out (a sliver's face).
// Its sign follows `reference`.
std::optional<CreaseLine> straightCrease(const std::vector<SharpEdge>& sharp,
                                         std::vector<std::size_t> edges, double tolerance,
                                         const glm::dvec3& reference) {
  if (edges.size() < 2) return std::nullopt;
  double total = 0.0;
  for (std::size_t i : edges) total += sharp[i].length;
  std::optional<CreaseLine> line;
  for (int pass = 0; pass < 2; ++pass) {
    line = lineThrough(sharp, edges);
    if (!line) return std::nullopt;
    std::vector<std::size_t> on;
    double kept = 0.0;
    for (std::size_t i : edges)
      if (offLine(*line, sharp[i].a) <= tolerance && offLine(*line, sharp[i].b) <= tolerance) {
        on.push_back(i);
        kept += sharp[i].length;
      }
    if (kept < 0.98 * total || on.size() < 2) return std::nullopt;
    edges = std::move(on);
  }
  std::vector<glm::dvec3> normals;
  for (std::size_t i : edges) {
    glm::dvec3 n = mirroringNormal(sharp[i], line->along);
    normals.push_back(glm::dot(n, reference) < 0.0 ? -n : n);
  }
  const double within = std::cos(0.5 * std::numbers::pi / 180.0);
  for (int pass = 0; pass < 2; ++pass) {
    const glm::dvec3 mean =
        line->normal == glm::dvec3(0.0) ? glm::dvec3(0.0) : glm::normalize(line->normal);
    glm::dvec3 sum(0.0);
    for (std::size_t k = 0; k < edges.size(); ++k)
      if (pass == 0 || glm::dot(normals[k], mean) >= within)
        sum += sharp[edges[k]].length * normals[k];
    if (!(glm::length(sum) > 0.0)) return std::nullopt;
    line->normal = sum;
  }
  line->normal = glm::normalize(line->normal - glm::dot(line->normal, line->along) * line->along);
  return line;
}

// The open sharp edges within `tolerance` of `line`.
std::vector<std::size_t> edgesAlong(const std::vector<SharpEdge>& sharp,
                                    const std::vector<std::size_t>& open, const CreaseLine& line,
                                    double tolerance) {
  std::vector<std::size_t> on;
  for (std::size_t i : open)
    if (offLine(line, sharp[i].a) <= tolerance && offLine(line, sharp[i].b) <= tolerance)
      on.push_back(i);
  return on;
}

// How near (of the diagonal) a fold's own crease lies in its plane: a mesh written to full
// precision keeps it to 1e-9, one written to six digits to about 1e-6.
constexpr double kTightTolerance = 2e-6;
constexpr int kTightHypotheses = 200;

// Of `inside` (sharp edges a plane holds within the consensus tolerance), the plane through
// three of their end points far apart that holds the most of their length within `within`
// (`holds(plane, edge, within)`), where it holds more than half of it; none where no wide triangle
// is drawn (a straight crease: its points leave the plane free to turn about it).
template <typename Holds>
std::optional<CreasePlane> tightPlane(const std::vector<SharpEdge>& sharp,
                                      const std::vector<std::size_t>& inside, Holds holds,
                                      double within, std::uint64_t seed) {
  if (inside.size() < 3) return std::nullopt;
  double total = 0.0;
  for (std::size_t i : inside) total += sharp[i].length;
  std::mt19937_64 random(seed);
  auto draw = [&]() -> const SharpEdge& {
    return sharp[inside[std::size_t(unit(random) * inside.size()) % inside.size()]];
  };
  std::optional<CreasePlane> best;
  for (int k = 0; k < kTightHypotheses; ++k) {
    const glm::dvec3 a = draw().a, b = draw().b, c = draw().a;
    const glm::dvec3 n = glm::cross(b - a, c - a);
    if (glm::length(n) < 1e-2 * glm::distance(a, b) * glm::distance(a, c) ||
        !(glm::length(n) > 0.0))
      continue;
    const ReflectionPlane plane{a, glm::normalize(n)};
    double held = 0.0;
    for (std::size_t i : inside)
      if (holds(plane, sharp[i], within)) held += sharp[i].length;
    if (!best || held > best->support) best = CreasePlane{plane, held};
  }
  if (!best || !(best->support > 0.5 * total)) return std::nullopt;
  return best;
}

constexpr double kMinimumSharpDegrees = 4.0;
// A crease this long (of the diagonal) names a plane: a fold of a corner makes a short one.
constexpr double kMinimumSupport = 0.005;

}  // namespace

double largestDihedralDegrees(const TriangleMesh& mesh) {
  double largest = 0.0;
  forEachInteriorEdge(mesh, [&](auto, auto, const auto&, const auto&, double degrees) {
    largest = std::max(largest, degrees);
  });
  return largest;
}

double largestBendBelow(const TriangleMesh& mesh, double degrees) {
  double largest = 0.0;
  forEachInteriorEdge(mesh, [&](auto, auto, const auto&, const auto&, double bend) {
    if (bend < degrees) largest = std::max(largest, bend);
  });
  return largest;
}

double sharpEdgeThreshold(const TriangleMesh& initialSheet) {
  // A flat sheet's faces do not bend at all: a shallow fold (a drag mostly off the sheet bends
  // it by a few degrees) is read there as well as a steep one.
  return sharpEdgeThresholdFor(largestDihedralDegrees(initialSheet));
}

double facetBendDegrees(const TriangleMesh& target) {
  std::vector<std::pair<double, double>> bends;  // degrees, length
  double total = 0.0;
  forEachInteriorEdge(
      target, [&](std::uint32_t u, std::uint32_t v, const auto&, const auto&, double degrees) {
        const double length = glm::distance(target.positions[u], target.positions[v]);
        bends.emplace_back(degrees, length);
        total += length;
      });
  std::sort(bends.begin(), bends.end());
  double below = 0.0, facets = 0.0;
  for (const auto& [degrees, length] : bends) {
    facets = degrees;
    if ((below += length) >= 0.9 * total) break;
  }
  return facets;
}

std::optional<double> facetBendBelowGap(const TriangleMesh& target, double* above) {
  const double floor = facetBendDegrees(target);
  std::vector<double> bends;
  forEachInteriorEdge(target,
                      [&](std::uint32_t, std::uint32_t, const auto&, const auto&, double degrees) {
                        if (degrees >= floor) bends.push_back(degrees);
                      });
  std::sort(bends.begin(), bends.end());
  // Bends under a degree part by large ratios from nothing: they are facets whatever follows.
  double best = kFacetGap, lower = 0.0, upper = 0.0;
  for (std::size_t k = 0; k + 1 < bends.size(); ++k) {
    const double low = std::max(bends[k], 1.0), ratio = bends[k + 1] / low;
    if (ratio >= best) {
      best = ratio;
      lower = bends[k];
      upper = bends[k + 1];
    }
  }
  if (upper <= 0.0) return std::nullopt;
  if (above) *above = upper;
  return lower;
}

double sharpEdgeThresholdFor(double facetBendDegrees) {
  return std::max(kMinimumSharpDegrees, 1.5 * facetBendDegrees + 2.0);
}

std::vector<CreasePlane> findCreasePlanes(const TriangleMesh& mesh,
                                          const CreasePlaneOptions& options) {
  const double diagonal = boundingDiagonal(mesh);
  const double tolerance = options.tolerance > 0.0 ? options.tolerance : 1e-4 * diagonal;
  const double minSupport =
      options.minSupport > 0.0 ? options.minSupport : kMinimumSupport * diagonal;
  std::vector<SharpEdge> sharp;
  forEachInteriorEdge(mesh, [&](std::uint32_t u, std::uint32_t v, const glm::dvec3& n1,
                                const glm::dvec3& n2, double degrees) {
    if (degrees < options.minDihedralDegrees) return;
    SharpEdge e{mesh.positions[u], mesh.positions[v], n1, n2, 0.0};
    e.length = glm::distance(e.a, e.b);
    if (e.length > 0.0) sharp.push_back(e);
  });

  std::vector<CreasePlane> planes;
  std::vector<char> used(sharp.size(), 0);
  std::mt19937_64 random(options.seed);
  // An edge is in a fold's plane when it lies in it and the plane mirrors one face's
  // normal onto the other's (up to sign): the plane of a flat region that holds two creases
  // lies along both, but mirrors neither. Within the threshold, not less: where a crease runs
  // along an edge of a curved sheet's facets, its faces come from two facets, which bent apart
  // by up to two thirds of it before the fold.
  const double consistent = std::cos(options.minDihedralDegrees * std::numbers::pi / 180.0);
  auto holdsWithin = [&](const ReflectionPlane& plane, const SharpEdge& e, double within) {
    if (std::abs(plane.signedDistance(e.a)) > within ||
        std::abs(plane.signedDistance(e.b)) > within)
      return false;
    // A reflection turns a face over: the fold's plane mirrors one face's normal onto the
    // other's reversed. The plane across it through the crease mirrors it onto the other's
    // unreversed; where flaps lie flat on the sheet, every crease lies in the sheet's plane,
    // which would otherwise hold them all.
    const glm::dvec3 mirrored = e.na - 2.0 * glm::dot(e.na, plane.normal) * plane.normal;
    return -glm::dot(mirrored, e.nb) >= consistent;
  };
  auto holds = [&](const ReflectionPlane& plane, const SharpEdge& e) {
    return holdsWithin(plane, e, tolerance);
  };
  auto support = [&](const ReflectionPlane& plane) {
    double total = 0.0;
    for (std::size_t i = 0; i < sharp.size(); ++i)
      if (!used[i] && holds(plane, sharp[i])) total += sharp[i].length;
    return total;
  };
  while (planes.size() < options.maxPlanes) {
    std::vector<std::size_t> open;
    for (std::size_t i = 0; i < sharp.size(); ++i)
      if (!used[i]) open.push_back(i);
    if (open.empty()) break;
    CreasePlane best;
    auto consider = [&](const glm::dvec3& point, glm::dvec3 normal) {
      const double length = glm::length(normal);
      if (!(length > 1e-9)) return;
      const ReflectionPlane plane{point, normal / length};
      const double s = support(plane);
      if (s > best.support) best = {plane, s};
    };
    // Straight creases: the plane through each sharp edge that mirrors its faces (of at most 400
    // edges, spread over all), and through the line of the sharp edges collinear with it.
    const std::size_t stride = std::max<std::size_t>(1, open.size() / 400);
    for (std::size_t k = 0; k < open.size(); k += stride) {
      const SharpEdge& e = sharp[open[k]];
      const glm::dvec3 middle = 0.5 * (e.a + e.b), along = (e.b - e.a) / e.length;
      const glm::dvec3 normal = mirroringNormal(e, along);
      consider(middle, normal);
      // The edges along it, gathered again along the line they give (one short edge's
      // direction may miss the far end of a long crease).
      std::optional<CreaseLine> line = straightCrease(
          sharp, edgesAlong(sharp, open, {middle, along, normal}, tolerance), tolerance, normal);
      if (line)
        line = straightCrease(sharp, edgesAlong(sharp, open, *line, tolerance), tolerance, normal);
      if (line) consider(line->point, line->normal);
    }
    // Curved creases: three points of sharp edges.
    for (std::size_t k = 0; k < options.hypotheses; ++k) {
      const SharpEdge& e = sharp[open[std::size_t(unit(random) * open.size()) % open.size()]];
      const SharpEdge& f = sharp[open[std::size_t(unit(random) * open.size()) % open.size()]];
      const glm::dvec3 n = glm::cross(e.b - e.a, f.a - e.a);
      // Nearly collinear points leave the plane free to turn: only a wide triangle counts.
      if (glm::length(n) < 1e-2 * e.length * glm::distance(f.a, e.a)) continue;
      consider(e.a, n);
    }
    if (best.support < minSupport) break;
    // Many planes turned slightly about a straight crease hold all of it: the one its edges
    // name together, not whichever hypothesis came first.
    std::vector<std::size_t> inside;
    for (std::size_t i : open)
      if (holds(best.plane, sharp[i])) inside.push_back(i);
    const std::optional<CreaseLine> line =
        straightCrease(sharp, inside, tolerance, best.plane.normal);
    if (line) {
      const ReflectionPlane refined{line->point, line->normal};
      const double s = support(refined);
      if (s >= 0.98 * best.support) best = {refined, s};
    }
    // Near-coplanar folds lay their creases along each other: a plane within the tolerance of
    // both may hold edges of each and so lie up to the tolerance off the fold's own plane, enough
    // to leave a crease vertex of the other fold on the wrong side of it (the unfolding then
    // reflects a piece short of that vertex). A fold's own crease lies in its plane to the digits
    // the mesh keeps: where a plane through three of the edges holds most of them (by length)
    // within kTightTolerance, that plane is the fold's. Its own random draws, so the planes read
    // after it are drawn as before.
    inside.clear();
    for (std::size_t i : open)
      if (holds(best.plane, sharp[i])) inside.push_back(i);
    // A straight crease's plane is refitted to its whole line above (three of its points and a
    // stub of another crease beside it name a plane turned about it).
    if (const std::optional<CreasePlane> tight =
            line ? std::nullopt
                 : tightPlane(sharp, inside, holdsWithin, kTightTolerance * diagonal,
                              options.seed + planes.size())) {
      // The normal's sign as the consensus read it (a fold's plane faces the way it was read).
      const ReflectionPlane plane{tight->plane.point,
                                  glm::dot(tight->plane.normal, best.plane.normal) < 0.0
                                      ? -tight->plane.normal
                                      : tight->plane.normal};
      best = {plane, support(plane)};
      inside.clear();
      for (std::size_t i : open)
        if (holds(best.plane, sharp[i])) inside.push_back(i);
    }
    for (std::size_t i : inside) used[i] = 1;
    planes.push_back(best);
  }
  return planes;
}

}  // namespace curvefold
