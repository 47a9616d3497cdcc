// The gesture-script reader and generator: a GestureError, or a recording that reads back and
// replays keeping every invariant. Scripts are bounded to 20,000 frames here so that each input
// runs in well under a second; the limits themselves are the unit tests' and the command line's.
#include <sstream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "fuzz/fuzz_support.hpp"
#include "sim_input/gestures.hpp"
#include "sim_input/player.hpp"
#include "sim_input/recording.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(bytes), size);
  // Small sheets only, as in the recording fuzzer: a resolution of 2000 is valid but makes each
  // input take seconds, which hides everything else.
  const nlohmann::json peek = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (peek.is_object() && peek.contains("surface") && peek["surface"].is_object()) {
    const nlohmann::json& surface = peek["surface"];
    if (surface.contains("parameters") && surface["parameters"].is_object() &&
        surface["parameters"].contains("resolution")) {
      const nlohmann::json& resolution = surface["parameters"]["resolution"];
      if (!resolution.is_number() || !(resolution.get<double>() <= 40.0)) return 0;
    }
  }
  curvefold::Recording recording;
  try {
    recording = curvefold::recordGestureScriptText(text, "fuzz.gesture.json", 20'000);
  } catch (const curvefold::GestureError&) {
    return 0;
  }
  // What was made is a recording the reader takes back as it is.
  std::string lines = curvefold::headerLine(recording.header) + "\n";
  for (const curvefold::InputFrame& frame : recording.frames)
    lines += curvefold::frameLine(frame) + "\n";
  std::istringstream in(lines);
  const curvefold::Recording again = curvefold::parseRecording(in, "fuzz.jsonl");
  if (again.frames.size() != recording.frames.size())
    curvefold::fuzz::fail("a generated recording did not read back whole");
  curvefold::validate(curvefold::replayRecording(again).sheet);
  return 0;
}
