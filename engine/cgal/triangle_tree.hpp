// CGAL's AABB tree over a mesh's triangles, for closest-point and distance queries (the surface
// picker's and the fit's). Header-only; the libraries that use it link CGAL privately.
#pragma once

#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <glm/vec3.hpp>

namespace curvefold {

using CgalKernel = CGAL::Simple_cartesian<double>;
using CgalTriangle = CgalKernel::Triangle_3;

inline CgalKernel::Point_3 cgalPoint(const glm::dvec3& p) {
  return {p.x, p.y, p.z};
}

// The triangles and their tree; a triangle's index is its place in `triangles`.
struct CgalTriangleTree {
  using Primitive =
      CGAL::AABB_triangle_primitive<CgalKernel, std::vector<CgalTriangle>::const_iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<CgalKernel, Primitive>>;

  // Builds the tree over `triangles`, which stay as they are from then on. `searchTree`: CGAL's
  // own KD-tree of the triangles' first vertices, the hint of a query without one (a caller that
  // gives its own hints leaves it out).
  void build(bool searchTree = true) {
    tree.insert(triangles.cbegin(), triangles.cend());
    tree.build();
    if (searchTree) tree.accelerate_distance_queries();
  }

  std::vector<CgalTriangle> triangles;
  Tree tree;
};

}  // namespace curvefold
