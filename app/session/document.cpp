#include "app/session/document.hpp"

#include <cstring>
#include <filesystem>

#include "engine/geometry/symmetry.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "engine/text/excerpt.hpp"

namespace curvefold::session {

namespace fs = std::filesystem;

Design Document::design() const {
  const auto& history = session->folds();
  Design design{surface, baseFolds, symmetry};
  design.folds.insert(design.folds.end(), history.begin(),
                      history.begin() + std::ptrdiff_t(session->foldCount()));
  return design;
}

std::string Document::recordingSymmetry() const {
  if (!session->symmetry()) return "";
  const std::string name = session->symmetry()->name();
  try {
    parseSymmetry(name, initialSheet(Design{recordingSurface(), {}}, "recording"));
    return name;
  } catch (const InvalidSymmetry&) {
    return "";
  }
}

InitialSurface Document::recordingSurface() const {
  if (baseFolds.empty()) return surface;
  return session->initial();
}

void startFromCommittedFolds(Document& doc) {
  if (doc.session->foldCount() == 0) return;
  doc.baseFolds = doc.design().folds;
  const Pose worldFromSheet = doc.core->worldFromSheet();
  const HandSide handedness = doc.core->handedness();
  Sheet folded = doc.session->fixed();
  doc.core.reset();
  doc.session = std::make_unique<FoldSession>(std::move(folded));
  // The folded sheet keeps the symmetry when every image was made (none was skipped).
  if (!doc.symmetry.empty()) {
    try {
      doc.session->setSymmetry(parseSymmetry(doc.symmetry, doc.session->initial()));
    } catch (const InvalidSymmetry&) {
    }
  }
  doc.core = std::make_unique<InteractionCore>(*doc.session, worldFromSheet, handedness);
}

Document makeDocument(const Design& design, const std::string& name, const Pose& worldFromSheet,
                      HandSide handedness) {
  Document doc;
  doc.surface = design.surface;
  doc.session = std::make_unique<FoldSession>(initialSheet(design, name));
  doc.session->applyRecords(design.folds);
  // Folds from here on bring their images (the ones above already hold theirs).
  doc.symmetry = design.symmetry;
  if (!design.symmetry.empty())
    doc.session->setSymmetry(parseSymmetry(design.symmetry, doc.session->initial()));
  doc.core = std::make_unique<InteractionCore>(*doc.session, worldFromSheet, handedness);
  return doc;
}

std::string designName(const std::string& name) {
  std::string stem = fs::path(name).filename().string();
  for (const char* suffix : {".json", ".curvefold", ".autosave", ".jsonl"})
    if (stem.size() > std::strlen(suffix) && stem.ends_with(suffix))
      stem.resize(stem.size() - std::strlen(suffix));
  return stem.empty() ? "design" : stem;
}

std::string surfaceName(const Design& design) {
  if (const auto* generated = std::get_if<GeneratedSurface>(&design.surface))
    return generated->generator;
  return "embedded mesh";
}

std::string symmetryProblem(const InvalidSymmetry& error) {
  return std::string(error.what()) + (error.surfaceLacksIt() ? " (see `curvefold surfaces`)" : "");
}

Design designFor(const std::string& input, const std::string& fallbackSurface) {
  if (input.empty()) return {GeneratedSurface{fallbackSurface, {}}, {}};
  if (fs::exists(input)) return loadDesign(input);
  for (const SurfaceInfo& info : surfaceCatalog())
    if (info.name == input) return {GeneratedSurface{input, {}}, {}};
  throw UnknownInput(quotedExcerpt(input) + " is neither a design file nor a surface name");
}

std::string defaultAutosave(const std::string& input, const std::string& fallbackSurface) {
  std::string name = input.empty() ? fallbackSurface : fs::path(input).filename().string();
  for (const char* suffix : {".json", ".curvefold", ".jsonl"})
    if (name.size() > std::strlen(suffix) && name.ends_with(suffix))
      name.resize(name.size() - std::strlen(suffix));
  return name + ".autosave.curvefold.json";
}

std::string nextAutosave(const std::string& current, const std::string& name) {
  const fs::path dir = fs::path(current).parent_path();
  std::string stem = defaultAutosave(name, name);
  stem.resize(stem.size() - std::strlen(".autosave.curvefold.json"));
  for (int i = 1;; ++i) {
    // Appended piece by piece: GCC 12 inlines "-" + std::to_string(i) into a false -Wrestrict.
    std::string numbered = stem;
    if (i > 1) {
      numbered += '-';
      numbered += std::to_string(i);
    }
    const fs::path candidate = dir / (numbered + ".autosave.curvefold.json");
    std::error_code error;
    if (!fs::exists(candidate, error) && candidate.string() != current) return candidate.string();
  }
}

}  // namespace curvefold::session
