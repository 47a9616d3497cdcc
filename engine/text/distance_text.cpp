#include "engine/text/distance_text.hpp"

#include <cmath>
#include <cstdio>

namespace curvefold {

std::string millimetresText(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g mm", std::abs(metres) < 1e-9 ? 0.0 : metres * 1000.0);
  return text;
}

std::string percentText(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g%%", std::abs(fraction) < 1e-9 ? 0.0 : fraction * 100.0);
  return text;
}

std::string unitsText(double length) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g units", length);
  return text;
}

std::string lengthText(double length, bool metres) {
  return metres ? millimetresText(length) : unitsText(length);
}

std::string distanceText(double hausdorff, double chamfer, double diagonal, bool metres) {
  return "Hausdorff " + lengthText(hausdorff, metres) + " (" + percentText(hausdorff / diagonal) +
         "), Chamfer " + lengthText(chamfer, metres) + " (" + percentText(chamfer / diagonal) + ")";
}

std::string distanceText(double hausdorff, double chamfer, double diagonal) {
  return distanceText(hausdorff, chamfer, diagonal, true);
}

}  // namespace curvefold
