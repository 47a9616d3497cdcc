// The view a still picture takes of a sheet, chosen from the sheet's own shape (issue 38 2d): the
// fixed iso view (y up) sees a nearly flat sheet standing in the xy plane as a wall, and one lying
// in the xz plane almost edge on, so a fitted saddle does not read as a saddle.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

struct SheetView {
  glm::mat4 worldFromSheet{1.0f};         // a rotation about the sheet's centre, or the identity
  glm::vec3 direction{0.0f, 0.0f, 1.0f};  // unit, from the centre towards the eye, in the world
};

// Below this ratio of the smallest to the middle principal variance of its area a sheet counts
// as nearly flat (a cylinder of radius r only when shorter than 0.77 r; the default square with a
// 22 mm saddle on its 20 cm is at 0.008).
inline constexpr double kFlatVarianceRatio = 0.1;

// Inputs: sheet (positions and triangles). Output: for a nearly flat sheet, the rotation about its
// area's centre that lays it down (its thinnest principal direction onto +y, away from the ground:
// the side a bowl or dome opens to, else the iso view's side) and a direction 35 degrees from +y
// towards the iso view's azimuth: the sheet lying on the ground, seen from above at an angle. For
// any other sheet (a tube, a vase, a cone, a deep bowl) or one without area: the identity and the
// iso direction, as before. Limits: O(triangles); positions only, so a sheet folded flat onto
// itself reads as flat.
SheetView viewForSheet(const Sheet& sheet);

}  // namespace curvefold
