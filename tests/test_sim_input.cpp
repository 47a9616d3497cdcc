// Recorded input: the recording format (bit-for-bit round trip, every bad input refused with its
// line), the recorder's journal (a killed process keeps its committed folds) and the player.
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "recording_fixtures.hpp"
#include "sanitizer_support.hpp"
#include "sim_input/player.hpp"
#include "sim_input/recorder.hpp"
#include "sim_input/recording.hpp"
#include "test_paths.hpp"

namespace curvefold {
namespace {

namespace fs = std::filesystem;
using testing::handFrame;
using testing::squareFoldFrames;
using testing::squareRecordingHeader;

const fs::path kRecordings = fs::path(CURVEFOLD_TEST_DATA) / "recordings";

// Same bits (so -0.0 differs from 0.0, and NaN never sneaks through as equal).
bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void expectSameBits(const glm::dvec3& a, const glm::dvec3& b, const std::string& what) {
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(sameBits(a[i], b[i])) << what << "[" << i << "]";
}

void expectSameBits(const Pose& a, const Pose& b, const std::string& what) {
  expectSameBits(a.position, b.position, what + ".position");
  EXPECT_TRUE(sameBits(a.orientation.w, b.orientation.w)) << what;
  EXPECT_TRUE(sameBits(a.orientation.x, b.orientation.x)) << what;
  EXPECT_TRUE(sameBits(a.orientation.y, b.orientation.y)) << what;
  EXPECT_TRUE(sameBits(a.orientation.z, b.orientation.z)) << what;
}

void expectSameFrame(const InputFrame& a, const InputFrame& b, std::size_t index) {
  const std::string what = "frame " + std::to_string(index);
  EXPECT_TRUE(sameBits(a.time, b.time)) << what;
  expectSameBits(a.sheetHand.pose, b.sheetHand.pose, what + " sheet");
  EXPECT_EQ(a.sheetHand.tracked, b.sheetHand.tracked) << what;
  EXPECT_TRUE(sameBits(a.sheetHand.clutch, b.sheetHand.clutch)) << what;
  expectSameBits(a.pointHand.position, b.pointHand.position, what + " point");
  EXPECT_EQ(a.pointHand.tracked, b.pointHand.tracked) << what;
  EXPECT_TRUE(sameBits(a.pointHand.select, b.pointHand.select)) << what;
  EXPECT_TRUE(sameBits(a.pointHand.grip, b.pointHand.grip)) << what;
  ASSERT_EQ(a.pointHand.aim.has_value(), b.pointHand.aim.has_value()) << what;
  if (a.pointHand.aim) {
    for (int i = 0; i < 4; ++i)
      EXPECT_TRUE(sameBits((*a.pointHand.aim)[i], (*b.pointHand.aim)[i])) << what << " aim";
  }
  EXPECT_TRUE(sameBits(a.pointHand.scroll, b.pointHand.scroll)) << what;
  EXPECT_EQ(a.buttons, b.buttons) << what;
  ASSERT_EQ(a.suggestions.size(), b.suggestions.size()) << what;
  for (std::size_t i = 0; i < a.suggestions.size(); ++i) {
    const std::string which = what + " suggestion " + std::to_string(i);
    EXPECT_TRUE(sameBits(a.suggestions[i].seed.x, b.suggestions[i].seed.x)) << which;
    EXPECT_TRUE(sameBits(a.suggestions[i].seed.y, b.suggestions[i].seed.y)) << which;
    expectSameBits(a.suggestions[i].grab, b.suggestions[i].grab, which + " grab");
    expectSameBits(a.suggestions[i].to, b.suggestions[i].to, which + " to");
  }
  ASSERT_EQ(a.simulation.has_value(), b.simulation.has_value()) << what;
  if (a.simulation) {
    EXPECT_TRUE(sameBits(a.simulation->percent, b.simulation->percent)) << what;
    EXPECT_EQ(a.simulation->steps, b.simulation->steps) << what;
    ASSERT_EQ(a.simulation->pull.has_value(), b.simulation->pull.has_value()) << what;
    if (a.simulation->pull) {
      EXPECT_EQ(a.simulation->pull->vertex, b.simulation->pull->vertex) << what;
      expectSameBits(a.simulation->pull->to, b.simulation->pull->to, what + " pull");
    }
  }
}

std::string recordingText(const RecordingHeader& header, const std::vector<InputFrame>& frames) {
  std::string text = headerLine(header) + "\n";
  for (const InputFrame& frame : frames) text += frameLine(frame) + "\n";
  return text;
}

Recording parse(const std::string& text, const ReadOptions& options = {}) {
  std::istringstream in(text);
  return parseRecording(in, "test.jsonl", options);
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from << " not in " << text;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

using curvefold::testing::slurp;

class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("curvefold-sim-" + std::string(info->name()) + "-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// --- Format ------------------------------------------------------------------------------------

TEST(Recording, HeaderAndFramesRoundTripBitForBit) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> any(-3.0, 3.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Values that a lossy decimal form would change.
  const double awkward[] = {
      0.1, 1.0 / 3.0,          -0.0, 5e-324, 1e300, -2.2250738585072014e-308, 0.3, 1e-17,
      2.0, 123456789.123456789};

  RecordingHeader header;
  header.source = "openxr";
  header.handedness = HandSide::Left;
  header.rate = 72.5;
  header.sheetFrame.position = {1.0 / 3.0, -0.0, 1e-17};
  header.sheetFrame.orientation = glm::normalize(glm::dquat(0.9, 0.1, -0.3, 1.0 / 7.0));
  header.surface = GeneratedSurface{"cylinder", {{"radius", 0.1 / 3.0}, {"angle", 180.0}}};

  std::vector<InputFrame> frames;
  double time = 0.0;
  for (int i = 0; i < 200; ++i) {
    InputFrame frame;
    time += unit(random) / 90.0;
    frame.time = time;
    const double a = awkward[i % std::size(awkward)];
    frame.sheetHand.pose.position = {any(random), a, any(random)};
    frame.sheetHand.pose.orientation =
        glm::normalize(glm::dquat(any(random), any(random), any(random), any(random)));
    frame.sheetHand.tracked = i % 3 != 0;
    frame.sheetHand.clutch = i % 5 == 0 ? 1.0 : unit(random);
    frame.pointHand.position = {a, any(random), any(random)};
    frame.pointHand.tracked = i % 4 != 0;
    frame.pointHand.select = i % 7 == 0 ? 0.0 : unit(random);
    // The point hand's squeeze (issue 14): absent from the line at +0, any other value kept.
    frame.pointHand.grip = i % 3 == 0 ? 0.0 : (i % 11 == 0 ? -0.0 : unit(random));
    // The headset's aim and thumbstick (the panel's ray and scroll): absent or kept exactly.
    if (i % 2 == 0)
      frame.pointHand.aim =
          glm::normalize(glm::dquat(any(random), any(random), any(random), any(random)));
    frame.pointHand.scroll = i % 5 == 0 ? 0.0 : (i % 13 == 0 ? -0.0 : 2.0 * unit(random) - 1.0);
    frame.buttons = static_cast<std::uint32_t>(i % 128);  // every button, take and next too
    // The studio's suggestions (issue 27, 3): in a few frames, kept exactly.
    if (i % 9 == 0)
      for (int k = 0; k <= i % 4; ++k)
        frame.suggestions.push_back(
            {{a, any(random)}, {any(random), a, any(random)}, {any(random), any(random), a}});
    // The live simulation (issue 39, 4): its fold amount, steps and pull, kept exactly.
    if (i % 3 == 1) {
      frame.simulation = SimulationInput{100.0 * unit(random), std::uint32_t(i % 40), {}};
      if (i % 2 == 0)
        frame.simulation->pull = SimulationPull{std::uint32_t(i * 7), {a, any(random), -0.0}};
    }
    frames.push_back(frame);
  }
  header.studio = RecordingHeader::Studio{{"a.curvefold.json", "designs/b c.curvefold.json"}};

  const Recording read = parse(recordingText(header, frames));
  EXPECT_FALSE(read.truncated);
  EXPECT_EQ(read.lineCount, frames.size() + 1);
  EXPECT_EQ(read.header.source, "openxr");
  EXPECT_EQ(read.header.handedness, HandSide::Left);
  EXPECT_TRUE(sameBits(read.header.rate, 72.5));
  expectSameBits(read.header.sheetFrame, header.sheetFrame, "sheet_frame");
  const auto& surface = std::get<GeneratedSurface>(read.header.surface);
  EXPECT_EQ(surface.generator, "cylinder");
  EXPECT_TRUE(sameBits(surface.parameters.at("radius"), 0.1 / 3.0));
  EXPECT_EQ(read.header.studio, header.studio);
  ASSERT_EQ(read.frames.size(), frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) expectSameFrame(read.frames[i], frames[i], i);
  // Writing what was read gives the same text again.
  EXPECT_EQ(recordingText(read.header, read.frames), recordingText(header, frames));
}

TEST(Recording, EmbeddedMeshSurfaceRoundTrips) {
  RecordingHeader header = squareRecordingHeader();
  const Sheet sheet = makeSurface("cone", {{"resolution", 6}});
  header.surface = sheet;
  const Recording read = parse(recordingText(header, squareFoldFrames()));
  ASSERT_TRUE(std::holds_alternative<Sheet>(read.header.surface));
  EXPECT_TRUE(identical(std::get<Sheet>(read.header.surface), sheet));
}

TEST(Recording, FrameLinesAreJsonWithTheDocumentedKeys) {
  InputFrame frame = handFrame(
      0.5, {0, 1, 2}, 0.25, {3, 4, 5}, 1.0,
      static_cast<std::uint32_t>(Button::Undo) | static_cast<std::uint32_t>(Button::SwitchHands));
  EXPECT_EQ(frameLine(frame),
            R"({"t":0.5,"sheet":{"position":[0.0,1.0,2.0],"orientation":[1.0,0.0,0.0,0.0],)"
            R"("tracked":true,"clutch":0.25},"point":{"position":[3.0,4.0,5.0],"tracked":true,)"
            R"("select":1.0},"buttons":["undo","switch_hands"]})");
  frame.buttons = 0;
  EXPECT_EQ(frameLine(frame).find("buttons"), std::string::npos);
  EXPECT_EQ(headerLine(squareRecordingHeader()),
            R"({"format":"curvefold-recording","version":2,"source":"synthetic",)"
            R"("handedness":"right","units":"m","rate":10.0,"sheet_frame":{"position":[0.0,0.0,)"
            R"(0.0],"orientation":[1.0,0.0,0.0,0.0]},"surface":{"generator":"square",)"
            R"("parameters":{"resolution":10.0}}})");
}

// Every way a recording can be wrong: a RecordingError whose one line names the file and line.
struct BadInput {
  const char* name;
  std::size_t line;      // 1 = header, 2 = first frame
  std::string from, to;  // replaced in that line of a good recording
  const char* fragment;  // expected in the message
};

TEST(Recording, BadInputNamesFileAndLine) {
  const std::vector<std::string> good =
      lines(recordingText(squareRecordingHeader(), squareFoldFrames()));
  const std::vector<BadInput> cases = {
      {"not json", 4, "{\"t\"", "{t", "not valid JSON"},
      {"not an object", 3, good[2], "[1,2]", "must be a JSON object"},
      {"missing t", 2, "\"t\":0.0,", "", "missing \"t\""},
      {"missing sheet", 2, "\"sheet\"", "\"sheeet\"", "missing \"sheet\""},
      {"missing clutch", 3, ",\"clutch\":1.0", "", "missing \"clutch\""},
      {"ill-typed tracked", 5, "\"tracked\":true", "\"tracked\":1", "sheet.tracked"},
      {"ill-typed position", 7, "\"position\":[0.1,0.1,0.01]", "\"position\":[0.1,0.1]",
       "point.position"},
      {"string number", 2, "\"t\":0.0", "\"t\":\"0\"", "t: must be a finite number"},
      {"NaN (null)", 8, "\"select\":1.0", "\"select\":null", "point.select: must be a finite"},
      {"overflowing literal", 8, "\"position\":[0.0,-0.1,0.0]", "\"position\":[0.0,-1e999,0.0]",
       "line 8"},
      {"non-unit quaternion", 9, "\"orientation\":[1.0,0.0,0.0,0.0]",
       "\"orientation\":[1.0,0.0,0.0,1e-2]", "not a unit quaternion"},
      {"clutch above 1", 4, "\"clutch\":1.0", "\"clutch\":1.5", "sheet.clutch: must lie in [0, 1]"},
      {"select below 0", 2, "\"select\":0.0", "\"select\":-0.1", "point.select: must lie in"},
      {"grip above 1", 2, "\"select\":0.0", "\"select\":0.0,\"grip\":1.5",
       "point.grip: must lie in [0, 1]"},
      {"grip not a number", 2, "\"select\":0.0", "\"select\":0.0,\"grip\":true",
       "point.grip: must be a finite number"},
      {"aim not unit", 2, "\"select\":0.0", "\"select\":0.0,\"aim\":[1.0,0.5,0.0,0.0]",
       "point.aim: is not a unit quaternion"},
      {"scroll beyond 1", 2, "\"select\":0.0", "\"select\":0.0,\"scroll\":-1.5",
       "point.scroll: must lie in [-1, 1]"},
      {"studio not an object", 1, "\"units\"", "\"studio\":[],\"units\"",
       "studio: must be an object"},
      {"studio recent not paths", 1, "\"units\"", "\"studio\":{\"recent\":[1]},\"units\"",
       "studio.recent[0]"},
      {"time backwards", 11, "\"t\":0.9", "\"t\":0.75", "time goes backwards"},
      {"unknown button", 11, "\"select\":1.0}", "\"select\":1.0},\"buttons\":[\"jump\"]",
       "unknown button \"jump\""},
      {"suggestions not an array", 11, "\"select\":1.0}", "\"select\":1.0},\"suggestions\":{}",
       "suggestions: must be an array of 1 to 16 folds"},
      {"suggestions empty", 11, "\"select\":1.0}", "\"select\":1.0},\"suggestions\":[]",
       "suggestions: must be an array of 1 to 16 folds"},
      {"suggestion without to", 11, "\"select\":1.0}",
       "\"select\":1.0},\"suggestions\":[{\"seed\":[0,0],\"grab\":[0,0,0]}]",
       "suggestions[0]: missing \"to\""},
      {"suggestion seed NaN", 11, "\"select\":1.0}",
       "\"select\":1.0},\"suggestions\":[{\"seed\":[null,0],\"grab\":[0,0,0],\"to\":[0,0,1]}]",
       "suggestions[0].seed"},
      {"simulation percent past 100", 11, "\"select\":1.0}",
       "\"select\":1.0},\"simulation\":{\"percent\":150,\"steps\":4}",
       "simulation.percent: must lie in [0, 100]"},
      {"simulation steps past the limit", 11, "\"select\":1.0}",
       "\"select\":1.0},\"simulation\":{\"percent\":50,\"steps\":20000}",
       "simulation.steps: must be at most"},
      {"simulation without steps", 11, "\"select\":1.0}",
       "\"select\":1.0},\"simulation\":{\"percent\":50}", "missing \"steps\""},
      {"simulation pull NaN", 11, "\"select\":1.0}",
       "\"select\":1.0},\"simulation\":{\"percent\":50,\"steps\":4,"
       "\"pull\":{\"vertex\":3,\"to\":[0,null,0]}}",
       "simulation.pull.to"},
      {"simulation pull negative vertex", 11, "\"select\":1.0}",
       "\"select\":1.0},\"simulation\":{\"percent\":50,\"steps\":4,"
       "\"pull\":{\"vertex\":-1,\"to\":[0,0,0]}}",
       "simulation.pull.vertex"},
      {"buttons not an array", 11, "\"select\":1.0}", "\"select\":1.0},\"buttons\":\"undo\"",
       "buttons"},
      {"unknown version", 1, "\"version\":2", "\"version\":3", "unsupported version 3"},
      {"version not integer", 1, "\"version\":2", "\"version\":1.5", "unsupported version 1.5"},
      {"not a recording", 1, "curvefold-recording", "curvefold-design",
       "not a curvefold recording"},
      {"unknown source", 1, "\"synthetic\"", "\"kinect\"", "unknown source \"kinect\""},
      // Sources are case-sensitive, and the list names every one, hands too.
      {"source in capitals", 1, "\"synthetic\"", "\"HANDS\"",
       "unknown source \"HANDS\" (expected one of synthetic, script, desktop, openxr, hands)"},
      {"unknown handedness", 1, "\"right\"", "\"both\"", "unknown handedness \"both\""},
      {"units", 1, "\"units\":\"m\"", "\"units\":\"mm\"", "units: must be \"m\""},
      {"rate", 1, "\"rate\":10.0", "\"rate\":0", "rate: must be positive"},
      {"sheet frame quaternion", 1, "\"orientation\":[1.0,0.0,0.0,0.0]",
       "\"orientation\":[2.0,0.0,0.0,0.0]", "sheet_frame.orientation"},
      {"missing surface", 1,
       ",\"surface\":{\"generator\":\"square\",\"parameters\":{"
       "\"resolution\":10.0}}",
       "", "missing \"surface\""},
      {"unknown generator", 1, "\"generator\":\"square\"", "\"generator\":\"teapot\"", "teapot"},
      {"generator refuses a parameter", 1, "\"resolution\":10.0", "\"resolution\":0.0",
       "resolution"},
      {"surface not an object", 1,
       "\"surface\":{\"generator\":\"square\",\"parameters\":{\"resolution\":10.0}}",
       "\"surface\":\"square\"", "surface: must be an object"},
  };
  for (const BadInput& bad : cases) {
    std::vector<std::string> text = good;
    text[bad.line - 1] = replaced(text[bad.line - 1], bad.from, bad.to);
    try {
      parse(joined(text));
      ADD_FAILURE() << bad.name << ": accepted";
    } catch (const RecordingError& e) {
      const std::string message = e.what();
      EXPECT_EQ(e.line(), bad.line) << bad.name << ": " << message;
      EXPECT_NE(message.find("test.jsonl: line " + std::to_string(bad.line) + ": "),
                std::string::npos)
          << bad.name << ": " << message;
      EXPECT_NE(message.find(bad.fragment), std::string::npos) << bad.name << ": " << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << bad.name << ": " << message;
    }
  }
}

TEST(Recording, EmbeddedMeshTheEngineRefusesNamesTheHeader) {
  RecordingHeader header = squareRecordingHeader();
  header.surface = makeSurface("square", {{"resolution", 2}});
  const nlohmann::json good = nlohmann::json::parse(headerLine(header));
  auto expectRefused = [](const nlohmann::json& value, const std::string& fragment) {
    try {
      parse(value.dump() + "\n");
      ADD_FAILURE() << "accepted " << fragment;
    } catch (const RecordingError& e) {
      EXPECT_NE(std::string(e.what()).find("test.jsonl: line 1: " + fragment), std::string::npos)
          << e.what();
      EXPECT_EQ(e.line(), 1u);
    }
  };
  nlohmann::json bad = good;
  bad["surface"]["mesh"]["triangles"][0][2] = 99999;
  expectRefused(bad, "surface.mesh.triangles[0][2]: vertex 99999 does not exist");
  bad = good;
  bad["surface"]["mesh"]["positions"][0][2] = 0.05;  // no longer congruent to its development
  expectRefused(bad, "surface.mesh: ");
}

TEST(Recording, EmptyOrHeaderlessInputIsRefused) {
  EXPECT_THROW(parse(""), RecordingError);
  EXPECT_THROW(parse("\n\n"), RecordingError);
  try {
    parse("{\"t\":0}\n");
    FAIL();
  } catch (const RecordingError& e) {
    EXPECT_NE(std::string(e.what()).find("line 1: not a curvefold recording"), std::string::npos)
        << e.what();
  }
}

// Issue 13, A1: a header whose "format" or "version" is nested a million deep was dumped into the
// message recursively and overflowed the stack. The message quotes an excerpt of at most 60
// characters.
TEST(Recording, DeeplyNestedHeaderValuesAreQuotedByAnExcerpt) {
  const std::string deep = std::string(1'000'000, '[') + std::string(1'000'000, ']');
  for (const auto& [text, fragment] :
       {std::pair{R"({"format":)" + deep + "}\n", std::string("line 1: not a curvefold recording "
                                                              "(format [[[[")},
        std::pair{R"({"format":"curvefold-recording","version":)" + deep + "}\n",
                  std::string("line 1: unsupported version [[[[")}}) {
    try {
      parse(text);
      ADD_FAILURE() << "accepted";
    } catch (const RecordingError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(fragment), std::string::npos) << message.substr(0, 200);
      EXPECT_LT(message.size(), 200u);
      EXPECT_EQ(message.find('\n'), std::string::npos);
    }
  }
}

TEST(Recording, BlankLinesAndAMissingFinalNewlineAreFine) {
  std::string text = recordingText(squareRecordingHeader(), squareFoldFrames());
  EXPECT_EQ(parse(text + "\n\n").frames.size(), squareFoldFrames().size());
  text.pop_back();  // the last frame is whole, just without its newline
  const Recording read = parse(text);
  EXPECT_FALSE(read.truncated);
  EXPECT_EQ(read.frames.size(), squareFoldFrames().size());
}

TEST(Recording, TruncatedFileIsRefusedUnlessAllowed) {
  const std::string whole = recordingText(squareRecordingHeader(), squareFoldFrames());
  const std::size_t frames = squareFoldFrames().size();
  // Cut the last line in the middle, as a killed writer leaves it.
  const std::string cut = whole.substr(0, whole.size() - 30);
  try {
    parse(cut);
    FAIL() << "accepted";
  } catch (const RecordingError& e) {
    EXPECT_NE(
        std::string(e.what()).find("test.jsonl: truncated at line " + std::to_string(frames + 1)),
        std::string::npos)
        << e.what();
    EXPECT_EQ(e.line(), frames + 1);
  }
  const Recording read = parse(cut, {.allowTruncated = true});
  EXPECT_TRUE(read.truncated);
  EXPECT_EQ(read.frames.size(), frames - 1);
  EXPECT_EQ(read.lineCount, frames);
  const Recording full = parse(whole);
  for (std::size_t i = 0; i + 1 < frames; ++i) expectSameFrame(read.frames[i], full.frames[i], i);

  // A bad whole line stays an error even when truncation is allowed.
  EXPECT_THROW(parse(replaced(cut, "\"clutch\":1.0", "\"clutch\":7"), {.allowTruncated = true}),
               RecordingError);
  // Without a whole header there is nothing to replay.
  EXPECT_THROW(parse(whole.substr(0, 40), {.allowTruncated = true}), RecordingError);
}

TEST(Recording, WritersRefuseWhatTheReaderWouldRefuse) {
  InputFrame frame = squareFoldFrames().front();
  InputFrame bad = frame;
  bad.pointHand.position.x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(frameLine(bad), RecordingError);
  bad = frame;
  bad.sheetHand.pose.orientation = glm::dquat(1.0, 0.5, 0.0, 0.0);
  EXPECT_THROW(frameLine(bad), RecordingError);
  bad = frame;
  bad.sheetHand.clutch = 1.0000001;
  EXPECT_THROW(frameLine(bad), RecordingError);
  bad = frame;
  bad.buttons = 1u << 9;
  EXPECT_THROW(frameLine(bad), RecordingError);
  bad = frame;
  bad.time = std::numeric_limits<double>::infinity();
  EXPECT_THROW(frameLine(bad), RecordingError);
  bad = frame;  // more suggestions in a frame than the reader takes
  bad.suggestions.assign(17, SuggestedFold{});
  EXPECT_THROW(frameLine(bad), RecordingError);
  bad.suggestions.resize(16);
  EXPECT_NO_THROW(frameLine(bad));
  bad.suggestions[3].to.z = std::numeric_limits<double>::infinity();
  EXPECT_THROW(frameLine(bad), RecordingError);

  RecordingHeader header = squareRecordingHeader();
  header.source = "kinect";
  EXPECT_THROW(headerLine(header), RecordingError);
  header = squareRecordingHeader();
  header.rate = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(headerLine(header), RecordingError);
  header = squareRecordingHeader();
  header.surface = GeneratedSurface{"teapot", {}};
  EXPECT_THROW(headerLine(header), RecordingError);
}

TEST(Recording, DataFilesAreReadWithTheirPathInErrors) {
  const Recording good = readRecording(kRecordings / "square_one_fold.jsonl");
  EXPECT_EQ(good.frames.size(), squareFoldFrames().size());
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"nan.jsonl", "line 5"},
      {"bad_quaternion.jsonl", "line 7"},
      {"backwards.jsonl", "line 10"},
      {"version3.jsonl", "line 1"},
      {"unknown_source.jsonl", "line 1"},
      {"bad_surface.jsonl", "line 1"},
      {"truncated.jsonl", "truncated at line 14"}};
  for (const auto& [name, fragment] : bad) {
    try {
      readRecording(kRecordings / name);
      ADD_FAILURE() << name << " accepted";
    } catch (const RecordingError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find((kRecordings / name).string() + ": "), std::string::npos) << message;
      EXPECT_NE(message.find(fragment), std::string::npos) << message;
    }
  }
  EXPECT_THROW(readRecording(kRecordings / "missing.jsonl"), RecordingError);
  EXPECT_THROW(readRecording(kRecordings), RecordingError);
}

