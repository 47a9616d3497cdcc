// Synthetic gestures and the example recordings made from them.
#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <variant>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "recording_fixtures.hpp"
#include "sanitizer_support.hpp"
#include "sheet_fixtures.hpp"
#include "sim_input/gestures.hpp"
#include "sim_input/recording.hpp"
#include "symmetry_test_support.hpp"
#include "test_paths.hpp"

namespace curvefold {
namespace {

namespace fs = std::filesystem;
using testing::heldSquareHeader;

const fs::path kExamples = fs::path(CURVEFOLD_SOURCE_DIR) / "examples";

struct Replayed {
  std::unique_ptr<FoldSession> session;
  std::size_t commits = 0;
  std::size_t commitsWhileTurning = 0;  // drags during which the sheet hand moved the sheet
};

// Feeds a recording to a fresh core, checking every invariant after every committed fold.
Replayed replay(const Recording& recording) {
  Replayed result;
  result.session =
      std::make_unique<FoldSession>(initialSheet(Design{recording.header.surface, {}}));
  if (!recording.header.symmetry.empty())
    result.session->setSymmetry(
        parseSymmetry(recording.header.symmetry, result.session->initial()));
  InteractionCore core(*result.session, recording.header.sheetFrame, recording.header.handedness);
  bool turnedDuringDrag = false;
  for (const InputFrame& frame : recording.frames) {
    const Pose before = core.worldFromSheet();
    const bool wasDragging = core.state() == InteractionState::Dragging;
    core.process(frame);
    if (wasDragging && core.state() == InteractionState::Dragging &&
        !(core.worldFromSheet() == before))
      turnedDuringDrag = true;
    for (const InteractionEvent& event : core.events()) {
      if (event.kind == InteractionEventKind::Grab) turnedDuringDrag = false;
      if (event.kind != InteractionEventKind::Commit) continue;
      ++result.commits;
      result.commitsWhileTurning += turnedDuringDrag;
      testing::expectInvariants(result.session->fixed(), result.session->initial());
    }
  }
  return result;
}

TEST(Gestures, RecordingReplaysToTheSameSheetBitForBit) {
  GestureRecorder recorder(heldSquareHeader(20));
  recorder.drag({0.1, 0.1, 0.0}, {{0.03, 0.04, 0.05}}, 0.6);
  recorder.turnSheet({{0, 1, 0}, 30}, 0.3);
  recorder.drag({-0.1, 0.1, 0.0}, {{-0.04, 0.02, 0.05}}, 0.6, SheetTurn{{1, 0, 0}, 20});
  recorder.press(Button::Undo);
  recorder.press(Button::Redo);
  ASSERT_EQ(recorder.session().foldCount(), 2u);

  const Replayed first = replay(recorder.recording());
  const Replayed second = replay(recorder.recording());
  EXPECT_EQ(first.commits, 2u);
  EXPECT_EQ(first.commitsWhileTurning, 1u);
  EXPECT_TRUE(identical(first.session->fixed(), recorder.session().fixed()));
  EXPECT_TRUE(identical(first.session->fixed(), second.session->fixed()));
}

TEST(Gestures, TurningTheSheetDuringADragChangesTheFold) {
  GestureRecorder still(heldSquareHeader(20)), turning(heldSquareHeader(20));
  still.drag({0.1, 0.1, 0.0}, {{0.03, 0.04, 0.05}}, 0.6);
  turning.drag({0.1, 0.1, 0.0}, {{0.03, 0.04, 0.05}}, 0.6, SheetTurn{{0, 0, 1}, 15});
  ASSERT_EQ(still.session().foldCount(), 1u);
  ASSERT_EQ(turning.session().foldCount(), 1u);
  EXPECT_NE(still.session().folds()[0].target, turning.session().folds()[0].target);
}

TEST(Gestures, ClutchAtPoseAMoveToPoseB) {
  GestureRecorder recorder(heldSquareHeader(20));
  const Pose a{{-0.2, 1.0, -0.3}, glm::dquat(1, 0, 0, 0)};
  const Pose b{{-0.1, 1.2, -0.35}, glm::angleAxis(0.5, glm::dvec3(0, 1, 0))};
  const Pose sheetBefore = recorder.core().worldFromSheet();
  recorder.moveSheetHand(a, 0.3, false);  // reposition the hand: the sheet stays
  EXPECT_EQ(recorder.core().worldFromSheet(), sheetBefore);
  recorder.moveSheetHand(b, 0.5, true);  // clutched: the sheet follows rigidly
  const Pose expected = b * a.inverse() * sheetBefore;
  const Pose& now = recorder.core().worldFromSheet();
  EXPECT_NEAR(glm::distance(now.position, expected.position), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(glm::dot(now.orientation, expected.orientation)), 1.0, 1e-12);
  EXPECT_FALSE(recorder.core().clutched());
}

TEST(Gestures, AFarGrabPointGrabsTheNearestEdge) {
  GestureRecorder recorder(heldSquareHeader(20));
  // The grabbed point is the nearest surface point, so a point off the sheet grabs its edge.
  EXPECT_NO_THROW(recorder.drag({1.0, 0.0, 0.0}, {{0.05, 0.0, 0.05}}, 0.3));
  ASSERT_EQ(recorder.session().foldCount(), 1u);
  // The grabbed point is on the square's right edge (x = 0.1, its half size), level with the
  // far point (y = 0): the nearest point of the sheet to (1, 0, 0).
  const glm::dvec3 grabbed = recorder.session().folds()[0].grabbed;
  EXPECT_NEAR(grabbed.x, 0.1, 1e-9);
  EXPECT_NEAR(grabbed.y, 0.0, 1e-9);
  EXPECT_NEAR(grabbed.z, 0.0, 1e-9);
}

// Each gesture script in DIR/scripts records to exactly the checked-in recording in
// DIR/recordings, which replays with every invariant after every fold, and, unless a desktop
// session, with a fold committed while the sheet turned. Calls check(stored, replayed) for each
// (a headset studio script runs the panel, Dear ImGui: test_headset_studio checks those).
template <typename Check>
std::size_t forEachCurrentRecording(const fs::path& dir, Check check) {
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator(dir / "scripts")) {
    const std::string name = entry.path().stem().stem().string();  // x.gesture.json -> x
    SCOPED_TRACE(name);
    const fs::path recording = dir / "recordings" / (name + ".jsonl");
    if (readRecording(recording).header.studio) continue;
    ++count;
    const Recording made = recordGestureScript(entry.path());
    const Recording stored = readRecording(recording);
    EXPECT_EQ(stored.frames.size(), made.frames.size()) << "regenerate: scripts/make-examples.sh";
    if (stored.frames.size() != made.frames.size()) continue;
    std::size_t same = 0;
    while (same < made.frames.size() &&
           frameLine(stored.frames[same]) == frameLine(made.frames[same]))
      ++same;
    EXPECT_EQ(same, made.frames.size()) << "frame " << same << " differs";
    if (same != made.frames.size()) continue;
    const Replayed result = replay(stored);
    if (stored.header.source != "desktop") {
      EXPECT_GE(result.commitsWhileTurning, 1u);
    }
    check(stored, result);
  }
  return count;
}

// 8 folds or more, and the folded sheet does not pass through itself.
void expectRich(const Replayed& result) {
  EXPECT_GE(result.session->foldCount(), 8u);
  EXPECT_EQ(findSelfIntersections(result.session->fixed()).intersections.size(), 0u);
}

// The two-handed example sessions have four folds or more and never pass the paper through
// itself (issue 28, 4). The symmetric ones (issue 17, 3) are rich and map onto themselves under
// their symmetry.
TEST(Gestures, ExampleRecordingsAreCurrentAndValid) {
  std::size_t symmetric = 0;
  const std::size_t examples =
      forEachCurrentRecording(kExamples, [&](const Recording& stored, const Replayed& result) {
        EXPECT_GE(result.session->foldCount(), 4u);
        EXPECT_EQ(findSelfIntersections(result.session->fixed()).intersections.size(), 0u);
        if (stored.header.symmetry.empty()) return;
        ++symmetric;
        expectRich(result);
        const Symmetry symmetry = parseSymmetry(stored.header.symmetry, result.session->initial());
        for (const Isometry& g : symmetry.images())
          testing::expectMapsOntoItself(result.session->fixed(), g,
                                        1e-9 * sheetSize(result.session->initial()));
      });
  EXPECT_EQ(examples, 8u);
  EXPECT_EQ(symmetric, 2u);
}

// Issue 18, 3: the showcase's sessions are rich (8 folds or more, free of self-intersections),
// and with the symmetric examples they start from every surface the catalog makes and from an
// OBJ. The symmetric ones (arch_tongues; star_lily, issue 28, 2) map onto themselves under their
// symmetry.
TEST(Gestures, ShowcaseRecordingsAreCurrentAndRichOnEverySurface) {
  std::set<std::string> surfaces;
  std::size_t symmetric = 0;
  auto surfaceOf = [&](const Recording& stored) {
    const auto* generated = std::get_if<GeneratedSurface>(&stored.header.surface);
    surfaces.insert(generated ? generated->generator : "an OBJ mesh");
  };
  const std::size_t showcase = forEachCurrentRecording(
      kExamples / "showcase", [&](const Recording& stored, const Replayed& result) {
        expectRich(result);
        surfaceOf(stored);
        if (stored.header.symmetry.empty()) return;
        ++symmetric;
        const Symmetry symmetry = parseSymmetry(stored.header.symmetry, result.session->initial());
        for (const Isometry& g : symmetry.images())
          testing::expectMapsOntoItself(result.session->fixed(), g,
                                        1e-9 * sheetSize(result.session->initial()));
      });
  EXPECT_EQ(showcase, 9u);
  EXPECT_EQ(symmetric, 2u);  // arch_tongues and star_lily
  for (const auto& entry : fs::directory_iterator(kExamples / "recordings")) {
    const Recording stored = readRecording(entry.path());
    if (!stored.header.symmetry.empty()) surfaceOf(stored);
  }
  std::set<std::string> kinds = {"an OBJ mesh"};
  for (const SurfaceInfo& surface : surfaceCatalog()) kinds.insert(surface.name);
  EXPECT_EQ(surfaces, kinds);
}

// The address sanitizer keeps freed memory in quarantine: the process grows with every frame
// line made and freed, so only the plain build measures the growth (kSanitized).

// Issue 14, 2: "scale_sheet" takes the sheet with both hands and spreads them: the recording
// holds the point hand's squeeze, a replay of it reaches the same view scale, and a drag after it
// still grabs where the script says (its points are sheet coordinates) and folds once.
TEST(Gestures, ScaleSheetTakesTheSheetWithBothHands) {
  GestureRecorder recorder(heldSquareHeader(20));
  recorder.scaleSheet(1.5, 0.5);
  EXPECT_NEAR(recorder.core().viewScale(), 1.5, 1e-9);
  recorder.drag({0.05, 0.05, 0.0}, {{0.05, 0.05, 0.04}}, 0.5);
  EXPECT_EQ(recorder.session().foldCount(), 1u);
  const Recording& made = recorder.recording();
  std::size_t squeezed = 0;
  for (const InputFrame& frame : made.frames) squeezed += frame.pointHand.grip > 0.5;
  EXPECT_GT(squeezed, 10u);
  const Replayed again = replay(made);
  EXPECT_EQ(again.commits, 1u);
  EXPECT_TRUE(identical(again.session->fixed(), recorder.session().fixed()));
  // Beyond the view scale's range: refused by name.
  GestureRecorder far(heldSquareHeader(20));
  EXPECT_THROW(far.scaleSheet(100.0, 0.5), GestureError);
}

long peakResidentKilobytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// Issue 13, A4: a long script streams its frames (record-script writes each as it is made): 400,000
// frames (about 80 MB held in memory before) grow the process by a few megabytes, and the stream
// is the in-memory recording, line for line.
TEST(Gestures, ALongScriptStreamsItsFrames) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("stream-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path script = dir / "long.gesture.json";
  std::ofstream(script) << R"({"format": "curvefold-gesture-script", "version": 1, "rate": 1000,
    "surface": {"generator": "square", "parameters": {"resolution": 8}},
    "gestures": [{"drag": {"grab": [0.05, 0.05, 0], "to": [0.05, 0.05, 0.06]}}, {"wait": 400}]})";
  const long before = peakResidentKilobytes();
  std::size_t streamed = 0, headers = 0;
  std::string firstLines;
  const GestureStream stream = streamGestureScript(
      script,
      [&](const RecordingHeader& header) { firstLines += headerLine(header) + "\n", ++headers; },
      [&](const InputFrame& frame) {
        if (++streamed <= 3000) firstLines += frameLine(frame) + "\n";
      });
  const long grown = peakResidentKilobytes() - before;
  EXPECT_EQ(headers, 1u);
  EXPECT_EQ(stream.frames, streamed);
  EXPECT_GT(streamed, 400'000u);
  EXPECT_NEAR(stream.seconds, (streamed - 1) / 1000.0, 1e-6);
  if (!testing::kSanitized) {
    EXPECT_LT(grown, 16 * 1024) << "kilobytes";
  }
  // The same frames as the in-memory recording of the same script (the first 3000: the drag).
  const Recording held = recordGestureScript(script);
  ASSERT_EQ(held.frames.size(), streamed);
  std::string heldLines = headerLine(held.header) + "\n";
  for (std::size_t i = 0; i < 3000; ++i) heldLines += frameLine(held.frames[i]) + "\n";
  EXPECT_EQ(firstLines, heldLines);
  fs::remove_all(dir);
}

