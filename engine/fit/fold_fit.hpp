// Folding toward a goal (issue 27, docs/design.md 9): the reflection folds that bring a sheet
// closest to a target shape. Mitani & Igarashi, "Interactive Design of Planar Curved Folding by
// Reflection" (Pacific Graphics 2011), close on design by reflection being explorative, and hope
// for "a more goal-oriented modeling process" (Sec. 6); this is one.
//
// A fold is a grabbed point of the sheet and where it is dropped (the plane is their bisector,
// Sec. 3.3), so one fold is a point on the sheet and three numbers. One step of the search:
//  1. An evaluation copy of the sheet: the same surface with area-uniform sample points made
//     vertices. A fold is defined by the surface, not by its triangulation (display_session.hpp),
//     so a candidate folds the copy and its folded form is read at the samples with no point
//     location. Its distance to the target is approximated on both sides by nearest neighbours
//     (nanoflann) among samples, corrected through each sample's normal: the mean two-sided
//     distance (Chamfer), which the step lowers.
//  2. Proposals: the planes of the target's creases (crease_planes.hpp: a target folded by
//     reflection names its folds' planes there), each tried from samples on either side, and
//     drags from a sample far from the target (drawn by how far) either to a target point far
//     from the sheet or onto the target point nearest it (a correspondence, as in ICP), all
//     scored on all cores; the best few, with distinct planes, refined
//     by a derivative-free local search of the drop point (NLopt's Subplex), which moves the plane
//     the way a correspondence step of ICP would, without needing its gradient.
//  3. Each refined drag is made on a FoldSession over the real sheet (so a sliver is refused as a
//     designer's drag is, and a symmetric design's images follow), checked for self-intersection,
//     scored again on the real folded form, and taken back.
//
// Deterministic: proposals come from a seeded generator, every evaluation lands in its own slot
// and ties go to the lower index, so the result does not depend on the threads' timing. The
// exceptions are the clock and a cancel (FitOptions::cancelled), either of which can cut a step
// short (FitResult::timedOut and cancelled say which); a budget of evaluations
// (FitOptions::maxEvaluations) is checked between steps, where the count is the same on every
// run, so a fit it stops repeats exactly.
//
// Known limits: each fold of a sequence must bring the sheet closer on its own; a target that
// needs a fold that makes it worse before a later one makes it better is not reached, except a
// pleat (pleat_folds.hpp: two folds offered as one step, in a design without symmetry).
// A symmetric design's images are scored as a display previews them (without the pieces a slit
// cuts off an image), and checked for self-intersection only when the drags are made.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/fit/deadline.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/sheet.hpp"
#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {

