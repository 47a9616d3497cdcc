#include "engine/simulation/layer_order.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <numbers>
#include <set>

#include <glm/geometric.hpp>

#include "engine/geometry/self_intersection.hpp"
#include "engine/simulation/contact.hpp"

namespace curvefold {
namespace {

// How many times separateLayersUnlessCrossing flips the sides of pairs where the sheet crosses.
constexpr int kFlipAttempts = 3;

// The triangles' neighbours across hinges, for the shortest paths between layers.
class LayerPaths {
 public:
  LayerPaths(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
             const std::vector<double>& angles)
      : model_(model), x_(positions), angles_(angles), across_(model.triangles.size()) {
    for (std::uint32_t j = 0; j < model.hinges.size(); ++j) {
      const auto& [left, right] = model.hingeTriangles[j];
      across_[left].push_back({j, right});
      across_[right].push_back({j, left});
    }
  }

  int side(std::uint32_t v, std::uint32_t t) const {
    const auto& tri = model_.triangles[t];
    const glm::dvec3 &a = x_[tri[0]], &b = x_[tri[1]], &c = x_[tri[2]];
    glm::dvec3 normal = glm::cross(b - a, c - a);
    const double area = glm::length(normal);
    if (!(area > 0.0)) return 1;
    normal /= area;
    const glm::dvec3 w = nearestTriangleWeights(x_[v], a, b, c);
    const double off = glm::dot(normal, x_[v] - (w.x * a + w.y * b + w.z * c));
    if (std::abs(off) > 1e-3 * model_.contact.thickness) return off > 0.0 ? 1 : -1;
    const std::vector<std::uint32_t> path = hingesTo(v, t);
    for (const double degrees : {170.0, 90.0}) {
      const double along = glm::dot(normal, openingVelocity(v, t, path, degrees));
      if (std::abs(along) > 1e-9 * std::sqrt(area)) return along > 0.0 ? 1 : -1;
    }
    return off < 0.0 ? -1 : 1;
  }

 private:
  struct Across {
    std::uint32_t hinge = 0, triangle = 0;
  };

  // The hinges crossed from t to the nearest triangle (fewest hinges; ties by index) that has v.
  std::vector<std::uint32_t> hingesTo(std::uint32_t v, std::uint32_t t) const {
    constexpr std::uint32_t kNone = UINT32_MAX;
    std::vector<std::uint32_t> from(model_.triangles.size(), kNone), by(from.size(), kNone);
    std::deque<std::uint32_t> queue{t};
    from[t] = t;
    const auto has = [&](std::uint32_t u) {
      const auto& tri = model_.triangles[u];
      return tri[0] == v || tri[1] == v || tri[2] == v;
    };
    while (!queue.empty()) {
      const std::uint32_t u = queue.front();
      queue.pop_front();
      if (has(u)) {
        std::vector<std::uint32_t> path;
        for (std::uint32_t k = u; k != t; k = from[k]) path.push_back(by[k]);
        std::reverse(path.begin(), path.end());
        return path;
      }
      for (const Across& next : across_[u])
        if (from[next.triangle] == kNone) {
          from[next.triangle] = u;
          by[next.triangle] = next.hinge;
          queue.push_back(next.triangle);
        }
    }
    return {};
  }

  // How v moves while every fold on the path at least `degrees` from flat opens at one radian a
  // second, t held: the part beyond each hinge turns about its edge.
  glm::dvec3 openingVelocity(std::uint32_t v, std::uint32_t t,
                             const std::vector<std::uint32_t>& path, double degrees) const {
    glm::dvec3 velocity(0.0);
    std::uint32_t near = t;  // the path's triangle before this hinge
    for (std::uint32_t j : path) {
      const Hinge& h = model_.hinges[j];
      const bool farIsRight = model_.hingeTriangles[j][0] == near;
      near = model_.hingeTriangles[j][farIsRight ? 1 : 0];
      const double angle = angles_[j];
      if (std::abs(angle) < degrees * std::numbers::pi / 180.0) continue;
      const glm::dvec3 &a = x_[h.a], &b = x_[h.b];
      const glm::dvec3 axis = glm::normalize(b - a);
      // Which way about the axis opens the fold: turn the far wing a little and see.
      const double turn = 1e-3;
      const std::uint32_t wing = farIsRight ? h.d : h.c;
      const glm::dvec3 r = x_[wing] - a;
      const glm::dvec3 turned = a + r * std::cos(turn) + glm::cross(axis, r) * std::sin(turn) +
                                axis * glm::dot(axis, r) * (1.0 - std::cos(turn));
      const double after = farIsRight ? hingeAngle(a, b, x_[h.c], turned, angle)
                                      : hingeAngle(a, b, turned, x_[h.d], angle);
      const double opens = std::abs(after) < std::abs(angle) ? 1.0 : -1.0;
      velocity += opens * glm::cross(axis, x_[v] - a);
    }
    return velocity;
  }