// The shortest run, in seconds at the recording's rate, of frames holding a button or the
// trigger: what a runtime syncing at a lower rate must see as a press.
double shortestPress(const Recording& recording) {
  double shortest = std::numeric_limits<double>::infinity();
  auto scan = [&](auto pressed) {
    std::size_t run = 0;
    for (const InputFrame& frame : recording.frames) {
      if (pressed(frame)) {
        ++run;
      } else if (run > 0) {
        shortest = std::min(shortest, double(run) / recording.header.rate);
        run = 0;
      }
    }
  };
  for (Button button :
       {Button::Undo, Button::Redo, Button::Cancel, Button::SwitchHands, Button::Panel})
    scan([&](const InputFrame& frame) { return frame.held(button); });
  scan([](const InputFrame& frame) { return frame.pointHand.select >= 0.5; });
  return shortest;
}

// Issue 28, 3: a runtime reports a button at each sync, so a click of two frames at 60 Hz (33 ms)
// is lost at 20 frames a second. Scripts hold presses as a person does, 100 ms or more (or as
// "hold" says, with a warning when shorter), and so every example recording does.
TEST(Gestures, ClicksAreHeldAsLongAsAPersonsAndShortOnesWarn) {
  const std::string head =
      R"({"format":"curvefold-gesture-script","version":1,"surface":{"generator":"square"},)";
  for (const char* rate : {"20", "60", "90"}) {
    const Recording made = recordGestureScriptText(
        head + R"("rate":)" + rate +
            R"(,"gestures":[{"drag":{"grab":[0.1,0.1,0],"to":[0.05,0.05,0.05]}},{"undo":{}},)"
            R"({"redo":{}},{"switch_hands":{}}]})",
        "clicks.gesture.json");
    SCOPED_TRACE(rate);
    EXPECT_GE(shortestPress(made), kShortestSeenClickSeconds - 1e-9);
    EXPECT_LT(shortestPress(made), 0.2);  // the undo and the redo were made
  }
  for (const char* dir : {"", "showcase"}) {
    for (const auto& entry : fs::directory_iterator(kExamples / dir / "recordings")) {
      SCOPED_TRACE(entry.path().filename().string());
      EXPECT_GE(shortestPress(readRecording(entry.path())), kShortestSeenClickSeconds - 1e-9);
    }
  }

  const fs::path dir = fs::temp_directory_path() / ("curvefold-clicks-" + std::to_string(getpid()));
  fs::create_directories(dir);
  auto warningsOf = [&](const std::string& gestures) {
    const fs::path file = dir / "clicks.gesture.json";
    std::ofstream(file) << head + R"("rate":60,"gestures":[)" + gestures + "]}";
    return streamGestureScript(file, nullptr, [](const InputFrame&) {}).warnings;
  };
  EXPECT_TRUE(warningsOf(R"({"undo":{}},{"redo":{"hold":0.1}})").empty());
  const std::vector<std::string> warnings = warningsOf(R"({"undo":{"hold":0.03}})");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "gesture 1 (undo): a click held 33 ms may be missed; a runtime syncing 20 times a "
            "second sees presses held 100 ms or more");
  fs::remove_all(dir);
}