TEST_F(TempDir, WriteRecordingRoundTrips) {
  Recording recording{squareRecordingHeader(), squareFoldFrames(), false, 0};
  writeRecording(recording, dir_ / "a.jsonl");
  EXPECT_EQ(slurp(dir_ / "a.jsonl"), recordingText(recording.header, recording.frames));
  std::swap(recording.frames[2], recording.frames[3]);
  EXPECT_THROW(writeRecording(recording, dir_ / "b.jsonl"), RecordingError);
  EXPECT_FALSE(fs::exists(dir_ / "b.jsonl"));
}

// --- Recorder ----------------------------------------------------------------------------------

TEST_F(TempDir, KilledRecorderKeepsEverythingUpToTheCommitPoint) {
  const fs::path path = dir_ / "killed.jsonl";
  const std::vector<InputFrame> frames = squareFoldFrames();
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // No destructor runs: _exit is a kill as far as the file is concerned.
    auto* recorder = new Recorder(path, squareRecordingHeader());
    for (std::size_t i = 0; i < 8; ++i) recorder->append(frames[i]);
    recorder->commitPoint();
    for (std::size_t i = 8; i < frames.size(); ++i) recorder->append(frames[i]);
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  const Recording read = readRecording(path);
  EXPECT_FALSE(read.truncated);
  ASSERT_EQ(read.frames.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) expectSameFrame(read.frames[i], frames[i], i);
}

