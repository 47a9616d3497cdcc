// Distances for a person: millimetres and percentages in three digits, the same in the command
// line's `fit` and `distance` lines and the studio panel's distance line, which both word what
// engine/fit/surface_distance.hpp measures.
#pragma once

#include <string>

namespace curvefold {

// "12.3 mm" and "4.1%": three digits; what lies below a nanometre is rounding, printed as 0.
std::string millimetresText(double metres);
std::string percentText(double fraction);
// "Hausdorff 4.2 mm (1.3%), Chamfer 1.1 mm (0.35%)": each also relative to the target's diagonal.
std::string distanceText(double hausdorff, double chamfer, double diagonal);
// "12.3 units": a length of a target in other units (a millimetre scan is read as metres, 1000
// times paper's size), in its own numbers, since which units they are cannot be known.
std::string unitsText(double length);
// millimetresText where `metres`, else unitsText.
std::string lengthText(double length, bool metres);
// As above, in the target's own units where `metres` is false: "Hausdorff 4.2 units (1.3%), ...".
std::string distanceText(double hausdorff, double chamfer, double diagonal, bool metres);

}  // namespace curvefold
