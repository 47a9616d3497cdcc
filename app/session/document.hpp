// The design a live session edits (the desktop designer, `curvefold xr`): its initial surface
// and the fold session and interaction core over it, made from a design file or a surface name,
// with the autosave that follows every committed fold.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/io/design_document.hpp"
#include "interaction/interaction_core.hpp"

namespace curvefold::session {

struct Document {
  InitialSurface surface;
  // Folds baked into the session's initial sheet (a recorded session starts from the folds it
  // opened with, since a recording starts from its header's surface): kept so the design stays
  // whole, its generator and history included.
  std::vector<FoldRecord> baseFolds;
  std::string symmetry;  // the design's ("" none); the session folds images while its sheet has it
  std::unique_ptr<FoldSession> session;
  std::unique_ptr<InteractionCore> core;

  // The initial surface, the base folds and the folds committed so far (a drag in progress is
  // not one).
  Design design() const;
  // The surface a recording of this session starts from: the design's surface, or the folded
  // sheet when there are base folds.
  InitialSurface recordingSurface() const;
  // The symmetry a recording of this session carries: the session's, when its recording surface
  // has it (folds baked into the surface may have left images out); else none.
  std::string recordingSymmetry() const;
};

// Bakes the folds committed so far into a new session's initial sheet (they move to baseFolds;
// the sheet's pose and handedness are kept), so that a recording can start here.
void startFromCommittedFolds(Document& doc);

// A document from a design (its folds remade live, so they can be undone), with the sheet at
// `worldFromSheet`.
Document makeDocument(const Design& design, const std::string& name,
                      const Pose& worldFromSheet = {}, HandSide handedness = HandSide::Right);

// The design's name for its files and titles: "cone" for a surface, "bowl" for
// "designs/bowl.curvefold.json" (or its autosave); "design" for none.
std::string designName(const std::string& name);

// The design's surface for a person: the generator's name, or "embedded mesh".
std::string surfaceName(const Design& design);

// What is wrong with a symmetry, for a person: the engine's line, and where a surface lacks it,
// where the surfaces' symmetries are listed.
std::string symmetryProblem(const InvalidSymmetry& error);

// An INPUT that names neither a design file nor a surface (one line naming it).
class UnknownInput : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The design a command line INPUT names: a design file, a surface name (default parameters), or
// empty for `fallbackSurface`. Throws UnknownInput for anything else.
Design designFor(const std::string& input, const std::string& fallbackSurface);

// "<name>.autosave.curvefold.json" beside the working directory, <name> from INPUT.
std::string defaultAutosave(const std::string& input, const std::string& fallbackSurface);

// The autosave for a design named `name` (a surface, a file's stem) that a session switches to,
// beside `current`: <name>.autosave.curvefold.json, or <name>-2..., whichever does not exist yet,
// so no earlier design's autosave is overwritten.
std::string nextAutosave(const std::string& current, const std::string& name);

}  // namespace curvefold::session
