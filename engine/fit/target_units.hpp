// A target's units (issue 38): a mesh in millimetres is read as metres, a thousand times paper's
// size, and whether its lengths mean metres cannot be known from the file. The fit sizes its sheet
// to such a target and prints the target's lengths in its own numbers; these two functions are
// the one rule that the check of a target, the fit's texts and the command line's lines share.
#pragma once

namespace curvefold {

// Whether a shape of bounding diagonal `size` reads in the units of one of diagonal `reference`:
// within a hundredfold either way. Both positive.
bool sameUnits(double size, double reference);

// How many times the default square's diagonal a target's may be and its lengths still read as
// metres (2.83 m): below sameUnits' hundredfold, since a model in inches or centimetres (a
// lampshade 18.7 inches across) is read as that many metres and sameUnits passes it.
inline constexpr double kMetresAtMost = 10.0;

// Whether a target's lengths read as metres: its diagonal within a hundredth and kMetresAtMost
// times the default square's. Else they are printed as its own numbers ("12.3 units":
// distance_text.hpp's unitsText). The check of a sheet against a target keeps sameUnits.
bool lengthsInMetres(double targetDiagonal);

}  // namespace curvefold
