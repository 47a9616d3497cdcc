#include "app/studio/studio_panel.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "app/session/cover_facts.hpp"
#include "engine/fabrication/svg_crease_pattern.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/io/design_document.hpp"
#include "engine/io/fold_format.hpp"
#include "engine/io/gltf_writer.hpp"
#include "engine/io/obj_writer.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "engine/text/input_path.hpp"
#include "engine/text/utf8.hpp"
#include "sim_input/player.hpp"

namespace curvefold::studio {

std::string wrapAtSpaces(const std::string& text, float width) {
  std::string wrapped, line;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t space = std::min(text.find(' ', at), text.size());
    const std::string word = text.substr(at, space - at);
    const std::string longer = line.empty() ? word : line + ' ' + word;
    if (!line.empty() && ImGui::CalcTextSize(longer.c_str()).x > width) {
      wrapped += line + '\n';
      line = word;
    } else {
      line = longer;
    }
    at = space + 1;
  }
  return wrapped + line;
}

std::string pathEnd(const std::string& path, float width) {
  if (ImGui::CalcTextSize(path.c_str()).x <= width) return path;
  // The longest end that fits after "...", starting at a character (not inside a UTF-8 one).
  std::size_t from = 0;
  while (from < path.size()) {
    ++from;
    while (from < path.size() && (static_cast<unsigned char>(path[from]) & 0xC0) == 0x80) ++from;
    const std::string shown = "..." + path.substr(from);
    if (ImGui::CalcTextSize(shown.c_str()).x <= width) return shown;
  }
  return "...";
}

StudioPanel::StudioPanel(bool recording, std::string help, std::string exportBase)
    : recording_(recording), help_(std::move(help)), exportBase_(std::move(exportBase)) {
  resetParameters();
}

void StudioPanel::setExportBase(const std::string& base) {
  exportBase_ = base;
}

void StudioPanel::setSavePath(const std::string& path) {
  savePath_ = path;
}

void StudioPanel::nameDesign(const std::string& name) {
  const std::filesystem::path dir =
      filesDir_ ? std::filesystem::path(*filesDir_) : std::filesystem::path(name).parent_path();
  exportBase_ = (dir / session::designName(name)).string();
  savePath_ = exportBase_ + ".curvefold.json";
}

void StudioPanel::setDesktop(bool desktop,
                             const std::function<std::unique_ptr<FilePicker>()>& findPicker) {
  desktop_ = desktop;
  picker_.reset();
  if (!desktop) return;
  picker_ = findPicker();
}

void StudioPanel::browse(bool save) {
  try {
    picker_->start(save, save ? savePath_ : openPath_);
    pickingSave_ = save;
    message_ = "choosing a file to " + std::string(save ? "save to" : "open");
  } catch (const std::exception& e) {
    message_ = e.what();
  }
}

void StudioPanel::takePicked() {
  if (!picker_) return;
  const std::optional<FilePicker::Picked> picked = picker_->poll();
  if (!picked) return;
  if (!picked->error.empty()) {
    message_ = picked->error;
  } else if (picked->path.empty()) {
    message_ = "no file chosen";
  } else {
    (pickingSave_ ? savePath_ : openPath_) = picked->path;
    message_ =
        "chosen: " + picked->path + (pickingSave_ ? " (Save writes it)" : " (Open opens it)");
  }
}

void StudioPanel::setTargetPath(const std::string& path) {
  targetPath_ = path;
}

void StudioPanel::setRecent(std::vector<std::string> recent) {
  // Only what a recording can hold: one line of UTF-8 (a recording is JSON), of a path's length.
  std::erase_if(recent, [](const std::string& path) {
    return path.empty() || path.size() >= kMaxRecentPathBytes ||
           path.find('\n') != std::string::npos || !isUtf8(path);
  });
  if (recent.size() > kMaxRecentDesigns) recent.resize(kMaxRecentDesigns);
  recent_ = std::move(recent);
}

