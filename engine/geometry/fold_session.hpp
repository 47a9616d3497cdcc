// The fixed and temporal sheets of [Mitani & Igarashi 2011, Sec. 3.3] with grab, drag, commit,
// cancel, undo and redo (docs/design.md 2). Folds are recorded as a plane and a 2D development
// seed, so a design replays independent of vertex numbering.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "engine/geometry/reflection.hpp"
#include "engine/geometry/sheet.hpp"
#include "engine/geometry/surface_point.hpp"
#include "engine/geometry/topology.hpp"

namespace curvefold {

class SymmetricFolder;
struct Symmetry;

// One committed fold: the grabbed point as a development point, and the plane it was reflected
// through. grabbed/target are the 3D drag (informative; the plane is what replays).
// The most moreSeeds a fold records: an image whose part a slit cuts into more pieces than this
// is refused when the fold is made, not first when its design is saved.
inline constexpr std::size_t kMaxMoreSeeds = 64;

struct FoldRecord {
  glm::dvec2 seed{0.0};
  ReflectionPlane plane;
  glm::dvec3 grabbed{0.0};
  glm::dvec3 target{0.0};
  // In a symmetric design, the group of a fold and its images (from 1; 0: no group). Replay does
  // not need it; undo takes a group at once.
  std::uint32_t group = 0;
  // Development points of vertices the reflected part also grows from (usually none): an image
  // whose part a slit cuts in pieces, though the fold's own part was whole (symmetry.hpp).
  std::vector<glm::dvec2> moreSeeds;
};

// Applies one recorded fold: the seed becomes a vertex (insertVertexAt), then the part containing
// it (and any of its moreSeeds) is reflected. Throws InvalidSheet when the seed lies outside the
// sheet. Bit-identical to the same fold made live through FoldSession.
Sheet applyFold(const Sheet& sheet, const FoldRecord& fold);

// Applies folds in order to an initial sheet.
Sheet replayFolds(Sheet initial, const std::vector<FoldRecord>& folds);

// Bytes a session holds, for the memory budget of docs/design.md 8 (fixed + temporal below 3
// sheets).
struct SessionMemory {
  std::size_t fixed = 0;      // the fixed sheet's arrays
  std::size_t temporal = 0;   // the temporal sheet's arrays
  std::size_t adjacency = 0;  // the fixed sheet's vertex rows
  std::size_t workspace = 0;  // the reflection's scratch
  std::size_t history = 0;    // undo keyframes and the last point undone to (the initial sheet is
                              // shared with the caller's)
};

class FoldSession {
 public:
  explicit FoldSession(Sheet initial);

  const Sheet& initial() const { return *initial_; }
  // The committed sheet; during a drag it also holds the grabbed point as a vertex.
  const Sheet& fixed() const { return fixed_; }
  // What to show: the temporal sheet while dragging (with the images, when previewed), else the
  // fixed one.
  const Sheet& current() const { return dragging_ ? (previewing_ ? preview_ : temporal_) : fixed_; }
  double epsilon() const { return epsilon_; }
  // The shortest drag that folds (kRelativeMinimumDrag of the sheet's size); shorter ones show
  // the unfolded sheet and commit nothing.
  double minimumDrag() const { return kRelativeMinimumDrag * epsilon_ / kRelativeEpsilon; }
  // Changes whenever the fixed sheet does (commit, undo, redo), for caches built on it.
  std::uint64_t fixedRevision() const { return fixedRevision_; }
  // Changes when the committed design does (commit of a fold, undo, redo), not when a grab makes
  // a vertex: followers that replay the drags themselves (DisplaySession) watch this one.
  std::uint64_t designRevision() const { return designRevision_; }

  // --- Dragging -----------------------------------------------------------------------------
  bool dragging() const { return dragging_; }
  // Grabs a surface point (it becomes a vertex of the temporal sheet). Ends any drag in progress
  // by cancelling it. Returns the grabbed 3D position.
  glm::dvec3 beginDrag(const SurfacePoint& point);
  // `triangle`, when known, holds the seed (a picked point's): it spares a scan for it.
  glm::dvec3 beginDragAtDevelopment(const glm::dvec2& seed, TriangleIndex triangle = kNoIndex);
  glm::dvec3 beginDragNear(const glm::dvec3& p);
  // Moves the grabbed point to `target` (sheet coordinates); the temporal sheet is the fixed one
  // with the part containing the point reflected through the bisector plane. A target within
  // epsilon of the grabbed point shows the unfolded sheet. Returns what changed since the last
  // update, for incremental upload.
  const ReflectionChanges& updateDrag(const glm::dvec3& target);
  // Commits the temporal sheet as the new fixed sheet (a drag that never left its start adds no
  // fold). Returns true if a fold was added. A fold whose new triangles fail validate()'s rules
  // (a sliver), or whose symmetric images cannot be made or would not be symmetric (symmetry.hpp),
  // is not kept: the drag is cancelled and refusal() says why.
  bool commit();
  const std::string& refusal() const { return refusal_; }
  void cancel();

  const glm::dvec3& grabbedPoint() const { return grabbed_; }
  const glm::dvec2& grabbedSeed() const { return grabSeed_; }  // the grab in the development
  const glm::dvec3& dragTarget() const { return target_; }
  bool hasPlane() const { return folded_; }
  const ReflectionPlane& plane() const { return plane_; }
  VertexIndex grabbedVertex() const { return grabVertex_; }
  const ReflectionChanges& lastChanges() const { return workspace_.changes(); }
  // Triangles of current() in the reflected part (empty unless a drag folds the sheet), with the
  // images' while they are previewed; derived on the first call after each update.
  const std::vector<TriangleIndex>& reflectedTriangles() const;

