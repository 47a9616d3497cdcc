#include "sim_input/gestures.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

namespace curvefold {
namespace {

// Eases in and out, so hands start and stop smoothly as people's do.
double smoothstep(double t) {
  return t * t * (3.0 - 2.0 * t);
}

int stepsFor(double seconds, double rate) {
  return std::max(1, static_cast<int>(std::lround(seconds * rate)));
}

// Where a hand rests: a quarter metre in front of the sheet's centre, out of hover range.
constexpr double kRestDistance = 0.25;
constexpr double kApproachSeconds = 0.25;

}  // namespace

GestureRecorder::GestureRecorder(RecordingHeader header) {
  recording_.header = std::move(header);
  if (!(recording_.header.rate > 0.0) || !std::isfinite(recording_.header.rate))
    throw GestureError("rate must be a positive number of frames per second");
  dt_ = 1.0 / recording_.header.rate;
  session_ = std::make_unique<FoldSession>(
      initialSheet(Design{recording_.header.surface, {}}, "gesture script"));
  core_ = std::make_unique<InteractionCore>(*session_, recording_.header.sheetFrame,
                                            recording_.header.handedness);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const glm::dvec3& p : session_->fixed().positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  sheetCentre_ = 0.5 * (lo + hi);
  const Pose& sheet = recording_.header.sheetFrame;
  frame_.time = 0.0;
  frame_.sheetHand.pose = sheet * Pose{sheetCentre_, glm::dquat(1, 0, 0, 0)};
  frame_.sheetHand.tracked = true;
  frame_.pointHand.position = sheet.apply(sheetCentre_ + glm::dvec3(0.0, 0.0, kRestDistance));
  frame_.pointHand.tracked = true;
  step();
}

void GestureRecorder::step() {
  recording_.frames.push_back(frame_);
  core_->process(frame_);
  frame_.time = static_cast<double>(recording_.frames.size()) * dt_;
}

void GestureRecorder::wait(double seconds) {
  for (int i = 0, n = stepsFor(seconds, recording_.header.rate); i < n; ++i) step();
}

Pose GestureRecorder::turnedHand(const Pose& start, const Pose& sheetAtStart, const SheetTurn& turn,
                                 double fraction) const {
  const glm::dvec3 pivot = sheetAtStart.apply(sheetCentre_);
  const glm::dquat rotation =
      glm::angleAxis(turn.degrees * fraction * std::numbers::pi / 180.0, glm::normalize(turn.axis));
  const Pose aboutPivot{pivot - rotation * pivot, rotation};
  return aboutPivot * start;
}

void GestureRecorder::turnSheet(const SheetTurn& turn, double seconds) {
  frame_.sheetHand.clutch = 1.0;
  step();
  const Pose start = frame_.sheetHand.pose, sheet = core_->worldFromSheet();
  for (int i = 1, n = stepsFor(seconds, recording_.header.rate); i <= n; ++i) {
    frame_.sheetHand.pose = turnedHand(start, sheet, turn, smoothstep(double(i) / n));
    step();
  }
  frame_.sheetHand.clutch = 0.0;
  step();
}

void GestureRecorder::moveSheet(const glm::dvec3& by, double seconds) {
  frame_.sheetHand.clutch = 1.0;
  step();
  const Pose start = frame_.sheetHand.pose;
  for (int i = 1, n = stepsFor(seconds, recording_.header.rate); i <= n; ++i) {
    frame_.sheetHand.pose.position = start.position + by * smoothstep(double(i) / n);
    step();
  }
  frame_.sheetHand.clutch = 0.0;
  step();
}

void GestureRecorder::moveSheetHand(const Pose& to, double seconds, bool clutch) {
  frame_.sheetHand.clutch = clutch ? 1.0 : 0.0;
  step();
  const Pose start = frame_.sheetHand.pose;
  for (int i = 1, n = stepsFor(seconds, recording_.header.rate); i <= n; ++i) {
    const double fraction = smoothstep(double(i) / n);
    frame_.sheetHand.pose.position = start.position + (to.position - start.position) * fraction;
    frame_.sheetHand.pose.orientation = glm::slerp(start.orientation, to.orientation, fraction);
    step();
  }
  frame_.sheetHand.clutch = 0.0;
  step();
}

void GestureRecorder::drag(const glm::dvec3& grabNear, const std::vector<glm::dvec3>& path,
                           double seconds, const std::optional<SheetTurn>& turnDuring) {
  const Sheet& fixed = session_->fixed();
  const glm::dvec3 grabbed = positionOf(fixed, closestSurfacePoint(fixed, grabNear));
  const Pose sheet = core_->worldFromSheet();

  // Approach the point with the trigger released, then pull it.
  const glm::dvec3 from = frame_.pointHand.position, to = sheet.apply(grabbed);
  for (int i = 1, n = stepsFor(kApproachSeconds, recording_.header.rate); i <= n; ++i) {
    frame_.pointHand.position = from + (to - from) * smoothstep(double(i) / n);
    step();
  }
  frame_.pointHand.select = 1.0;
  if (turnDuring) frame_.sheetHand.clutch = 1.0;
  step();
  if (core_->state() != InteractionState::Dragging)
    throw GestureError("drag: could not grab the sheet near the given point");

  // Along the polyline grabbed -> path..., by arc length, in the sheet frame of the start.
  std::vector<glm::dvec3> points{grabbed};
  points.insert(points.end(), path.begin(), path.end());
  std::vector<double> length{0.0};
  for (std::size_t i = 1; i < points.size(); ++i)
    length.push_back(length.back() + glm::distance(points[i - 1], points[i]));
  const Pose handStart = frame_.sheetHand.pose;
  for (int i = 1, n = stepsFor(seconds, recording_.header.rate); i <= n; ++i) {
    const double fraction = smoothstep(double(i) / n);
    const double s = fraction * length.back();
    std::size_t k = 1;
    while (k + 1 < points.size() && length[k] < s) ++k;
    const double span = length[k] - length[k - 1];
    const double u = span > 0.0 ? (s - length[k - 1]) / span : 1.0;
    frame_.pointHand.position = sheet.apply(points[k - 1] + (points[k] - points[k - 1]) * u);
    if (turnDuring) frame_.sheetHand.pose = turnedHand(handStart, sheet, *turnDuring, fraction);
    step();
  }
  frame_.pointHand.select = 0.0;
  frame_.sheetHand.clutch = 0.0;
  step();
}

void GestureRecorder::press(Button button) {
  frame_.buttons = static_cast<std::uint32_t>(button);
  step();
  frame_.buttons = 0;
  step();
}

namespace {

class ScriptReader {
 public:
  explicit ScriptReader(std::string name) : name_(std::move(name)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    throw GestureError(name_ + ": " + (where.empty() ? "" : where + ": ") + problem);
  }
  double number(const nlohmann::json& object, const char* key, const std::string& where,
                std::optional<double> fallback = std::nullopt) const {
    const auto it = object.find(key);
    if (it == object.end()) {
      if (fallback) return *fallback;
      fail(where, std::string("missing \"") + key + "\"");
    }
    if (!it->is_number() || !std::isfinite(it->get<double>()))
      fail(where, std::string("\"") + key + "\" must be a finite number");
    return it->get<double>();
  }
  double duration(const nlohmann::json& object, const std::string& where, double fallback) const {
    const double seconds = number(object, "duration", where, fallback);
    if (!(seconds > 0.0) || seconds > 600.0)
      fail(where, "\"duration\" must lie in (0, 600] seconds");
    return seconds;
  }
  glm::dvec3 vector(const nlohmann::json& value, const std::string& where) const {
    if (!value.is_array() || value.size() != 3) fail(where, "must be [x, y, z]");
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i) {
      if (!value[i].is_number() || !std::isfinite(value[i].get<double>()))
        fail(where, "must hold finite numbers");
      v[i] = value[i].get<double>();
    }
    return v;
  }
  glm::dvec3 vector(const nlohmann::json& object, const char* key, const std::string& where) const {
    const auto it = object.find(key);
    if (it == object.end()) fail(where, std::string("missing \"") + key + "\"");
    return vector(*it, where + "." + key);
  }
  SheetTurn turn(const nlohmann::json& value, const std::string& where) const {
    if (!value.is_object()) fail(where, "must be an object");
    SheetTurn turn{vector(value, "axis", where), number(value, "degrees", where)};
    if (glm::length(turn.axis) == 0.0) fail(where, "axis must not be zero");
    return turn;
  }
  Pose pose(const nlohmann::json& value, const std::string& where) const {
    if (!value.is_object()) fail(where, "must be an object");
    Pose pose;
    pose.position = vector(value, "position", where);
    if (const auto it = value.find("orientation"); it != value.end()) {
      if (!it->is_array() || it->size() != 4) fail(where, "orientation must be [w, x, y, z]");
      double c[4];
      for (int i = 0; i < 4; ++i) {
        if (!(*it)[i].is_number()) fail(where, "orientation must hold numbers");
        c[i] = (*it)[i].get<double>();
      }
      const glm::dquat q(c[0], c[1], c[2], c[3]);  // w, x, y, z
      if (std::abs(glm::length(q) - 1.0) > kQuaternionUnitTolerance)
        fail(where, "orientation must be a unit quaternion");
      pose.orientation = q;
    }
    return pose;
  }