// The design at `designPath` goes to the top of the recent list.
void StudioPanel::remember(const std::string& designPath, const StudioActions& actions) {
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(designPath, error);
  const std::string full = error ? designPath : absolute.lexically_normal().string();
  std::vector<std::string> recent{full};
  for (const std::string& path : recent_)
    if (path != full) recent.push_back(path);
  setRecent(std::move(recent));
  if (actions.recentChanged) actions.recentChanged(recent_);
}

void StudioPanel::writeThrough(const StudioActions& actions, const std::string& path,
                               const std::function<void(const std::string&)>& write) {
  if (actions.writeFile)
    actions.writeFile(path, write);
  else
    write(path);
}

void StudioPanel::resetParameters() {
  parameterValues_.clear();
  for (const SurfaceParameter& p : surfaceCatalog()[surfaceIndex_].parameters)
    parameterValues_.push_back(float(p.defaultValue));
}

GeneratedSurface StudioPanel::chosenSurface() const {
  const SurfaceInfo& info = surfaceCatalog()[surfaceIndex_];
  GeneratedSurface surface{info.name, {}};
  for (std::size_t i = 0; i < info.parameters.size(); ++i)
    surface.parameters[info.parameters[i].name] =
        info.parameters[i].integer ? std::round(parameterValues_[i]) : parameterValues_[i];
  return surface;
}

namespace {

// What the symmetry list says, instead of a choice, when it cannot offer the sheet's own.
constexpr std::string_view kNoSymmetriesBecause = "no symmetries: ";

bool isReason(const std::string& entry) {
  return entry.rfind(kNoSymmetriesBecause, 0) == 0;
}

// "none", then the sheet's symmetries; for parameters the surface refuses (or a sheet that cannot
// be made), "none" and the reason, which the list shows.
std::vector<std::string> symmetryListOf(const GeneratedSurface& surface) {
  std::vector<std::string> list = {"none"};
  try {
    for (std::string& choice : symmetryChoices(makeSurface(surface.generator, surface.parameters)))
      list.push_back(std::move(choice));
  } catch (const std::exception& e) {
    list.push_back(std::string(kNoSymmetriesBecause) + e.what());
  }
  return list;
}

bool isReady(const std::future<std::vector<std::string>>& future) {
  return future.valid() && future.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

}  // namespace

void StudioPanel::findSymmetries() {
  const GeneratedSurface surface = chosenSurface();
  if (isReady(finding_)) {
    std::vector<std::string> found = finding_.get();
    if (findingFor_ && *findingFor_ == surface) {
      symmetryChoices_ = std::move(found);
      symmetriesFor_ = findingFor_;
    }
    findingFor_.reset();
  }
  if (finding_.valid() || (symmetriesFor_ && *symmetriesFor_ == surface)) return;
  findingFor_ = surface;
  finding_ = std::async(std::launch::async, symmetryListOf, surface);
}

void StudioPanel::refreshSymmetries() {
  const GeneratedSurface surface = chosenSurface();
  // The list is whole on the frame it opens, as a recorded gesture's next frame expects it: the
  // background's search is mostly done by then (the pointer took frames to get here); else it is
  // waited for, or made here when the one under way is for other parameters.
  if (!(symmetriesFor_ && *symmetriesFor_ == surface)) {
    if (findingFor_ && *findingFor_ == surface) {
      finding_.wait();
      findSymmetries();
    } else {
      symmetryChoices_ = symmetryListOf(surface);
      symmetriesFor_ = surface;
    }
  }
  if (std::find(symmetryChoices_.begin(), symmetryChoices_.end(), symmetry_) ==
      symmetryChoices_.end())
    symmetry_ = kNoSymmetry;
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

void StudioPanel::guarded(const StudioActions& actions, const std::string& done,
                          const std::function<void()>& action) {
  try {
    action();
    message_ = done;
  } catch (const std::exception& e) {
    message_ = e.what();
    if (actions.failed) actions.failed(message_);
  }
}

void StudioPanel::targetLines(const StudioStats& stats) {
  // kTargetLineRows rows, more only for lines longer than those (a long path's failed load), so
  // that no line is ever cut or hidden.
  const float width = ImGui::GetContentRegionAvail().x;
  const ImGuiStyle& style = ImGui::GetStyle();
  // Broken at spaces, so that a figure is never split at its decimal point.
  const std::string target = wrapAtSpaces(stats.targetLine, width),
                    suggestion = wrapAtSpaces(stats.suggestionLine, width);
  float needed = 0.0f;
  for (const std::string* line : {&target, &suggestion})
    needed += ImGui::CalcTextSize(line->c_str(), nullptr, false, width).y + style.ItemSpacing.y;
  const float height =
      std::max(float(kTargetLineRows) * ImGui::GetTextLineHeightWithSpacing(), needed);
  ImGui::BeginChild("##target lines", ImVec2(0.0f, height), false,
                    ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoScrollbar);
  ImGui::TextWrapped("%s", target.c_str());
  ImGui::TextWrapped("%s", suggestion.c_str());
  ImGui::EndChild();
}

void StudioPanel::draw(session::Document& doc, const StudioActions& actions,
                       const StudioStats& stats, bool& creasePattern) {
  items_.clear();
  takePicked();
  beginWindow();
  drawNewSheet(actions);
  drawEditButtons(actions, creasePattern);
  // Null while recording (no open).
  const std::function<void(const std::string&)> openRecent = drawSaveAndOpen(doc, actions);
  drawExports(doc, actions);
  if (actions.loadTarget && actions.suggest) drawTarget(doc, actions, stats);
  // After every other item, and drawn whether or not the list is empty: what this machine has
  // recently opened moves nothing else, so a recorded session's pointing replays onto the same
  // items on any machine.
  if (openRecent) drawRecentDesigns(openRecent);
  drawSimulation(doc);
  if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
  drawFacts(doc, stats);
  ImGui::End();
}

bool StudioPanel::button(const char* label) {
  const bool pressed = ImGui::Button(label);
  item(label);
  return pressed;
}

void StudioPanel::beginWindow() {
  ImGuiWindowFlags flags = 0;
  if (fillsDisplay_) {
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImGui::GetIO().DisplaySize);
    flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;
  } else {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(300, 0), ImGuiCond_FirstUseEver);
  }
  ImGui::Begin("curvefold", nullptr, flags);
}

