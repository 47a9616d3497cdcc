#include "app/studio_panel.hpp"

#include <imgui.h>

#include <cmath>
#include <cstring>
#include <exception>
#include <utility>

#include "engine/io/design_document.hpp"
#include "engine/io/fold_format.hpp"
#include "engine/io/gltf_writer.hpp"
#include "engine/io/obj_writer.hpp"
#include "engine/io/svg_crease_pattern.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "sim_input/player.hpp"

namespace curvefold::cli {

StudioPanel::StudioPanel(bool recording, std::string help, std::string exportBase)
    : recording_(recording), help_(std::move(help)) {
  std::strncpy(exportBase_, exportBase.c_str(), sizeof exportBase_ - 1);
  resetParameters();
}

void StudioPanel::resetParameters() {
  parameterValues_.clear();
  for (const SurfaceParameter& p : surfaceCatalog()[surfaceIndex_].parameters)
    parameterValues_.push_back(float(p.defaultValue));
}

void StudioPanel::item(const char* label) {
  const ImVec2 low = ImGui::GetItemRectMin(), high = ImGui::GetItemRectMax();
  items_[label] = {0.5f * (low.x + high.x), 0.5f * (low.y + high.y)};
}

std::optional<glm::vec2> StudioPanel::itemCentre(const std::string& label) const {
  const auto found = items_.find(label);
  if (found == items_.end()) return std::nullopt;
  return found->second;
}

void StudioPanel::guarded(const std::string& done, const std::function<void()>& action) {
  try {
    action();
    message_ = done;
  } catch (const std::exception& e) {
    message_ = e.what();
  }
}

void StudioPanel::draw(Document& doc, const StudioActions& actions, const StudioStats& stats,
                       bool& creasePattern) {
  items_.clear();
  const std::vector<SurfaceInfo>& catalog = surfaceCatalog();
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(300, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("curvefold");
  if (ImGui::CollapsingHeader("New sheet", recording_ ? 0 : ImGuiTreeNodeFlags_DefaultOpen)) {
    if (recording_) {
      ImGui::TextWrapped("Recording: the sheet is fixed by the recording's header.");
    } else {
      if (ImGui::BeginCombo("surface", catalog[surfaceIndex_].name.c_str())) {
        for (int i = 0; i < int(catalog.size()); ++i) {
          if (ImGui::Selectable(catalog[i].name.c_str(), i == surfaceIndex_)) {
            surfaceIndex_ = i;
            resetParameters();
          }
          item(catalog[i].name.c_str());
        }
        ImGui::EndCombo();
      }
      item("surface");
      // The sliders stay within the catalog's ranges.
      const auto& parameters = catalog[surfaceIndex_].parameters;
      for (std::size_t i = 0; i < parameters.size(); ++i) {
        ImGui::SliderFloat(parameters[i].name.c_str(), &parameterValues_[i],
                           float(parameters[i].min), float(parameters[i].max), "%.4g");
        item(parameters[i].name.c_str());
      }
      const bool create = ImGui::Button("Create");
      item("Create");
      if (create) {
        GeneratedSurface surface{catalog[surfaceIndex_].name, {}};
        for (std::size_t i = 0; i < parameters.size(); ++i)
          surface.parameters[parameters[i].name] =
              parameters[i].integer ? std::round(parameterValues_[i]) : parameterValues_[i];
        guarded("new " + surface.generator, [&] {
          actions.replaceDocument({surface, {}}, surface.generator);
        });
      }
    }
  }
  auto button = [&](const char* label) {
    const bool pressed = ImGui::Button(label);
    item(label);
    return pressed;
  };
  if (button("Undo")) actions.press(Button::Undo);
  ImGui::SameLine();
  if (button("Redo")) actions.press(Button::Redo);
  ImGui::SameLine();
  if (button("Cancel")) actions.press(Button::Cancel);
  ImGui::SameLine();
  if (button("Switch hands")) actions.press(Button::SwitchHands);
  ImGui::Checkbox("crease pattern", &creasePattern);
  item("crease pattern");
  ImGui::InputText("save as", savePath_, sizeof savePath_);
  item("save as");
  if (button("Save"))
    guarded(std::string("saved ") + savePath_, [&] { saveDesign(doc.design(), savePath_); });
  if (!recording_) {
    ImGui::InputText("open", openPath_, sizeof openPath_);
    item("open");
    if (button("Open"))
      guarded(std::string("opened ") + openPath_,
              [&] { actions.replaceDocument(loadDesign(openPath_), openPath_); });
  }
  ImGui::InputText("export to", exportBase_, sizeof exportBase_);
  item("export to");
  const std::string base = exportBase_;
  if (button("FOLD"))
    guarded("wrote " + base + ".fold", [&] { writeFold(doc.session->fixed(), base + ".fold"); });
  ImGui::SameLine();
  if (button("SVG"))
    guarded("wrote " + base + ".svg",
            [&] { writeSvgCreasePattern(doc.session->fixed(), base + ".svg"); });
  ImGui::SameLine();
  if (button("OBJ"))
    guarded("wrote " + base + ".obj", [&] { writeObj(doc.session->fixed(), base + ".obj"); });
  ImGui::SameLine();
  if (button("glTF"))
    guarded("wrote " + base + ".glb", [&] { writeGlb(doc.session->fixed(), base + ".glb"); });
  ImGui::SameLine();
  if (button("PNG")) guarded("wrote " + base + ".png", [&] { actions.exportPng(base + ".png"); });
  if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
  ImGui::Separator();
  // The isometry error walks every edge: measured again only when the committed sheet changes.
  if (statsSession_ != doc.session.get() || statsRevision_ != doc.session->fixedRevision()) {
    statsSession_ = doc.session.get();
    statsRevision_ = doc.session->fixedRevision();
    maxError_ = maxEdgeLengthError(doc.session->fixed());
  }
  ImGui::Text("triangles %zu (drawn %zu), folds %zu", doc.session->current().triangleCount(),
              stats.drawnTriangles, doc.session->foldCount());
  ImGui::Text("max edge-length error %.3g m", maxError_);
  ImGui::Text("drag update %.2f ms, frame %.2f ms", stats.dragUpdateMs, stats.frameMs);
  ImGui::TextWrapped("%s", help_.c_str());
  ImGui::End();
}

}  // namespace curvefold::cli
