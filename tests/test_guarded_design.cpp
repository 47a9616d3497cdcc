// GuardedDesign (issue 40, 2), the Python module's Design: many threads fold, undo, redo, read,
// check and export one design at once, as Python threads do with the GIL released. Run in the
// plain suite and under ThreadSanitizer (scripts/test-sanitized.sh, the "tsan" preset), where a
// use of the session outside the design's lock is reported as a data race.
#include <atomic>
#include <chrono>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "app/session/design_check.hpp"
#include "app/session/guarded_design.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/io/fold_format.hpp"

namespace curvefold::session {
namespace {

Design coarseSquare() {
  // Coarse: under ThreadSanitizer a fold takes about ten times as long.
  return Design{GeneratedSurface{"square", {{"resolution", 8.0}}}, {}};
}

// Folds near random points of the square, each dropped toward the middle and up, as
// python/tests/thread_scenarios.py makes them; a fold the session refuses is counted, not thrown.
void foldAtRandom(GuardedDesign& design, unsigned seed, int folds, std::atomic<int>& refused) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> along(-0.09, 0.09);
  for (int i = 0; i < folds; ++i) {
    const glm::dvec3 grab{along(random), along(random), 0.0};
    const glm::dvec3 to{0.8 * grab.x, 0.8 * grab.y, 0.03};
    const GuardedDesign::Lock lock(design);
    try {
      design.fold(lock, grab, to);
    } catch (const std::exception&) {
      ++refused;
    }
  }
}

// A mutex is not fair: a thread that takes the lock again at once can keep it from the folders
// waiting on it. Under ThreadSanitizer on 2 idle cores one looping thread did, for 60-170 s a run
// (1-3 s when it let them in).
void letTheFoldersIn() {
  std::this_thread::sleep_for(std::chrono::microseconds(100));
}

// Every triangle names vertices of its own sheet, and development and positions agree in count.
bool consistent(const Sheet& sheet) {
  for (const auto& triangle : sheet.triangles)
    for (const auto corner : triangle)
      if (corner.value >= sheet.positions.size()) return false;
  return sheet.development.size() == sheet.positions.size();
}

TEST(GuardedDesign, ManyThreadsFoldUndoReadCheckAndExportOneDesign) {
  GuardedDesign design(coarseSquare(), "square");
  std::atomic<int> refused{0}, inconsistent{0}, reads{0};
  std::atomic<bool> folding{true};
  std::vector<std::thread> threads;
  threads.emplace_back([&] { foldAtRandom(design, 1, 8, refused); });
  threads.emplace_back([&] { foldAtRandom(design, 2, 8, refused); });
  std::thread undoer([&] {
    while (folding) {
      {
        const GuardedDesign::Lock lock(design);
        design.session(lock).undo();
      }
      {
        const GuardedDesign::Lock lock(design);
        design.session(lock).redo();
      }
      letTheFoldersIn();
    }
  });
  auto reader = [&](bool exportIt) {
    while (folding) {
      std::shared_ptr<const Sheet> sheet;
      Design whole;
      {
        const GuardedDesign::Lock lock(design);
        sheet = design.snapshot(lock);
        whole = design.design(lock);
      }
      // Outside the lock, as the module's export and arrays read it.
      if (!consistent(*sheet)) ++inconsistent;
      if (exportIt && foldText(*sheet).empty()) ++inconsistent;
      ++reads;
      letTheFoldersIn();
    }
  };
  std::thread arrays(reader, false), exporter(reader, true);
  std::thread checker([&] {
    while (folding) {
      {
        const GuardedDesign::Lock lock(design);
        checkDesign(design.design(lock), design.name(), design.session(lock).initial(),
                    *design.snapshot(lock), true);
      }
      letTheFoldersIn();
    }
  });
  for (std::thread& folder : threads) folder.join();
  folding = false;
  for (std::thread* thread : {&undoer, &arrays, &exporter, &checker}) thread->join();

  EXPECT_EQ(inconsistent, 0);
  EXPECT_GT(reads, 0);
  const GuardedDesign::Lock lock(design);
  const Design whole = design.design(lock);
  EXPECT_GT(whole.folds.size(), 0u);
  EXPECT_LE(whole.folds.size() + std::size_t(refused), 16u);
  const std::shared_ptr<const Sheet> sheet = design.snapshot(lock);
  EXPECT_NO_THROW(validate(*sheet));
  // The history and the sheet agree: the folds made again from scratch give the same sheet.
  GuardedDesign again(whole, "again");
  const GuardedDesign::Lock againLock(again);
  EXPECT_EQ(again.snapshot(againLock)->positions, sheet->positions);
}

TEST(GuardedDesign, SeparateDesignsFoldInParallel) {
  GuardedDesign first(coarseSquare(), "first"), second(coarseSquare(), "second");
  std::atomic<int> refused{0};
  std::thread a([&] { foldAtRandom(first, 3, 4, refused); });
  std::thread b([&] { foldAtRandom(second, 3, 4, refused); });
  a.join();
  b.join();
  const GuardedDesign::Lock lockFirst(first), lockSecond(second);
  EXPECT_EQ(first.snapshot(lockFirst)->positions, second.snapshot(lockSecond)->positions);
}

TEST(GuardedDesign, AnotherDesignsLockIsRefused) {
  GuardedDesign first(coarseSquare(), "first"), second(coarseSquare(), "second");
  const GuardedDesign::Lock lock(first);
  EXPECT_THROW(second.snapshot(lock), std::logic_error);
  EXPECT_THROW(second.session(lock), std::logic_error);
}

}  // namespace
}  // namespace curvefold::session
