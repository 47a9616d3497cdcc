#include "sim_input/recording.hpp"

#include <bit>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <new>
#include <optional>

#include <nlohmann/json.hpp>

#include "engine/geometry/symmetry.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/input_limits.hpp"
#include "engine/io/json_reader.hpp"
#include "engine/text/bounded_line.hpp"
#include "engine/text/input_path.hpp"

namespace curvefold {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

constexpr Button kButtons[] = {Button::Cancel,        Button::Undo,  Button::Redo,
                               Button::SwitchHands,   Button::Panel, Button::TakeSuggestion,
                               Button::NextSuggestion};

// A simulated frame's largest step count and pulled vertex index (the model's limits are far
// below; a file's wild number is refused here rather than run for hours).
constexpr std::uint64_t kMaxSimulationStepsPerFrame = 10000;
constexpr std::uint64_t kMaxPullVertex = 0xFFFFFFFEu;

// The most suggestions one frame brings (the studio asks for a few).
constexpr std::size_t kMaxSuggestionsPerFrame = 16;

// "parse error at line 1, column 7: problem" without the line, which the message names already.
std::string jsonLineProblem(const json::exception& e) {
  std::string message = jsonParseProblem(e);
  if (const auto at = message.find("parse error at line 1, "); at != std::string::npos)
    message.erase(at, 23);
  return message;
}

bool blank(const std::string& line) {
  return line.find_first_not_of(" \t\r") == std::string::npos;
}

// Reads one line's JSON value, with messages that start with the file and line.
class LineReader : public JsonReader {
 public:
  LineReader(std::string prefix, std::size_t line) : JsonReader(std::move(prefix)), line_(line) {}

  [[noreturn]] void refuse(const std::string& where, const std::string& problem) const {
    throw RecordingError(prefix() + ": " + (where.empty() ? "" : where + ": ") + problem, line_);
  }

  RecordingHeader header(const json& value) const {
    try {
      return readHeader(value);
    } catch (const JsonReadError& e) {
      throw RecordingError(e.what(), line_);
    }
  }

  InputFrame frame(const json& value) const {
    try {
      return readFrame(value);
    } catch (const JsonReadError& e) {
      throw RecordingError(e.what(), line_);
    }
  }

 private:
  glm::dquat orientation(const json& value, const std::string& where) const {
    double q[4];
    numbers(value, 4, q, where);
    const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (std::abs(length - 1.0) > kQuaternionUnitTolerance)
      fail(where, "is not a unit quaternion [w, x, y, z] (length " + shortestDouble(length) + ")");
    return glm::dquat(q[0], q[1], q[2], q[3]);  // w, x, y, z
  }

  Pose pose(const json& value, const std::string& where) const {
    Pose pose;
    pose.position = vector3(member(value, "position", where), join(where, "position"));
    pose.orientation = orientation(member(value, "orientation", where), join(where, "orientation"));
    return pose;
  }

  RecordingHeader readHeader(const json& value) const {
    formatAndVersion(value, kRecordingFormat, kOldestRecordingVersion, kRecordingVersion,
                     "curvefold recording");

    RecordingHeader header;
    header.source = string(member(value, "source", ""), "source");
    bool known = false;
    for (std::string_view source : kRecordingSources) known = known || source == header.source;
    if (!known) {
      // The list comes from the table, so a source added there is named here too.
      std::string expected;
      for (std::string_view source : kRecordingSources)
        expected += (expected.empty() ? "" : ", ") + std::string(source);
      fail("source", "unknown source " + quotedExcerpt(header.source) + " (expected one of " +
                         expected + ")");
    }
    const std::string& hand = string(member(value, "handedness", ""), "handedness");
    if (hand == "right")
      header.handedness = HandSide::Right;
    else if (hand == "left")
      header.handedness = HandSide::Left;
    else
      fail("handedness", "unknown handedness " + quotedExcerpt(hand) + " (expected right or left)");
    const std::string& units = string(member(value, "units", ""), "units");
    if (units != "m") fail("units", "must be \"m\" (metres), got " + quotedExcerpt(units));
    header.rate = number(member(value, "rate", ""), "rate");
    if (header.rate <= 0.0) fail("rate", "must be positive, got " + shortestDouble(header.rate));
    header.sheetFrame = pose(member(value, "sheet_frame", ""), "sheet_frame");

    if (const json* studio = optionalMember(value, "studio", "")) {
      header.studio.emplace();
      if (!studio->is_object()) fail("studio", "must be an object");
      if (const json* recent = optionalMember(*studio, "recent", "studio")) {
        if (!recent->is_array() || recent->size() > kMaxRecentDesigns)
          fail("studio.recent",
               "must be an array of at most " + std::to_string(kMaxRecentDesigns) + " paths");
        for (std::size_t i = 0; i < recent->size(); ++i)
          header.studio->recent.push_back(string((*recent)[i], item("studio.recent", i)));
      }
    }
    if (const json* symmetry = optionalMember(value, "symmetry", ""))
      header.symmetry = string(*symmetry, "symmetry");
    const json& surface = member(value, "surface", "");
    try {
      header.surface = parseInitialSurface(surface, prefix());
      // The engine builds it, or refuses here; so with a symmetry it lacks.
      const Sheet sheet = initialSheet(Design{header.surface, {}}, prefix());
      if (!header.symmetry.empty()) parseSymmetry(header.symmetry, sheet);
    } catch (const DesignError& e) {
      throw RecordingError(e.what(), line_);
    } catch (const InvalidSymmetry& e) {
      fail("symmetry", e.what());
    }
    return header;
  }

