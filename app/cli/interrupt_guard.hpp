// Ctrl+C (SIGINT) and SIGTERM while a long command runs (`xr`, `fit`): caught, they set a flag
// the work polls, so the command ends cleanly and keeps what it made (a session its design, a
// fit the best folds found) instead of the process being killed with it.
#pragma once

#include <atomic>
#include <csignal>

namespace curvefold::cli {

class InterruptGuard {
 public:
  InterruptGuard();   // clears the flag and catches both signals
  ~InterruptGuard();  // the handlers before it, back
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // Set once either signal came (lock-free: the handler only stores).
  static const std::atomic<bool>& flag();
  // The signal that came (SIGINT or SIGTERM), 0 when none.
  static int caught();
  // The status a shell gives a process that signal ended: 128 + its number (130, 143).
  static int exitStatus() { return 128 + caught(); }

 private:
  struct sigaction previousInt_ {};
  struct sigaction previousTerm_ {};
};

}  // namespace curvefold::cli
