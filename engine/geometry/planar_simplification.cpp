#include "engine/geometry/planar_simplification.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/gtx/exterior_product.hpp>

#include "engine/geometry/topology.hpp"

namespace curvefold {
namespace {

std::uint64_t edgeKey(VertexIndex u, VertexIndex v) {
  const Edge e = Edge::of(u, v);
  return (std::uint64_t{e.a} << 32) | e.b;
}

// Smallest height of a development triangle: twice its area over its longest edge.
double smallestHeight(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  const double longest =
      std::sqrt(std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)}));
  return longest > 0.0 ? glm::cross(b - a, c - a) / longest : 0.0;
}

// An edge at a vertex that a collapse must keep straight: on the boundary, or tagged.
struct FeatureEdge {
  VertexIndex other = kNoIndex;
  bool boundary = false;
  int kind = -1;  // EdgeKind, or -1 untagged
};

class Simplifier {
 public:
  Simplifier(const Sheet& sheet, const PlanarSimplificationOptions& options)
      : input_(sheet), triangles_(sheet.triangles) {
    const double size = sheetSize(sheet);
    planeTolerance_ = options.relativePlaneTolerance * size;
    minHeight_ = options.relativeMinHeight * size;
    for (const TaggedEdge& tag : sheet.tags)
      tags_.emplace(edgeKey(tag.edge.a, tag.edge.b), tag.kind);
    const VertexTriangles incident = buildVertexTriangles(sheet);
    fans_.resize(sheet.vertexCount());
    for (VertexIndex v = 0; v < sheet.vertexCount(); ++v)
      fans_[v].assign(incident.of(v).begin(), incident.of(v).end());
    vertexAlive_.assign(sheet.vertexCount(), 1);
    slot_.assign(sheet.vertexCount(), 0);
    slotStamp_.assign(sheet.vertexCount(), 0);
    triangleAlive_.assign(sheet.triangleCount(), 1);
  }

  void run() {
    // Each pass tries every vertex whose neighbourhood changed since it was last refused (all of
    // them at first): a refused vertex may pass once its neighbours have gone. Passes repeat until
    // one changes nothing. A vertex first goes only into a neighbour with at least as many
    // triangles (so a triangle moves a logarithmic number of times, not once per vertex along a
    // ruling); then the few collapses that rule held back are made.
    for (const bool intoLarger : {true, false}) {
      intoLarger_ = intoLarger;
      pending_.assign(input_.vertexCount(), 1);
      for (int pass = 0; pass < 16; ++pass) {
        std::size_t collapsed = 0;
        for (VertexIndex v = 0; v < input_.vertexCount(); ++v) {
          if (!vertexAlive_[v] || !pending_[v]) continue;
          pending_[v] = 0;
          if (tryRemove(v)) ++collapsed;
        }
        if (collapsed == 0) break;
      }
    }
  }

  PlanarSimplification result() const {
    PlanarSimplification out;
    std::vector<VertexIndex> newIndex(input_.vertexCount(), kNoIndex);
    for (VertexIndex v = 0; v < input_.vertexCount(); ++v) {
      if (!vertexAlive_[v]) continue;
      newIndex[v] = VertexIndex(out.originalVertex.size());
      out.originalVertex.push_back(v);
      out.sheet.positions.push_back(input_.positions[v]);
      out.sheet.development.push_back(input_.development[v]);
    }
    for (TriangleIndex t = 0; t < triangles_.size(); ++t)
      if (triangleAlive_[t])
        out.sheet.triangles.push_back(
            {newIndex[triangles_[t][0]], newIndex[triangles_[t][1]], newIndex[triangles_[t][2]]});
    for (const auto& [key, kind] : tags_)
      out.sheet.tags.push_back(
          {Edge::of(newIndex[VertexIndex(key >> 32)], newIndex[VertexIndex(key)]), kind});
    out.sheet.normalizeTags();
    return out;
  }

