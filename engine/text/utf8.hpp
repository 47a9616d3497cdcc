// UTF-8 as the JSON files take it: names and paths that go into a recording or a design must be
// valid UTF-8, or writing the file fails.
#pragma once

#include <cstddef>
#include <string_view>

namespace curvefold {

// The length of the UTF-8 sequence starting at text[at] (1 for ASCII), or 0 when none starts there.
std::size_t utf8SequenceLength(std::string_view text, std::size_t at);

// Whether all of text is valid UTF-8.
bool isUtf8(std::string_view text);

}  // namespace curvefold
