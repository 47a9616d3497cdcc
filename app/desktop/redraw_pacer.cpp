#include "app/desktop/redraw_pacer.hpp"

#include <algorithm>

namespace curvefold::desktop {

void RedrawPacer::drawn(bool moving, Clock::time_point now) {
  moving_ = moving;
  if (settle_ > 0) --settle_;
  last_ = now;
}

bool RedrawPacer::due(Clock::time_point now) const {
  return moving_ || settle_ > 0 ||
         std::chrono::duration<double>(now - last_).count() >= kSeldomRedrawSeconds;
}

double RedrawPacer::wait(Clock::time_point now) const {
  if (due(now)) return 0.0;
  const double sinceLast = std::chrono::duration<double>(now - last_).count();
  return std::min(kStudioCheckSeconds, kSeldomRedrawSeconds - sinceLast);
}

}  // namespace curvefold::desktop
