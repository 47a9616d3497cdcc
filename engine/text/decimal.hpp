// Numbers read from options and settings: the whole text, in decimal. std::from_chars takes no
// leading space, "+" or "0x" that sscanf and strtod would, and says when a value does not fit, so
// "0x10" is refused rather than read as 16 and 2^64 rather than wrapped.
#pragma once

#include <charconv>
#include <cstddef>
#include <string_view>
#include <system_error>

namespace curvefold {

// Whether text is exactly one decimal number of Number's type (a minus sign only for signed and
// floating-point types), stored in value.
template <typename Number>
bool readDecimal(std::string_view text, Number& value) {
  if (text.empty() || text[0] == '+') return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

// "WxH": two whole numbers from low to high, as in image and window sizes.
template <typename Whole>
bool readSize(std::string_view text, Whole low, Whole high, Whole& width, Whole& height) {
  const std::size_t x = text.find('x');
  return x != std::string_view::npos && readDecimal(text.substr(0, x), width) &&
         readDecimal(text.substr(x + 1), height) && width >= low && height >= low &&
         width <= high && height <= high;
}

}  // namespace curvefold
