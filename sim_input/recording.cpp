#include "sim_input/recording.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include <nlohmann/json.hpp>

#include "engine/io/atomic_file.hpp"

namespace curvefold {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

constexpr Button kButtons[] = {Button::Cancel, Button::Undo, Button::Redo, Button::SwitchHands};

// The shortest text that reads back as the same double, for messages.
std::string format(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

bool blank(const std::string& line) {
  return line.find_first_not_of(" \t\r") == std::string::npos;
}

// nlohmann's message reads "[json.exception.parse_error.101] parse error at line 1, column 7:
// problem"; keep the column and the problem.
std::string jsonProblem(const json::exception& e) {
  std::string message = e.what();
  if (const auto start = message.find("] "); start != std::string::npos)
    message.erase(0, start + 2);
  if (const auto at = message.find("parse error at line 1, "); at != std::string::npos)
    message.erase(at, 23);
  return message;
}

// Reads one line's JSON value, with messages that start with `prefix` (file and line).
class LineReader {
 public:
  LineReader(std::string prefix, std::size_t line) : prefix_(std::move(prefix)), line_(line) {}

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    throw RecordingError(prefix_ + ": " + (where.empty() ? "" : where + ": ") + problem, line_);
  }

  const std::string& prefix() const { return prefix_; }

  const json& member(const json& object, const char* key, const std::string& where) const {
    if (!object.is_object())
      fail(where, "must be an object, got " + std::string(object.type_name()));
    const auto it = object.find(key);
    if (it == object.end()) fail(where, std::string("missing \"") + key + "\"");
    return *it;
  }

  static std::string join(const std::string& where, const char* key) {
    return where.empty() ? std::string(key) : where + "." + key;
  }

  double number(const json& value, const std::string& where) const {
    // JSON has no NaN or infinity: nlohmann writes them as null, and huge literals do not parse.
    if (!value.is_number())
      fail(where, "must be a finite number, got " + std::string(value.type_name()));
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(where, "must be a finite number");
    return x;
  }

  double unitInterval(const json& value, const std::string& where) const {
    const double x = number(value, where);
    if (x < 0.0 || x > 1.0) fail(where, "must lie in [0, 1], got " + format(x));
    return x;
  }

  bool boolean(const json& value, const std::string& where) const {
    if (!value.is_boolean())
      fail(where, "must be true or false, got " + std::string(value.type_name()));
    return value.get<bool>();
  }

  const std::string& string(const json& value, const std::string& where) const {
    if (!value.is_string()) fail(where, "must be a string, got " + std::string(value.type_name()));
    return value.get_ref<const std::string&>();
  }

  template <std::size_t N>
  std::array<double, N> numbers(const json& value, const std::string& where) const {
    if (!value.is_array() || value.size() != N)
      fail(where, "must be an array of " + std::to_string(N) + " numbers");
    std::array<double, N> result;
    for (std::size_t i = 0; i < N; ++i)
      result[i] = number(value[i], where + "[" + std::to_string(i) + "]");
    return result;
  }

  glm::dvec3 position(const json& value, const std::string& where) const {
    const auto p = numbers<3>(value, where);
    return {p[0], p[1], p[2]};
  }

  glm::dquat orientation(const json& value, const std::string& where) const {
    const auto q = numbers<4>(value, where);
    const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (std::abs(length - 1.0) > kQuaternionUnitTolerance)
      fail(where, "is not a unit quaternion [w, x, y, z] (length " + format(length) + ")");
    return glm::dquat(q[0], q[1], q[2], q[3]);  // w, x, y, z
  }

  Pose pose(const json& value, const std::string& where) const {
    Pose pose;
    pose.position = position(member(value, "position", where), join(where, "position"));
    pose.orientation = orientation(member(value, "orientation", where), join(where, "orientation"));
    return pose;
  }

  RecordingHeader header(const json& value) const {
    if (!value.is_object())
      fail("", "not a curvefold recording (the header is a JSON " + std::string(value.type_name()) +
                   ", not an object)");
    const auto formatName = value.find("format");
    if (formatName == value.end()) fail("", "not a curvefold recording (no \"format\")");
    if (!formatName->is_string() || formatName->get_ref<const std::string&>() != kRecordingFormat)
      fail("", "not a curvefold recording (format " + formatName->dump() + ", expected \"" +
                   std::string(kRecordingFormat) + "\")");
    const json& version = member(value, "version", "");
    if (!version.is_number_integer() || version.get<std::int64_t>() != kRecordingVersion)
      fail("", "unsupported version " + version.dump() + " (this build reads version " +
                   std::to_string(kRecordingVersion) + ")");

    RecordingHeader header;
    header.source = string(member(value, "source", ""), "source");
    bool known = false;
    for (std::string_view source : kRecordingSources) known = known || source == header.source;
    if (!known)
      fail("source", "unknown source \"" + header.source +
                         "\" (expected synthetic, script, desktop or openxr)");
    const std::string& hand = string(member(value, "handedness", ""), "handedness");
    if (hand == "right")
      header.handedness = Handedness::Right;
    else if (hand == "left")
      header.handedness = Handedness::Left;
    else
      fail("handedness", "unknown handedness \"" + hand + "\" (expected right or left)");
    const std::string& units = string(member(value, "units", ""), "units");
    if (units != "m") fail("units", "must be \"m\" (metres), got \"" + units + "\"");
    header.rate = number(member(value, "rate", ""), "rate");
    if (header.rate <= 0.0) fail("rate", "must be positive, got " + format(header.rate));
    header.sheetFrame = pose(member(value, "sheet_frame", ""), "sheet_frame");

    const json& surface = member(value, "surface", "");
    try {
      header.surface = parseInitialSurface(surface, prefix_);
      initialSheet(Design{header.surface, {}}, prefix_);  // the engine builds it, or refuses here
    } catch (const DesignError& e) {
      throw RecordingError(e.what(), line_);
    }
    return header;
  }

  InputFrame frame(const json& value) const {
    if (!value.is_object())
      fail("", "a frame must be a JSON object, got " + std::string(value.type_name()));
    InputFrame frame;
    frame.time = number(member(value, "t", ""), "t");

    const json& sheet = member(value, "sheet", "");
    frame.sheetHand.pose = pose(sheet, "sheet");
    frame.sheetHand.tracked = boolean(member(sheet, "tracked", "sheet"), "sheet.tracked");
    frame.sheetHand.clutch = unitInterval(member(sheet, "clutch", "sheet"), "sheet.clutch");

    const json& point = member(value, "point", "");
    frame.pointHand.position = position(member(point, "position", "point"), "point.position");
    frame.pointHand.tracked = boolean(member(point, "tracked", "point"), "point.tracked");
    frame.pointHand.select = unitInterval(member(point, "select", "point"), "point.select");

    if (const auto buttons = value.find("buttons"); buttons != value.end()) {
      if (!buttons->is_array()) fail("buttons", "must be an array of button names");
      for (std::size_t i = 0; i < buttons->size(); ++i) {
        const std::string where = "buttons[" + std::to_string(i) + "]";
        const std::string& name = string((*buttons)[i], where);
        bool known = false;
        for (Button button : kButtons) {
          if (buttonName(button) != name) continue;
          frame.buttons |= static_cast<std::uint32_t>(button);
          known = true;
        }
        if (!known)
          fail(where,
               "unknown button \"" + name + "\" (expected cancel, undo, redo or switch_hands)");
      }
    }
    return frame;
  }

 private:
  std::string prefix_;
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
  }
  return "unknown";
}