TEST(Gestures, BadScriptsNameTheProblem) {
  const fs::path dir =
      fs::temp_directory_path() / ("curvefold-gestures-" + std::to_string(getpid()));
  fs::create_directories(dir);
  auto expectError = [&](const std::string& text, const std::string& fragment) {
    const fs::path file = dir / "bad.gesture.json";
    std::ofstream(file) << text;
    try {
      recordGestureScript(file);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const GestureError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  const std::string head =
      R"({"format":"curvefold-gesture-script","version":1,"surface":{"generator":"square"},)";
  expectError("{", "not valid JSON");
  expectError(R"({"format":"x","version":1})", "not a curvefold gesture script");
  expectError(head + R"("gestures":[{"fly":{}}]})", "gesture 1 (fly): unknown gesture");
  expectError(head + R"("gestures":[{"wait":0.1},{"drag":{"grab":[0,0,0]}}]})",
              "gesture 2 (drag): missing \"to\"");
  expectError(head + R"("gestures":[{"turn_sheet":{"axis":[0,0,0],"degrees":4}}]})",
              "axis must not be zero");
  expectError(
      R"({"format":"curvefold-gesture-script","version":1,"surface":{"generator":"blob"},"gestures":[]})",
      "blob");
  // Bounds that keep a script's cost within its limits (issue 13, A4): a rate of 1e9 frames per
  // second, and 200 ten-minute waits (each within its own limit), are refused before they run.
  expectError(head + R"("rate":1e9,"gestures":[]})", "rate: must lie in (0, 1000]");
  expectError(head + R"("gestures":[{"undo":{"hold":20}}]})",
              "gesture 1 (undo): \"hold\" must lie in (0, 10] seconds");
  expectError(head + R"("gestures":[{"redo":3}]})", "gesture 1 (redo): must be an object");
  std::string waits = head + R"("rate":60,"gestures":[)";
  for (int i = 0; i < 200; ++i) {
    if (i > 0) waits += ',';
    waits += R"({"wait":600})";  // appended piece by piece: GCC 12's -Wrestrict on "," + string
  }
  expectError(waits + "]}", "gesture 28 (wait): the script makes more than 1000000 frames");
  // Issue 29, 1: refused before any frame is made (it once generated frames for 10-35 s first).
  {
    const fs::path file = dir / "long.gesture.json";
    std::ofstream(file) << waits + "]}";
    std::size_t made = 0;
    EXPECT_THROW(streamGestureScript(file, nullptr, [&](const InputFrame&) { ++made; }),
                 GestureError);
    EXPECT_EQ(made, 0u);
  }
  // Two hands scaling the sheet (issue 14): a factor that is not a number or leaves the view
  // scale's range is named.
  expectError(head + R"("gestures":[{"scale_sheet":{"by":"big"}}]})",
              "gesture 1 (scale_sheet).by: must be a finite number");
  expectError(head + R"("gestures":[{"scale_sheet":{}}]})",
              "gesture 1 (scale_sheet): missing \"by\"");
  expectError(head + R"("gestures":[{"scale_sheet":{"by":0}}]})",
              "gesture 1 (scale_sheet): scale_sheet: the view scale would leave [0.05, 20]");
  // A grab absurdly far from the sheet (A3) is one line naming the point, not a crash.
  expectError(head + R"("gestures":[{"drag":{"grab":[1e155,0,0],"to":[0,0,0.05]}}]})",
              "gesture 1 (drag): point (1e+155, 0, 0) lies too far from the sheet");
  expectError(head + R"("gestures":[{"drag":{"grab":[0,0,0],"to":[1e300,0,0]}}]})",
              "gesture 1 (drag): drag point (1e+300, 0, 0) lies too far from the sheet");
  // A symmetry the surface lacks, or one that is not a string (issue 17): named in one line.
  expectError(head + R"("symmetry":"rotational:3","gestures":[]})", "symmetry");
  expectError(head + R"("symmetry":6,"gestures":[]})", "symmetry");
  // A surface parameter the engine does not know, with a symmetry to check against the sheet
  // (found by fuzz_gesture_script): the reader's error, not the engine's escaping it.
  expectError(R"({"format":"curvefold-gesture-script","version":1,"symmetry":"mirror:x",)"
              R"("surface":{"generator":"cylinder","parameters":{"resolu":8}},"gestures":[]})",
              "has no parameter \"resolu\"");
  // A value nested a million deep is quoted by an excerpt, not dumped recursively (A1).
  std::string deep = R"({"format":)";
  deep.append(1'000'000, '[').append(1'000'000, ']').append("}");
  expectError(deep, "(format [[[[[[[[");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace curvefold
