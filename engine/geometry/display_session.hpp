// What to draw of a FoldSession: the same surface with planar regions merged (simplifyPlanar),
// kept in step with the session by making the same grabs, drags and commits on the coarse sheet.
//
// A fold is defined by the surface, not by the triangulation: the reflected part is the connected
// piece of the surface on the grabbed point's side of the plane, and the flood fill over vertices
// finds the same piece on any triangulation of it. So the coarse sheet, grabbed at the same
// development point and reflected through the same plane, stays a triangulation of the session's
// sheet, and a drag update costs what the coarse sheet costs (a 100k-triangle cylinder is ~500
// triangles). Only a design that changes otherwise (undo, redo, open, a new session) is simplified
// afresh. In a symmetric design the coarse drag also previews the fold's images
// (FoldSession::setImagePreview); a symmetric commit, which adds a group, is simplified afresh.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "engine/geometry/fold_session.hpp"

namespace curvefold {

class DisplaySession {
 public:
  // simplify = false shows the source's own sheet (every triangle), for comparison.
  explicit DisplaySession(bool simplify = true) : simplify_(simplify) {}

  // Brings the coarse sheet in line with `source` (its drag, target and committed folds). Call
  // once per frame, before drawing.
  void follow(const FoldSession& source);

  // The sheet to draw and its reflected triangles: the coarse one, or the source's own if the
  // coarse sheet could not follow (an operation on it threw), until the next rebuild.
  const Sheet& sheet() const;
  std::span<const TriangleIndex> reflectedTriangles() const;
  // The session behind sheet(), for its change records (SessionSheetTracker).
  const FoldSession& shownSession() const;
  // Counts rebuilds, so a cache of the shown sheet can tell a new coarse session from the old one.
  std::uint64_t generation() const { return generation_; }

 private:
  void rebuild(const FoldSession& source);
  void followDrag(const FoldSession& source);

  bool simplify_ = true;
  const FoldSession* source_ = nullptr;
  std::unique_ptr<FoldSession> coarse_;  // null while showing the source itself
  std::uint64_t generation_ = 0;
  std::uint64_t designRevision_ = 0;  // the source's, as of the last follow()
  std::size_t baseFolds_ = 0;         // the source's folds when coarse_ was made
  glm::dvec2 grabSeed_{0.0};
  std::optional<glm::dvec3> target_;  // last target given to the coarse drag
};

}  // namespace curvefold
