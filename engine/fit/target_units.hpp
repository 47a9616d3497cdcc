// A target's units (issue 38): a mesh in millimetres is read as metres, a thousand times paper's
// size, and whether its lengths mean metres cannot be known from the file. The fit sizes its sheet
// to such a target and prints the target's lengths in its own numbers; these two functions are
// the one rule that the check of a target, the fit's texts and the command line's lines share.
#pragma once

namespace curvefold {

// Whether a shape of bounding diagonal `size` reads in the units of one of diagonal `reference`:
// within a hundredfold either way. Both positive.
bool sameUnits(double size, double reference);

// Whether a target's lengths read as metres: sameUnits against the default square's diagonal.
// Else they are printed as its own numbers ("12.3 units": distance_text.hpp's unitsText).
bool lengthsInMetres(double targetDiagonal);

}  // namespace curvefold