void StudioPanel::showPathEnd(const std::string& path, float fieldWidth) {
  if (ImGui::IsItemActive()) return;  // being edited: ImGui's own text, scrolled to the cursor
  const ImGuiStyle& style = ImGui::GetStyle();
  const std::string shown = pathEnd(path, fieldWidth - 2.0f * style.FramePadding.x);
  if (shown == path) return;
  const ImVec2 min = ImGui::GetItemRectMin();
  const ImVec2 max(min.x + fieldWidth, min.y + ImGui::GetFrameHeight());
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(
      min, max,
      ImGui::GetColorU32(ImGui::IsItemHovered() ? ImGuiCol_FrameBgHovered : ImGuiCol_FrameBg),
      style.FrameRounding);
  draw->AddText(ImVec2(min.x + style.FramePadding.x, min.y + style.FramePadding.y),
                ImGui::GetColorU32(ImGuiCol_Text), shown.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", path.c_str());
}

void StudioPanel::drawNewSheet(const StudioActions& actions) {
  if (!ImGui::CollapsingHeader("New sheet", recording_ ? 0 : ImGuiTreeNodeFlags_DefaultOpen))
    return;
  if (recording_) {
    ImGui::TextWrapped("Recording: the sheet is fixed by the recording's header.");
    return;
  }
  const std::vector<SurfaceInfo>& catalog = surfaceCatalog();
  if (ImGui::BeginCombo("surface", catalog[surfaceIndex_].name.c_str())) {
    for (int i = 0; i < int(catalog.size()); ++i) {
      if (ImGui::Selectable(catalog[i].name.c_str(), i == surfaceIndex_)) {
        surfaceIndex_ = i;
        resetParameters();
        symmetry_ = kNoSymmetry;
      }
      item(catalog[i].name.c_str());
    }
    ImGui::EndCombo();
  }
  item("surface");
  // The sliders stay within the catalog's ranges.
  const auto& parameters = catalog[surfaceIndex_].parameters;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    ImGui::SliderFloat(parameters[i].name.c_str(), &parameterValues_[i], float(parameters[i].min),
                       float(parameters[i].max), "%.4g");
    item(parameters[i].name.c_str());
  }
  drawSymmetryChoice();
  if (button("Create")) {
    const GeneratedSurface surface = chosenSurface();
    const std::string symmetry = symmetry_ == kNoSymmetry ? "" : symmetry_;
    guarded(actions, "new " + surface.generator + (symmetry.empty() ? "" : ", " + symmetry), [&] {
      actions.replaceDocument({surface, {}, symmetry}, surface.generator);
      nameDesign(surface.generator);
    });
  }
}

