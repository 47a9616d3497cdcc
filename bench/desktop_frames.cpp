// The designer window's frames while a target loads and a suggestion is searched (issue 38, 3:
// "no frame over 50 ms while suggesting, on a 10k sheet, lavapipe"). Not a Google Benchmark: it
// runs `curvefold design` on a private Xvfb, on the default cylinder at resolution 82 (10,004
// triangles) with a 2-fold target, and drives it as a person would (xdotool): each round presses
// S (suggest) and, while the search runs, "Load target" (the field holds the target's path: it is
// read, checked and sampled anew), then waits 4 s. The window writes each frame's duration
// (--frame-times); this prints their median, 99th percentile and the longest, leaving out the
// first second (the window's start: pipelines, the font atlas).
//
//   build/bench/desktop_frames [ROUNDS] [--idle]   (default 4 rounds; needs Xvfb and xdotool)
//
// --idle: the same rounds with neither a suggestion nor a load (the pointer only moves), to tell
// what the machine's load does to the frames from what the studio does.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <imgui.h>

#include "app/session/document.hpp"
#include "app/studio/studio_panel.hpp"
#include "engine/io/design_document.hpp"
#include "tests/support/random_fold_target.hpp"

namespace fs = std::filesystem;
using namespace curvefold;

namespace {

constexpr int kWidth = 1280, kHeight = 720;

int shell(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string slurp(const fs::path& path) {
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

void writeObj(const Sheet& sheet, const fs::path& path) {
  std::ofstream out(path);
  out.precision(17);
  for (const glm::dvec3& p : sheet.positions)
    out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
  for (const Triangle& t : sheet.triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

// Where the designer's panel draws an item (the same panel, headless, at the window's size).
glm::vec2 panelItem(const fs::path& design, const std::string& label) {
  ImGuiContext* context = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.DisplaySize = ImVec2(float(kWidth), float(kHeight));
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  session::Document doc = session::makeDocument(loadDesign(design), design.string());
  studio::StudioPanel panel(false, "help");
  panel.setDesktop(true);
  studio::StudioActions actions;
  actions.loadTarget = [](const std::string&) {};
  actions.suggest = [] {};
  studio::StudioStats stats;
  bool creasePattern = false;
  for (int i = 0; i < 2; ++i) {
    io.DeltaTime = 1.0f / 60.0f;
    ImGui::NewFrame();
    panel.draw(doc, actions, stats, creasePattern);
    ImGui::Render();
  }
  const glm::vec2 at = panel.itemCentre(label).value_or(glm::vec2(-1.0f));
  ImGui::DestroyContext(context);
  return at;
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 4;
  const bool idle = argc > 2 && std::string(argv[2]) == "--idle";
  const fs::path dir = fs::temp_directory_path() / ("curvefold-frames-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string binary = CURVEFOLD_BINARY;
  const fs::path design = dir / "cylinder.curvefold.json";
  if (shell(binary + " new cylinder --resolution 82 -o " + design.string() + " >/dev/null") != 0) {
    std::cerr << "desktop_frames: `curvefold new` failed\n";
    return 1;
  }
  const SurfaceParameters parameters{{"resolution", 82}};
  const fs::path target = dir / "target.obj";
  writeObj(makeRandomFoldTarget("cylinder", parameters, 2, 4002).sheet, target);
  const glm::vec2 load = panelItem(design, "Load target");

  const fs::path displayFile = dir / "display", xvfbPid = dir / "xvfb.pid";
  shell("Xvfb -displayfd 3 -screen 0 1600x900x24 -nolisten tcp 3>" + displayFile.string() +
        " >/dev/null 2>&1 & echo $! >" + xvfbPid.string());
  std::string display;
  for (int i = 0; i < 100 && display.empty(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const std::string text = slurp(displayFile);
    if (!text.empty() && text.back() == '\n') display = ":" + text.substr(0, text.size() - 1);
  }
  if (display.empty()) {
    std::cerr << "desktop_frames: Xvfb did not start\n";
    return 1;
  }
  const std::string env = "DISPLAY=" + display + " ";
  const fs::path times = dir / "frames.txt", log = dir / "designer.log";
  shell(env + binary + " design " + design.string() + " --target " + target.string() + " --size " +
        std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --autosave " +
        (dir / "auto.curvefold.json").string() + " --frame-times " + times.string() + " >" +
        log.string() + " 2>&1 &");
  const fs::path windowFile = dir / "window";
  shell(env + "timeout 60 xdotool search --sync --name '^curvefold$' | head -1 >" +
        windowFile.string());
  const std::string window = std::to_string(std::atol(slurp(windowFile).c_str()));
  auto at = [&](glm::vec2 p) {
    return env + "xdotool mousemove --window " + window + " " + std::to_string(int(p.x)) + " " +
           std::to_string(int(p.y)) + " && sleep 0.1 && ";
  };
  auto click = [&](glm::vec2 p) {
    return at(p) + env + "xdotool mousedown 1 && sleep 0.1 && " + env +
           "xdotool mouseup 1 && sleep 0.1 && ";
  };
  shell("sleep 2");
  for (int round = 0; round < rounds; ++round) {
    if (idle) {
      shell(at({kWidth * 0.75f, kHeight * 0.5f}) + "sleep 0.3 && " + at(load) + "sleep 4");
      continue;
    }
    // Suggest (the pointer off the panel, so the key reaches the window), then load the target
    // again (the field holds its path: read, checked and sampled anew) while the search runs.
    shell(at({kWidth * 0.75f, kHeight * 0.5f}) + env + "xdotool key --window " + window +
          " s && sleep 0.3 && " + click(load) + "sleep 4");
  }
  shell(env + "xdotool key --window " + window + " ctrl+q || true");
  for (int i = 0; i < 300 && !fs::exists(times); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  shell("kill " + slurp(xvfbPid) + " 2>/dev/null");

  std::vector<double> all;
  std::istringstream in(slurp(times));
  for (double ms = 0.0; in >> ms;) all.push_back(ms);
  // The first second is the window's start.
  std::size_t first = 0;
  for (double sum = 0.0; first < all.size() && sum < 1000.0; ++first) sum += all[first];
  std::vector<double> frames(all.begin() + std::ptrdiff_t(first), all.end());
  if (frames.empty()) {
    std::cerr << "desktop_frames: no frames measured; the designer said: " << slurp(log) << "\n";
    return 1;
  }
  std::vector<double> sorted = frames;
  std::sort(sorted.begin(), sorted.end());
  const auto quantile = [&](double q) {
    return sorted[std::min(sorted.size() - 1, std::size_t(q * double(sorted.size())))];
  };
  std::printf("frames %zu (after the first second), rounds %d%s\n", frames.size(), rounds,
              idle ? " (idle: no suggestion, no load)" : "");
  std::printf("median %.2f ms, 99th percentile %.2f ms, longest %.2f ms\n", quantile(0.5),
              quantile(0.99), sorted.back());
  std::printf("frames over 50 ms: %zd\n",
              std::count_if(frames.begin(), frames.end(), [](double ms) { return ms > 50.0; }));
  std::printf("the designer said: %s\n", slurp(log).empty() ? "nothing" : slurp(log).c_str());
  fs::remove_all(dir);
  return 0;
}
