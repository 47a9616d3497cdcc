// The process's CPU time by thread group, for --frame-times (issue 38, 3): where a suggestion's
// time goes between the frame that asks and the frame that takes it in, counted in CPU time, which
// does not depend on the machine's load as wall time does. Each live thread's time on the CPU is
// read from /proc/self/task/*/schedstat (nanoseconds) and grouped by the thread's name.
//
// Groups: frame (the thread that calls, the window's), search (SuggestionWorker's thread,
// "cf-search"), render (Mesa's lavapipe/llvmpipe threads), other (every other live thread:
// TBB's workers, which the search and the measures share, the loads and measures still running);
// process: the whole process (CLOCK_PROCESS_CPUTIME_ID), so process minus the others counts the
// threads that ended (a load, a measure). Limits: Linux only (empty without /proc); reading costs
// about a file per thread (a fraction of a millisecond), so it is read on the few frames that
// note something, not every frame.
#pragma once

#include <string>

namespace curvefold::desktop {

struct ThreadGroupCpu {
  double frameMs = 0.0, searchMs = 0.0, renderMs = 0.0, otherMs = 0.0, processMs = 0.0;
};

ThreadGroupCpu threadGroupCpu();

// "cpu=frame:F,search:S,render:R,other:O,process:P" (ms), one token for --frame-times.
std::string threadGroupCpuToken(const ThreadGroupCpu& cpu);

}  // namespace curvefold::desktop