  const BarHingeModel& model_;
  const std::vector<glm::dvec3>& x_;
  const std::vector<double>& angles_;
  std::vector<std::vector<Across>> across_;
};

}  // namespace

int layerSide(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
              const std::vector<double>& hingeAngles, std::uint32_t vertex,
              std::uint32_t triangle) {
  return LayerPaths(model, positions, hingeAngles).side(vertex, triangle);
}

namespace {

// separateLayers with the sides of some pairs given (`sides`: those already in it are kept, the
// others chosen by the folds and added).
LayerSeparation separateWithSides(const BarHingeModel& model, std::vector<glm::dvec3>& positions,
                                  const std::vector<double>& hingeAngles,
                                  std::map<ContactPair, int>& sides) {
  LayerSeparation out;
  if (!model.contact.enabled) return out;
  const double thickness = model.contact.thickness;
  const double wanted = thickness + 0.5 * model.contact.activation;
  constexpr std::size_t kSweeps = 20;
  for (; out.sweeps < kSweeps; ++out.sweeps) {
    std::vector<ContactPair> pairs = findContactPairs(model, positions, 0.0);
    std::erase_if(pairs, [](const ContactPair& pair) { return pair.edges != 0; });
    if (pairs.empty()) break;
    // The sides from the state before this sweep's moves (the first: the folds as designed).
    {
      const LayerPaths paths(model, positions, hingeAngles);
      for (const ContactPair& pair : pairs)
        if (!sides.count(pair)) sides[pair] = paths.side(pair.vertex, pair.triangle);
    }
    for (const ContactPair& pair : pairs) {
      const auto& tri = model.triangles[pair.triangle];
      const glm::dvec3 &a = positions[tri[0]], &b = positions[tri[1]], &c = positions[tri[2]];
      glm::dvec3 normal = glm::cross(b - a, c - a);
      const double area = glm::length(normal);
      if (!(area > 0.0)) continue;
      normal *= sides[pair] / area;
      const glm::dvec3 w = nearestTriangleWeights(positions[pair.vertex], a, b, c);
      const double gap = glm::dot(normal, positions[pair.vertex] - (w.x * a + w.y * b + w.z * c));
      if (gap >= wanted) continue;
      const double weights[4] = {1.0, -w.x, -w.y, -w.z};
      const std::uint32_t vertices[4] = {pair.vertex, tri[0], tri[1], tri[2]};
      double sum = 0.0;
      for (int k = 0; k < 4; ++k)
        if (!model.pinned[vertices[k]]) sum += weights[k] * weights[k];
      if (!(sum > 0.0)) continue;
      const double move = (wanted - gap) / sum;
      for (int k = 0; k < 4; ++k)
        if (!model.pinned[vertices[k]]) positions[vertices[k]] += move * weights[k] * normal;
    }
  }
  out.pairs = sides.size();
  for (const ContactPair& pair : findContactPairs(model, positions, 0.0)) out.left += !pair.edges;
  return out;
}

// The triangles of the pairs that cross (self_intersection.hpp).
std::set<std::uint32_t> crossingTriangles(const BarHingeModel& model,
                                          const std::vector<glm::dvec3>& positions) {
  Sheet sheet;
  sheet.positions = positions;
  for (const glm::dvec3& p : model.flatPositions) sheet.development.emplace_back(p.x, p.y);
  for (const auto& t : model.triangles) sheet.triangles.push_back({t[0], t[1], t[2]});
  std::set<std::uint32_t> out;
  for (const auto& [first, second] : findSelfIntersections(sheet).intersections) {
    out.insert(static_cast<std::uint32_t>(first));
    out.insert(static_cast<std::uint32_t>(second));
  }
  return out;
}

}  // namespace

LayerSeparation separateLayers(const BarHingeModel& model, std::vector<glm::dvec3>& positions,
                               const std::vector<double>& hingeAngles) {
  std::map<ContactPair, int> sides;  // chosen once, at the first sweep that finds the pair
  return separateWithSides(model, positions, hingeAngles, sides);
}

bool separateLayersUnlessCrossing(const BarHingeModel& model, std::vector<glm::dvec3>& positions,
                                  const std::vector<double>& hingeAngles) {
  const std::vector<glm::dvec3> given = positions;
  std::map<ContactPair, int> sides;
  if (separateWithSides(model, positions, hingeAngles, sides).pairs == 0) return false;
  if (crossingTrianglePairs(model, positions) == 0) return true;
  if (crossingTrianglePairs(model, given) > 0) return true;  // crossed as given: kept, as before
  // Sides the folds chose wrongly pass the sheet through itself where they moved it (xr_studio
  // glued: 3 pairs in touch became 3 crossing pairs): the pairs with a vertex or triangle among
  // the crossing triangles take the other side, and the separation is made again from the given
  // positions, a few times; what still crosses is undone.
  for (int attempt = 0; attempt < kFlipAttempts; ++attempt) {
    const std::set<std::uint32_t> crossing = crossingTriangles(model, positions);
    std::set<std::uint32_t> crossingVertices;
    for (std::uint32_t t : crossing)
      for (std::uint32_t v : model.triangles[t]) crossingVertices.insert(v);
    bool flipped = false;
    for (auto& [pair, side] : sides)
      if (crossing.count(pair.triangle) || crossingVertices.count(pair.vertex)) {
        side = -side;
        flipped = true;
      }
    if (!flipped) break;
    positions = given;
    separateWithSides(model, positions, hingeAngles, sides);
    if (crossingTrianglePairs(model, positions) == 0) return true;
  }
  positions = given;
  return false;
}

}  // namespace curvefold
