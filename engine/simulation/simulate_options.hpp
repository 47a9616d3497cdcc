// The simulation's options as a person gives them, turned into the model's: design mode's
// stiffness preset, pins and glue at points of the flat sheet, and the folding motion's size
// limit. `curvefold simulate` (--stiffness, --pin, --glue, --motion) and Python's simulate
// (stiffness=, pin=, glue=, motion=) both call these, so the two check the same values with the
// same messages and build the same model, bit for bit (as setPaperMode does for --paper).
//
// Every message starts with the value's name and a colon ("pin: ...", "glue slits: ..."), for
// each caller to prefix as it names them ("--" on the command line, nothing in Python); each is
// thrown as std::invalid_argument.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "engine/io/crease_pattern.hpp"
#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/folding_motion.hpp"

namespace curvefold {

// Design mode's stiffnesses by name: "curvefold" (ModelOptions' own) or "origami-simulator"
// (simulatorModelOptions'). Inputs: options (its other fields kept), name, and whether paper
// mode is asked too (refused: paper mode takes paper's stiffnesses). Throws "stiffness: ...".
void setStiffnessPreset(ModelOptions& options, std::string_view name, bool paperMode);

// "X,Y": a point of the flat sheet in metres, as the command line takes it. Throws
// "NAME: expected X,Y on the flat sheet in metres, got '...'".
glm::dvec2 parseSheetPoint(std::string_view text, std::string_view name);

// The vertex of the pattern nearest p (metres, on the flat sheet; the lowest index on a tie). A
// point past the sheet's bounding box by more than 1% of its diagonal is refused rather than
// taken to the nearest corner: it is most often a point in the wrong unit (millimetres for
// metres). Throws "NAME: (x, y) is off the flat sheet, which spans ..." or, for a coordinate that
// is not finite, "NAME: expected X,Y on the flat sheet in metres, got (x, y)".
std::uint32_t sheetVertexNear(const CreasePattern& pattern, glm::dvec2 p, std::string_view name);

// Holds the vertex nearest p where it starts (options.pins; --pin). Throws "pin: ...".
void addPin(ModelOptions& options, const CreasePattern& pattern, glm::dvec2 p);

// Pulls the vertices nearest a and b together (options.glue; --glue X1,Y1:X2,Y2). Throws
// "glue: ..." (off the sheet, or both points nearest one vertex).
void addGlue(ModelOptions& options, const CreasePattern& pattern, glm::dvec2 a, glm::dvec2 b);

// Glues every slit of a design shut (--glue slits): seams are designPattern's (design_input.hpp);
// a crease pattern has none. Throws "glue slits: the design has no slit" when there is none.
void glueSlits(ModelOptions& options,
               const std::vector<std::pair<std::uint32_t, std::uint32_t>>& seams);

// One --glue value: "slits" or "X1,Y1:X2,Y2" (glueSlits, addGlue). Throws "glue...: ...".
void addGlueText(ModelOptions& options, const CreasePattern& pattern,
                 const std::vector<std::pair<std::uint32_t, std::uint32_t>>& seams,
                 std::string_view text);

// The most vertices a folding motion is found for: a static solve per step of the motion.
inline constexpr std::size_t kMaxMotionVertices = 20'000;

// The model's targets follow its folding motion (foldingMotion, setFoldingMotion; --motion).
// Returns the motion found. Throws "motion: the pattern has N vertices; ..." past
// kMaxMotionVertices, before any work.
FoldingMotion followFoldingMotion(BarHingeModel& model);

}  // namespace curvefold