void StudioPanel::drawSymmetryChoice() {
  // The symmetries the new sheet has, found in the background as the surface and its
  // parameters change: symmetryChoices takes 1.3 ms on the default cylinder (resolution 48)
  // but 17 ms at resolution 200 and 0.14 s at 500 (BM_SymmetryChoices), besides making the
  // sheet: more than a frame.
  findSymmetries();
  if (ImGui::BeginCombo("symmetry", symmetry_.c_str())) {
    refreshSymmetries();
    for (const std::string& choice : symmetryChoices_) {
      if (isReason(choice)) {
        ImGui::TextDisabled("%s", choice.c_str());
        item("no symmetries");
        message_ = choice;
        continue;
      }
      if (ImGui::Selectable(choice.c_str(), choice == symmetry_)) symmetry_ = choice;
      item(choice.c_str());
    }
    ImGui::EndCombo();
  }
  item("symmetry");
}

void StudioPanel::drawEditButtons(const StudioActions& actions, bool& creasePattern) {
  if (button("Undo")) actions.press(Button::Undo);
  ImGui::SameLine();
  if (button("Redo")) actions.press(Button::Redo);
  ImGui::SameLine();
  if (button("Cancel")) actions.press(Button::Cancel);
  ImGui::SameLine();
  if (button("Switch hands")) actions.press(Button::SwitchHands);
  ImGui::Checkbox("crease pattern", &creasePattern);
  item("crease pattern");
  if (actions.resetView) {
    ImGui::SameLine();
    if (button("Reset view")) actions.resetView();
  }
}

void StudioPanel::browseButton(const char* label, bool save) {
  // On the Save or Open line, after its button: the desktop's items move nothing the headset has.
  if (!picker_) return;
  ImGui::SameLine();
  ImGui::BeginDisabled(picker_->busy());
  if (button(label)) browse(save);
  ImGui::EndDisabled();
}

std::function<void(const std::string&)> StudioPanel::drawSaveAndOpen(session::Document& doc,
                                                                     const StudioActions& actions) {
  ImGui::InputText("save as", &savePath_);
  item("save as");
  if (button("Save")) {
    const std::string path = savePath_;
    guarded(actions, "saved " + path, [&] {
      writeThrough(actions, path, [&](const std::string& to) { saveDesign(doc.design(), to); });
      remember(path, actions);
    });
  }
  browseButton("Browse...##save", true);
  if (recording_) return {};
  ImGui::InputText("open", &openPath_);
  item("open");
  auto open = [this, &actions](const std::string& path) {
    guarded(actions, "opened " + path, [&] {
      // A FIFO or a device named here (a recent entry from another machine's recording) would
      // block the open or never end: only regular files are read.
      if (const std::optional<std::string> why = notRegularFile(path))
        throw std::runtime_error("cannot open " + path + ": " + *why);
      actions.replaceDocument(loadDesign(path), path);
      nameDesign(path);  // Save and the exports follow the opened design
      remember(path, actions);
    });
  };
  if (button("Open")) open(openPath_);
  if (desktop_) {
    browseButton("Browse...##open", false);
    if (const std::optional<std::string> chosen = drawRecentBesideOpen()) open(*chosen);
  }
  return open;
}