TEST_F(TempDir, RecorderFlushesTheCommittingFrameOfALiveSession) {
  const fs::path path = dir_ / "live.jsonl";
  const RecordingHeader header = squareRecordingHeader();
  FoldSession session(initialSheet(Design{header.surface, {}}));
  InteractionCore core(session, header.sheetFrame, header.handedness);
  Recorder recorder(path, header);
  // Before any frame, the header is already on disk.
  EXPECT_EQ(readRecording(path).frames.size(), 0u);
  std::size_t flushedAt = 0;
  for (const InputFrame& frame : squareFoldFrames()) {
    core.process(frame);
    recorder.append(frame);
    if (isCommitPoint(core.events())) {
      recorder.commitPoint();
      flushedAt = recorder.frameCount();
    }
    // What is on disk always replays: the file never holds half a line.
    EXPECT_EQ(readRecording(path).frames.size(), flushedAt);
  }
  EXPECT_EQ(flushedAt, squareFoldFrames().size());  // the last frame commits
  EXPECT_EQ(replayRecording(readRecording(path)).design.folds.size(), 1u);
}

TEST_F(TempDir, RecorderWritesEverythingOnCloseAndOnDestruction) {
  const std::vector<InputFrame> frames = squareFoldFrames();
  {
    Recorder recorder(dir_ / "closed.jsonl", squareRecordingHeader());
    for (const InputFrame& frame : frames) recorder.append(frame);
    EXPECT_EQ(recorder.pendingFrames(), frames.size());
    recorder.close();
    EXPECT_THROW(recorder.append(frames.back()), FileError);
  }
  {
    Recorder recorder(dir_ / "destroyed.jsonl", squareRecordingHeader());
    for (const InputFrame& frame : frames) recorder.append(frame);
  }
  const std::string expected = recordingText(squareRecordingHeader(), frames);
  EXPECT_EQ(slurp(dir_ / "closed.jsonl"), expected);
  EXPECT_EQ(slurp(dir_ / "destroyed.jsonl"), expected);
}

