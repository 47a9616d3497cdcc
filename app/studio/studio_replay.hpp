// Replay with the studio (issue 14): a studio recording's panel runs again, undrawn, from the
// recorded hands, and a studio gesture script acts on a studio, so `point_at` finds the panel's
// items by label. Plain recordings replay as sim_input/player.hpp's replayRecording does; this
// is the studio's side of replay, which sim_input cannot hold (it knows no panel).
#pragma once

#include "sim_input/gestures.hpp"
#include "sim_input/player.hpp"
#include "sim_input/recording.hpp"

namespace curvefold::studio {

// Replays a studio recording (its header has "studio"): the panel runs without drawing and writes
// no file, so the design comes out as the session made it. The log lists folds, undos and redos
// as replayRecording's does, across new sheets. Safe from several threads: studio replays take
// turns (Dear ImGui's current context is process-wide), other replays run in parallel.
ReplayResult replayStudioRecording(const Recording& recording, const ReplayOptions& options = {});

// Any recording: a studio one with its panel, any other as replayRecording does.
ReplayResult replayAnyRecording(const Recording& recording, const ReplayOptions& options = {});

// What a studio gesture script acts on: a studio over the script's surface, which writes no file,
// so `point_at` can find the panel's items by label.
GestureWorldFactory studioGestureWorld();

}  // namespace curvefold::studio
