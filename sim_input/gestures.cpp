#include "sim_input/gestures.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>

#include <glm/gtc/quaternion.hpp>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "engine/geometry/symmetry.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/input_limits.hpp"
#include "engine/io/json_reader.hpp"

namespace curvefold {
namespace {

// Eases in and out, so hands start and stop smoothly as people's do.
double smoothstep(double t) {
  return t * t * (3.0 - 2.0 * t);
}

// Where a hand rests: a quarter metre in front of the sheet's centre, out of hover range.
constexpr double kRestDistance = 0.25;
constexpr double kApproachSeconds = 0.25;

}  // namespace

namespace {

// The interaction core over a fold session: what a script without a panel acts on.
class CoreWorld : public GestureWorld {
 public:
  explicit CoreWorld(const RecordingHeader& header)
      : session_(initialSheet(Design{header.surface, {}}, "gesture script")),
        core_(session_, header.sheetFrame, header.handedness) {
    if (!header.symmetry.empty())
      session_.setSymmetry(parseSymmetry(header.symmetry, session_.initial()));
  }
  void process(const InputFrame& frame) override { core_.process(frame); }
  const InteractionCore& core() const override { return core_; }

 private:
  FoldSession session_;
  InteractionCore core_;
};

// Straight down (world -Y): the pointing direction, -Z, turned a quarter about +X.
const glm::dquat kAimDown = glm::angleAxis(-0.5 * std::numbers::pi, glm::dvec3(1.0, 0.0, 0.0));

// Where a hand points at a panel item from.
constexpr double kPointingDistance = 0.2;

}  // namespace

GestureRecorder::GestureRecorder(RecordingHeader header, std::size_t maxFrames, FrameSink sink,
                                 const GestureWorldFactory& world)
    : sink_(std::move(sink)), maxFrames_(maxFrames) {
  recording_.header = std::move(header);
  if (!(recording_.header.rate > 0.0) || !(recording_.header.rate <= kMaxGestureRate))
    throw GestureError("rate must lie in (0, " + std::to_string(int(kMaxGestureRate)) +
                       "] frames per second");
  dt_ = 1.0 / recording_.header.rate;
  if (recording_.header.studio && !world)
    throw GestureError(
        "a studio script (\"studio\") runs the headset's panel: make its recording with "
        "`curvefold record-script`");
  if (recording_.header.studio)
    world_ = world(recording_.header);
  else
    world_ = std::make_unique<CoreWorld>(recording_.header);
  const glm::dvec3 centre = sheetCentre();
  const Pose& sheet = recording_.header.sheetFrame;
  frame_.time = 0.0;
  frame_.sheetHand.pose = sheet * Pose{centre, glm::dquat(1, 0, 0, 0)};
  frame_.sheetHand.tracked = true;
  frame_.pointHand.position = sheet.apply(centre + glm::dvec3(0.0, 0.0, kRestDistance));
  frame_.pointHand.tracked = true;
  if (recording_.header.studio) frame_.pointHand.aim = kAimDown;
  step();
}

glm::dvec3 GestureRecorder::sheetCentre() {
  if (centreOf_ != &session()) {
    centreOf_ = &session();
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const glm::dvec3& p : session().fixed().positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    sheetCentre_ = 0.5 * (lo + hi);
  }
  return sheetCentre_;
}

void GestureRecorder::aimAtPaper() {
  if (frame_.pointHand.aim) frame_.pointHand.aim = kAimDown;
}

namespace {

std::string tooManyFrames(std::size_t maxFrames) {
  return "the script makes more than " + std::to_string(maxFrames) + " frames (" +
         std::to_string(maxFrames / 90 / 60) + " minutes at 90 Hz); split it or lower its rate";
}

// The frames a timed piece of `seconds` makes at `rate` (every piece makes at least one).
double framesOf(double seconds, double rate) {
  return std::max(1.0, std::round(seconds * rate));
}

}  // namespace

int GestureRecorder::stepsFor(double seconds) const {
  // Refused before any frame is made, so that a script's cost is bounded by its limits.
  const double steps = framesOf(seconds, recording_.header.rate);
  if (static_cast<double>(frameCount_) + steps + 2.0 > static_cast<double>(maxFrames_))
    throw GestureError(tooManyFrames(maxFrames_));
  return static_cast<int>(steps);
}

void GestureRecorder::step() {
  if (sink_)
    sink_(frame_);
  else
    recording_.frames.push_back(frame_);
  world_->process(frame_);
  frame_.time = static_cast<double>(++frameCount_) * dt_;
}

void GestureRecorder::wait(double seconds) {
  for (int i = 0, n = stepsFor(seconds); i < n; ++i) step();
}

Pose GestureRecorder::turnedHand(const Pose& start, const Pose& sheetAtStart, const SheetTurn& turn,
                                 double fraction) const {
  const glm::dvec3 pivot = sheetAtStart.apply(core().viewScale() * sheetCentre_);
  const glm::dquat rotation =
      glm::angleAxis(turn.degrees * fraction * std::numbers::pi / 180.0, glm::normalize(turn.axis));
  const Pose aboutPivot{pivot - rotation * pivot, rotation};
  return aboutPivot * start;
}

void GestureRecorder::turnSheet(const SheetTurn& turn, double seconds) {
  sheetCentre();  // of the sheet now, for turnedHand
  frame_.sheetHand.clutch = 1.0;
  step();
  const Pose start = frame_.sheetHand.pose, sheet = core().worldFromSheet();
  for (int i = 1, n = stepsFor(seconds); i <= n; ++i) {
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
  for (int i = 1, n = stepsFor(seconds); i <= n; ++i) {
    frame_.sheetHand.pose.position = start.position + by * smoothstep(double(i) / n);
    step();
  }
  frame_.sheetHand.clutch = 0.0;
  step();
}

void GestureRecorder::scaleSheet(double factor, double seconds) {
  aimAtPaper();
  const InteractionThresholds& limits = core().thresholds();
  const double target = core().viewScale() * factor;
  if (!(target >= limits.minimumViewScale && target <= limits.maximumViewScale))
    throw GestureError("scale_sheet: the view scale would leave [" +
                       shortestDouble(limits.minimumViewScale) + ", " +
                       shortestDouble(limits.maximumViewScale) + "]");
  // The point hand to 20 cm beside the sheet hand (trigger released), then both squeeze.
  const glm::dvec3 anchor = frame_.sheetHand.pose.position;
  const glm::dvec3 from = frame_.pointHand.position, beside = anchor + glm::dvec3(0.2, 0.0, 0.0);
  for (int i = 1, n = stepsFor(kApproachSeconds); i <= n; ++i) {
    frame_.pointHand.position = from + (beside - from) * smoothstep(double(i) / n);
    step();
  }
  frame_.sheetHand.clutch = 1.0;
  frame_.pointHand.grip = 1.0;
  step();
  for (int i = 1, n = stepsFor(seconds); i <= n; ++i) {
    const double span = 0.2 * (1.0 + (factor - 1.0) * smoothstep(double(i) / n));
    frame_.pointHand.position = anchor + glm::dvec3(span, 0.0, 0.0);
    step();
  }
  frame_.sheetHand.clutch = 0.0;
  frame_.pointHand.grip = 0.0;
  step();
}

void GestureRecorder::moveSheetHand(const Pose& to, double seconds, bool clutch) {
  frame_.sheetHand.clutch = clutch ? 1.0 : 0.0;
  step();
  const Pose start = frame_.sheetHand.pose;
  for (int i = 1, n = stepsFor(seconds); i <= n; ++i) {
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
  sheetCentre();  // of the sheet now, for turnedHand
  aimAtPaper();
  const Sheet& fixed = session().fixed();
  const glm::dvec3 grabbed = positionOf(fixed, closestSurfacePoint(fixed, grabNear));
  const Pose sheet = core().worldFromSheet();
  const double scale = core().viewScale();

  // Approach the point with the trigger released, then pull it.
  const glm::dvec3 from = frame_.pointHand.position, to = core().worldOf(grabbed);
  for (int i = 1, n = stepsFor(kApproachSeconds); i <= n; ++i) {
    frame_.pointHand.position = from + (to - from) * smoothstep(double(i) / n);
    step();
  }
  frame_.pointHand.select = 1.0;
  if (turnDuring) frame_.sheetHand.clutch = 1.0;
  step();
  // While the sheet is simulated (issue 39, 4) the trigger pulls the point instead of folding.
  const bool pulling = core().simulation() && core().simulation()->pull();
  if (core().state() != InteractionState::Dragging && !pulling)
    throw GestureError("drag: could not grab the sheet near the given point");

  // Along the polyline grabbed -> path..., by arc length, in the sheet frame of the start. Points
  // out of reach are refused first: their distances would overflow.
  const double size = sheetSize(fixed);
  for (const glm::dvec3& p : path) checkWithinReach(p, grabbed, size, "drag point");
  std::vector<glm::dvec3> points{grabbed};
  points.insert(points.end(), path.begin(), path.end());
  std::vector<double> length{0.0};
  for (std::size_t i = 1; i < points.size(); ++i)
    length.push_back(length.back() + glm::distance(points[i - 1], points[i]));
  const Pose handStart = frame_.sheetHand.pose;
  for (int i = 1, n = stepsFor(seconds); i <= n; ++i) {
    const double fraction = smoothstep(double(i) / n);
    const double s = fraction * length.back();
    std::size_t k = 1;
    while (k + 1 < points.size() && length[k] < s) ++k;
    const double span = length[k] - length[k - 1];
    const double u = span > 0.0 ? (s - length[k - 1]) / span : 1.0;
    frame_.pointHand.position =
        sheet.apply(scale * (points[k - 1] + (points[k] - points[k - 1]) * u));
    if (turnDuring) frame_.sheetHand.pose = turnedHand(handStart, sheet, *turnDuring, fraction);
    step();
  }
  frame_.pointHand.select = 0.0;
  frame_.sheetHand.clutch = 0.0;
  step();
}

void GestureRecorder::press(Button button, double holdSeconds) {
  frame_.buttons = static_cast<std::uint32_t>(button);
  for (int i = 0, n = stepsFor(holdSeconds); i < n; ++i) step();
  frame_.buttons = 0;
  step();
}

void GestureRecorder::pointAt(const std::string& label, double seconds, bool click,
                              double holdSeconds) {
  std::optional<glm::dvec3> item = world_->panelItem(label);
  const std::optional<glm::dvec3> facing = world_->panelFacing();
  if (!item || !facing)
    throw GestureError("point_at: the panel shows no item " + quotedExcerpt(label));
  const glm::dvec3 from = frame_.pointHand.position;
  const glm::dquat aimFrom = frame_.pointHand.aim.value_or(kAimDown);
  for (int i = 1, n = stepsFor(seconds); i <= n; ++i) {
    // Where the item is now: a popup settles its place a frame after it opens.
    if (const std::optional<glm::dvec3> now = world_->panelItem(label)) item = now;
    const glm::dvec3 to = *item + kPointingDistance * glm::normalize(*facing);
    // The aim that turns the pointing direction (-Z) towards the item.
    const glm::dquat aimTo =
        glm::normalize(glm::dquat(glm::dvec3(0.0, 0.0, -1.0), glm::normalize(*item - to)));
    const double fraction = smoothstep(double(i) / n);
    frame_.pointHand.position = from + (to - from) * fraction;
    frame_.pointHand.aim = glm::normalize(glm::slerp(aimFrom, aimTo, fraction));
    step();
  }
  if (!click) return;
  // Press and release, as a finger does; the panel clicks on the release.
  frame_.pointHand.select = 1.0;
  for (int i = 0, n = stepsFor(holdSeconds); i < n; ++i) step();
  frame_.pointHand.select = 0.0;
  step();
}

namespace {

class ScriptReader : public JsonReader {
 public:
  using JsonReader::JsonReader;

  double number(const nlohmann::json& object, const char* key, const std::string& where,
                std::optional<double> fallback = std::nullopt) const {
    const nlohmann::json* value = optionalMember(object, key, where);
    if (!value) {
      if (fallback) return *fallback;
      fail(where, std::string("missing \"") + key + "\"");
    }
    return JsonReader::number(*value, join(where, key));
  }
  double duration(const nlohmann::json& object, const std::string& where, double fallback) const {
    const double seconds = number(object, "duration", where, fallback);
    if (!(seconds > 0.0) || seconds > kMaxGestureSeconds)
      fail(where, "\"duration\" must lie in (0, 600] seconds");
    return seconds;
  }
  glm::dvec3 vector(const nlohmann::json& object, const char* key, const std::string& where) const {
    return vector3(member(object, key, where), join(where, key));
  }
  SheetTurn turn(const nlohmann::json& value, const std::string& where) const {
    object(value, where);
    SheetTurn turn{vector(value, "axis", where), number(value, "degrees", where)};
    if (glm::length(turn.axis) == 0.0) fail(where, "axis must not be zero");
    return turn;
  }
  Pose pose(const nlohmann::json& value, const std::string& where) const {
    object(value, where);
    Pose pose;
    pose.position = vector(value, "position", where);
    if (const nlohmann::json* orientation = optionalMember(value, "orientation", where)) {
      double c[4];
      numbers(*orientation, 4, c, join(where, "orientation"));
      const glm::dquat q(c[0], c[1], c[2], c[3]);  // w, x, y, z
      if (std::abs(glm::length(q) - 1.0) > kQuaternionUnitTolerance)
        fail(where, "orientation must be a unit quaternion");
      pose.orientation = q;
    }
    return pose;
  }
  std::string text(const nlohmann::json& document, const char* key, const char* fallback) const {
    const nlohmann::json* value = optionalMember(document, key, "");
    return value ? string(*value, key) : fallback;
  }
};

// The recording's header from the script's: source, rate, handedness, the surface (built here, so
// a parameter the engine does not know is refused before any symmetry is checked against it),
// the symmetry, the sheet's frame and a studio script's recent designs.
RecordingHeader readScriptHeader(const ScriptReader& reader, const nlohmann::json& document,
                                 const std::string& name) {
  RecordingHeader header;
  header.source = reader.text(document, "source", "script");
  if (header.source != "script" && header.source != "desktop" && header.source != "synthetic")
    reader.fail("source", "must be \"script\", \"desktop\" or \"synthetic\"");
  header.rate = reader.number(document, "rate", "", 90.0);
  if (!(header.rate > 0.0) || header.rate > kMaxGestureRate)
    reader.fail("rate", "must lie in (0, " + std::to_string(int(kMaxGestureRate)) +
                            "] frames per second, got " + jsonExcerpt(document["rate"]));
  const std::string handedness = reader.text(document, "handedness", "right");
  if (handedness != "right" && handedness != "left")
    reader.fail("handedness", "must be \"right\" or \"left\"");
  header.handedness = handedness == "left" ? HandSide::Left : HandSide::Right;
  // The engine builds the sheet here or refuses it (a parameter it does not know), before any
  // symmetry is checked against it.
  std::optional<Sheet> initial;
  try {
    header.surface = parseInitialSurface(reader.member(document, "surface", ""), name);
    initial.emplace(initialSheet(Design{header.surface, {}}, name));
  } catch (const DesignError& e) {
    throw GestureError(e.what());
  }
  if (reader.optionalMember(document, "symmetry", "")) {
    header.symmetry = reader.text(document, "symmetry", "");
    try {
      parseSymmetry(header.symmetry, *initial);
    } catch (const InvalidSymmetry& e) {
      reader.fail("symmetry", e.what());
    }
  }
  // By default the sheet is held at chest height half a metre in front of the user (OpenXR's
  // stage space: y up, -z forward), facing them.
  header.sheetFrame = defaultSheetFrame();
  if (const nlohmann::json* frame = reader.optionalMember(document, "sheet_frame", ""))
    header.sheetFrame = reader.pose(*frame, "sheet_frame");

  if (const nlohmann::json* studio = reader.optionalMember(document, "studio", "")) {
    reader.object(*studio, "studio");
    header.studio.emplace();
    if (const nlohmann::json* recent = reader.optionalMember(*studio, "recent", "studio")) {
      reader.array(*recent, "studio.recent");
      if (recent->size() > kMaxRecentDesigns)
        reader.fail("studio.recent", "lists more than " + std::to_string(kMaxRecentDesigns));
      for (std::size_t k = 0; k < recent->size(); ++k)
        header.studio->recent.push_back(
            reader.string((*recent)[k], JsonReader::item("studio.recent", k)));
    }
  }
  return header;
}

// The frames each gesture makes at least (its duration at the rate; a drag adds its approach),
// summed before any frame is made: a script far over the limit (200 waits of 600 s) is refused
// at once, not after generating a million frames. Values out of range are the gestures' pass's.
void refuseTooManyFrames(const ScriptReader& reader, const nlohmann::json& all, double rate,
                         std::size_t maxFrames) {
  double leastFrames = 0.0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (!all[i].is_object() || all[i].size() != 1) continue;
    const std::string& kind = all[i].begin().key();
    const nlohmann::json& value = all[i].begin().value();
    static const std::map<std::string, double, std::less<>> kTimed = {
        {"turn_sheet", 0.5}, {"move_sheet", 0.5}, {"scale_sheet", 0.8},
        {"sheet_hand", 0.5}, {"drag", 1.0},       {"point_at", 0.5}};
    double seconds = 0.0;
    if (kind == "wait" && value.is_number()) {
      seconds = value.get<double>();
    } else if (const auto timed = kTimed.find(kind); timed != kTimed.end()) {
      seconds = timed->second;
      if (value.is_object() && value.contains("duration") && value["duration"].is_number())
        seconds = value["duration"].get<double>();
    } else {
      continue;
    }
    if (!(seconds >= 0.0 && seconds <= kMaxGestureSeconds)) continue;
    leastFrames += framesOf(seconds, rate);
    if (leastFrames + 2.0 > static_cast<double>(maxFrames)) {
      const std::string kindText = kind.size() <= kJsonExcerptLength ? kind : quotedExcerpt(kind);
      reader.fail("gesture " + std::to_string(i + 1) + " (" + kindText + ")",
                  tooManyFrames(maxFrames));
    }
  }
}

// How long a press or click is held: "hold" seconds, or a person's click; a click too short for
// a runtime to see is warned of.
double holdOf(const ScriptReader& reader, const nlohmann::json& value, const std::string& at,
              double rate, std::vector<std::string>& warnings) {
  reader.object(value, at);
  const double hold = reader.number(value, "hold", at, kClickSeconds);
  if (!(hold > 0.0 && hold <= kMaxClickSeconds))
    reader.fail(at, "\"hold\" must lie in (0, 10] seconds");
  const double held = framesOf(hold, rate) / rate;
  if (held < kShortestSeenClickSeconds - 1e-9)
    warnings.push_back(at + ": a click held " + std::to_string(std::lround(held * 1000.0)) +
                       " ms may be missed; a runtime syncing 20 times a second sees presses "
                       "held 100 ms or more");
  return hold;
}

// One gesture, `kind` with its `value`, made by the recorder (`at` names it in messages).
void playGesture(const ScriptReader& reader, GestureRecorder& recorder,
                 const RecordingHeader& header, const std::string& kind,
                 const nlohmann::json& value, const std::string& at,
                 std::vector<std::string>& warnings) {
  if (kind == "wait") {
    if (!value.is_number() || !(value.get<double>() >= 0.0) ||
        value.get<double>() > kMaxGestureSeconds)
      reader.fail(at, "must be a number of seconds in [0, 600]");
    recorder.wait(value.get<double>());
  } else if (kind == "turn_sheet") {
    recorder.turnSheet(reader.turn(value, at), reader.duration(value, at, 0.5));
  } else if (kind == "move_sheet") {
    recorder.moveSheet(reader.vector(value, "by", at), reader.duration(value, at, 0.5));
  } else if (kind == "scale_sheet") {
    recorder.scaleSheet(reader.number(value, "by", at), reader.duration(value, at, 0.8));
  } else if (kind == "sheet_hand") {
    const nlohmann::json* clutch = reader.optionalMember(value, "clutch", at);
    recorder.moveSheetHand(reader.pose(reader.member(value, "to", at), at + ".to"),
                           reader.duration(value, at, 0.5),
                           clutch && reader.boolean(*clutch, at + ".clutch"));
  } else if (kind == "drag") {
    reader.object(value, at);
    std::vector<glm::dvec3> path;
    if (const nlohmann::json* via = reader.optionalMember(value, "via", at)) {
      reader.array(*via, at + ".via");
      for (std::size_t k = 0; k < via->size(); ++k)
        path.push_back(reader.vector3((*via)[k], JsonReader::item(at + ".via", k)));
    }
    path.push_back(reader.vector(value, "to", at));
    std::optional<SheetTurn> turn;
    if (const nlohmann::json* during = reader.optionalMember(value, "turn_sheet", at))
      turn = reader.turn(*during, at + ".turn_sheet");
    recorder.drag(reader.vector(value, "grab", at), path, reader.duration(value, at, 1.0), turn);
  } else if (kind == "undo") {
    recorder.press(Button::Undo, holdOf(reader, value, at, header.rate, warnings));
  } else if (kind == "redo") {
    recorder.press(Button::Redo, holdOf(reader, value, at, header.rate, warnings));
  } else if (kind == "cancel") {
    recorder.press(Button::Cancel, holdOf(reader, value, at, header.rate, warnings));
  } else if (kind == "switch_hands") {
    recorder.press(Button::SwitchHands, holdOf(reader, value, at, header.rate, warnings));
  } else if (kind == "toggle_panel" && header.studio) {
    recorder.press(Button::Panel, holdOf(reader, value, at, header.rate, warnings));
  } else if (kind == "point_at" && header.studio) {
    reader.object(value, at);
    const nlohmann::json* click = reader.optionalMember(value, "click", at);
    const bool clicks = !click || reader.boolean(*click, at + ".click");
    const double hold = clicks ? holdOf(reader, value, at, header.rate, warnings) : kClickSeconds;
    recorder.pointAt(reader.string(reader.member(value, "item", at), at + ".item"),
                     reader.duration(value, at, 0.5), clicks, hold);
  } else if (kind == "toggle_panel" || kind == "point_at") {
    reader.fail(at, "needs a studio script (\"studio\":{} in its header)");
  } else {
    reader.fail(at,
                "unknown gesture (wait, turn_sheet, move_sheet, scale_sheet, sheet_hand, "
                "drag, undo, redo, cancel, switch_hands, point_at, toggle_panel)");
  }
}

// Runs the script; with a sink the frames stream out (`onHeader` first) and the returned
// recording holds none.
Recording runGestureScript(std::string_view text, const std::string& name, std::size_t maxFrames,
                           const std::function<void(const RecordingHeader&)>& onHeader = nullptr,
                           const GestureRecorder::FrameSink& sink = nullptr,
                           GestureStream* stream = nullptr,
                           const GestureWorldFactory& world = nullptr) {
  const ScriptReader reader(name);
  const nlohmann::json document = parseJsonText(text, name);
  reader.formatAndVersion(document, "curvefold-gesture-script", 1, "curvefold gesture script");

  const RecordingHeader header = readScriptHeader(reader, document, name);

  refuseTooManyFrames(reader, reader.array(reader.member(document, "gestures", ""), "gestures"),
                      header.rate, maxFrames);

  if (onHeader) onHeader(header);
  std::optional<GestureRecorder> made;
  try {
    made.emplace(header, maxFrames, sink, world);
  } catch (const DesignError& e) {
    throw GestureError(e.what());
  }
  GestureRecorder& recorder = *made;
  std::vector<std::string> warnings;
  const nlohmann::json* gestures =
      &reader.array(reader.member(document, "gestures", ""), "gestures");
  for (std::size_t i = 0; i < gestures->size(); ++i) {
    const nlohmann::json& gesture = (*gestures)[i];
    const std::string where = "gesture " + std::to_string(i + 1);
    if (!gesture.is_object() || gesture.size() != 1)
      reader.fail(where, "must be an object with one key (the gesture's name)");
    // One key: the gesture's name. (Binding to items() would outlive its proxy.)
    const std::string kind = gesture.begin().key();
    const nlohmann::json& value = gesture.begin().value();
    const std::string at =
        where + " (" + (kind.size() <= kJsonExcerptLength ? kind : quotedExcerpt(kind)) + ")";
    try {
      playGesture(reader, recorder, header, kind, value, at, warnings);
    } catch (const GestureError& e) {
      if (std::string(e.what()).rfind(name, 0) == 0) throw;
      reader.fail(at, e.what());
    } catch (const InvalidSheet& e) {
      reader.fail(at, e.what());  // a grab or drag point out of reach
    }
  }
  recorder.wait(0.1);  // a moment of rest after the last gesture
  if (stream) *stream = {recorder.frameCount(), recorder.duration(), std::move(warnings)};
  return recorder.recording();
}

}  // namespace

Recording recordGestureScriptText(std::string_view text, std::string_view name,
                                  std::size_t maxFrames, const GestureWorldFactory& world) {
  if (text.size() > kMaxGestureScriptBytes)
    throw GestureError(tooLarge(name, text.size(), kMaxGestureScriptBytes, "gesture script"));
  try {
    return runGestureScript(text, std::string(name), maxFrames, nullptr, nullptr, nullptr, world);
  } catch (const JsonReadError& e) {
    throw GestureError(e.what());
  }
}

namespace {

std::string readGestureScript(const std::filesystem::path& script) {
  try {
    return readWholeFile(script, kMaxGestureScriptBytes, "gesture script");
  } catch (const FileError& e) {
    throw GestureError(e.what());
  }
}

}  // namespace

Recording recordGestureScript(const std::filesystem::path& script,
                              const GestureWorldFactory& world) {
  return recordGestureScriptText(readGestureScript(script), script.string(), kMaxGestureFrames,
                                 world);
}

GestureStream streamGestureScript(const std::filesystem::path& script,
                                  const std::function<void(const RecordingHeader&)>& header,
                                  const GestureRecorder::FrameSink& frame,
                                  const GestureWorldFactory& world) {
  const std::string text = readGestureScript(script);
  GestureStream stream;
  try {
    runGestureScript(text, script.string(), kMaxGestureFrames, header, frame, &stream, world);
  } catch (const JsonReadError& e) {
    throw GestureError(e.what());
  }
  return stream;
}

}  // namespace curvefold
