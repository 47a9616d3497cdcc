#include "app/session/cover_facts.hpp"

#include <ctime>

#include "app/session/document.hpp"

namespace curvefold::session {

std::string today() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[16];
  std::strftime(text, sizeof text, "%Y-%m-%d", &local);
  return text;
}

std::vector<std::string> coverFacts(const Design& design) {
  return {
      "surface: " + surfaceName(design) + (design.symmetry.empty() ? "" : ", " + design.symmetry),
      "folds: " + std::to_string(design.folds.size()), "date: " + today()};
}

}  // namespace curvefold::session
