// The benchmarks' recorded session: twelve drags of 4.7 s around the rim of a cylinder, each along
// a wavering path, every other one while the other hand turns the sheet: 60 s of two-handed
// dragging at 90 Hz. `resolution` sets the cylinder's size (116: ~20k triangles, 259: ~100k).
#pragma once

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "sim_input/gestures.hpp"
#include "sim_input/recording.hpp"

namespace curvefold {

inline Recording sixtySecondsOfDragging(int resolution) {
  RecordingHeader header;
  header.surface = GeneratedSurface{"cylinder", {{"resolution", resolution}}};
  header.sheetFrame = defaultSheetFrame();
  header.rate = 90.0;
  GestureRecorder recorder(header);
  const double r = 0.045, top = 0.105;
  for (int i = 0; i < 12; ++i) {
    const double angle = i * 2.0 * std::numbers::pi / 12.0 + 0.1;
    const double end = (i % 2 == 0) ? top : -top;
    const glm::dvec3 grab{r * std::sin(angle), end, r * std::cos(angle)};
    const glm::dvec3 inward{-0.5 * grab.x, -0.5 * end, -0.5 * grab.z};
    std::vector<glm::dvec3> path;
    for (int k = 1; k <= 6; ++k) {
      const double s = k / 6.0;
      path.push_back(grab + s * inward + glm::dvec3(0.01 * std::sin(3 * s), 0.0, 0.01 * s));
    }
    std::optional<SheetTurn> turn;
    if (i % 2 == 1) turn = SheetTurn{{0.0, 1.0, 0.0}, 20.0};
    recorder.drag(grab, path, 4.7, turn);
  }
  return recorder.recording();
}

}  // namespace curvefold
