// The design document, `*.curvefold.json` (docs/design.md 4): the initial surface and the ordered
// committed folds. Folds are stored as a plane and a development seed, so loading replays them
// independent of vertex numbering. Doubles are written in their shortest exact form, so a saved
// design rebuilds bit for bit.
#pragma once

#include <filesystem>
#include <istream>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/sheet.hpp"

namespace curvefold {

inline constexpr std::string_view kDesignFormat = "curvefold-design";
// Version 2 records the generator version that made a generated sheet ("generator_version");
// version 1 (until 2026-12-04) did not: see loadDesign for how its meshing is told.
inline constexpr int kDesignVersion = 2;
// A fold's "more_seeds" (FoldRecord::moreSeeds) hold at most kMaxMoreSeeds (fold_session.hpp).

// One line naming the file and the problem, e.g.
// "bird.curvefold.json: fold 3: seed (0.5, 1.2) lies outside the sheet". Folds count from 1.
class DesignError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An initial surface made by a generator of the surfaces library (makeSurface).
struct GeneratedSurface {
  std::string generator;
  std::map<std::string, double> parameters;
  // The meshing that made the sheet (makeSurface's generatorVersion); 0: the generator's latest,
  // which a design read from a file holds as 0 too.
  int generatorVersion = 0;
  bool operator==(const GeneratedSurface&) const = default;
};

// Either a generator with its parameters or an embedded mesh (its crease and slit tags kept).
using InitialSurface = std::variant<GeneratedSurface, Sheet>;

struct Design {
  Design() = default;
  Design(InitialSurface surface, std::vector<FoldRecord> folds, std::string symmetry = {})
      : surface(std::move(surface)), folds(std::move(folds)), symmetry(std::move(symmetry)) {}

  InitialSurface surface;
  std::vector<FoldRecord> folds;
  // A symmetry of the initial surface every fold is followed by the images of
  // (engine/geometry/symmetry.hpp: "rotational:6:y", "mirror:x"); empty: none.
  std::string symmetry;
};

// The sheet before any fold: makeSurface's result or the embedded mesh. Throws DesignError when
// the generator refuses its parameters. nameForErrors starts every message.
Sheet initialSheet(const Design& design, std::string_view nameForErrors = "design");

// The initial sheet with every fold replayed in order (what replayFolds gives). Throws DesignError
// naming the fold that cannot be applied.
Sheet buildSheet(const Design& design, std::string_view nameForErrors = "design");

// Writes the design atomically. Throws DesignError for a design that could not be loaded back
// (a number that is not finite, a plane normal that is not a unit vector, an invalid embedded
// mesh), FileError when the file cannot be written.
void saveDesign(const Design& design, const std::filesystem::path& path);
// The text saveDesign writes (the design's canonical form).
std::string designText(const Design& design);

// Reads and checks a design (everything but the replay, which buildSheet does). Throws FileError
// when the file cannot be read, DesignError for anything wrong with its content, also for a file
// or a generator version newer than this build's ("unsupported version 3, newer than ...").
//
// A version-1 design does not say which meshing made its generated sheet, and the flat sheets'
// changed on 2026-12-04 (generator version 2). It is read as generator version 1, the meshing of
// the twelve days before, unless only version 2 fits it: its symmetry is one the version-1 sheet
// lacks (symmetries came with version 2), or its folds replay on version 2 but not on version 1.
// That one replay is the cost of reading such a file; saving it again writes version 2.
Design loadDesign(const std::filesystem::path& path);
// The reading alone, without that replay: a version-1 flat sheet stays generator version 1 (so a
// fuzzer's input costs no replay before it is looked at).
Design parseDesign(std::istream& in, std::string_view nameForErrors);

// The "surface" object of a design document, for other formats that embed an initial surface (a
// recording's header). parseInitialSurface checks the JSON (not whether a generator accepts its
// parameters: initialSheet does that) and throws DesignError starting with nameForErrors. These
// formats name no generator version: their generated surfaces are the latest meshing.
nlohmann::ordered_json initialSurfaceJson(const InitialSurface& surface);
InitialSurface parseInitialSurface(const nlohmann::json& value, std::string_view nameForErrors);

}  // namespace curvefold
