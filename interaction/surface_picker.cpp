#include "interaction/surface_picker.hpp"

#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <glm/geometric.hpp>

namespace curvefold {

namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using CgalTriangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<CgalTriangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 point(const glm::dvec3& p) {
  return {p.x, p.y, p.z};
}
}  // namespace

struct SurfacePicker::Tree {
  std::vector<CgalTriangle> triangles;
  curvefold::Tree tree;
};

SurfacePicker::SurfacePicker(const Sheet& sheet) : sheet_(sheet), tree_(std::make_unique<Tree>()) {
  tree_->triangles.reserve(sheet.triangleCount());
  for (const Triangle& t : sheet.triangles)
    tree_->triangles.emplace_back(point(sheet.positions[t[0]]), point(sheet.positions[t[1]]),
                                  point(sheet.positions[t[2]]));
  tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
  tree_->tree.build();
  tree_->tree.accelerate_distance_queries();
}

SurfacePicker::~SurfacePicker() = default;

std::optional<SurfacePoint> SurfacePicker::nearest(const glm::dvec3& p, double maxDistance) const {
  if (tree_->triangles.empty()) return std::nullopt;
  const auto [closest, primitive] = tree_->tree.closest_point_and_primitive(point(p));
  (void)closest;
  const auto triangle = static_cast<TriangleIndex>(primitive - tree_->triangles.cbegin());
  // Barycentric coordinates from the geometry core, so a grab from here and from
  // closestSurfacePoint agree.
  const SurfacePoint nearest = closestPointOnTriangle(sheet_, triangle, p);
  if (glm::distance(positionOf(sheet_, nearest), p) > maxDistance) return std::nullopt;
  return nearest;
}

}  // namespace curvefold