 private:
  std::string name_;
};

}  // namespace

Recording recordGestureScript(const std::filesystem::path& script) {
  const std::string name = script.string();
  std::ifstream in(script, std::ios::binary);
  if (!in) throw GestureError("cannot read " + name);
  std::stringstream text;
  text << in.rdbuf();
  ScriptReader reader(name);
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::parse_error& e) {
    reader.fail("", std::string("not JSON: ") + e.what());
  }
  if (!document.is_object() || document.value("format", "") != "curvefold-gesture-script")
    reader.fail("", "not a curvefold gesture script (format must be \"curvefold-gesture-script\")");
  if (document.value("version", 0) != 1)
    reader.fail("", "unsupported version (this build reads 1)");

  RecordingHeader header;
  header.source = document.value("source", "script");
  if (header.source != "script" && header.source != "desktop" && header.source != "synthetic")
    reader.fail("source", "must be \"script\", \"desktop\" or \"synthetic\"");
  header.rate = reader.number(document, "rate", "", 90.0);
  const std::string handedness = document.value("handedness", "right");
  if (handedness != "right" && handedness != "left")
    reader.fail("handedness", "must be \"right\" or \"left\"");
  header.handedness = handedness == "left" ? Handedness::Left : Handedness::Right;
  if (!document.contains("surface")) reader.fail("", "missing \"surface\"");
  try {
    header.surface = parseInitialSurface(document["surface"], name);
  } catch (const DesignError& e) {
    throw GestureError(e.what());
  }
  // By default the sheet is held at chest height half a metre in front of the user (OpenXR's
  // stage space: y up, -z forward), facing them.
  header.sheetFrame = defaultSheetFrame();
  if (document.contains("sheet_frame"))
    header.sheetFrame = reader.pose(document["sheet_frame"], "sheet_frame");

  std::optional<GestureRecorder> made;
  try {
    made.emplace(header);
  } catch (const DesignError& e) {
    throw GestureError(e.what());
  }
  GestureRecorder& recorder = *made;
  const auto gestures = document.find("gestures");
  if (gestures == document.end() || !gestures->is_array())
    reader.fail("", "\"gestures\" must be an array");
  for (std::size_t i = 0; i < gestures->size(); ++i) {
    const nlohmann::json& gesture = (*gestures)[i];
    const std::string where = "gesture " + std::to_string(i + 1);
    if (!gesture.is_object() || gesture.size() != 1)
      reader.fail(where, "must be an object with one key (the gesture's name)");
    // One key: the gesture's name. (Binding to items() would outlive its proxy.)
    const std::string kind = gesture.begin().key();
    const nlohmann::json& value = gesture.begin().value();
    const std::string at = where + " (" + kind + ")";
    try {
      if (kind == "wait") {
        if (!value.is_number() || !(value.get<double>() >= 0.0) || value.get<double>() > 600.0)
          reader.fail(at, "must be a number of seconds in [0, 600]");
        recorder.wait(value.get<double>());
      } else if (kind == "turn_sheet") {
        recorder.turnSheet(reader.turn(value, at), reader.duration(value, at, 0.5));
      } else if (kind == "move_sheet") {
        recorder.moveSheet(reader.vector(value, "by", at), reader.duration(value, at, 0.5));
      } else if (kind == "sheet_hand") {
        if (!value.is_object() || !value.contains("to")) reader.fail(at, "missing \"to\"");
        const auto clutch = value.find("clutch");
        if (clutch != value.end() && !clutch->is_boolean())
          reader.fail(at, "\"clutch\" must be true or false");
        recorder.moveSheetHand(reader.pose(value["to"], at + ".to"),
                               reader.duration(value, at, 0.5),
                               clutch != value.end() && clutch->get<bool>());
      } else if (kind == "drag") {
        if (!value.is_object()) reader.fail(at, "must be an object");
        std::vector<glm::dvec3> path;
        if (const auto via = value.find("via"); via != value.end()) {
          if (!via->is_array()) reader.fail(at, "\"via\" must be an array of points");
          for (const auto& p : *via) path.push_back(reader.vector(p, at + ".via"));
        }
        path.push_back(reader.vector(value, "to", at));
        std::optional<SheetTurn> turn;
        if (value.contains("turn_sheet"))
          turn = reader.turn(value["turn_sheet"], at + ".turn_sheet");
        recorder.drag(reader.vector(value, "grab", at), path, reader.duration(value, at, 1.0),
                      turn);
      } else if (kind == "undo") {
        recorder.press(Button::Undo);
      } else if (kind == "redo") {
        recorder.press(Button::Redo);
      } else if (kind == "cancel") {
        recorder.press(Button::Cancel);
      } else if (kind == "switch_hands") {
        recorder.press(Button::SwitchHands);
      } else {
        reader.fail(at,
                    "unknown gesture (wait, turn_sheet, move_sheet, drag, undo, redo, "
                    "cancel, switch_hands)");
      }
    } catch (const GestureError& e) {
      if (std::string(e.what()).rfind(name, 0) == 0) throw;
      reader.fail(at, e.what());
    }
  }
  recorder.wait(0.1);  // a moment of rest after the last gesture
  return recorder.recording();
}

}  // namespace curvefold
