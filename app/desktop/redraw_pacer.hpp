// When the designer window draws a frame (issue 38, 3). Drawing at full rate when nothing on screen
// changes costs a CPU renderer (lavapipe) most of the cores: a suggestion searched below the frame
// (SuggestionWorker::kYieldToFrames) then waited for the renderer's threads, and reached the
// window in 2.3 s where the search alone takes 0.8 s (docs/performance.md). So the window draws at
// once when something changes (an input event, the studio's news: a load, an answer or a measure
// ready), on for a few frames after it (ImGui's hover and a click's result show a frame later; the
// sheet is drawn a frame behind its fold), and while something moves by itself (a drag, the live
// simulation, typed text); otherwise it waits, looking at the studio now and then, and redraws
// seldom for what announces itself by no event (a file chooser's answer, a tooltip).
//
// Inputs: changed() for each event or news, drawn(moving) after each frame, the clock.
// Outputs: due(now), whether to draw now; wait(now), how long to wait for events before asking
// again. Limits: news that comes with no event is seen within kStudioCheckSeconds, and anything
// else within kSeldomRedrawSeconds.
#pragma once

#include <chrono>

namespace curvefold::desktop {

class RedrawPacer {
 public:
  using Clock = std::chrono::steady_clock;
  // Frames drawn after the last change: ImGui answers an event a frame later, the renderer draws
  // the sheet a frame behind the core (performance.md), and a frame in flight may hold the old.
  static constexpr int kSettleFrames = 3;
  // How often, at most, the window looks at the studio's threads while it draws nothing.
  static constexpr double kStudioCheckSeconds = 0.01;
  // The longest the window goes without a frame.
  static constexpr double kSeldomRedrawSeconds = 0.25;

  // An input event, or news from the studio: the next frames are drawn at once.
  void changed() { settle_ = kSettleFrames; }
  // After a frame; moving: something on screen changes by itself (drawn again at once).
  void drawn(bool moving, Clock::time_point now);
  bool due(Clock::time_point now) const;
  // Seconds to wait for an event before due() is asked again (0: draw now).
  double wait(Clock::time_point now) const;

 private:
  int settle_ = kSettleFrames;
  bool moving_ = false;
  Clock::time_point last_{};
};

}  // namespace curvefold::desktop