std::string_view handednessName(Handedness handedness) {
  return handedness == Handedness::Left ? "left" : "right";
}

std::string headerLine(const RecordingHeader& header) {
  ordered_json value;
  value["format"] = kRecordingFormat;
  value["version"] = kRecordingVersion;
  value["source"] = header.source;
  value["handedness"] = handednessName(header.handedness);
  value["units"] = "m";
  value["rate"] = header.rate;
  value["sheet_frame"] = poseJson(header.sheetFrame);
  value["surface"] = initialSurfaceJson(header.surface);
  std::string line = value.dump();
  // Refuse what could not be read back (nlohmann writes NaN as null) before anyone writes it.
  LineReader("cannot record header", 1).header(json::parse(line));
  return line;
}

std::string frameLine(const InputFrame& frame) {
  std::uint32_t known = 0;
  for (Button button : kButtons) known |= static_cast<std::uint32_t>(button);
  if ((frame.buttons & ~known) != 0)
    throw RecordingError("cannot record frame at t=" + format(frame.time) +
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
  if (frame.buttons != 0) {
    ordered_json& buttons = value["buttons"] = ordered_json::array();
    for (Button button : kButtons)
      if (frame.held(button)) buttons.push_back(buttonName(button));
  }
  std::string line = value.dump();
  LineReader("cannot record frame at t=" + format(frame.time), 0).frame(json::parse(line));
  return line;
}

void writeRecording(const Recording& recording, const std::filesystem::path& path) {
  // Every line is made (and checked) before the file is touched.
  std::string text = headerLine(recording.header) + "\n";
  double lastTime = -std::numeric_limits<double>::infinity();
  for (const InputFrame& frame : recording.frames) {
    if (frame.time < lastTime)
      throw RecordingError("cannot record frame at t=" + format(frame.time) +
                           ": time goes backwards (after t=" + format(lastTime) + ")");
    lastTime = frame.time;
    text += frameLine(frame);
    text += '\n';
  }
  writeFileAtomically(path, text);
}

Recording readRecording(const std::filesystem::path& path, const ReadOptions& options) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw RecordingError("cannot read " + path.string() + ": " + std::strerror(EISDIR));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RecordingError("cannot read " + path.string() + ": " + std::strerror(errno));
  return parseRecording(in, path.string(), options);
}

Recording parseRecording(std::istream& in, std::string_view nameForErrors,
                         const ReadOptions& options) {
  const std::string name(nameForErrors);
  Recording recording;
  bool haveHeader = false;
  double lastTime = -std::numeric_limits<double>::infinity();
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    // getline stops at end of file without a newline: the writer may have been cut off mid-line.
    const bool complete = !in.eof();
    if (blank(line)) {
      if (complete) recording.lineCount = number;
      continue;
    }
    const LineReader reader(name + ": line " + std::to_string(number), number);
    json value;
    try {
      value = json::parse(line);
    } catch (const json::exception& e) {
      if (complete) reader.fail("", "not valid JSON: " + jsonProblem(e));
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
        reader.fail(
            "t", "time goes backwards (" + format(frame.time) + " after " + format(lastTime) + ")");
      lastTime = frame.time;
      recording.frames.push_back(frame);
    }
    recording.lineCount = number;
  }
  if (in.bad()) throw RecordingError("cannot read " + name + ": read error");
  if (!haveHeader) throw RecordingError(name + ": empty, not a curvefold recording");
  return recording;
}

}  // namespace curvefold