std::optional<std::string> StudioPanel::drawRecentBesideOpen() {
  // The recent designs, one click from Open (the list at the bottom holds them too).
  ImGui::SameLine();
  const char* preview = "Recent";
  ImGui::SetNextItemWidth(ImGui::CalcTextSize(preview).x + ImGui::GetFrameHeight() +
                          2.0f * ImGui::GetStyle().FramePadding.x);
  std::optional<std::string> chosen;
  if (ImGui::BeginCombo("##recent beside open", preview)) {
    if (recent_.empty()) ImGui::TextDisabled("none yet");
    for (std::size_t i = 0; i < recent_.size(); ++i) {
      const std::string name = std::filesystem::path(recent_[i]).filename().string();
      if (ImGui::Selectable((name + "##open recent" + std::to_string(i)).c_str()))
        chosen = recent_[i];
      if (!items_.count(name)) item(name.c_str());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", recent_[i].c_str());
    }
    ImGui::EndCombo();
  }
  item("Recent");
  return chosen;
}

void StudioPanel::drawExports(session::Document& doc, const StudioActions& actions) {
  ImGui::InputText("export to", &exportBase_);
  item("export to");
  const std::string base = exportBase_;
  const Sheet& fixed = doc.session->fixed();
  auto exportAs = [&](const std::string& extension,
                      const std::function<void(const std::string&)>& write) {
    guarded(actions, "wrote " + base + extension,
            [&] { writeThrough(actions, base + extension, write); });
  };
  if (button("FOLD")) exportAs(".fold", [&](const std::string& to) { writeFold(fixed, to); });
  ImGui::SameLine();
  if (button("SVG"))
    exportAs(".svg", [&](const std::string& to) { writeSvgCreasePattern(fixed, to); });
  ImGui::SameLine();
  if (button("OBJ")) exportAs(".obj", [&](const std::string& to) { writeObj(fixed, to); });
  ImGui::SameLine();
  if (button("glTF")) exportAs(".glb", [&](const std::string& to) { writeGlb(fixed, to); });
  ImGui::SameLine();
  if (button("PNG")) exportAs(".png", [&](const std::string& to) { actions.exportPng(to); });
  // On a line of its own: the headset's panel is no wider than the row above.
  if (button("PDF")) {
    // To print at real size on A4, after a cover with the folded form and the facts.
    const Design design = doc.design();
    PdfOptions print;
    print.title = std::filesystem::path(base).filename().string();
    print.facts = session::coverFacts(design);  // the command line's, with the date
    exportAs(".pdf", [&](const std::string& to) {
      if (actions.foldedForm) print.picture = actions.foldedForm();
      writeCreasePatternPdf(fixed, to, print);
    });
  }
}

void StudioPanel::drawTarget(session::Document& doc, const StudioActions& actions,
                             const StudioStats& stats) {
  // The same items whatever the lines say: the lines wrap inside a box of fixed height, so the
  // items keep their places and a recorded session's pointing replays onto the same buttons.
  ImGui::Separator();
  const float fieldWidth = ImGui::CalcItemWidth();
  ImGui::InputText("target", &targetPath_);
  item("target");
  showPathEnd(targetPath_, fieldWidth);
  if (button("Load target")) {
    const std::string path = targetPath_;
    guarded(actions, "", [&] { actions.loadTarget(path); });  // the target line says how it went
  }
  ImGui::SameLine();
  if (button("Suggest")) guarded(actions, "", [&] { actions.suggest(); });
  targetLines(stats);
  const bool offered = doc.core->offeredFold() != nullptr;
  ImGui::BeginDisabled(!offered);
  if (button("Take")) actions.press(Button::TakeSuggestion);
  ImGui::SameLine();
  if (button("Another")) actions.press(Button::NextSuggestion);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::TextWrapped("or grab the marked point");
}