  SessionMemory memoryUse() const;

  // --- History ------------------------------------------------------------------------------
  const std::vector<FoldRecord>& folds() const { return history_; }
  std::size_t foldCount() const { return applied_; }  // folds in the fixed sheet
  bool canUndo() const { return applied_ > 0; }
  bool canRedo() const { return applied_ < history_.size(); }
  // Applies recorded folds as committed (a design opened), groups as recorded; drops any redo.
  void applyRecords(const std::vector<FoldRecord>& folds);
  // Starts over from `initial`: no folds, no history, no symmetry, no drag (a fit that moved its
  // start whole, FitResult::placedStart): a session cannot be moved or assigned (its workspace's
  // memory pool), so it starts over in place.
  void restartFrom(Sheet initial);
  // Undo and redo take a symmetric fold's group (the fold and its images) at once.
  bool undo();
  bool redo();
  // Undoes until at most `foldCount` folds are left (whole groups, as repeated undo() does), the
  // sheet folded again from its keyframe once, not once per fold taken back: the same sheet as
  // `while (foldCount() > n) undo();`, for a search that makes a ring or pleats and takes them
  // back (a ring of 16 folds took 16 replays of up to 7 folds each). Returns the folds taken back.
  std::size_t undoTo(std::size_t foldCount);

  // --- Symmetry -----------------------------------------------------------------------------
  // From now on every commit is followed by the fold's images under `symmetry` (which the initial
  // sheet must have: throws InvalidSymmetry), as one group (engine/geometry/symmetry.hpp).
  void setSymmetry(const Symmetry& symmetry);
  const Symmetry* symmetry() const;
  const std::shared_ptr<const SymmetricFolder>& symmetricFolder() const { return symmetric_; }
  // While a drag folds the sheet, current() also shows the fold's images as `folder` makes them
  // (SymmetricFolder::previewImages), remade at every update: for a small sheet only, such as a
  // display's coarse one following a session that has the symmetry (DisplaySession). Null: none.
  void setImagePreview(std::shared_ptr<const SymmetricFolder> folder);
  // Whether current() holds previewed images now, and a number that changes whenever it is
  // remade (its changes are not recorded: a renderer uploads it whole).
  bool previewingImages() const { return dragging_ && previewing_; }
  std::uint64_t previewRevision() const { return previewRevision_; }
  // Images the last commit left out (their seed lay in a part the fold moved).
  std::size_t lastSkippedImages() const { return lastSkipped_; }
  // Images the last commit made whose part overlapped an earlier fold's of its group.
  std::size_t lastOverlappingImages() const { return lastOverlapping_; }

 private:
  void setFixed(Sheet sheet);
  void fixedChanged();  // after fixed_ changed: its adjacency and revision
  void addKeyframes();  // up to the folds applied
  Sheet sheetAfter(std::size_t foldCount) const;
  void fixedFromHistory();  // fixed_ as the first applied_ folds make it (undo, undoTo)
  void historyChangesFrom(std::size_t fold);  // the records from `fold` on are dropped

  std::shared_ptr<const Sheet> initial_;
  double epsilon_ = 0.0;
  Sheet fixed_;
  SheetAdjacency fixedAdjacency_;
  SheetAdjacency adjacencyBeforeGrab_;  // fixed_'s before the grab's insertion, for a cancel
  std::uint64_t fixedRevision_ = 0;
  std::uint64_t designRevision_ = 0;

  // Drag state: while dragging, fixed_ holds the grabbed point as a vertex (grabUndo_ takes it
  // back on cancel) and temporal_ is fixed_ with the reflection applied.
  bool dragging_ = false;
  bool folded_ = false;
  bool sliver_ = false;  // the last target's plane would cut a sliver: no fold there
  InsertionUndo grabUndo_;
  bool grabInserted_ = false;
  VertexIndex grabVertex_ = kNoIndex;
  glm::dvec2 grabSeed_{0.0};
  glm::dvec3 grabbed_{0.0};
  glm::dvec3 target_{0.0};
  ReflectionPlane plane_;
  std::string refusal_;
  Sheet temporal_;
  mutable ReflectionWorkspace workspace_;  // its reflected-triangle list is a cache

  // Committed folds; the first applied_ are in fixed_, the rest can be redone. Keyframes every
  // kKeyframeInterval folds bound the cost of undo to a few replayed folds.
  static constexpr std::size_t kKeyframeInterval = 8;
  std::vector<FoldRecord> history_;
  std::size_t applied_ = 0;
  std::vector<std::shared_ptr<const Sheet>> keyframes_;  // keyframes_[k]: after k*interval folds
  // The sheet and adjacency of the last point undone to, while the folds before it stand: a search
  // that makes folds and takes them back to one point (tucks, pleats, rings: undoTo) copies them
  // there, not folding the sheet again from its keyframe and building its adjacency each time.
  struct UndoPoint {
    std::size_t foldCount = 0;
    Sheet sheet;
    SheetAdjacency adjacency;
  };
  std::optional<UndoPoint> undoPoint_;

  std::shared_ptr<const SymmetricFolder> symmetric_;  // none: folds have no images
  std::shared_ptr<const SymmetricFolder> previewFolder_;
  bool previewing_ = false;  // preview_ holds temporal_ with the images
  Sheet preview_;
  std::vector<TriangleIndex> previewReflected_;
  std::uint64_t previewRevision_ = 0;
  std::size_t lastSkipped_ = 0;
  std::size_t lastOverlapping_ = 0;
};

}  // namespace curvefold
