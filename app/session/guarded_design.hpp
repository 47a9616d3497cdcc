// A design and the live FoldSession over it, safe to share between threads (issue 40, 2): the
// Python module's Design, which any number of Python threads may call at once while the GIL is
// released. One mutex per design; every read or write of the session (and of the snapshot cache
// the arrays share) takes a Lock, and the accessors that reach the session ask for one, so code
// that forgets it does not compile. Nothing here knows Python: a C++ test runs many threads over
// it under ThreadSanitizer (tests/test_guarded_design.cpp).
//
// Known limit: the lock is per design, so two threads on one design take turns (a long fold or
// check holds the others back); designs of their own run in parallel.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "engine/geometry/fold_session.hpp"
#include "engine/io/design_document.hpp"

namespace curvefold::session {

// What one fold did.
struct FoldResult {
  bool folded = false;             // false: the drop point lay within the shortest drag
  std::vector<double> grabbed;     // the surface point grabbed (x, y, z)
  std::vector<double> planePoint;  // the reflection plane
  std::vector<double> planeNormal;
  std::size_t triangles = 0;  // after the fold
  std::size_t images = 0;     // symmetric images made with it
  std::string notes;          // images skipped or overlapping, as the command says
};

class GuardedDesign {
 public:
  // Builds the session over `design`'s sheet and folds (throws the surface's or the fold's error).
  // `name` names it in messages.
  GuardedDesign(Design design, std::string name);

  // Holds the design's mutex while it lives: proof, for the accessors below, that the caller has
  // it. Never take it while holding a lock another thread may wait for while wanting this one
  // (the Python module releases the GIL first).
  class Lock {
   public:
    explicit Lock(const GuardedDesign& design) : design_(&design), lock_(*design.mutex_) {}

   private:
    friend class GuardedDesign;
    const GuardedDesign* design_;
    std::unique_lock<std::mutex> lock_;
  };

  // Fixed at construction: no lock needed.
  const std::string& name() const { return name_; }
  const std::string& symmetry() const { return symmetry_; }

  // The design as saved: surface, the applied folds (not the undone ones) and symmetry.
  Design design(const Lock& lock) const;
  FoldSession& session(const Lock& lock);
  const FoldSession& session(const Lock& lock) const;
  // The folded sheet as it is now, shared with whatever holds it (arrays handed out stay valid
  // and unchanged after the design changes: a change makes a new snapshot, one copy per change).
  std::shared_ptr<const Sheet> snapshot(const Lock& lock) const;

  // Grabs the surface point nearest `grab` and drops it at `to`, checked as the command line's
  // fold checks it (a fold that breaks validate() is taken back and its error thrown); a refused
  // fold throws std::invalid_argument with the session's reason.
  FoldResult fold(const Lock& lock, const glm::dvec3& grab, const glm::dvec3& to);

 private:
  void owns(const Lock& lock) const;  // throws std::logic_error on another design's lock

  std::string name_;
  InitialSurface surface_;
  std::string symmetry_;
  std::unique_ptr<FoldSession> session_;
  // In a unique_ptr so a design can still be moved (returned by value) before it is shared.
  std::unique_ptr<std::mutex> mutex_ = std::make_unique<std::mutex>();
  mutable std::shared_ptr<const Sheet> snapshot_;  // under mutex_
  mutable std::uint64_t snapshotRevision_ = 0;     // under mutex_
};

}  // namespace curvefold::session
