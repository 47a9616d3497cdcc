// A value quoted in an error message: one line, bounded in length whatever it was given (a
// 100,000-digit option, a megabyte label, a newline), so every message stays a single short line.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace curvefold {

// The longest excerpt a message quotes.
inline constexpr std::size_t kExcerptLength = 60;

// text in double quotes, with quotes, backslashes and control characters escaped as in JSON
// ("\n", "\u0001") and bytes that are not UTF-8 as "\xNN"; cut to at most maxLength bytes,
// ending in "..." (without the closing quote) when cut. Its cost is bounded by maxLength, not by
// the size of text.
std::string quotedExcerpt(std::string_view text, std::size_t maxLength = kExcerptLength);

}  // namespace curvefold
