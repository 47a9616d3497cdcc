// Nearest surface point queries for hovering, on CGAL's AABB tree: a frame's query costs a few
// microseconds instead of a pass over every triangle.
#pragma once

#include <memory>
#include <optional>

#include <glm/vec3.hpp>

#include "engine/geometry/sheet.hpp"
#include "engine/geometry/surface_point.hpp"

namespace curvefold {

class SurfacePicker {
 public:
  explicit SurfacePicker(const Sheet& sheet);
  ~SurfacePicker();
  SurfacePicker(const SurfacePicker&) = delete;
  SurfacePicker& operator=(const SurfacePicker&) = delete;

  // The surface point nearest p (sheet coordinates), if it lies within maxDistance.
  std::optional<SurfacePoint> nearest(const glm::dvec3& p, double maxDistance) const;

 private:
  struct Tree;
  const Sheet& sheet_;
  std::unique_ptr<Tree> tree_;
};

}  // namespace curvefold
