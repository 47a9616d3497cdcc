// Makes a Dear ImGui context current for a scope and puts the previous one back: the desktop
// window's panel and the headset studio's each have their own context, and the headset's
// renderer draws in the studio's.
#pragma once

#include <imgui.h>

namespace curvefold::studio {

class ImGuiContextScope {
 public:
  explicit ImGuiContextScope(ImGuiContext* context) : previous_(ImGui::GetCurrentContext()) {
    ImGui::SetCurrentContext(context);
  }
  ~ImGuiContextScope() { ImGui::SetCurrentContext(previous_); }
  ImGuiContextScope(const ImGuiContextScope&) = delete;
  ImGuiContextScope& operator=(const ImGuiContextScope&) = delete;

 private:
  ImGuiContext* previous_;
};

}  // namespace curvefold::studio
