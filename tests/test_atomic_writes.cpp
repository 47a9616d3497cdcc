// Saves are atomic (issue 6, item 4): a child process writes designs, SVG crease patterns and FOLD
// files over the same paths in a loop and is killed with SIGKILL at random moments. After every
// kill each target is absent or whole (it parses, and equals one of the contents written), and
// whatever else is left is a temporary file that no reader would take for a target. A write in
// place (the target opened, truncated and written, no rename) is also seen directly, every run:
// the kernel's notices on the folder (inotify) name a target written, where a random kill
// lands inside its short write only now and then (one run in three missed it).
#include <signal.h>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "engine/fabrication/svg_crease_pattern.hpp"
#include "engine/io/design_document.hpp"
#include "engine/io/fold_format.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "io_test_support.hpp"

namespace curvefold {
namespace {

namespace fs = std::filesystem;
using curvefold::testing::ScratchDirectory;

using AtomicWrites = ScratchDirectory;

// The file's last non-space characters are `suffix`.
bool endsWithTrimmed(std::string text, std::string_view suffix) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text.ends_with(suffix);
}

TEST_F(AtomicWrites, KilledWriterLeavesOnlyWholeFiles) {
  // A megabyte or more each, so that a kill often lands inside a write.
  const Sheet sheets[2] = {makeSurface("square", {{"resolution", 60}}),
                           makeSurface("rectangle", {{"resolution", 60}})};
  const Design designs[2] = {{sheets[0], {}}, {sheets[1], {}}};
  const std::string names[3] = {"sheet.curvefold.json", "sheet.svg", "sheet.fold"};
  // Step k writes target k % 3 with content (k / 3) % 2.
  auto write = [&](const fs::path& dir, int step) {
    const int file = step % 3, which = (step / 3) % 2;
    if (file == 0) saveDesign(designs[which], dir / names[0]);
    if (file == 1) writeSvgCreasePattern(sheets[which], dir / names[1]);
    if (file == 2) writeFold(sheets[which], dir / names[2]);
  };

  // The complete contents of each target, two apiece, and how long one cycle of writes takes.
  std::vector<std::string> complete[3];
  const fs::path reference = dir() / "reference", target = dir() / "target";
  fs::create_directories(reference);
  fs::create_directories(target);
  const auto start = std::chrono::steady_clock::now();
  for (int step = 0; step < 6; ++step) {
    write(reference, step);
    complete[step % 3].push_back(readText(reference / names[step % 3]));
  }
  const int cycleMs = int(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  for (int i = 0; i < 3; ++i) ASSERT_NE(complete[i][0], complete[i][1]) << names[i];
  ASSERT_GT(complete[0][0].size(), 1u << 20);

  // The folder's notices: a target created, written or closed after writing is a write in
  // place, which a reader could find half-written (the writer only writes its temporaries and
  // renames them over the targets).
  const int notices = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  ASSERT_GE(notices, 0);
  ASSERT_GE(::inotify_add_watch(notices, target.c_str(), IN_CREATE | IN_MODIFY | IN_CLOSE_WRITE),
            0);
  std::string writtenInPlace;  // the first target so written, with its notice
  auto readNotices = [&] {
    alignas(inotify_event) char buffer[1 << 16];
    for (ssize_t got; (got = ::read(notices, buffer, sizeof buffer)) > 0;)
      for (const char* at = buffer; at < buffer + got;) {
        const auto* event = reinterpret_cast<const inotify_event*>(at);
        const std::string name = event->len > 0 ? event->name : "";
        if (writtenInPlace.empty() &&
            std::find(std::begin(names), std::end(names), name) != std::end(names))
          writtenInPlace = name + " (inotify mask " + std::to_string(event->mask) + ")";
        at += sizeof(inotify_event) + event->len;
      }
  };

  // Kills spread over a cycle and a half; the writer starts at a different step each round.
  std::mt19937 random(6);  // fixed, so a failure repeats
  std::uniform_int_distribution<int> delayMs(0, cycleMs * 3 / 2);
  int killedWithTemporary = 0, targetsSeen = 0;
  for (int round = 0; round < 20; ++round) {
    const int delay = delayMs(random);
    SCOPED_TRACE("round " + std::to_string(round) + ", killed after " + std::to_string(delay) +
                 " ms");
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      // The writer: every target in turn, alternating contents, until killed.
      try {
        for (int step = round;; ++step) write(target, step);
      } catch (...) {
      }
      ::_exit(1);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(delay));
    ASSERT_EQ(::kill(child, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "the writer failed";

    for (int i = 0; i < 3; ++i) {
      const fs::path path = target / names[i];
      if (!fs::exists(path)) continue;
      ++targetsSeen;
      const std::string text = readText(path);
      // Each parses as its format.
      if (i == 0) {
        EXPECT_NO_THROW(loadDesign(path));
      } else if (i == 1) {
        EXPECT_TRUE(endsWithTrimmed(text, "</svg>"));
      } else {
        EXPECT_TRUE(nlohmann::json::accept(text));
      }
      EXPECT_TRUE(text == complete[i][0] || text == complete[i][1])
          << names[i] << " is not one of the contents written (" << text.size() << " bytes)";
    }
    // Anything else is the killed writer's temporary file: hidden, named after its target and the
    // writer, and ending in neither a target's name nor its extension.
    const std::regex temporary(R"(\.sheet\.(curvefold\.json|svg|fold)\.tmp-)" +
                               std::to_string(child) + R"(-\d+)");
    for (const auto& entry : fs::directory_iterator(target)) {
      const std::string name = entry.path().filename().string();
      if (std::find(std::begin(names), std::end(names), name) != std::end(names)) continue;
      EXPECT_TRUE(std::regex_match(name, temporary)) << "unexpected file " << name;
      for (const char* extension : {".json", ".svg", ".fold"})
        EXPECT_FALSE(name.ends_with(extension)) << name;
      ++killedWithTemporary;
      fs::remove(entry.path());
    }
    readNotices();
    EXPECT_EQ(writtenInPlace, "") << "a target was written in place, not renamed over";
    if (!writtenInPlace.empty()) break;  // the rounds after would say it again
  }
  // Most kills land inside a write (informative: timing decides).
  std::printf("cycle %d ms; %d of 20 kills left a temporary file; %d targets checked\n", cycleMs,
              killedWithTemporary, targetsSeen);
  ::close(notices);
  EXPECT_GT(targetsSeen, 0) << "the writer never finished a file: nothing was checked";
}

}  // namespace
}  // namespace curvefold
