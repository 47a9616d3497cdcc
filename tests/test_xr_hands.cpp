// Bare hands through `curvefold xr` (issue 16): the simulated runtime serves XR_EXT_hand_tracking
// hands made from each recorded frame, with 2 mm of jitter on every joint, and the session folds
// what `curvefold replay` folds (same count, planes within 1 mm); a hand session records as
// "hands" and replays exactly; controllers put down and picked up mid-session keep folding, and a
// fold under way survives the handover;
// `--hands` without hand tracking is one line.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "sanitizer_support.hpp"
#include "xr_test_support.hpp"

namespace curvefold {
namespace {

using namespace curvefold::testing;
using nlohmann::json;

struct PlaneDifference {
  double offset = 0.0;  // metres: how far each plane passes from the other's point
  double degrees = 0.0;
};

PlaneDifference planeDifference(const json& a, const json& b) {
  const auto vec = [](const json& v) {
    return glm::dvec3(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  };
  const glm::dvec3 pa = vec(a["plane"]["point"]), na = vec(a["plane"]["normal"]);
  const glm::dvec3 pb = vec(b["plane"]["point"]), nb = vec(b["plane"]["normal"]);
  PlaneDifference d;
  d.offset = std::max(std::abs(glm::dot(pb - pa, na)), std::abs(glm::dot(pa - pb, nb)));
  d.degrees = glm::degrees(std::acos(std::min(1.0, glm::dot(na, nb))));
  return d;
}

class XrHands : public XrApp {
 protected:
  // One bound for every build (issue 40, 4). A millimetre of jitter left at either end of a 4 cm
  // drag turns its plane by about 1.5 degrees; a wrong grab gives centimetres and tens of degrees.
  // With 2 mm of jitter the showcase folds up to 4.11 mm and 4.35 degrees off its replays
  // (disk_chevrons, star_lily), in GCC's and clang's builds alike, sanitized or not. They once
  // differed (GCC 0.89 mm, clang 4.11 mm) because the jitter was drawn as
  // dvec3(unit(random), unit(random), unit(random)), whose arguments GCC evaluated right to left
  // and clang left to right: the two builds jittered the hands differently, and GCC's draw
  // happened to land within 1 mm. Drawn one component per statement, both take clang's draw.
  static constexpr double kMaxOffset = 0.005;
  static constexpr double kMaxDegrees = 5.0;
  // The environment of the command: hands, no controllers, 2 mm of jitter.
  std::string hands(const std::string& input, const std::string& more = "") const {
    return simulated(input, "CURVEFOLD_SIM_HANDS=1 CURVEFOLD_SIM_JITTER=2 " + more);
  }
  // Expects the same folds within the bounds, and returns the worst difference.
  PlaneDifference expectSameFolds(const json& folds, const json& reference,
                                  const std::string& what) {
    PlaneDifference worst;
    EXPECT_EQ(folds.size(), reference.size()) << what;
    if (folds.size() != reference.size()) return worst;
    for (std::size_t i = 0; i < folds.size(); ++i) {
      const PlaneDifference d = planeDifference(folds[i], reference[i]);
      EXPECT_LE(d.offset, kMaxOffset) << what << " fold " << i;
      EXPECT_LE(d.degrees, kMaxDegrees) << what << " fold " << i;
      worst.offset = std::max(worst.offset, d.offset);
      worst.degrees = std::max(worst.degrees, d.degrees);
    }
    return worst;
  }
  int servesEveryRecordingAsHands(const std::string& folder);
};

// Serves every recording in `folder` as bare hands with 2 mm of jitter, run with
// `curvefold xr R --autosave A` (drawn, not headless), and expects the folds its replay makes;
// returns how many recordings the folder holds.
int XrHands::servesEveryRecordingAsHands(const std::string& folder) {
  PlaneDifference worst;
  std::vector<fs::path> inputs;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.path().extension() == ".jsonl") inputs.push_back(entry.path());
  std::sort(inputs.begin(), inputs.end());
  int recordings = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    ++recordings;
    // Each drawn session takes 10-20 s under the sanitizers: there every third recording is served
    // (the plain build serves them all), which keeps CI within its time.
    if (kSanitized && i % 3 != 0) continue;
    const std::string input = inputs[i].string();
    const std::string stem = inputs[i].stem().string();
    SCOPED_TRACE(stem);
    const std::string autosave = path(stem + ".A.json").string();
    const CommandResult result = run("xr " + input + " --autosave " + autosave, hands(input));
    EXPECT_EQ(result.exitCode, 0) << result.err;
    if (result.exitCode != 0) continue;
    EXPECT_NE(result.out.find("interaction profiles: left none, right none"), std::string::npos)
        << result.out;
    // Every input frame came from bare hands.
    const std::size_t frames = std::stoul(result.out.substr(result.out.find("xr: ", 10) + 4));
    EXPECT_NE(result.out.find("bare hands drove " + std::to_string(frames) + " of " +
                              std::to_string(frames)),
              std::string::npos)
        << result.out;
    const json reference = replayed(input, "reference_" + stem);
    // A studio recording makes a new sheet from the panel (pinching its items): the design is
    // that sheet's, saved under its own name.
    const std::string surface = reference["surface"].value("generator", std::string());
    const fs::path design =
        fs::exists(path(surface + ".autosave.curvefold.json")) && stem == "xr_studio"
            ? path(surface + ".autosave.curvefold.json")
            : fs::path(autosave);
    const json made = json::parse(slurp(design));
    EXPECT_EQ(made["surface"], reference["surface"]);
    const PlaneDifference d = expectSameFolds(made["folds"], reference["folds"], stem);
    worst.offset = std::max(worst.offset, d.offset);
    worst.degrees = std::max(worst.degrees, d.degrees);
  }
  RecordProperty("worst_plane_offset_mm", std::to_string(1000.0 * worst.offset));
  RecordProperty("worst_plane_degrees", std::to_string(worst.degrees));
  return recordings;
}

// The acceptance: every example recording, served as hands, folds what its replay folds.
TEST_F(XrHands, EveryExampleRecordingServedAsHandsFoldsLikeItsReplay) {
  EXPECT_EQ(servesEveryRecordingAsHands(kExamples), 9);
}

// Issue 28, 3: and so does every showcase design, its grabs planned for hands.
TEST_F(XrHands, EveryShowcaseRecordingServedAsHandsFoldsLikeItsReplay) {
  EXPECT_EQ(servesEveryRecordingAsHands(kExamples + "../showcase/recordings/"), 9);
}

// A hand session records the frames HandInput made, under source "hands", and they replay to the
// very design; the runtime served joints, not controllers.
TEST_F(XrHands, AHandSessionRecordsAsHandsAndReplaysExactly) {
  const std::string input = kExamples + "half_cylinder.jsonl";  // folds, a turn, undo and redo
  const CommandResult result =
      run("xr " + input + " --headless --record hands.jsonl --autosave hands.json", hands(input));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::string recorded = slurp(path("hands.jsonl"));
  EXPECT_NE(recorded.substr(0, recorded.find('\n')).find("\"source\":\"hands\""),
            std::string::npos);
  const json design = load("hands.json");
  EXPECT_EQ(replayed(path("hands.jsonl").string(), "again")["folds"], design["folds"]);
  const std::string log = slurp(path("sim.log"));
  EXPECT_NE(log.find("hand tracker left"), std::string::npos);
  EXPECT_NE(log.find("hand tracker right"), std::string::npos);
  EXPECT_EQ(log.find("profile /interaction_profiles"), std::string::npos) << "controllers served";
}

// The controllers put down (hands from frame 10) and picked up again (frame 210), at rest: every
// fold is made as with either alone.
TEST_F(XrHands, ControllersPutDownAndPickedUpAgainKeepFolding) {
  const std::string input = kExamples + "half_cylinder.jsonl";  // folds, a turn, undo and redo
  const CommandResult result =
      run("xr " + input + " --headless --autosave switched.json",
          simulated(input, "CURVEFOLD_SIM_JITTER=2 CURVEFOLD_SIM_EVENTS=10:hands,210:controllers"));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_NE(result.out.find("bare hands drove 200 of 327"), std::string::npos) << result.out;
  // The runtime dropped the controllers' profile while hands were served, and gave it back.
  const std::string log = slurp(path("sim.log"));
  EXPECT_NE(log.find("event hands\nprofile \n"), std::string::npos);
  EXPECT_NE(log.find("event controllers\nprofile /interaction_profiles/"), std::string::npos);
  expectSameFolds(load("switched.json")["folds"], replayed(input, "reference")["folds"],
                  "switched");
}

// Put down in the middle of a fold (frame 110, the sheet turning under the other hand), the fold
// goes on in the hand: the frame of the handover reads as lost and both roles re-anchor, so the
// fold is neither dropped nor committed early; it misses only that frame's motion (about 1.5 mm
// there), since a controller and a hand are never tracked at once to measure their offset.
TEST_F(XrHands, ControllersPutDownMidFoldHandTheFoldOver) {
  const std::string input = kExamples + "half_cylinder.jsonl";
  const CommandResult result =
      run("xr " + input + " --headless --autosave handed.json",
          simulated(input, "CURVEFOLD_SIM_JITTER=2 CURVEFOLD_SIM_EVENTS=110:hands"));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const json folds = load("handed.json")["folds"],
             reference = replayed(input, "reference")["folds"];
  ASSERT_EQ(folds.size(), reference.size());
  for (std::size_t i = 0; i < folds.size(); ++i)
    EXPECT_LE(planeDifference(folds[i], reference[i]).offset, 0.003) << "fold " << i;
}

// `--hands` folds with hands only: served controllers are ignored (nothing folds), and a runtime
// without XR_EXT_hand_tracking is one line naming it, before any file is made.
TEST_F(XrHands, HandsFlagUsesHandsOnlyAndNeedsHandTracking) {
  const std::string input = kExamples + "cone.jsonl";
  const CommandResult withHands =
      run("xr " + input + " --hands --headless --autosave h.json", hands(input));
  ASSERT_EQ(withHands.exitCode, 0) << withHands.err;
  expectSameFolds(load("h.json")["folds"], replayed(input, "reference")["folds"], "--hands");

  const CommandResult controllers =
      run("xr " + input + " --hands --headless --autosave c.json", simulated(input));
  ASSERT_EQ(controllers.exitCode, 0) << controllers.err;
  EXPECT_EQ(load("c.json")["folds"].size(), 0u);

  const CommandResult none =
      run("xr " + input + " --hands --headless --record r.jsonl --autosave n.json",
          simulated(input, "CURVEFOLD_SIM_NO_HAND_TRACKING=1"));
  EXPECT_EQ(none.exitCode, 1);
  EXPECT_EQ(std::count(none.err.begin(), none.err.end(), '\n'), 1) << none.err;
  EXPECT_NE(none.err.find("XR_EXT_hand_tracking"), std::string::npos) << none.err;
  // The XR program says what is missing; `curvefold xr` names the option that asked for it.
  EXPECT_NE(none.err.find("lacks XR_EXT_hand_tracking (needed for --hands)"), std::string::npos)
      << none.err;
  EXPECT_FALSE(fs::exists(path("r.jsonl")));
  EXPECT_FALSE(fs::exists(path("n.json")));
  // A jitter or seed the runtime cannot read, loose forms included (issue 29: "0x10" was read as
  // 16 mm, -1 and 2^64 as seeds): the runtime's line names the setting, and ours says the runtime
  // refused, not that there is none. Nothing is made.
  for (const char* bad :
       {"CURVEFOLD_SIM_JITTER=2mm", "CURVEFOLD_SIM_JITTER=-1", "CURVEFOLD_SIM_JITTER=0x10",
        "CURVEFOLD_SIM_JITTER=+2", "CURVEFOLD_SIM_SEED=seven", "CURVEFOLD_SIM_SEED=-1",
        "CURVEFOLD_SIM_SEED=18446744073709551616"}) {
    const CommandResult refused =
        run("xr " + input + " --headless --record b.jsonl --autosave b.json",
            simulated(input, std::string("CURVEFOLD_SIM_HANDS=1 ") + bad));
    EXPECT_EQ(refused.exitCode, 1) << bad;
    EXPECT_FALSE(fs::exists(path("b.jsonl"))) << bad;
    EXPECT_FALSE(fs::exists(path("b.json"))) << bad;
    const std::string setting = std::string(bad).substr(0, std::string(bad).find('='));
    EXPECT_NE(refused.err.find("curvefold sim runtime: " + setting + ": expected"),
              std::string::npos)
        << refused.err;
    // Issue 40: the runtime's reason inside curvefold's one line, not a line of its own.
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
    const std::string last = refused.err.substr(refused.err.rfind("curvefold:"));
    EXPECT_EQ(std::count(last.begin(), last.end(), '\n'), 1) << refused.err;
    EXPECT_NE(last.find("the OpenXR runtime was found but refused to start"), std::string::npos)
        << refused.err;
    EXPECT_EQ(last.find("no OpenXR runtime"), std::string::npos) << refused.err;
  }
  // Without --hands, the same runtime folds with its controllers.
  const CommandResult plain = run("xr " + input + " --headless --autosave p.json",
                                  simulated(input, "CURVEFOLD_SIM_NO_HAND_TRACKING=1"));
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_EQ(load("p.json")["folds"].size(), replayed(input, "again")["folds"].size());
}

}  // namespace
}  // namespace curvefold
