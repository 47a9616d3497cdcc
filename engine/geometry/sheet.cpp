#include "engine/geometry/sheet.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/common.hpp>

namespace curvefold {

std::optional<EdgeKind> Sheet::edgeKind(Edge edge) const {
  auto it = std::lower_bound(tags.begin(), tags.end(), edge,
                             [](const TaggedEdge& t, const Edge& e) { return t.edge < e; });
  if (it == tags.end() || it->edge != edge) return std::nullopt;
  return it->kind;
}

void Sheet::normalizeTags() {
  std::stable_sort(tags.begin(), tags.end(),
                   [](const TaggedEdge& x, const TaggedEdge& y) { return x.edge < y.edge; });
  tags.erase(std::unique(tags.begin(), tags.end(),
                         [](const TaggedEdge& x, const TaggedEdge& y) { return x.edge == y.edge; }),
             tags.end());
}

namespace {
template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}
}  // namespace

bool identical(const Sheet& a, const Sheet& b) {
  return sameBytes(a.positions, b.positions) && sameBytes(a.development, b.development) &&
         sameBytes(a.triangles, b.triangles) && a.tags == b.tags;
}

std::size_t sheetBytes(const Sheet& sheet) {
  return sheet.positions.capacity() * sizeof(glm::dvec3) +
         sheet.development.capacity() * sizeof(glm::dvec2) +
         sheet.triangles.capacity() * sizeof(Triangle) + sheet.tags.capacity() * sizeof(TaggedEdge);
}

DevelopmentBounds developmentBounds(const Sheet& sheet) {
  if (sheet.development.empty()) return {};
  DevelopmentBounds bounds{glm::dvec2(std::numeric_limits<double>::infinity()),
                           glm::dvec2(-std::numeric_limits<double>::infinity())};
  for (const glm::dvec2& p : sheet.development) {
    bounds.low = glm::min(bounds.low, p);
    bounds.high = glm::max(bounds.high, p);
  }
  return bounds;
}

double sheetSize(const Sheet& sheet) {
  const DevelopmentBounds bounds = developmentBounds(sheet);
  const glm::dvec2 extent = bounds.high - bounds.low;
  return std::sqrt(extent.x * extent.x + extent.y * extent.y);
}

}  // namespace curvefold
