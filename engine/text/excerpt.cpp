#include "engine/text/excerpt.hpp"

#include <vector>

#include "engine/text/utf8.hpp"

namespace curvefold {

std::string quotedExcerpt(std::string_view text, std::size_t maxLength) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out = "\"";
  // Where each whole piece ends, so a cut never splits an escape or a character.
  std::vector<std::size_t> ends;
  std::size_t at = 0;
  while (at < text.size() && out.size() <= maxLength) {
    const auto c = static_cast<unsigned char>(text[at]);
    std::size_t used = 1;
    if (c == '"' || c == '\\') {
      out += '\\';
      out += char(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c < 0x20 || c == 0x7F) {
      out += "\\u00";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    } else if (c < 0x80) {
      out += char(c);
    } else if (const std::size_t length = utf8SequenceLength(text, at); length > 0) {
      out.append(text.substr(at, length));
      used = length;
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
    at += used;
    ends.push_back(out.size());
  }
  if (at == text.size() && out.size() + 1 <= maxLength) return out + "\"";
  // Cut: keep the whole pieces that leave room for "...".
  std::size_t keep = 1;
  for (std::size_t end : ends)
    if (end + 3 <= maxLength) keep = end;
  out.resize(maxLength >= 3 ? std::min(keep, maxLength - 3) : 0);
  return out + "...";
}

}  // namespace curvefold
