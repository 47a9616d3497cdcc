// Driving the designer window as a person would, for the desktop tests: a private Xvfb, the
// designer started in the background, and xdotool commands for the pointer and keys.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "test_paths.hpp"

namespace curvefold::testing {

namespace fs = std::filesystem;

inline std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// Runs a /bin/sh command line; its exit status, or -1 when it did not exit normally.
inline int shell(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline bool have(const char* program) {
  return shell(std::string("command -v ") + program + " >/dev/null 2>&1") == 0;
}

// The first of `programs` that is not installed, or "" when all are.
inline std::string missingProgram(std::initializer_list<const char*> programs) {
  for (const char* program : programs)
    if (!have(program)) return program;
  return "";
}

// Under CI (CI=true) a test that cannot run fails: a missing tool must not pass as a skip.
inline bool underCi() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string(ci) == "true";
}

}  // namespace curvefold::testing

// Skips the test when a program it drives is missing (a developer's machine), fails it under CI.
#define CURVEFOLD_REQUIRE_PROGRAMS(...)                                                      \
  do {                                                                                       \
    const std::string missing = ::curvefold::testing::missingProgram({__VA_ARGS__});         \
    if (!missing.empty()) {                                                                  \
      if (::curvefold::testing::underCi())                                                   \
        FAIL() << missing << " is not installed, and CI=true: scripts/setup.sh installs it"; \
      GTEST_SKIP() << missing << " is not installed";                                        \
    }                                                                                        \
  } while (false)

namespace curvefold::testing {

class DesktopTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("curvefold-desktop-" + std::to_string(getpid()) + "-" +
                                        info->test_suite_name() + "-" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    // A designer left by a failed test: the process itself first, then its `timeout`.
    if (designer_ > 0) {
      if (const int child = designerProcess(); child > 0)
        shell("kill -9 " + std::to_string(child) + " 2>/dev/null");
      shell("kill -9 " + std::to_string(designer_) + " 2>/dev/null");
    }
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
        display_ = text;
        return text;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return "";
  }

  // "DISPLAY=:N " to put in front of a command.
  std::string env() const { return "DISPLAY=" + display_ + " "; }

  // Starts `curvefold design ARGUMENTS` in the background (its output to `log`), waits for its
  // window and returns the window id, or "" when none appeared. The pid is designer().
  std::string startDesigner(const std::string& arguments, const fs::path& log) {
    const fs::path pidFile = dir_ / "designer.pid", windowFile = dir_ / "window";
    shell(env() + "timeout 120 " + CURVEFOLD_BINARY + " design " + arguments + " >" + log.string() +
          " 2>&1 & echo $! >" + pidFile.string());
    designer_ = std::atoi(slurp(pidFile).c_str());
    if (shell(env() + "timeout 60 xdotool search --sync --name '^curvefold$' | head -1 >" +
              windowFile.string()) != 0)
      return "";
    window_ = std::to_string(std::atol(slurp(windowFile).c_str()));
    return window_;
  }

  // Replays `recording` headless (`curvefold replay`) into dir()/replayed: the design it saved
  // there, or "" when the replay failed.
  fs::path replay(const fs::path& recording) const {
    const fs::path out = dir_ / "replayed";
    if (shell(std::string(CURVEFOLD_BINARY) + " replay " + recording.string() + " --out " +
              out.string() + " >/dev/null") != 0)
      return {};
    return out / "session.curvefold.json";
  }

  // The designer process itself: startDesigner runs it under `timeout`, whose pid that is.
  int designerProcess() const {
    const fs::path child = dir_ / "designer.child";
    shell("pgrep -P " + std::to_string(designer_) + " >" + child.string());
    return std::atoi(slurp(child).c_str());
  }

  // Shell text that moves the pointer over the window to p (pixels) and waits a little.
  std::string move(glm::dvec2 p, double pause = 0.15) const {
    return env() + "xdotool mousemove --window " + window_ + " " + std::to_string(int(p.x + 0.5)) +
           " " + std::to_string(int(p.y + 0.5)) + " && sleep " + std::to_string(pause) + " && ";
  }

  // Shell text for a left drag from `from` to `to` in `steps` moves `pause` seconds apart, with a
  // wheel step for depth on the way; `release` false leaves the button held (a drag in progress).
  std::string drag(glm::dvec2 from, glm::dvec2 to, bool release = true, int steps = 6,
                   double pause = 0.15) const {
    std::string script =
        move(from, pause) + move(from, pause) + env() + "xdotool mousedown 1 && sleep 0.3 && ";
    for (int i = 1; i <= steps; ++i)
      script += move(from + (to - from) * (double(i) / steps), pause);
    script += env() + "xdotool click 5 && sleep 0.3 && ";
    if (release) script += env() + "xdotool mouseup 1 && sleep 0.5 && ";
    return script;
  }

  // Shell text for a key chord sent to the window (e.g. "ctrl+q").
  std::string key(const std::string& chord) const {
    return env() + "xdotool key --window " + window_ + " " + chord;
  }

  // Shell text for Ctrl+Q. Its status is not the test's: the designer may close its window on the
  // key press, before xdotool has sent the releases to it (X error BadWindow, status 1). Callers
  // check that the designer exited.
  std::string quit() const { return key("ctrl+q") + " || true"; }

  // Waits up to `seconds` for the designer to exit; true when it did.
  bool waitForDesignerExit(double seconds = 30.0) {
    for (int i = 0; i < int(seconds * 10); ++i) {
      if (shell("kill -0 " + std::to_string(designer_) + " 2>/dev/null") != 0) {
        designer_ = 0;
        return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
  }

  const fs::path& dir() const { return dir_; }

 private:
  fs::path dir_;
  std::string display_, window_;
  int xvfb_ = 0, designer_ = 0;
};

}  // namespace curvefold::testing
