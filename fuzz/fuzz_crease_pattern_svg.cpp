// The SVG crease-pattern reader (Origami Simulator's convention): a CreasePatternError (one line)
// or a pattern that keeps every promise of crease_pattern.hpp (validateCreasePattern).
#include <string_view>

#include "engine/io/crease_pattern_graph.hpp"
#include "engine/io/svg_crease_pattern.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(bytes), size);
  try {
    const curvefold::CreasePattern pattern = curvefold::readSvgCreasePatternText(text, "fuzz.svg");
    if (const auto problem = curvefold::validateCreasePattern(pattern))
      curvefold::fuzz::fail("SVG crease pattern: " + *problem);
  } catch (const curvefold::CreasePatternError& error) {
    if (std::string_view(error.what()).find('\n') != std::string_view::npos)
      curvefold::fuzz::fail("an error of more than one line");
  }
  return 0;
}
