// Settings read from the environment that take a few named values (CURVEFOLD_REDRAW=always,
// CURVEFOLD_VK_VALIDATION=1). Any other value is refused in one line naming the variable and the
// values it takes, where it used to be ignored without a word (CURVEFOLD_VK_VALIDATION=yes left
// the validation layer off, CURVEFOLD_REDRAW=Always the pacer on).
//
// environmentChoice(name, allowed): the variable's value, or nothing where it is unset or empty
// (`NAME= curvefold ...` is unset); throws EnvironmentError for any value not in `allowed`.
// checkEnvironmentChoices(): every such variable of curvefold's checked at once, as the command
// line does before any command runs (so no file is read or written under a misspelt setting).
// The standard library only: the renderer, the windows and the command line read them alike.
#pragma once

#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace curvefold {

class EnvironmentError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

std::optional<std::string> environmentChoice(const char* name,
                                             std::initializer_list<std::string_view> allowed);

// CURVEFOLD_VK_VALIDATION: "1" turns the Vulkan validation layer on, "0" leaves it off.
bool vulkanValidationAsked();
// CURVEFOLD_REDRAW: "always" draws every frame at once (the window's pacer off).
bool redrawAlways();

void checkEnvironmentChoices();

}  // namespace curvefold