  InputFrame readFrame(const json& value) const {
    if (!value.is_object())
      fail("", "a frame must be a JSON object, got " + std::string(value.type_name()));
    InputFrame frame;
    frame.time = number(member(value, "t", ""), "t");

    const json& sheet = member(value, "sheet", "");
    frame.sheetHand.pose = pose(sheet, "sheet");
    frame.sheetHand.tracked = boolean(member(sheet, "tracked", "sheet"), "sheet.tracked");
    frame.sheetHand.clutch = unitInterval(member(sheet, "clutch", "sheet"), "sheet.clutch");

    const json& point = member(value, "point", "");
    frame.pointHand.position = vector3(member(point, "position", "point"), "point.position");
    frame.pointHand.tracked = boolean(member(point, "tracked", "point"), "point.tracked");
    frame.pointHand.select = unitInterval(member(point, "select", "point"), "point.select");
    // Written only when squeezed, so recordings from before it read the same.
    if (const json* grip = optionalMember(point, "grip", "point"))
      frame.pointHand.grip = unitInterval(*grip, "point.grip");
    // A headset's aim and thumbstick, written only when there are (the panel's ray and scroll).
    if (const json* aim = optionalMember(point, "aim", "point"))
      frame.pointHand.aim = orientation(*aim, "point.aim");
    if (const json* scroll = optionalMember(point, "scroll", "point")) {
      frame.pointHand.scroll = number(*scroll, "point.scroll");
      if (!(frame.pointHand.scroll >= -1.0 && frame.pointHand.scroll <= 1.0))
        fail("point.scroll", "must lie in [-1, 1], got " + shortestDouble(frame.pointHand.scroll));
    }

    if (const json* buttons = optionalMember(value, "buttons", "")) {
      if (!buttons->is_array()) fail("buttons", "must be an array of button names");
      for (std::size_t i = 0; i < buttons->size(); ++i) {
        const std::string where = item("buttons", i);
        const std::string& name = string((*buttons)[i], where);
        bool known = false;
        for (Button button : kButtons) {
          if (buttonName(button) != name) continue;
          frame.buttons |= static_cast<std::uint32_t>(button);
          known = true;
        }
        if (!known)
          fail(where, "unknown button " + quotedExcerpt(name) +
                          " (expected cancel, undo, redo, switch_hands, panel, "
                          "take_suggestion or next_suggestion)");
      }
    }
    if (const json* suggestions = optionalMember(value, "suggestions", "")) {
      if (!suggestions->is_array() || suggestions->empty() ||
          suggestions->size() > kMaxSuggestionsPerFrame)
        fail("suggestions",
             "must be an array of 1 to " + std::to_string(kMaxSuggestionsPerFrame) + " folds");
      for (std::size_t i = 0; i < suggestions->size(); ++i) {
        const std::string where = item("suggestions", i);
        const json& fold = (*suggestions)[i];
        if (!fold.is_object()) fail(where, "must be an object with seed, grab and to");
        frame.suggestions.push_back({vector2(member(fold, "seed", where), where + ".seed"),
                                     vector3(member(fold, "grab", where), where + ".grab"),
                                     vector3(member(fold, "to", where), where + ".to")});
      }
    }
    if (const json* simulation = optionalMember(value, "simulation", ""))
      frame.simulation = readSimulation(*simulation);
    return frame;
  }