 private:
  // Drops dead triangles from v's fan (they are left there when a neighbour's collapse kills them)
  // and lists v's neighbours with how many of its triangles hold each edge.
  void gatherNeighbourhood(VertexIndex v) {
    std::vector<TriangleIndex>& fan = fans_[v];
    std::erase_if(fan, [&](TriangleIndex t) { return !triangleAlive_[t]; });
    neighbours_.clear();
    ++gatherStamp_;
    for (TriangleIndex t : fan)
      for (VertexIndex w : triangles_[t]) {
        if (w == v) continue;
        if (slotStamp_[w] != gatherStamp_) {
          slotStamp_[w] = gatherStamp_;
          slot_[w] = std::uint32_t(neighbours_.size());
          neighbours_.push_back({w, 0});
        }
        ++neighbours_[slot_[w]].second;
      }
    features_.clear();
    nonManifold_ = false;
    for (const auto& [w, count] : neighbours_) {
      nonManifold_ = nonManifold_ || count > 2;
      const auto tag = tags_.find(edgeKey(v, w));
      const int kind = tag == tags_.end() ? -1 : int(tag->second);
      if (count == 1 || kind >= 0) features_.push_back({w, count == 1, kind});
    }
  }

  bool tryRemove(VertexIndex v) {
    gatherNeighbourhood(v);
    if (fans_[v].empty() || nonManifold_) return false;
    if (features_.empty()) {
      // Into the lowest-numbered neighbour first: in this pass it was tried already and stayed,
      // so the triangles drain into survivors and the fan moved is v's own small one.
      candidates_.clear();
      for (const auto& [u, count] : neighbours_) candidates_.push_back(u);
      std::sort(candidates_.begin(), candidates_.end());
      for (VertexIndex u : candidates_)
        if (canCollapse(v, u)) {
          collapse(v, u);
          return true;
        }
      return false;
    }
    // On a boundary, slit or crease: only along it, where it runs straight through v, so its
    // shape is kept.
    if (features_.size() != 2) return false;
    const FeatureEdge& a = features_[0];
    const FeatureEdge& b = features_[1];
    if (a.boundary != b.boundary || a.kind != b.kind) return false;
    const glm::dvec3& pv = input_.positions[v];
    const glm::dvec3 along = input_.positions[b.other] - input_.positions[a.other];
    const double length = glm::length(along);
    if (length == 0.0) return false;
    const glm::dvec3 offLine = glm::cross(pv - input_.positions[a.other], along) / length;
    if (glm::length(offLine) > planeTolerance_) return false;
    const double t = glm::dot(pv - input_.positions[a.other], along) / (length * length);
    if (t <= 0.0 || t >= 1.0) return false;  // v must lie between its two neighbours
    for (VertexIndex u : {a.other, b.other})
      if (canCollapse(v, u)) {
        collapse(v, u);
        return true;
      }
    return false;
  }

  // Whether a live triangle holds both a and b, looked up in the smaller fan.
  bool shareEdge(VertexIndex a, VertexIndex b) const {
    const bool aSmaller = fans_[a].size() <= fans_[b].size();
    const VertexIndex other = aSmaller ? b : a;
    for (TriangleIndex t : fans_[aSmaller ? a : b])
      if (triangleAlive_[t] &&
          std::find(triangles_[t].begin(), triangles_[t].end(), other) != triangles_[t].end())
        return true;
    return false;
  }

