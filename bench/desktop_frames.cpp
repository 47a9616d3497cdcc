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
// The window draws only when something changes (app/desktop/redraw_pacer.hpp): a frame's
// duration leaves out the rest before it (waited=), a latency counts it. On the frames that note
// something the window also writes the process's CPU by thread group (cpu=, thread_cpu.hpp):
// this prints, for each suggestion offered, the CPU each group spent between the asking frame
// and the offer, and the frames drawn meanwhile, which do not depend on the machine's load.
//
//   build/bench/desktop_frames [ROUNDS] [--idle] [--full-rate]   (default 4 rounds; needs Xvfb
//   and xdotool; CURVEFOLD=path/to/curvefold measures another build)
//
// --idle: the same rounds with neither a suggestion nor a load (the pointer only moves), to tell
// what the machine's load does to the frames from what the studio does. --full-rate: the window
// draws every frame at once (CURVEFOLD_REDRAW=always), as it did before the pacer.
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
  int rounds = 4;
  bool idle = false, fullRate = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--idle")
      idle = true;
    else if (arg == "--full-rate")
      fullRate = true;
    else
      rounds = std::max(1, std::atoi(arg.c_str()));
  }
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
  shell(env + (fullRate ? "CURVEFOLD_REDRAW=always " : "") + binary + " design " + design.string() +
        " --target " + target.string() + " --size " + std::to_string(kWidth) + "x" +
        std::to_string(kHeight) + " --autosave " + (dir / "auto.curvefold.json").string() +
        " --frame-times " + times.string() + " >" + log.string() + " 2>&1 &");
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
  // of the frame loop (phases=, in kPhases' order), the rest before it (waited=), a note, and on a
  // noted frame the process's CPU by thread group (cpu=).
  struct FrameTime {
    double wallMs = 0.0, cpuMs = 0.0, waitedMs = 0.0;
    std::string note, phases;
    std::vector<double> groupCpu;  // frame, search, render, other, process (ms)
  };
  std::vector<FrameTime> all;
  {
    std::istringstream in(slurp(times));
    for (std::string line; std::getline(in, line);) {
      std::istringstream fields(line);
      FrameTime frame;
      if (fields >> frame.wallMs >> frame.cpuMs) {
        for (std::string token; fields >> token;) {
          if (token.rfind("phases=", 0) == 0) {
            frame.phases = token;
          } else if (token.rfind("waited=", 0) == 0) {
            frame.waitedMs = std::atof(token.c_str() + 7);
          } else if (token.rfind("cpu=", 0) == 0) {
            for (std::size_t at = token.find(':'); at != std::string::npos;
                 at = token.find(':', at + 1))
              frame.groupCpu.push_back(std::atof(token.c_str() + at + 1));
          } else {
            frame.note = token;
          }
        }
        all.push_back(frame);
      }
    }
  }
  // The first second is the window's start.
  std::size_t first = 0;
  for (double sum = 0.0; first < all.size() && sum < 1000.0; ++first)
    sum += all[first].waitedMs + all[first].wallMs;
  const std::vector<FrameTime> frames(all.begin() + std::ptrdiff_t(first), all.end());
  if (frames.empty()) {
    std::cerr << "desktop_frames: no frames measured; the designer said: " << slurp(log) << "\n";
    return 1;
  }
  double seconds = 0.0;
  for (const FrameTime& frame : frames) seconds += (frame.waitedMs + frame.wallMs) * 1e-3;
  std::printf("frames %zu in %.1f s (after the first second: %.1f a second), rounds %d%s%s\n",
              frames.size(), seconds, double(frames.size()) / seconds, rounds,
              idle ? " (idle: no suggestion, no load)" : "", fullRate ? " (full rate)" : "");
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
  // Where each frame over 50 ms spent its time: the loop's steps (the designer's --frame-times);
  // on a loaded machine, the 20 longest.
  std::vector<std::size_t> slow;
  for (std::size_t i = 0; i < frames.size(); ++i)
    if (frames[i].wallMs > 50.0) slow.push_back(i);
  std::stable_sort(slow.begin(), slow.end(), [&](std::size_t a, std::size_t b) {
    return frames[a].wallMs > frames[b].wallMs;
  });
  slow.resize(std::min<std::size_t>(slow.size(), 20));
  std::sort(slow.begin(), slow.end());
  std::printf(
      "frames over 50 ms (the 20 longest), each step's wall time (ms; events,panel,input,process,"
      "view,scene,draw):\n");
  for (const std::size_t i : slow)
    std::printf("  frame %zu: %.1f ms, thread CPU %.1f ms, %s %s\n", i, frames[i].wallMs,
                frames[i].cpuMs, frames[i].phases.c_str(), frames[i].note.c_str());
  // A suggestion's latency: the frames after the one that asked, up to the one it joined. A
  // request followed by a newer one before its answer was abandoned (not counted). For each, the
  // frames drawn meanwhile, when the target swapped in (a request asked while it loaded), and the
  // CPU each thread group spent from the asking frame's end to the offering frame's.
  std::vector<double> latencies;
  std::optional<double> sinceAsked;
  std::size_t asked = 0, framesSince = 0;
  double loadedAt = -1.0;
  std::printf(
      "each suggestion offered: latency, frames drawn, target swapped in at; CPU ms from the ask "
      "to the offer (frame thread, search thread, lavapipe's threads, the rest: TBB's workers, "
      "loads, measures; the process)\n");
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const FrameTime& frame = frames[i];
    if (sinceAsked) {
      *sinceAsked += frame.waitedMs + frame.wallMs;
      ++framesSince;
    }
    if (frame.note == "suggest") {
      sinceAsked = 0.0;
      asked = i;
      framesSince = 0;
      loadedAt = -1.0;
    }
    if (frame.note == "loaded" && sinceAsked) loadedAt = *sinceAsked;
    if (frame.note == "offered" && sinceAsked) {
      latencies.push_back(*sinceAsked);
      std::printf("  %.0f ms, %zu frames", *sinceAsked, framesSince);
      if (loadedAt >= 0.0) std::printf(", loaded at %.0f ms", loadedAt);
      const std::vector<double>& a = frames[asked].groupCpu;
      const std::vector<double>& b = frame.groupCpu;
      if (a.size() == 5 && b.size() == 5) {
        // The rest from the process's clock: it counts the threads that ended meanwhile.
        const double rest = (b[4] - a[4]) - (b[0] - a[0]) - (b[1] - a[1]) - (b[2] - a[2]);
        std::printf(": %.0f, %.0f, %.0f, %.0f; %.0f", b[0] - a[0], b[1] - a[1], b[2] - a[2], rest,
                    b[4] - a[4]);
      }
      std::printf("\n");
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