void StudioPanel::drawRecentDesigns(const std::function<void(const std::string&)>& open) {
  ImGui::Separator();
  const bool showRecent = ImGui::CollapsingHeader("Recent designs");
  item("Recent designs");
  if (!showRecent) return;
  if (recent_.empty()) ImGui::TextDisabled("none yet");
  // Copied: opening one reorders the list.
  const std::vector<std::string> recent = recent_;
  for (std::size_t i = 0; i < recent.size(); ++i) {
    const std::string name = std::filesystem::path(recent[i]).filename().string();
    const bool chosen = ImGui::Selectable((name + "##recent" + std::to_string(i)).c_str());
    if (!items_.count(name)) item(name.c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", recent[i].c_str());
    if (chosen) open(recent[i]);
  }
}

void StudioPanel::drawFacts(const session::Document& doc, const StudioStats& stats) {
  ImGui::Separator();
  // The isometry error walks every edge: measured again only when the committed sheet changes.
  if (statsSession_ != doc.session.get() || statsRevision_ != doc.session->fixedRevision()) {
    statsSession_ = doc.session.get();
    statsRevision_ = doc.session->fixedRevision();
    maxError_ = maxEdgeLengthError(doc.session->fixed());
  }
  // After every item: these wrap rather than run past the panel's edge.
  ImGui::TextWrapped("triangles %zu (drawn %zu), folds %zu", doc.session->current().triangleCount(),
                     stats.drawnTriangles, doc.session->foldCount());
  ImGui::TextWrapped("max edge-length error %.3g m", maxError_);
  // Paper cannot pass through itself: say so while the fold does, and after (issue 17).
  const ImVec4 crossing(1.0f, 0.35f, 0.8f, 1.0f);
  if (doc.core->session().dragging() && doc.core->intersectionPairs() > 0) {
    ImGui::PushStyleColor(ImGuiCol_Text, crossing);
    ImGui::TextWrapped("self-intersection: %zu triangle pairs", doc.core->intersectionPairs());
    ImGui::PopStyleColor();
  } else if (doc.core->lastCommitIntersections() > 0) {
    ImGui::PushStyleColor(ImGuiCol_Text, crossing);
    ImGui::TextWrapped("the last fold passes through the sheet (%zu triangle pairs)",
                       doc.core->lastCommitIntersections());
    ImGui::PopStyleColor();
  } else {
    ImGui::TextWrapped("self-intersection: none");
  }
  ImGui::TextWrapped("drag update %.2f ms, frame %.2f ms", stats.dragUpdateMs, stats.frameMs);
  ImGui::TextWrapped("%s", help_.c_str());
}

std::optional<double> StudioPanel::simulationPercent() const {
  if (!simulating_) return std::nullopt;
  return double(foldPercent_);
}

void StudioPanel::setSimulation(bool on, double percent) {
  simulating_ = on;
  foldPercent_ = float(std::clamp(percent, 0.0, 100.0));
}

void StudioPanel::drawSimulation(const session::Document& doc) {
  ImGui::Separator();
  ImGui::Checkbox("simulate", &simulating_);
  item("simulate");
  ImGui::SameLine();
  ImGui::Checkbox("strain", &strainColours_);
  item("strain");
  if (gpuAvailable_) {
    ImGui::SameLine();
    ImGui::Checkbox("GPU", &gpuSolver_);
    item("GPU");
  }
  ImGui::BeginDisabled(!simulating_);
  ImGui::SliderFloat("fold %", &foldPercent_, 0.0f, 100.0f, "%.0f%%", ImGuiSliderFlags_AlwaysClamp);
  item("fold %");
  ImGui::EndDisabled();
  // One line whatever it says, so nothing below moves.
  const LiveSimulation* simulation = doc.core->simulation();
  if (!simulating_) {
    ImGui::TextDisabled("simulation off: the design as designed");
  } else if (!simulation) {
    ImGui::TextColored(ImVec4(0.8f, 0.2f, 0.1f, 1.0f), "cannot simulate: %s",
                       doc.core->simulationProblem().c_str());
  } else if (strainColours_) {
    const std::vector<double>& strain = simulation->vertexStrain();
    const double largest = strain.empty() ? 0.0 : *std::max_element(strain.begin(), strain.end());
    ImGui::Text("%.0f%%, %zu steps, largest strain %.2e", simulation->percent(),
                simulation->steps(), largest);
  } else {
    ImGui::Text("%.0f%%, %zu steps%s", simulation->percent(), simulation->steps(),
                simulation->pull() ? ", pulled" : "");
  }
}

}  // namespace curvefold::studio
