#include "interaction/surface_picker.hpp"

#include <glm/geometric.hpp>

#include "engine/cgal/triangle_tree.hpp"

namespace curvefold {

struct SurfacePicker::Tree : CgalTriangleTree {};

SurfacePicker::SurfacePicker(const Sheet& sheet) : sheet_(sheet), tree_(std::make_unique<Tree>()) {
  tree_->triangles.reserve(sheet.triangleCount());
  for (const Triangle& t : sheet.triangles)
    tree_->triangles.emplace_back(cgalPoint(sheet.positions[t[0]]),
                                  cgalPoint(sheet.positions[t[1]]),
                                  cgalPoint(sheet.positions[t[2]]));
  tree_->build();
}

SurfacePicker::~SurfacePicker() = default;

std::optional<SurfacePoint> SurfacePicker::nearest(const glm::dvec3& p, double maxDistance) const {
  if (tree_->triangles.empty()) return std::nullopt;
  const auto [closest, primitive] = tree_->tree.closest_point_and_primitive(cgalPoint(p));
  (void)closest;
  const auto triangle = static_cast<TriangleIndex>(primitive - tree_->triangles.cbegin());
  // Barycentric coordinates from the geometry core, so a grab from here and from
  // closestSurfacePoint agree.
  const SurfacePoint nearest = closestPointOnTriangle(sheet_, triangle, p);
  if (glm::distance(positionOf(sheet_, nearest), p) > maxDistance) return std::nullopt;
  return nearest;
}

}  // namespace curvefold
