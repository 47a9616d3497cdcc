// The designer window's frames while a target loads and a suggestion is searched (issue 38, 3:
// "no frame over 50 ms while suggesting, on a 10k sheet, lavapipe"). Not a Google Benchmark: it
// runs `curvefold design` on a private Xvfb, on the default cylinder at resolution 82 (10,004
// triangles) with a 2-fold target, and drives it as a person would (xdotool). Each round clicks
// "Load target" (the field holds the target's path: it is read, checked and sampled anew) and at
// once presses S (a suggestion asked while the target loads), waits 10 s for the suggestion, then
// presses S twice 0.3 s apart (a newer request abandons the search in flight) and waits 10 s.
// The window writes each frame's duration, the frame thread's CPU time in it, and the frames a
// suggestion was asked and offered in (--frame-times); this prints the median, 99th percentile and
// longest of both, and each suggestion's latency (from the frame that asked to the frame it joined,
// in window time), leaving out the first second (the window's start: pipelines, the font atlas).
// The frame thread's CPU time is the frame's own work (the studio's calls, the scene, the upload,
// the panel, what lavapipe does on that thread); the duration adds lavapipe's rasteriser threads
// and whatever else shares the cores (the search's threads, other processes).
//
//   build/bench/desktop_frames [ROUNDS] [--idle]   (default 4 rounds; needs Xvfb and xdotool;
//   CURVEFOLD=path/to/curvefold measures another build)
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
#include <optional>
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
  // CURVEFOLD names another build of curvefold to measure (a before and after on one machine).
  const std::string binary = std::getenv("CURVEFOLD") ? std::getenv("CURVEFOLD") : CURVEFOLD_BINARY;
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
      shell(at({kWidth * 0.75f, kHeight * 0.5f}) + "sleep 0.3 && " + at(load) + "sleep 20");
      continue;
    }
    // Load the target again and ask while it loads, then (the pointer off the panel, so the
    // keys reach the window) ask twice: the second request abandons the first's search.
    const std::string suggest = env + "xdotool key --window " + window + " s && ";
    shell(click(load) + at({kWidth * 0.75f, kHeight * 0.5f}) + suggest + "sleep 10 && " + suggest +
          "sleep 0.3 && " + suggest + "sleep 10");
  }
  shell(env + "xdotool key --window " + window + " ctrl+q || true");
  for (int i = 0; i < 300 && !fs::exists(times); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  shell("kill " + slurp(xvfbPid) + " 2>/dev/null");

  // Each line: the frame's duration, the frame thread's CPU time (ms), the wall time of each step
  // of the frame loop (phases=, in kPhases' order), and a note.
  struct FrameTime {
    double wallMs = 0.0, cpuMs = 0.0;
    std::string note, phases;
  };
  std::vector<FrameTime> all;
  {
    std::istringstream in(slurp(times));
    for (std::string line; std::getline(in, line);) {
      std::istringstream fields(line);
      FrameTime frame;
      if (fields >> frame.wallMs >> frame.cpuMs) {
        for (std::string token; fields >> token;)
          (token.rfind("phases=", 0) == 0 ? frame.phases : frame.note) = token;
        all.push_back(frame);
      }
    }
  }
  // The first second is the window's start.
  std::size_t first = 0;
  for (double sum = 0.0; first < all.size() && sum < 1000.0; ++first) sum += all[first].wallMs;
  const std::vector<FrameTime> frames(all.begin() + std::ptrdiff_t(first), all.end());
  if (frames.empty()) {
    std::cerr << "desktop_frames: no frames measured; the designer said: " << slurp(log) << "\n";
    return 1;
  }
  std::printf("frames %zu (after the first second), rounds %d%s\n", frames.size(), rounds,
              idle ? " (idle: no suggestion, no load)" : "");
  const auto summary = [](const char* what, std::vector<double> ms) {
    std::sort(ms.begin(), ms.end());
    const auto quantile = [&](double q) {
      return ms[std::min(ms.size() - 1, std::size_t(q * double(ms.size())))];
    };
    std::printf("%s: median %.2f ms, 99th percentile %.2f ms, longest %.2f ms, over 50 ms: %zd\n",
                what, quantile(0.5), quantile(0.99), ms.back(),
                std::count_if(ms.begin(), ms.end(), [](double v) { return v > 50.0; }));
  };
  std::vector<double> wall, cpu;
  for (const FrameTime& frame : frames) {
    wall.push_back(frame.wallMs);
    cpu.push_back(frame.cpuMs);
  }
  summary("frame duration", wall);
  summary("frame thread CPU", cpu);
  // Where each frame over 50 ms spent its time: the loop's steps (the designer's --frame-times).
  std::printf(
      "frames over 50 ms, each step's wall time (ms; events,panel,input,process,view,"
      "scene,draw):\n");
  for (std::size_t i = 0; i < frames.size(); ++i)
    if (frames[i].wallMs > 50.0)
      std::printf("  frame %zu: %.1f ms, thread CPU %.1f ms, %s %s\n", i, frames[i].wallMs,
                  frames[i].cpuMs, frames[i].phases.c_str(), frames[i].note.c_str());
  // A suggestion's latency: the frames after the one that asked, up to the one it joined. A
  // request followed by a newer one before its answer was abandoned (not counted).
  std::vector<double> latencies;
  std::optional<double> sinceAsked;
  for (const FrameTime& frame : frames) {
    if (sinceAsked) *sinceAsked += frame.wallMs;
    if (frame.note == "suggest") sinceAsked = 0.0;
    if (frame.note == "offered" && sinceAsked) {
      latencies.push_back(*sinceAsked);
      sinceAsked.reset();
    }
  }
  std::printf(
      "frames that asked for a suggestion %zd, started a load %zd, took in a suggestion %zd\n",
      std::count_if(frames.begin(), frames.end(), [](auto& f) { return f.note == "suggest"; }),
      std::count_if(frames.begin(), frames.end(), [](auto& f) { return f.note == "load"; }),
      std::count_if(frames.begin(), frames.end(), [](auto& f) { return f.note == "offered"; }));
  std::sort(latencies.begin(), latencies.end());
  if (!latencies.empty())
    std::printf("suggestions offered %zu: latency median %.0f ms, longest %.0f ms\n",
                latencies.size(), latencies[latencies.size() / 2], latencies.back());
  else if (!idle)
    std::printf("no suggestion offered\n");
  std::printf("the designer said: %s\n", slurp(log).empty() ? "nothing" : slurp(log).c_str());
  fs::remove_all(dir);
  return 0;
}
