// The designer window under Xvfb, driven by xdotool as a person would: a drag on a known vertex
// of a flat square must leave exactly one committed fold in the autosave, a screenshot showing the
// sheet, and a recording that `curvefold replay` turns into the same folds. Also: without a
// display, plain `curvefold` says so in one line and exits non-zero.
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>
#include <stb/stb_image.h>
#include <nlohmann/json.hpp>

#include "app/desktop/desktop_input.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace fs = std::filesystem;

namespace curvefold {
namespace {

constexpr int kWidth = 640, kHeight = 480;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

int shell(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool have(const char* program) {
  return shell(std::string("command -v ") + program + " >/dev/null 2>&1") == 0;
}

class DesktopWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("curvefold-desktop-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (xvfb_ > 0) shell("kill " + std::to_string(xvfb_) + " 2>/dev/null");
    fs::remove_all(dir_);
  }

  // Starts Xvfb on a free display (-displayfd) and returns its name, or "" when it failed.
  std::string startXvfb() {
    const fs::path number = dir_ / "display", pid = dir_ / "xvfb.pid";
    shell("Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>" + number.string() +
          " >/dev/null 2>&1 & echo $! >" + pid.string());
    xvfb_ = std::atoi(slurp(pid).c_str());
    for (int i = 0; i < 100; ++i) {
      std::string text = slurp(number);
      if (!text.empty() && text.back() == '\n') {
        text.pop_back();
        text.insert(text.begin(), ':');
        return text;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return "";
  }

  fs::path dir_;
  int xvfb_ = 0;
};

TEST_F(DesktopWindow, DragOnAVertexCommitsOneFoldThatReplays) {
  if (!have("Xvfb") || !have("xdotool")) GTEST_SKIP() << "Xvfb or xdotool is not installed";
  const std::string display = startXvfb();
  ASSERT_FALSE(display.empty()) << "Xvfb did not start";

  // Where a vertex of the square appears: the designer's initial view is OrbitCamera::framing.
  const Sheet sheet = makeSurface("square");
  const OrbitCamera camera = OrbitCamera::framing(sheet, Pose{}, float(kWidth) / kHeight);
  // The vertex nearest (0.06, -0.04): right of the panel, below the middle.
  std::size_t vertex = 0;
  for (std::size_t i = 0; i < sheet.positions.size(); ++i)
    if (glm::length(sheet.positions[i] - glm::dvec3(0.06, -0.04, 0)) <
        glm::length(sheet.positions[vertex] - glm::dvec3(0.06, -0.04, 0)))
      vertex = i;
  const glm::dvec2 from = camera.project(sheet.positions[vertex], kWidth, kHeight);
  const glm::dvec2 to = camera.project({0.0, -0.04, 0.0}, kWidth, kHeight);

  const fs::path recording = dir_ / "session.jsonl", autosave = dir_ / "auto.curvefold.json",
                 screenshot = dir_ / "shot.png", log = dir_ / "designer.log";
  const std::string env = "DISPLAY=" + display + " ";
  const fs::path pidFile = dir_ / "designer.pid";
  shell(env + "timeout 120 " + CURVEFOLD_BINARY + " design square --size " +
        std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --record " + recording.string() +
        " --autosave " + autosave.string() + " --screenshot-on-exit " + screenshot.string() + " >" +
        log.string() + " 2>&1 & echo $! >" + pidFile.string());
  const std::string designer = std::to_string(std::atoi(slurp(pidFile).c_str()));
  const fs::path windowFile = dir_ / "window";
  ASSERT_EQ(shell(env + "timeout 60 xdotool search --sync --name '^curvefold$' | head -1 >" +
                  windowFile.string()),
            0)
      << slurp(log);
  const std::string window = std::to_string(std::atol(slurp(windowFile).c_str()));
  auto move = [&](glm::dvec2 p) {
    return env + "xdotool mousemove --window " + window + " " + std::to_string(int(p.x + 0.5)) +
           " " + std::to_string(int(p.y + 0.5)) + " && sleep 0.15 && ";
  };
  // Hover, press, drag in steps, a wheel step for depth, release, quit.
  std::string script =
      "sleep 1 && " + move(from) + move(from) + env + "xdotool mousedown 1 && sleep 0.3 && ";
  for (int i = 1; i <= 6; ++i) script += move(from + (to - from) * (i / 6.0));
  script += env + "xdotool click 5 && sleep 0.3 && " + env + "xdotool mouseup 1 && sleep 0.5 && " +
            env + "xdotool key --window " + window + " ctrl+q";
  ASSERT_EQ(shell(script), 0);
  // The designer exits by itself after ctrl+q.
  bool exited = false;
  for (int i = 0; i < 300 && !exited; ++i) {
    exited = shell("kill -0 " + designer + " 2>/dev/null") != 0;
    if (!exited) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(exited) << "the designer did not close";
  EXPECT_EQ(slurp(log), "");

  // Exactly one committed fold.
  ASSERT_TRUE(fs::exists(autosave)) << slurp(log);
  const nlohmann::json saved = nlohmann::json::parse(slurp(autosave));
  EXPECT_EQ(saved["folds"].size(), 1u);

  // The screenshot shows the paper-white sheet in the middle of a grey-blue background.
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load(screenshot.c_str(), &w, &h, &channels, 4);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(w, kWidth);
  EXPECT_EQ(h, kHeight);
  auto isPaper = [&](int x, int y) {
    const unsigned char* p = pixels + (std::size_t(y) * w + x) * 4;
    return p[0] > 200 && p[1] > 200 && p[2] > 190 && p[0] >= p[2];
  };
  int paper = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) paper += isPaper(x, y);
  EXPECT_GT(paper, w * h / 20);
  EXPECT_FALSE(isPaper(2, 2));  // background
  stbi_image_free(pixels);

  // The recording replays headless to the same folds.
  const fs::path out = dir_ / "replayed";
  ASSERT_EQ(shell(std::string(CURVEFOLD_BINARY) + " replay " + recording.string() + " --out " +
                  out.string() + " >/dev/null"),
            0);
  const nlohmann::json replayed = nlohmann::json::parse(slurp(out / "session.curvefold.json"));
  EXPECT_EQ(replayed["folds"], saved["folds"]);
  EXPECT_EQ(replayed["surface"], saved["surface"]);
}

TEST_F(DesktopWindow, NoDisplayIsOneLineAndNonZero) {
  const fs::path err = dir_ / "err";
  const int code = shell("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(CURVEFOLD_BINARY) +
                         " >/dev/null 2>" + err.string());
  EXPECT_NE(code, 0);
  const std::string text = slurp(err);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  EXPECT_NE(text.find("curvefold replay"), std::string::npos) << text;
  EXPECT_NE(text.find("curvefold render"), std::string::npos) << text;
  EXPECT_EQ(shell("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(CURVEFOLD_BINARY) +
                  " design square >/dev/null 2>&1"),
            1);
}

}  // namespace
}  // namespace curvefold
