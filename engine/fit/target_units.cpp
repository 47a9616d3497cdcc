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
  // A model 10 to 100 times paper's size (2.8 to 28 units across) is a lamp or a bowl in inches
  // or centimetres far oftener than a paper shape metres wide: read as metres, an 18.7-inch
  // lampshade's distances printed as "842 mm". Its own numbers are right in either case.
  const double ratio = targetDiagonal / paper;
  return ratio <= kMetresAtMost && ratio >= 0.01;
}

}  // namespace curvefold
