// The design-document reader and the replay of its folds: a DesignError or a valid sheet.
#include <sstream>

#include "engine/io/design_document.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(bytes), size));
  try {
    const curvefold::Design design = curvefold::parseDesign(in, "fuzz.curvefold.json");
    // Keep the replay small: a huge generated surface is valid but slow, not a finding.
    if (const auto* generated = std::get_if<curvefold::GeneratedSurface>(&design.surface)) {
      const auto resolution = generated->parameters.find("resolution");
      if (resolution == generated->parameters.end() || !(resolution->second <= 40)) return 0;
    }
    const curvefold::Sheet sheet = curvefold::buildSheet(design, "fuzz.curvefold.json");
    curvefold::validate(sheet);
  } catch (const curvefold::DesignError&) {
  }
  return 0;
}
