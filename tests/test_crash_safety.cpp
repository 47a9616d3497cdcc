// Crash safety of a live session (issue 6, item 4): the designer under Xvfb, recording and
// autosaving, is killed with SIGKILL in the middle of a drag after two committed folds. The
// autosave must hold exactly those two folds, the recording must be whole lines that replay to
// them, and `--resume` must carry on from them.
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/desktop/desktop_input.hpp"
#include "desktop_test_support.hpp"
#include "engine/io/design_document.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "sim_input/recording.hpp"

namespace curvefold {
namespace {

using namespace curvefold::testing;

// Wide, so that the whole square lies right of the designer's panel (300 px at the left).
constexpr int kWidth = 1024, kHeight = 480;
// Drags a little quicker than test_desktop_window's, to keep four of them near 15 s.
constexpr int kSteps = 4;
constexpr double kPause = 0.1;

// The folds as saved (plane, seed, target), for comparing designs.
nlohmann::json foldsOf(const fs::path& design) {
  return nlohmann::json::parse(slurp(design))["folds"];
}

class CrashSafety : public DesktopTest {
 protected:
  // Waits up to 30 s for the autosave to hold `folds` folds (it is written atomically).
  static bool autosaveHolds(const fs::path& autosave, std::size_t folds) {
    for (int i = 0; i < 300; ++i) {
      if (fs::exists(autosave) && foldsOf(autosave).size() == folds) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
  }

  // Screen points of a corner fold: from the vertex nearest corner * 0.8 halfway to the middle.
  // Corner folds touch disjoint parts of the sheet, so each grab lands on the flat sheet.
  std::pair<glm::dvec2, glm::dvec2> cornerFold(glm::dvec2 corner) const {
    const glm::dvec3 grab(corner * 0.08, 0.0);
    std::size_t vertex = 0;
    for (std::size_t i = 0; i < sheet_.positions.size(); ++i)
      if (glm::length(sheet_.positions[i] - grab) < glm::length(sheet_.positions[vertex] - grab))
        vertex = i;
    return {camera_.project(sheet_.positions[vertex], kWidth, kHeight),
            camera_.project(glm::dvec3(corner * 0.04, 0.0), kWidth, kHeight)};
  }

  std::string size() const {
    return " --size " + std::to_string(kWidth) + "x" + std::to_string(kHeight);
  }

  // The designer's initial view is OrbitCamera::framing of the sheet.
  Sheet sheet_ = makeSurface("square");
  desktop::OrbitCamera camera_ =
      desktop::OrbitCamera::framing(sheet_, Pose{}, float(kWidth) / kHeight);
};

TEST_F(CrashSafety, KillMidDragKeepsCommittedFoldsAndResumes) {
  CURVEFOLD_REQUIRE_PROGRAMS("Xvfb", "xdotool", "pgrep");
  ASSERT_FALSE(startXvfb().empty()) << "Xvfb did not start";
  const auto [from1, to1] = cornerFold({1.0, -1.0});
  const auto [from2, to2] = cornerFold({1.0, 1.0});
  const auto [from3, to3] = cornerFold({-1.0, 1.0});
  const auto [from4, to4] = cornerFold({-1.0, -1.0});
  for (const glm::dvec2 p : {from1, from2, from3, from4}) ASSERT_GT(p.x, 320.0);

  // Two committed folds, then a third drag held (pressed and moved, never released) and killed.
  const fs::path recording = dir() / "session.jsonl", autosave = dir() / "auto.curvefold.json",
                 log = dir() / "designer.log";
  ASSERT_FALSE(startDesigner("square" + size() + " --record " + recording.string() +
                                 " --autosave " + autosave.string(),
                             log)
                   .empty())
      << slurp(log);
  ASSERT_EQ(shell("sleep 1 && " + drag(from1, to1, true, kSteps, kPause) +
                  drag(from2, to2, true, kSteps, kPause) + "true"),
            0);
  // On a loaded machine the designer may lag behind the pointer: the held drag starts only once
  // both folds are committed, so that the kill always comes after them.
  ASSERT_TRUE(autosaveHolds(autosave, 2)) << slurp(log);
  ASSERT_EQ(shell(drag(from3, to3, /*release=*/false, kSteps, kPause) + "sleep 0.5"), 0);
  const int designer = designerProcess();
  ASSERT_GT(designer, 0);
  ASSERT_EQ(::kill(designer, SIGKILL), 0);
  ASSERT_TRUE(waitForDesignerExit());
  // The X server still holds the button down for the next window.
  ASSERT_EQ(shell(env() + "xdotool mouseup 1"), 0);

  // The autosave holds exactly the two committed folds.
  ASSERT_TRUE(fs::exists(autosave)) << slurp(log);
  const Design saved = loadDesign(autosave);
  EXPECT_EQ(saved.folds.size(), 2u);
  const nlohmann::json savedFolds = foldsOf(autosave);
  EXPECT_EQ(savedFolds.size(), 2u);

  // The recording is whole lines up to the last commit point: the held drag is not on disk.
  const Recording recorded = readRecording(recording);  // throws on a cut-off line
  EXPECT_FALSE(recorded.truncated);
  ASSERT_FALSE(recorded.frames.empty());
  EXPECT_EQ(recorded.frames.back().pointHand.select, 0.0);
  // It replays headless to the same two folds.
  const fs::path design = replay(recording);
  ASSERT_FALSE(design.empty()) << "the recording did not replay";
  EXPECT_EQ(foldsOf(design), savedFolds);

  // Resuming from the autosave: one more fold, quit, and the autosave has all three.
  const fs::path resumeLog = dir() / "resume.log";
  ASSERT_FALSE(
      startDesigner("--resume --autosave " + autosave.string() + size(), resumeLog).empty())
      << slurp(resumeLog);
  ASSERT_EQ(shell("sleep 1 && " + drag(from4, to4, true, kSteps, kPause) + quit()), 0);
  ASSERT_TRUE(waitForDesignerExit()) << "the designer did not close";
  EXPECT_EQ(slurp(resumeLog), "");
  const nlohmann::json resumedFolds = foldsOf(autosave);
  ASSERT_EQ(resumedFolds.size(), 3u);
  EXPECT_EQ(resumedFolds[0], savedFolds[0]);
  EXPECT_EQ(resumedFolds[1], savedFolds[1]);
  EXPECT_EQ(loadDesign(autosave).folds.size(), 3u);
}

}  // namespace
}  // namespace curvefold
