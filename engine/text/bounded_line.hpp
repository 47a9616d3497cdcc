// std::getline with a bound: a line longer than maxBytes is reported before it is held, so a
// reader's memory is bounded by its limits, not by its input (the OBJ and recording readers).
#pragma once

#include <cstddef>
#include <istream>
#include <string>

namespace curvefold {

enum class LineRead { End, Line, LastLineWithoutNewline, TooLong };

// Reads the next line into `line` (without its newline). TooLong leaves the rest unread.
inline LineRead readBoundedLine(std::istream& in, std::string& line, std::size_t maxBytes) {
  line.clear();
  std::streambuf* buffer = in.rdbuf();
  for (;;) {
    const int c = buffer->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in.setstate(std::ios::eofbit);
      return line.empty() ? LineRead::End : LineRead::LastLineWithoutNewline;
    }
    if (c == '\n') return LineRead::Line;
    if (line.size() == maxBytes) return LineRead::TooLong;
    line.push_back(static_cast<char>(c));
  }
}

}  // namespace curvefold
