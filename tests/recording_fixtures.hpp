// Hand-built input frames on the flat square (makeSurface("square"): side 0.2 in z = 0, centred on
// the origin) with the sheet frame the identity: clutch and lift the sheet, grab its right edge and
// fold it over, release.
#pragma once

#include <cstdint>
#include <vector>

#include "interaction/input_frame.hpp"
#include "sim_input/recording.hpp"

namespace curvefold::testing {

inline RecordingHeader squareRecordingHeader() {
  RecordingHeader header;
  header.source = "synthetic";
  header.surface = GeneratedSurface{"square", {{"resolution", 10}}};
  header.rate = 10;
  return header;
}

// A square of `resolution` held where a standing user reaches it (1.1 m up, 0.45 m ahead), at 60
// frames a second: the gesture scripts' and the session outputs' tests fold on it.
inline RecordingHeader heldSquareHeader(int resolution) {
  RecordingHeader header;
  header.surface = GeneratedSurface{"square", {{"resolution", resolution}}};
  header.sheetFrame = {{0.0, 1.1, -0.45}, glm::dquat(1, 0, 0, 0)};
  header.rate = 60;
  return header;
}

inline InputFrame handFrame(double time, const glm::dvec3& sheetHand, double clutch,
                            const glm::dvec3& point, double select, std::uint32_t buttons = 0) {
  InputFrame frame;
  frame.time = time;
  frame.sheetHand.pose.position = sheetHand;
  frame.sheetHand.tracked = true;
  frame.sheetHand.clutch = clutch;
  frame.pointHand.position = point;
  frame.pointHand.tracked = true;
  frame.pointHand.select = select;
  frame.buttons = buttons;
  return frame;
}

// One fold. The sheet hand clutches at (0, -0.2, 0) and lifts the sheet by 0.1 along y; the point
// then hovers 1 cm above the edge point (0.1, 0, 0) of the sheet, grabs it and drags it to
// (0.05, 0, 0.05) in sheet coordinates; release commits at t = 1.2.
inline std::vector<InputFrame> squareFoldFrames() {
  const glm::dvec3 hand{0.0, -0.2, 0.0};
  const glm::dvec3 away{0.1, 0.1, 0.1};
  std::vector<InputFrame> frames;
  frames.push_back(handFrame(0.0, hand, 0.0, away, 0.0));
  frames.push_back(handFrame(0.1, hand, 1.0, away, 0.0));
  frames.push_back(handFrame(0.2, hand + glm::dvec3(0, 0.05, 0), 1.0, away, 0.0));
  frames.push_back(handFrame(0.3, hand + glm::dvec3(0, 0.1, 0), 1.0, away, 0.0));
  frames.push_back(handFrame(0.4, hand + glm::dvec3(0, 0.1, 0), 0.0, away, 0.0));
  const glm::dvec3 lifted = hand + glm::dvec3(0, 0.1, 0);
  const glm::dvec3 above{0.1, 0.1, 0.01};  // world: the sheet now sits at y + 0.1
  frames.push_back(handFrame(0.5, lifted, 0.0, above, 0.0));
  frames.push_back(handFrame(0.6, lifted, 0.0, above, 1.0));
  const glm::dvec3 to{0.05, 0.1, 0.06};
  for (int i = 1; i <= 4; ++i)
    frames.push_back(handFrame(0.6 + 0.1 * i, lifted, 0.0, above + (to - above) * (i / 4.0), 1.0));
  frames.push_back(handFrame(1.1, lifted, 0.0, to, 1.0));
  frames.push_back(handFrame(1.2, lifted, 0.0, to, 0.0));
  return frames;
}

}  // namespace curvefold::testing