// A target that cannot be fitted: no area, or nowhere near the sheet. One line.
class InvalidTarget : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The one check of a target shape, whoever reads it (`fit`, the studio's --target, `render
// --target`). checkTarget: it has triangles with area, at coordinates that can be measured
// (unmeasurableVertex). checkTargetAgainst: it lies near the sheet (centres at most ten times the
// larger size apart) and is of its size within a hundredfold (its units). Throw InvalidTarget.
void checkTarget(const TriangleMesh& target);
void checkTargetAgainst(const TriangleMesh& target, const Sheet& sheet);

struct FitSettings {
  std::size_t sheetSamples = 1500;          // sample vertices of the evaluation copy
  std::size_t targetSamples = 1500;         // target points measured to the sheet
  std::size_t denseTargetSamples = 30'000;  // target points the sheet is measured to
  std::size_t proposals = 384;              // drags scored per step
  std::size_t refined = 6;                  // best distinct drags refined
  std::size_t refineEvaluations = 90;       // per refined drag
  // Distances count in full up to this fraction of the target's diagonal, a tenth beyond.
  double robustDistance = 0.01;
  // Rings of folds about a target of revolution's axis drawn per step (profile_folds.hpp); 0:
  // none.
  std::size_t rings = 256;
  // With rings, nested rings fitted to the profile of a target of revolution, from a flat sheet
  // across its axis (nested_rings.hpp).
  bool nestedRings = true;
  bool allowSelfIntersection = false;
  // Read folds from the target's creases (proposals through crease planes, and the unfolding
  // fitFolds tries first); off: search alone.
  bool useCreases = true;
  std::uint64_t seed = 1;
};

// A fold the search proposes, as made on the real sheet.
struct FoldSuggestion {
  std::vector<FoldRecord> folds;  // the fold, then its symmetric images (one group)
  Sheet sheet;                    // the sheet with them
  double before = 0.0;            // the search's score before and after (approximateDistance)
  double after = 0.0;
  bool crease = false;  // through a plane of the target's creases
};

struct TubeChains;  // ring_folds.hpp

class FoldFitter {
 public:
  // Samples the target once. Throws InvalidTarget for a target checkTarget refuses.
  explicit FoldFitter(TriangleMesh target, const FitSettings& settings = {});
  ~FoldFitter();
  FoldFitter(const FoldFitter&) = delete;
  FoldFitter& operator=(const FoldFitter&) = delete;

  const TriangleMesh& target() const;
  // The target as every exact measure sees it (surfaceDistance(sheet, measuredTarget())): its
  // tree and samples made once, at the first measure, for the fitter's life.
  const MeasuredSurface& measuredTarget() const;
  double targetDiagonal() const;
  // Whether the target is smooth or a scan (isSmoothOrScanned): the search then adds rings and
  // pleats to its single folds.
  bool smoothTarget() const;
  // Whether rings are drawn about the target's axis (a smooth surface of revolution).
  bool revolutionTarget() const;
  // Whether a fit from `initial` (a design's sheet before its folds) reads the target's creases
  // (the unfolding fitFolds tries first, and proposals through crease planes). A target folded
  // by reflections has creases to read. A smooth target or a scan may still be the sheet moved
  // whole (folds whose planes missed it), which the unfolding registers, so it is read too
  // unless it cannot be one: it is curved (isCurved: every reflection design is isometric to
  // its development) or its area differs from the sheet's by over 5% (every fold keeps the
  // area). Reading a vase, a bowl or a saddle finds nothing and took a third of a fit's time
  // (the whole-sheet registration), reading a scan's noise half of it (its crease planes).
  bool readsCreasesFrom(const Sheet& initial) const;
  const FitSettings& settings() const { return settings_; }

  // checkTargetAgainst with this target.
  void checkAgainst(const Sheet& sheet) const;

  // The search's score of a folded form (what it lowers): a robust Chamfer distance, whose
  // distances count at a tenth past 1% of the target's diagonal (FitSettings::robustDistance;
  // toward a smooth target with no axis, the target's side in full), so it is no distance to
  // print (a sheet 25 mm off scores 4 mm): approximateMeasure gives that.
  double approximateDistance(const Sheet& sheet) const;
  // The same for sheet samples given as points with unit normals, spaced about 2 * radius.
  double approximateDistance(const std::vector<glm::dvec3>& points,
                             const std::vector<glm::dvec3>& normals, double radius) const;
  // What the search's samples say of a folded form, without the cut the score makes: each side's
  // largest and mean distance, and their Hausdorff and Chamfer distances, as surfaceDistance
  // measures them exactly (surface_distance.hpp).
  SurfaceDistance approximateMeasure(const Sheet& sheet) const;

  // Up to `count` next folds for the design `session` holds (its symmetry, if any, makes each
  // fold's images), best first, each bringing it closer to the target; none when no fold found
  // does. Up to `count` more through the target's crease planes follow, when they are not among
  // the best (a fold that lays one part exactly, which the next fold may complete; such a fold
  // may leave the sheet up to 10% farther on its own). The session is dragged, committed and undone
  // on, and left as it was (a drag in progress is cancelled). `step` varies the proposals (a fit's
  // fold number). `nestedRings` false: without the nested rings (the fit tried them first).
  std::vector<FoldSuggestion> suggest(FoldSession& session, std::size_t count,
                                      const Deadline& deadline = {}, std::uint64_t step = 0,
                                      bool nestedRings = true) const;
  // The nested rings alone (nested_rings.hpp), when the session's sheet lies flat across the
  // target's axis: the fit tries them before the single folds, which from a flat sheet seldom
  // bring it as close to a bowl and cost more time. `tried`: set when the sheet lies so (the
  // rings were drawn), whether or not any brought it closer.
  // Whether the nested rings are drawn from `sheet` (it lies flat across the target's axis).
  bool nestedRingsFrom(const Sheet& sheet) const;
  // `handed`: tube chains the start's probe grew on this sheet (ring_folds.hpp), grown on
  // rather than again.
  std::vector<FoldSuggestion> suggestNestedRingsFirst(FoldSession& session, std::size_t count,
                                                      const Deadline& deadline, std::uint64_t step,
                                                      bool& tried,
                                                      const TubeChains* handed = nullptr) const;

 private:
  struct Target;
  // The target's crease planes with sharp edges above a sheet's own bends (crease_planes.hpp),
  // found once per threshold.
  const std::vector<ReflectionPlane>& creasePlanesAbove(double degrees) const;

  std::unique_ptr<Target> target_;
  FitSettings settings_;
  mutable std::mutex creaseMutex_;
  mutable std::map<double, std::vector<ReflectionPlane>> creasePlanes_;
};

struct FitProgress {
  std::size_t fold = 0;                                   // folds kept so far (0: the start)
  double hausdorff = 0.0, chamfer = 0.0, diagonal = 0.0;  // exact, to the target
  double seconds = 0.0;
  bool tucked = false;  // the step tucked corners under (tuck_folds.hpp)
};

struct FitOptions {
  std::size_t maxFolds = 6;
  // The whole fit (unfolding, search and the exact measures of what it found, the `progress`
  // calls included) ends within this many seconds of `started` (infinity: no clock).
  double seconds = 60.0;
  // When the clock of `seconds` started (unset: when fitFolds is called). A command passes its
  // own start, so that reading the target counts too.
  std::optional<std::chrono::steady_clock::time_point> started;
  // Candidate folds scored, at most (0: no limit). Checked between the search's steps, so a fit
  // stopped by it repeats bit for bit for one seed on any machine; a search step under way when
  // the count is reached is dropped whole (as one the clock cuts short).
  std::uint64_t maxEvaluations = 0;
  // Set from another thread (or a signal handler) to stop the search at its next check; the
  // folds found are still measured and committed.
  const std::atomic<bool>* cancelled = nullptr;
  // Each fold kept must lower the exact Chamfer distance by this fraction at least (or bring the
  // sheet within 1% of the diagonal, Hausdorff, from beyond it: a small flap read last).
  double minimumGain = 0.01;
  // and by this fraction of the target's diagonal (a fit already as close as the samples tell
  // gains nothing from more folds).
  double minimumAbsoluteGain = 1e-4;
  // Samples a side of each exact measure; under a clock, fewer when measuring the start with
  // them all would take over a tenth of the time left (a large or far target, a short limit).
  std::size_t distanceSamples = 20'000;
  std::size_t beamWidth = 3;    // fold sequences kept at each depth, the best
  std::size_t creaseWidth = 3;  // and this many more whose last fold is through a crease plane
  std::size_t branching = 3;    // next folds tried from each (and as many through crease planes)
  std::size_t pleats = 2;       // and this many pleats (pleat_folds.hpp: two folds as one step),
                                // toward a smooth target whose creases named no fold
  // After the start, then after each fold kept, with the session holding it.
  std::function<void(const FitProgress&)> progress;
  // While searching, after the unfolding and after each depth of the beam: folds, the best
  // sequence's Chamfer distance as the search's samples measure it (approximateMeasure), seconds.
  std::function<void(std::size_t, double, double)> searching;
  // The tube rings' chains the start's probe grew (reviseTubeByFirstStep): the search's first
  // step grows them on from there, on the sheet they were grown on.
  std::shared_ptr<const TubeChains> tubeChains;
  // The start may be moved whole (the caller chose it: `fit --from KIND` without parameters, or
  // no --from; never a sheet whose parameters or folds were given): where the target's reading
  // finds its creasing folds but the motion of the whole sheet takes more planes than the folds
  // left allow, the fit starts from the sheet moved by that motion and makes only the creasing
  // folds (FitResult::placedStart). Only on a session without folds, and on a symmetric one only
  // where its design is read as plain folds (FitResult::readPlain), which then drops the symmetry.
  bool mayPlaceStart = false;
};

struct FitResult {
  std::vector<FoldRecord> folds;   // every fold and image, groups numbered from 1 when symmetric
  std::vector<FitProgress> steps;  // the start, then one per fold kept
  std::string stopReason;          // why no further fold was added
  bool timedOut = false;           // the clock cut the fit short (it may differ run to run)
  bool cancelled = false;          // FitOptions::cancelled cut it short
  bool outOfEvaluations = false;   // maxEvaluations cut it short (the same on every run)
  std::uint64_t evaluations = 0;   // candidate folds scored
  // Sheet samples the search drew but could not place on the sheet (rounding put them outside
  // its development), summed over the search's steps: each step scores its folds on that many
  // fewer samples than FitSettings::sheetSamples. 0 on any sane sheet.
  std::uint64_t droppedSamples = 0;
  // Set where the fit started from the session's initial sheet moved whole (mayPlaceStart): the
  // session then holds it as its initial sheet, and the design must embed it as its surface.
  std::optional<Sheet> placedStart;
  // Set where a symmetric session's target was read only as a design without symmetry (its folds
  // and their images each a fold of its own, none grouped): the folds reach the target, and the
  // session keeps its symmetry for folds made after (unless placedStart, which drops it).
  bool readPlain = false;
};

// Folds `session`'s design toward the fitter's target: a beam search over fold sequences (the
// best `beamWidth` sequences at each depth and the best `creaseWidth` that end on a crease
// plane, each grown by its best `branching` next folds and as many through crease planes), at
// most maxFolds deep, within `seconds`; then the best sequence found is committed on the session
// up to where it comes closest (exactly measured), less last folds that gain under minimumGain.
// A fold on the way may bring the sheet no closer only when the sequence reaches the target
// (within 1% of its diagonal); otherwise every fold kept brings it closer.
FitResult fitFolds(FoldSession& session, const FoldFitter& fitter, const FitOptions& options);

}  // namespace curvefold