  // Whether moving v onto its neighbour u keeps the surface: every triangle that stays keeps its
  // plane, orientation and a usable height, and the link condition holds.
  bool canCollapse(VertexIndex v, VertexIndex u) {
    if (intoLarger_ && fans_[u].size() < fans_[v].size()) {
      pending_[u] = 1;  // u may go into v instead
      return false;
    }
    // Link condition: v and u share no neighbour except across the triangles on edge v-u.
    VertexIndex opposite[2] = {kNoIndex, kNoIndex};
    int oppositeCount = 0;
    for (TriangleIndex t : fans_[v]) {
      const Triangle& tri = triangles_[t];
      if (std::find(tri.begin(), tri.end(), u) == tri.end()) continue;
      if (oppositeCount == 2) return false;
      for (VertexIndex w : tri)
        if (w != u && w != v) opposite[oppositeCount++] = w;
    }
    for (const auto& [w, count] : neighbours_)
      if (w != u && w != opposite[0] && w != opposite[1] && shareEdge(u, w)) return false;
    const glm::dvec3& pu = input_.positions[u];
    const glm::dvec2& du = input_.development[u];
    for (TriangleIndex t : fans_[v]) {
      const Triangle& tri = triangles_[t];
      if (std::find(tri.begin(), tri.end(), u) != tri.end()) continue;  // removed by the collapse
      const glm::dvec3 p0 = input_.positions[tri[0]], p1 = input_.positions[tri[1]],
                       p2 = input_.positions[tri[2]];
      const glm::dvec3 normal = glm::cross(p1 - p0, p2 - p0);
      const double area2 = glm::length(normal);
      if (area2 == 0.0) return false;
      if (std::abs(glm::dot(normal, pu - input_.positions[v])) > planeTolerance_ * area2)
        return false;
      std::array<glm::dvec3, 3> moved{p0, p1, p2};
      std::array<glm::dvec2, 3> flat{input_.development[tri[0]], input_.development[tri[1]],
                                     input_.development[tri[2]]};
      for (int k = 0; k < 3; ++k)
        if (tri[k] == v) {
          moved[k] = pu;
          flat[k] = du;
        }
      if (glm::dot(glm::cross(moved[1] - moved[0], moved[2] - moved[0]), normal) <= 0.0)
        return false;
      if (smallestHeight(flat[0], flat[1], flat[2]) < minHeight_) return false;
    }
    return true;
  }

  void collapse(VertexIndex v, VertexIndex u) {
    for (TriangleIndex t : fans_[v]) {
      Triangle& tri = triangles_[t];
      if (std::find(tri.begin(), tri.end(), u) != tri.end()) {
        triangleAlive_[t] = 0;
        continue;
      }
      std::replace(tri.begin(), tri.end(), v, u);
      fans_[u].push_back(t);
      for (VertexIndex w : tri) pending_[w] = 1;
    }
    for (const auto& [w, count] : neighbours_) {
      const auto tag = tags_.find(edgeKey(v, w));
      std::optional<EdgeKind> kind;
      if (tag != tags_.end()) {
        kind = tag->second;
        tags_.erase(tag);
      }
      if (w == u) continue;
      if (kind) tags_[edgeKey(u, w)] = *kind;
    }
    fans_[v] = {};
    vertexAlive_[v] = 0;
  }

  const Sheet& input_;
  std::vector<Triangle> triangles_;
  std::vector<std::vector<TriangleIndex>> fans_;  // may hold dead triangles until next gathered
  std::vector<char> vertexAlive_;
  std::vector<char> pending_;  // to be tried in the next pass
  bool intoLarger_ = true;
  std::vector<char> triangleAlive_;
  std::unordered_map<std::uint64_t, EdgeKind> tags_;
  double planeTolerance_ = 0.0;
  double minHeight_ = 0.0;
  std::vector<std::pair<VertexIndex, int>> neighbours_;  // of the vertex being tried
  std::vector<FeatureEdge> features_;
  bool nonManifold_ = false;  // an edge at v with more than two triangles: v stays
  std::vector<VertexIndex> candidates_;
  std::vector<std::uint32_t> slot_;  // index in neighbours_, valid where slotStamp_ is current
  std::vector<std::uint32_t> slotStamp_;
  std::uint32_t gatherStamp_ = 0;
};

}  // namespace

PlanarSimplification simplifyPlanar(const Sheet& sheet,
                                    const PlanarSimplificationOptions& options) {
  Simplifier simplifier(sheet, options);
  simplifier.run();
  return simplifier.result();
}

}  // namespace curvefold
