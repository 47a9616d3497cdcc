#include "engine/fit/target_units.hpp"

#include "engine/geometry/triangle_mesh.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {

bool sameUnits(double size, double reference) {
  const double ratio = size / reference;
  return ratio <= 100.0 && ratio >= 0.01;
}

bool lengthsInMetres(double targetDiagonal) {
  static const double paper = boundingDiagonal(meshOf(makeSurface("square")));
  return sameUnits(targetDiagonal, paper);
}

}  // namespace curvefold