TEST_F(TempDir, RecorderRefusesToOverwriteUnlessAsked) {
  const fs::path path = dir_ / "existing.jsonl";
  { std::ofstream(path) << "someone's recording\n"; }
  try {
    Recorder recorder(path, squareRecordingHeader());
    FAIL() << "overwrote";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(path), "someone's recording\n");
  {
    Recorder recorder(path, squareRecordingHeader(), {.overwrite = true});
    recorder.append(squareFoldFrames().front());
  }
  EXPECT_EQ(readRecording(path).frames.size(), 1u);
  try {
    Recorder recorder(dir_ / "no" / "such" / "dir.jsonl", squareRecordingHeader());
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("no/such/dir.jsonl"), std::string::npos) << e.what();
  }
  // A bad header leaves no file.
  RecordingHeader bad = squareRecordingHeader();
  bad.source = "kinect";
  EXPECT_THROW(Recorder(dir_ / "bad.jsonl", bad), RecordingError);
  EXPECT_FALSE(fs::exists(dir_ / "bad.jsonl"));
}

TEST_F(TempDir, RecorderRefusesABadFrameAndKeepsGoing) {
  const std::vector<InputFrame> frames = squareFoldFrames();
  Recorder recorder(dir_ / "r.jsonl", squareRecordingHeader());
  recorder.append(frames[0]);
  recorder.append(frames[1]);
  InputFrame bad = frames[2];
  bad.sheetHand.clutch = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(recorder.append(bad), RecordingError);
  EXPECT_THROW(recorder.append(frames[0]), RecordingError);  // back in time
  recorder.append(frames[2]);
  recorder.close();
  EXPECT_EQ(readRecording(dir_ / "r.jsonl").frames.size(), 3u);
}

