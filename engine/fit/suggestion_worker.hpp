// Suggestions off the frame (issue 27, 3): the studio asks for the next fold and goes on drawing;
// a worker thread runs the search (FoldFitter::suggest, about a second at 10k triangles) on a
// snapshot of the design and the frame picks the result up when it is there. A newer request, a
// cancel (the design changed) or a new target abandons the one in flight: its search stops at its
// next check (the replay of the design's folds checks by the triangles it folds, the search
// between drags: tens of milliseconds of CPU apart) and its result is dropped; none of these
// calls waits for the search. Each search has a time limit; only the destructor waits (for the
// search to see it is abandoned), so a frame loop keeps its worker until it ends. A frame loop
// gives the search a nice (kYieldToFrames) so that on a machine of few cores the frame and a CPU
// renderer get the cores first (docs/performance.md, "The window itself"); its result does not
// depend on it, its time does: beside a renderer that keeps the cores busy it takes longer.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "engine/fit/fold_fit.hpp"

namespace curvefold {

// What a design is, for a search of its own: the initial sheet, the folds, the symmetry's name.
struct DesignSnapshot {
  std::shared_ptr<const Sheet> initial;
  std::vector<FoldRecord> folds;
  std::string symmetry;  // "" none
};

// Runs `work` on the calling thread lowered to `nice` (where that is below it), in the TBB arena a
// SuggestionWorker of that nice searches in, so that its parallel parts yield to the frames as the
// search's do: other work a studio does off the frame at the search's priority (the start's
// revision, app/studio/studio_target.hpp). The thread stays at `nice` after it.
void runAtSearchNice(int nice, const std::function<void()>& work);

class SuggestionWorker {
 public:
  // Seconds a search may take before it answers with the best it has scored (at least one
  // suggestion when any candidate brings the design closer).
  static constexpr double kDefaultTimeLimit = 10.0;
  // The nice a frame loop's search runs at: about a tenth of a contended core beside a thread at
  // nice 0, all of an idle one.
  static constexpr int kYieldToFrames = 10;
  // Before it searches, the worker makes the design's folds again on a session of its own, a
  // fold's work per fold (about 3.5 ms of CPU per 10k triangles): it looks for an abandon after
  // every this many triangles folded (folds times the sheet's triangles), so a long design on a
  // large sheet stops within about 35 ms of CPU, not at the end of its replay (issue 38, 3).
  static constexpr std::size_t kReplayTrianglesPerCheck = 100'000;
  // nice: the search's threads (this worker's and TBB's while they search for it) run at it, or
  // at their own when that is higher; the caller's thread is left as it is.
  explicit SuggestionWorker(std::shared_ptr<const FoldFitter> fitter,
                            double timeLimit = kDefaultTimeLimit, int nice = 0);
  ~SuggestionWorker();  // abandons the request in flight and waits for the thread
  SuggestionWorker(const SuggestionWorker&) = delete;
  SuggestionWorker& operator=(const SuggestionWorker&) = delete;

  // Starts the search for up to `count` next folds of `design` (never blocks on a search).
  // Returns the request's number.
  std::uint64_t request(DesignSnapshot design, std::size_t count);
  // Abandons the request in flight and any waiting (the design they were for changed).
  void cancel();
  // Searches toward another target from now on (the request in flight is abandoned).
  void retarget(std::shared_ptr<const FoldFitter> fitter);
  // Whether the latest request is still being searched.
  bool busy() const;
  // The request whose search runs now (0: none): an abandoned one until its search stops.
  std::uint64_t searching() const;
  struct Answer {
    std::uint64_t request = 0;
    std::vector<FoldSuggestion> suggestions;  // best first; none: no fold brings it closer
    std::string error;                        // the engine's refusal, when it refused
  };
  // The latest request's answer, once, when it is done.
  std::optional<Answer> take();

 private:
  void run();
  // The design's folds made on `session`, kReplayTrianglesPerCheck at a time: false when the
  // request was abandoned before they were all made.
  bool replay(FoldSession& session, const std::vector<FoldRecord>& folds) const;

  std::shared_ptr<const FoldFitter> fitter_;  // guarded by mutex_
  const double timeLimit_;
  const int nice_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<std::pair<DesignSnapshot, std::size_t>> pending_;
  std::uint64_t latest_ = 0;   // the newest request's number
  std::uint64_t working_ = 0;  // the number being searched (0: none)
  std::optional<Answer> answer_;
  std::atomic<bool> abandon_{false};
  bool stopping_ = false;
  std::thread thread_;  // last: started once everything above is ready
};

}  // namespace curvefold
