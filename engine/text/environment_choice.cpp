#include "engine/text/environment_choice.hpp"

#include <algorithm>
#include <cstdlib>

#include "engine/text/excerpt.hpp"

namespace curvefold {

std::optional<std::string> environmentChoice(const char* name,
                                             std::initializer_list<std::string_view> allowed) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') return std::nullopt;
  if (std::find(allowed.begin(), allowed.end(), std::string_view(value)) != allowed.end())
    return std::string(value);
  std::string takes;
  for (const std::string_view choice : allowed)
    takes += (takes.empty() ? "" : " or ") + std::string("\"") + std::string(choice) + "\"";
  throw EnvironmentError(std::string(name) + "=" + quotedExcerpt(value) +
                         ": not a value it takes (" + takes + ", or unset)");
}

bool vulkanValidationAsked() {
  return environmentChoice("CURVEFOLD_VK_VALIDATION", {"1", "0"}) == "1";
}

bool redrawAlways() {
  return environmentChoice("CURVEFOLD_REDRAW", {"always"}).has_value();
}

void checkEnvironmentChoices() {
  vulkanValidationAsked();
  redrawAlways();
}

}  // namespace curvefold
