// One uniform draw in [0, 1) from a 64-bit Mersenne Twister, the fit's and its test targets'
// every random choice: the top 53 bits of a draw as a double, so the same seed gives the same
// numbers on every standard library (std::uniform_real_distribution's are its own).
#pragma once

#include <random>

namespace curvefold {

inline double unit(std::mt19937_64& random) {
  return static_cast<double>(random() >> 11) * 0x1.0p-53;
}

}  // namespace curvefold