  SimulationInput readSimulation(const json& value) const {
    if (!value.is_object()) fail("simulation", "must be an object with percent and steps");
    SimulationInput simulation;
    simulation.percent = number(member(value, "percent", "simulation"), "simulation.percent");
    if (!(simulation.percent >= 0.0 && simulation.percent <= 100.0))
      fail("simulation.percent", "must lie in [0, 100], got " + shortestDouble(simulation.percent));
    const std::uint64_t steps =
        unsignedInteger(member(value, "steps", "simulation"), "simulation.steps");
    if (steps > kMaxSimulationStepsPerFrame)
      fail("simulation.steps", "must be at most " + std::to_string(kMaxSimulationStepsPerFrame) +
                                   ", got " + std::to_string(steps));
    simulation.steps = std::uint32_t(steps);
    if (const json* pull = optionalMember(value, "pull", "simulation")) {
      if (!pull->is_object()) fail("simulation.pull", "must be an object with vertex and to");
      const std::uint64_t vertex =
          unsignedInteger(member(*pull, "vertex", "simulation.pull"), "simulation.pull.vertex");
      if (vertex > kMaxPullVertex)
        fail("simulation.pull.vertex", "must be at most " + std::to_string(kMaxPullVertex));
      simulation.pull =
          SimulationPull{std::uint32_t(vertex),
                         vector3(member(*pull, "to", "simulation.pull"), "simulation.pull.to")};
    }
    if (const json* solver = optionalMember(value, "solver", "simulation")) {
      if (*solver == "gpu")
        simulation.solver = LiveSolverKind::Gpu;
      else if (*solver != "cpu")
        fail("simulation.solver", "must be \"cpu\" or \"gpu\"");
    }
    return simulation;
  }

  std::size_t line_;
};

ordered_json positionJson(const glm::dvec3& p) {
  return ordered_json::array({p.x, p.y, p.z});
}

ordered_json poseJson(const Pose& pose) {
  const glm::dquat& q = pose.orientation;
  return {{"position", positionJson(pose.position)},
          {"orientation", ordered_json::array({q.w, q.x, q.y, q.z})}};
}

}  // namespace

std::string_view buttonName(Button button) {
  switch (button) {
    case Button::Cancel:
      return "cancel";
    case Button::Undo:
      return "undo";
    case Button::Redo:
      return "redo";
    case Button::SwitchHands:
      return "switch_hands";
    case Button::Panel:
      return "panel";
    case Button::TakeSuggestion:
      return "take_suggestion";
    case Button::NextSuggestion:
      return "next_suggestion";
  }
  return "unknown";
}

std::string headerLine(const RecordingHeader& header) {
  ordered_json value;
  value["format"] = kRecordingFormat;
  value["version"] = kRecordingVersion;
  value["source"] = header.source;
  value["handedness"] = handSideName(header.handedness);
  value["units"] = "m";
  value["rate"] = header.rate;
  value["sheet_frame"] = poseJson(header.sheetFrame);
  value["surface"] = initialSurfaceJson(header.surface);
  if (header.studio) value["studio"] = {{"recent", header.studio->recent}};
  if (!header.symmetry.empty()) value["symmetry"] = header.symmetry;
  std::string line = value.dump();
  // Refuse what could not be read back (nlohmann writes NaN as null) before anyone writes it.
  LineReader("cannot record header", 1).header(json::parse(line));
  return line;
}

std::string frameLine(const InputFrame& frame) {
  std::uint32_t known = 0;
  for (Button button : kButtons) known |= static_cast<std::uint32_t>(button);
  if ((frame.buttons & ~known) != 0)
    throw RecordingError("cannot record frame at t=" + shortestDouble(frame.time) +
                         ": unknown button bits " + std::to_string(frame.buttons & ~known));

  ordered_json sheet = poseJson(frame.sheetHand.pose);
  sheet["tracked"] = frame.sheetHand.tracked;
  sheet["clutch"] = frame.sheetHand.clutch;
  ordered_json value;
  value["t"] = frame.time;
  value["sheet"] = std::move(sheet);
  value["point"] = {{"position", positionJson(frame.pointHand.position)},
                    {"tracked", frame.pointHand.tracked},
                    {"select", frame.pointHand.select}};
  // Any grip but +0 (even -0, so every value reads back bit for bit).
  if (std::bit_cast<std::uint64_t>(frame.pointHand.grip) != 0)
    value["point"]["grip"] = frame.pointHand.grip;
  if (frame.pointHand.aim) {
    const glm::dquat& q = *frame.pointHand.aim;
    value["point"]["aim"] = ordered_json::array({q.w, q.x, q.y, q.z});
  }
  if (std::bit_cast<std::uint64_t>(frame.pointHand.scroll) != 0)
    value["point"]["scroll"] = frame.pointHand.scroll;
  if (frame.buttons != 0) {
    ordered_json& buttons = value["buttons"] = ordered_json::array();
    for (Button button : kButtons)
      if (frame.held(button)) buttons.push_back(buttonName(button));
  }
  if (!frame.suggestions.empty()) {
    ordered_json& suggestions = value["suggestions"] = ordered_json::array();
    for (const SuggestedFold& fold : frame.suggestions)
      suggestions.push_back({{"seed", ordered_json::array({fold.seed.x, fold.seed.y})},
                             {"grab", positionJson(fold.grab)},
                             {"to", positionJson(fold.to)}});
  }
  if (frame.simulation) {
    ordered_json simulation = {{"percent", frame.simulation->percent},
                               {"steps", frame.simulation->steps}};
    if (const std::optional<SimulationPull>& pull = frame.simulation->pull)
      simulation["pull"] = {{"vertex", pull->vertex}, {"to", positionJson(pull->to)}};
    if (frame.simulation->solver == LiveSolverKind::Gpu) simulation["solver"] = "gpu";
    value["simulation"] = std::move(simulation);
  }
  std::string line = value.dump();
  LineReader("cannot record frame at t=" + shortestDouble(frame.time), 0).frame(json::parse(line));
  return line;
}

