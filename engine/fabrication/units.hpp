// Units of what goes to paper and machines (docs/design.md 4): the sheet is in metres, its
// outputs in millimetres (SVG, cutter SVG) and PDF points. Defined here once.
#pragma once

namespace curvefold {

inline constexpr double kMmPerMetre = 1000.0;
inline constexpr double kPointsPerMm = 72.0 / 25.4;

// Two points on paper closer than this (mm) are one: a picometre, far below any printer's or
// cutter's step, far above the rounding of millimetre coordinates. Also the least extent a pattern
// is divided by.
inline constexpr double kSamePointMm = 1e-9;
// A perforation's dash or gap with less than this (mm) left has run out: what is left is the
// rounding of subtracting its steps along the crease.
inline constexpr double kDashRoundingMm = 1e-12;

}  // namespace curvefold
