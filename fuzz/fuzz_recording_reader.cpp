// The recording reader and the player: a RecordingError or a replay that keeps every invariant.
#include <sstream>

#include "fuzz/fuzz_support.hpp"
#include "sim_input/player.hpp"
#include "sim_input/recording.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(bytes), size));
  curvefold::Recording recording;
  try {
    curvefold::ReadOptions options;
    options.allowTruncated = true;
    recording = curvefold::parseRecording(in, "fuzz.jsonl", options);
  } catch (const curvefold::RecordingError&) {
    return 0;
  }
  if (const auto* generated = std::get_if<curvefold::GeneratedSurface>(&recording.header.surface)) {
    const auto resolution = generated->parameters.find("resolution");
    if (resolution == generated->parameters.end() || !(resolution->second <= 40)) return 0;
  }
  const curvefold::ReplayResult result = curvefold::replayRecording(recording);
  curvefold::validate(result.sheet);
  return 0;
}