void writeRecording(const Recording& recording, const std::filesystem::path& path) {
  // Streamed line by line: a line the reader would refuse throws inside the writer, which leaves
  // the target untouched, without the whole text held in memory.
  const std::string header = headerLine(recording.header);
  writeFileAtomically(path, [&](std::ostream& out) {
    out << header << '\n';
    double lastTime = -std::numeric_limits<double>::infinity();
    for (const InputFrame& frame : recording.frames) {
      if (frame.time < lastTime)
        throw RecordingError("cannot record frame at t=" + shortestDouble(frame.time) +
                             ": time goes backwards (after t=" + shortestDouble(lastTime) + ")");
      lastTime = frame.time;
      out << frameLine(frame) << '\n';
    }
  });
}

Recording readRecording(const std::filesystem::path& path, const ReadOptions& options) {
  // Only a regular file: a FIFO would block the open, a device might never end.
  if (const std::optional<std::string> why = notRegularFile(path))
    throw RecordingError("cannot read " + path.string() + ": " + *why);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RecordingError("cannot read " + path.string() + ": " + std::strerror(errno));
  return parseRecording(in, path.string(), options);
}

namespace {

Recording parseRecordingLines(std::istream& in, const std::string& name,
                              const ReadOptions& options) {
  Recording recording;
  bool haveHeader = false;
  double lastTime = -std::numeric_limits<double>::infinity();
  std::string line;
  std::size_t number = 0;
  std::uint64_t bytes = 0;
  for (;;) {
    const LineRead read =
        readBoundedLine(in, line, haveHeader ? kMaxRecordingFrameBytes : kMaxRecordingHeaderBytes);
    if (read == LineRead::End) break;
    const bool complete = read == LineRead::Line, tooLong = read == LineRead::TooLong;
    ++number;
    bytes += line.size() + 1;
    if (tooLong)
      throw RecordingError(
          name + ": line " + std::to_string(number) + ": longer than a " +
              (haveHeader ? std::string("frame line may be (") +
                                std::to_string(kMaxRecordingFrameBytes >> 10) + " KiB)"
                          : std::string("header may be (") +
                                std::to_string(kMaxRecordingHeaderBytes >> 20) + " MiB)"),
          number);
    if (bytes > kMaxRecordingBytes)
      throw RecordingError(tooLarge(name, 0, kMaxRecordingBytes, "recording"), number);
    if (blank(line)) {
      if (complete) recording.lineCount = number;
      continue;
    }
    const LineReader reader(name + ": line " + std::to_string(number), number);
    json value;
    try {
      value = parseUniqueJson(line);
    } catch (const JsonDuplicateKey& e) {
      reader.refuse("", e.what());
    } catch (const json::exception& e) {
      if (complete) reader.refuse("", "not valid JSON: " + jsonLineProblem(e));
      if (!options.allowTruncated || !haveHeader)
        throw RecordingError(
            name + ": truncated at line " + std::to_string(number) +
                (haveHeader ? " (the last line is incomplete)" : " (the header is incomplete)"),
            number);
      recording.truncated = true;
      break;
    }
    if (!haveHeader) {
      recording.header = reader.header(value);
      haveHeader = true;
    } else {
      InputFrame frame = reader.frame(value);
      if (frame.time < lastTime)
        reader.refuse("t", "time goes backwards (" + shortestDouble(frame.time) + " after " +
                               shortestDouble(lastTime) + ")");
      lastTime = frame.time;
      recording.frames.push_back(frame);
    }
    recording.lineCount = number;
  }
  if (in.bad()) throw RecordingError("cannot read " + name + ": read error");
  if (!haveHeader) throw RecordingError(name + ": empty, not a curvefold recording");
  return recording;
}

}  // namespace

Recording parseRecording(std::istream& in, std::string_view nameForErrors,
                         const ReadOptions& options) {
  const std::string name(nameForErrors);
  try {
    return parseRecordingLines(in, name, options);
  } catch (const std::bad_alloc&) {
    throw RecordingError(name + ": out of memory reading it");
  }
}

}  // namespace curvefold