// --- Player ------------------------------------------------------------------------------------

Recording squareRecording(std::vector<InputFrame> frames = squareFoldFrames()) {
  return Recording{squareRecordingHeader(), std::move(frames), false, 0};
}

TEST(Player, HandBuiltDragMakesOneFoldBitIdenticalOnEveryReplay) {
  const Recording recording = squareRecording();
  std::size_t calls = 0;
  ReplayOptions options;
  options.onFrame = [&](const ReplayProgress& progress) {
    ++calls;
    EXPECT_EQ(progress.frame, calls);
    EXPECT_EQ(progress.frameCount, recording.frames.size());
  };
  const ReplayResult first = replayRecording(recording, options);
  EXPECT_EQ(calls, recording.frames.size());
  ASSERT_EQ(first.design.folds.size(), 1u);
  EXPECT_EQ(first.frameCount, recording.frames.size());
  EXPECT_DOUBLE_EQ(first.duration, 1.2);
  EXPECT_FALSE(first.endedWhileDragging);
  // The grabbed edge point went to (0.05, 0, 0.05): the plane bisects the drag.
  const ReflectionPlane& plane = first.design.folds[0].plane;
  EXPECT_NEAR(plane.normal.x, -std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(plane.normal.z, std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(plane.point.x, 0.075, 1e-9);

  ASSERT_EQ(first.log.size(), 1u);
  const FoldLogEntry& entry = first.log[0];
  EXPECT_EQ(entry.kind, FoldLogKind::Commit);
  EXPECT_DOUBLE_EQ(entry.time, 1.2);
  EXPECT_EQ(entry.fold, 1u);
  EXPECT_EQ(entry.foldCount, 1u);
  EXPECT_EQ(entry.plane.normal, plane.normal);
  EXPECT_EQ(entry.trianglesBefore, makeSurface("square", {{"resolution", 10}}).triangleCount());
  EXPECT_EQ(entry.trianglesAfter, first.sheet.triangleCount());
  EXPECT_GT(entry.trianglesAfter, entry.trianglesBefore);
  EXPECT_LT(entry.maxEdgeLengthError, 1e-12);

  const ReplayResult second = replayRecording(recording);
  EXPECT_TRUE(identical(first.sheet, second.sheet));
  // The design rebuilds the very sheet the session made.
  EXPECT_TRUE(identical(first.sheet, buildSheet(first.design)));
  // And so does a replay of the recording written to text and read back.
  const Recording reread = parse(recordingText(recording.header, recording.frames));
  EXPECT_TRUE(identical(first.sheet, replayRecording(reread).sheet));
}

TEST(Player, UndoAndRedoAreLogged) {
  std::vector<InputFrame> frames = squareFoldFrames();
  InputFrame last = frames.back();
  auto press = [&](Button button) {
    last.time += 0.1;
    last.buttons = static_cast<std::uint32_t>(button);
    frames.push_back(last);
    last.time += 0.1;
    last.buttons = 0;
    frames.push_back(last);
  };
  press(Button::Undo);
  press(Button::Redo);
  press(Button::Undo);
  const ReplayResult result = replayRecording(squareRecording(frames));
  ASSERT_EQ(result.log.size(), 4u);
  EXPECT_EQ(result.log[1].kind, FoldLogKind::Undo);
  EXPECT_EQ(result.log[1].fold, 1u);
  EXPECT_EQ(result.log[1].foldCount, 0u);
  EXPECT_EQ(result.log[1].trianglesBefore, result.log[0].trianglesAfter);
  EXPECT_EQ(result.log[1].trianglesAfter, result.log[0].trianglesBefore);
  EXPECT_EQ(result.log[1].plane.normal, result.log[0].plane.normal);
  EXPECT_EQ(result.log[2].kind, FoldLogKind::Redo);
  EXPECT_EQ(result.log[2].foldCount, 1u);
  EXPECT_EQ(result.log[2].trianglesAfter, result.log[0].trianglesAfter);
  EXPECT_EQ(result.log[3].kind, FoldLogKind::Undo);
  // The final design holds the folds in the fixed sheet, not the undone ones.
  EXPECT_TRUE(result.design.folds.empty());
  EXPECT_EQ(result.sheet.triangleCount(), result.log[0].trianglesBefore);

  // Undo and redo pressed in one frame: two entries, the sheet in between rebuilt.
  std::vector<InputFrame> together = squareFoldFrames();
  last = together.back();
  last.time += 0.1;
  last.buttons =
      static_cast<std::uint32_t>(Button::Undo) | static_cast<std::uint32_t>(Button::Redo);
  together.push_back(last);
  const ReplayResult both = replayRecording(squareRecording(together));
  ASSERT_EQ(both.log.size(), 3u);
  EXPECT_EQ(both.log[1].trianglesAfter, both.log[0].trianglesBefore);
  EXPECT_EQ(both.log[2].trianglesAfter, both.log[0].trianglesAfter);
  EXPECT_EQ(both.design.folds.size(), 1u);
}

TEST(Player, ARecordingThatStopsInsideADragKeepsOnlyCommittedFolds) {
  std::vector<InputFrame> frames = squareFoldFrames();
  frames.pop_back();  // never released
  const ReplayResult result = replayRecording(squareRecording(frames));
  EXPECT_TRUE(result.endedWhileDragging);
  EXPECT_TRUE(result.design.folds.empty());
  EXPECT_TRUE(identical(result.sheet, makeSurface("square", {{"resolution", 10}})));
}

TEST(Player, StepsFrameByFrame) {
  const Recording recording = squareRecording();
  Player player(recording);
  std::size_t steps = 0;
  while (!player.done()) {
    player.step();
    ++steps;
    if (steps == 8) {
      EXPECT_EQ(player.core().state(), InteractionState::Dragging);
    }
  }
  EXPECT_EQ(steps, recording.frames.size());
  EXPECT_EQ(player.design().folds.size(), 1u);
}

TEST(Player, RealTimeTakesTheRecordedTime) {
  std::vector<InputFrame> frames = squareFoldFrames();
  for (InputFrame& frame : frames) frame.time = 100.0 + frame.time / 4.0;  // 0.3 s, late start
  ReplayOptions options;
  options.realtime = true;
  const auto start = std::chrono::steady_clock::now();
  const ReplayResult result = replayRecording(squareRecording(frames), options);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // At least the recorded 0.3 s (a real-time replay never runs ahead of its frames); no upper
  // bound: a busy machine may take longer, and speed is a benchmark's business.
  EXPECT_GE(elapsed, 0.3);
  EXPECT_EQ(result.design.folds.size(), 1u);
}

TEST(Player, FoldLogLineIsJson) {
  FoldLogEntry entry;
  entry.kind = FoldLogKind::Redo;
  entry.time = 0.25;
  entry.fold = 3;
  entry.foldCount = 3;
  entry.plane = {{0.5, 0.0, 0.0}, {1.0, 0.0, 0.0}};
  entry.trianglesBefore = 10;
  entry.trianglesAfter = 12;
  entry.maxEdgeLengthError = 1e-17;
  EXPECT_EQ(foldLogLine(entry),
            R"({"event":"redo","t":0.25,"fold":3,"folds":3,"plane":{"point":[0.5,0.0,0.0],)"
            R"("normal":[1.0,0.0,0.0]},"triangles_before":10,"triangles_after":12,)"
            R"("max_edge_length_error":1e-17,"self_intersections":0})");
}

// Issue 17, 2: a recording keeps its design's symmetry, and its replay folds the images too (one
// drag on a 6-fold cylinder gives six folds in one group, which undo and redo take whole, and the
// fold log counts); a symmetry the surface lacks is refused by name.
TEST(Recording, ASymmetricSessionReplaysWithItsImages) {
  Recording recording;
  recording.header.source = "desktop";
  recording.header.surface = GeneratedSurface{"cylinder", {}};
  recording.header.sheetFrame = Pose{};  // world = sheet
  recording.header.symmetry = "rotational:6:y";
  const glm::dvec3 grab(0.045, 0.105, 0.0), to(0.036, 0.1, 0.0);
  auto frame = [&](double t, const glm::dvec3& at, double select) {
    InputFrame f;
    f.time = t;
    f.sheetHand.tracked = true;
    f.pointHand.position = at;
    f.pointHand.tracked = true;
    f.pointHand.select = select;
    recording.frames.push_back(f);
  };
  frame(0.0, grab, 0.0);
  frame(0.1, grab, 1.0);
  for (int i = 1; i <= 5; ++i) frame(0.1 + 0.1 * i, grab + (to - grab) * (i / 5.0), 1.0);
  frame(0.7, to, 0.0);
  // Undo and redo take the group whole, and the log says so.
  for (Button button : {Button::Undo, Button::Redo}) {
    InputFrame f = recording.frames.back();
    f.time += 0.1;
    f.buttons = static_cast<std::uint32_t>(button);
    recording.frames.push_back(f);
    f.time += 0.1;
    f.buttons = 0;
    recording.frames.push_back(f);
  }
  std::stringstream text;
  text << headerLine(recording.header) << "\n";
  std::istringstream in(text.str());
  EXPECT_EQ(parseRecording(in, "s.jsonl").header.symmetry, "rotational:6:y");

  Player player(recording);
  while (!player.done()) player.step();
  const Design design = player.design();
  ASSERT_EQ(design.folds.size(), 6u);
  for (const FoldRecord& fold : design.folds) EXPECT_EQ(fold.group, 1u);
  EXPECT_EQ(design.symmetry, "rotational:6:y");  // the replay's design keeps it
  const std::vector<FoldLogEntry>& log = player.log();
  ASSERT_EQ(log.size(), 3u);
  const std::size_t counts[] = {6, 0, 6};
  for (std::size_t i = 0; i < 3; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(log[i].fold, 1u);
    EXPECT_EQ(log[i].foldCount, counts[i]);
    EXPECT_EQ(log[i].images, 5u);
    EXPECT_EQ(log[i].skippedImages, 0u);
  }
  EXPECT_NE(foldLogLine(log[0]).find(R"("images":5,"skipped_images":0)"), std::string::npos);

  RecordingHeader wrong = recording.header;
  wrong.symmetry = "rotational:5";
  try {
    headerLine(wrong);
    ADD_FAILURE() << "a symmetry the cylinder lacks was written";
  } catch (const RecordingError& e) {
    EXPECT_NE(std::string(e.what()).find("rotational:5"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace curvefold

namespace curvefold {
namespace {

using namespace curvefold::testing;

// A half cylinder (cylinderHeader) simulated from flat: the fold amount ramps to 100%, a pull
// takes vertex `pulled` toward a point beside the sheet, and the amount goes down to 40%.
// `withPull`: the pull frames carry it (else the same frames without).
RecordingHeader cylinderHeader() {
  RecordingHeader header = squareRecordingHeader();
  header.surface = GeneratedSurface{"cylinder", {{"resolution", 8}}};
  return header;
}

std::vector<InputFrame> simulatedFrames(bool withPull, std::uint32_t pulled = 0) {
  std::vector<InputFrame> frames;
  const std::uint32_t steps = 60;
  double time = 0.0;
  auto add = [&](double percent, std::optional<SimulationPull> pull) {
    InputFrame frame = handFrame(time, {0.0, -0.2, 0.0}, 0.0, {0.1, 0.1, 0.1}, 0.0);
    time += 1.0 / 60.0;
    frame.simulation = SimulationInput{percent, steps, pull};
    frames.push_back(frame);
  };
  for (int i = 0; i <= 10; ++i) add(100.0 * i / 10.0, std::nullopt);
  for (int i = 0; i < 10; ++i)
    add(100.0,
        withPull ? std::optional(SimulationPull{pulled, {0.0, 0.05, 0.02 * i}}) : std::nullopt);
  for (int i = 0; i < 5; ++i) add(40.0, std::nullopt);
  return frames;
}

bool sameArrays(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::dvec3)) == 0;
}

// Issue 39, 4: the simulation is input like the hands. What a live session showed, written to a
// file and read back, replays to the very same vertex arrays, twice, on the desktop path (the
// plain player, which knows no panel: the frames carry the fold amount, steps and pull).
TEST_F(TempDir, ARecordedSimulationReplaysBitForBit) {
  Recording recording{cylinderHeader(), simulatedFrames(true)};
  // Live: the frames straight into a player, as a session feeds its core.
  Player live(recording);
  while (!live.done()) live.step();
  ASSERT_NE(live.core().simulation(), nullptr);
  const std::vector<glm::dvec3> shown = live.core().simulation()->sheet().positions;

  writeRecording(recording, dir_ / "simulated.jsonl");
  EXPECT_NE(slurp(dir_ / "simulated.jsonl").find("\"pull\":{\"vertex\":0"), std::string::npos);
  const Recording read = readRecording(dir_ / "simulated.jsonl");
  const ReplayResult first = replayRecording(read);
  const ReplayResult second = replayRecording(read);
  ASSERT_EQ(first.simulated.size(), shown.size());
  EXPECT_TRUE(sameArrays(first.simulated, shown));
  EXPECT_TRUE(sameArrays(second.simulated, first.simulated));

  // The pull is part of it: the same frames without it end elsewhere.
  const ReplayResult unpulled = replayRecording({cylinderHeader(), simulatedFrames(false)});
  ASSERT_EQ(unpulled.simulated.size(), shown.size());
  EXPECT_FALSE(sameArrays(unpulled.simulated, shown));
}

// A run the GPU solver stepped (the panel's "GPU", issue 39, 4) says so in its recording, which
// reads back as written; a replay refuses it in one line (float on one device: not bit for bit
// elsewhere), and a core with no GPU solver (a replay's) simulates nothing and says why.
TEST_F(TempDir, AGpuSimulationIsRecordedAndItsReplayRefused) {
  std::vector<InputFrame> frames = simulatedFrames(false);
  frames[3].simulation->solver = LiveSolverKind::Gpu;
  writeRecording({cylinderHeader(), frames}, dir_ / "gpu.jsonl");
  const std::string text = slurp(dir_ / "gpu.jsonl");
  EXPECT_NE(text.find("\"solver\":\"gpu\""), std::string::npos);
  EXPECT_EQ(text.find("\"solver\":\"gpu\""), text.rfind("\"solver\":\"gpu\""));  // one frame
  const Recording read = readRecording(dir_ / "gpu.jsonl");
  ASSERT_EQ(read.frames.size(), frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i)
    EXPECT_EQ(read.frames[i].simulation, frames[i].simulation) << "frame " << i;
  try {
    Player player(read);
    ADD_FAILURE() << "a GPU run was replayed";
  } catch (const RecordingError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("GPU"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  // The CPU's frames alone replay as ever.
  EXPECT_NO_THROW(Player(Recording{cylinderHeader(), simulatedFrames(false)}));

  FoldSession session(makeSurface("cylinder", {{"resolution", 8}}));
  InteractionCore core(session, Pose{});
  InputFrame frame = frames[3];
  core.process(frame);
  EXPECT_EQ(core.simulation(), nullptr);
  EXPECT_NE(core.simulationProblem().find("GPU"), std::string::npos) << core.simulationProblem();
}

// The live window steps on a worker (LiveSimulation's onWorker): each frame shows the state after
// the previous frame's input, and that state is the very one stepping in turn shows, bit for bit
// (pulls included: the pull's target goes into the model's frame by the shown state's placement).
TEST(LiveSimulation, OnAWorkerShowsTheSameStatesOneFrameLater) {
  const Sheet cylinder = makeSurface("cylinder", {{"resolution", 8}});
  LiveSimulation inTurn(cylinder), onWorker(cylinder, /*onWorker=*/true);
  std::vector<std::vector<glm::dvec3>> shownInTurn{inTurn.sheet().positions};
  std::vector<std::size_t> stepsInTurn{inTurn.steps()};
  const std::vector<InputFrame> frames = simulatedFrames(true);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    inTurn.advance(*frames[i].simulation);
    onWorker.advance(*frames[i].simulation);
    // Frame i on the worker shows what frame i - 1 in turn showed.
    EXPECT_TRUE(sameArrays(onWorker.sheet().positions, shownInTurn[i])) << "frame " << i;
    EXPECT_EQ(onWorker.steps(), stepsInTurn[i]) << "frame " << i;
    shownInTurn.push_back(inTurn.sheet().positions);
    stepsInTurn.push_back(inTurn.steps());
  }
  onWorker.finish();
  EXPECT_TRUE(sameArrays(onWorker.sheet().positions, inTurn.sheet().positions));
  EXPECT_TRUE(sameArrays(onWorker.state().positions, inTurn.state().positions));
  EXPECT_EQ(onWorker.vertexStrain(), inTurn.vertexStrain());
  EXPECT_GT(inTurn.steps(), 0u);
}

// Simulating never changes the design: leaving it gives back the design bit for bit, and the
// simulation folds from flat (0%) to the design (100%) and back.
TEST(LiveSimulation, FoldsFromFlatToTheDesignAndLeavesTheDesignUntouched) {
  // A half cylinder: design mode drives every edge to its bending, so 100% is the cylinder (a
  // reflection fold's sliver triangles would set a step far too short to reach it in a test).
  const Sheet cylinder = makeSurface("cylinder", {{"resolution", 8}});
  // A session over it and its core, fed frames as a host's loop feeds them.
  FoldSession session(cylinder);
  InteractionCore core(session, Pose{});
  const Sheet& design = session.fixed();
  double size = 0.0;
  for (const glm::dvec3& p : design.positions)
    size = std::max(size, glm::distance(p, design.positions[0]));
  auto distanceToDesign = [&] {
    double largest = 0.0;
    for (std::size_t v = 0; v < design.vertexCount(); ++v)
      largest = std::max(
          largest, glm::distance(core.simulation()->sheet().positions[v], design.positions[v]));
    return largest;
  };
  // The spread of the model's z (its flat state lies in z = 0).
  auto thickness = [&] {
    double low = 1e300, high = -1e300;
    for (const glm::dvec3& p : core.simulation()->state().positions) {
      low = std::min(low, p.z);
      high = std::max(high, p.z);
    }
    return high - low;
  };
  InputFrame frame;
  auto run = [&](double percent, int count) {
    for (int i = 0; i < count; ++i) {
      frame.time += 1.0 / 60.0;
      frame.simulation = liveSimulationInput(percent, design);
      core.process(frame);
    }
  };
  const int settleFrames = 2000 / int(liveStepsPerFrame(design.vertexCount()));
  run(0.0, 1);
  ASSERT_NE(core.simulation(), nullptr);
  EXPECT_EQ(thickness(), 0.0);  // it starts flat, the development itself
  EXPECT_GT(distanceToDesign(), 0.05 * size);
  run(100.0, settleFrames);
  EXPECT_LT(distanceToDesign(), 1e-4 * size);
  run(0.0, settleFrames);
  EXPECT_LT(thickness(), 0.01 * size);
  // Leaving the simulation: the design as it was, bit for bit, and no simulation.
  frame.simulation.reset();
  frame.time += 1.0 / 60.0;
  core.process(frame);
  EXPECT_EQ(core.simulation(), nullptr);
  EXPECT_TRUE(identical(session.fixed(), cylinder));
}

// crown_vessel, a curved fold with sliver triangles: the bundled design the live slider finds
// hardest.
Sheet crownVessel() {
  return replayRecording(readRecording(std::string(CURVEFOLD_SOURCE_DIR) +
                                       "/examples/recordings/crown_vessel.jsonl"))
      .sheet;
}

double diagonalOf(const Sheet& sheet) {
  glm::dvec3 low(1e300), high(-1e300);
  for (const glm::dvec3& p : sheet.positions) low = glm::min(low, p), high = glm::max(high, p);
  return glm::distance(low, high);
}

// A reflection design driven live from flat to 100%, as the window's slider drives it (issue 39,
// the check "at 100% in design mode every bundled design comes within 0.5% of its diagonal"):
// within the frame the slider reaches 100% the shown sheet is the design, every vertex within
// 0.5% of the diagonal of its own place and every edge within 0.1% of its length, and it stays
// there while the slider is held. crown_vessel: a curved fold whose sliver triangles set a step
// so short that the dynamic steps alone stayed 60% of the diagonal off after 600 frames.
TEST(LiveSimulation, ReachesABundledDesignOnTheFrameTheSliderReachesFull) {
  const Sheet design = crownVessel();
  const double diagonal = diagonalOf(design);
  LiveSimulation live(design);
  auto offDesign = [&] {
    double largest = 0.0;
    for (std::size_t v = 0; v < design.vertexCount(); ++v)
      largest = std::max(largest, glm::distance(live.sheet().positions[v], design.positions[v]));
    return largest / diagonal;
  };
  const int rampFrames = testing::kSanitized ? 5 : 30;  // the slider from 0 to 100% over these
  for (int frame = 1; frame < rampFrames; ++frame) {
    live.advance(liveSimulationInput(100.0 * frame / rampFrames, design));
    if (frame == rampFrames / 2) {
      EXPECT_GT(offDesign(), 0.05);  // not there before the slider is
    }
  }
  for (int frame = 0; frame < (testing::kSanitized ? 3 : 10); ++frame) {
    live.advance(liveSimulationInput(100.0, design));
    EXPECT_LE(offDesign(), 0.005) << "frame " << rampFrames + frame;
  }
  double worstStrain = 0.0;
  for (double strain : edgeStrain(live.model(), live.state().positions))
    worstStrain = std::max(worstStrain, std::abs(strain));
  EXPECT_LE(worstStrain, 1e-3);
}

// Issue 39, 4: "the sheet folds from flat to the design and back as it moves". A curved design
// driven by the slider over a few frames: on every frame of the ramp the creases are within a
// few degrees (mean) of their targets at the slider's amount, the sheet stays nearly isometric
// (median edge strain), and no frame moves any vertex by more than a small share of the
// diagonal, the frame the slider comes to rest at 100% included. crown_vessel: the dynamic steps
// alone left its creases 20 to 40 degrees behind and the sheet then jumped 80% of its diagonal
// to the design on that frame.
TEST(LiveSimulation, FollowsTheSliderOnACurvedDesignWithoutAJump) {
  const Sheet design = crownVessel();
  const double diagonal = diagonalOf(design);
  LiveSimulation live(design);
  const BarHingeModel& model = live.model();
  const int rampFrames = testing::kSanitized ? 8 : 20;
  std::vector<glm::dvec3> before = live.sheet().positions;
  for (int frame = 1; frame <= rampFrames + 2; ++frame) {
    const double amount = std::min(1.0, double(frame) / rampFrames);
    live.advance(liveSimulationInput(100.0 * amount, design));
    double move = 0.0;
    for (std::size_t v = 0; v < before.size(); ++v)
      move = std::max(move, glm::distance(before[v], live.sheet().positions[v]));
    before = live.sheet().positions;
    // A ramp of n frames moves the sheet about a 1/n share of its diagonal a frame.
    EXPECT_LE(move, 3.0 * diagonal / rampFrames) << "frame " << frame;
    if (frame >= rampFrames) continue;
    const std::vector<double> angles =
        hingeAngles(model, live.state().positions, live.state().hingeAngles);
    double lag = 0.0;
    std::size_t creases = 0;
    for (std::size_t j = 0; j < model.hinges.size(); ++j)
      if (model.hingeCrease[j]) lag += std::abs(angles[j] - model.target(j, amount)), ++creases;
    ASSERT_GT(creases, 0u);
    EXPECT_LE(lag / double(creases) * 180.0 / M_PI, 5.0) << "frame " << frame;
    std::vector<double> strain = edgeStrain(model, live.state().positions);
    for (double& e : strain) e = std::abs(e);
    std::nth_element(strain.begin(), strain.begin() + strain.size() / 2, strain.end());
    EXPECT_LE(strain[strain.size() / 2], 0.01) << "frame " << frame;
  }
  EXPECT_GT(live.pathFrames(), 0u);
}

// The fold path keeps a cone's edges near their length while the slider moves: the bundled cone
// (a slit cone, curved creases) driven from flat to 100%, the median edge strain of every ramp
// frame at most 0.4% (largest edge 8%). With two local-global relaxations a frame (kPathRelaxations
// before) this ramp strained it 0.75% (8.8%); six take it to 0.29% (7.0%), docs/performance.md.
TEST(LiveSimulation, TheSliderKeepsAConesEdgesNearTheirLength) {
  const Sheet design = replayRecording(readRecording(std::string(CURVEFOLD_SOURCE_DIR) +
                                                     "/examples/recordings/cone.jsonl"))
                           .sheet;
  LiveSimulation live(design);
  const int rampFrames = 30;  // under a sanitizer too: a shorter ramp strains more a frame
  double worstMedian = 0.0, worst = 0.0;
  for (int frame = 1; frame < rampFrames; ++frame) {
    live.advance(liveSimulationInput(100.0 * frame / rampFrames, design));
    std::vector<double> strain = edgeStrain(live.model(), live.state().positions);
    for (double& e : strain) e = std::abs(e);
    std::sort(strain.begin(), strain.end());
    worstMedian = std::max(worstMedian, strain[strain.size() / 2]);
    worst = std::max(worst, strain.back());
  }
  EXPECT_GT(live.pathFrames(), 0u);
  EXPECT_LE(worstMedian, 0.004);
  EXPECT_LE(worst, 0.08);
}

}  // namespace
}  // namespace curvefold
