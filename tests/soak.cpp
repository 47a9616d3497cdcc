// Soak: many random folds in a row on every initial surface, with random cancels, undos and redos
// among them; every invariant is checked after every step (docs/design.md 8). ctest runs it small;
// scripts/soak.sh runs 1,000 steps on 20k-triangle sheets.
//
//   curvefold_soak [--steps N] [--triangles T] [--seed S] [--surface NAME]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include <glm/geometric.hpp>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {
namespace {

struct Options {
  int steps = 1000;
  std::size_t triangles = 20'000;
  std::uint64_t seed = 1;
  std::string surface;  // empty: every surface
};

// The surface at about `triangles` triangles (resolution scales the count quadratically).
Sheet surfaceOfSize(const std::string& name, std::size_t triangles) {
  double resolution = 40;
  Sheet sheet = makeSurface(name, {{"resolution", resolution}});
  for (int i = 0; i < 2; ++i) {
    resolution = std::round(resolution * std::sqrt(double(triangles) / sheet.triangleCount()));
    resolution = std::clamp(resolution, 3.0, 2000.0);
    sheet = makeSurface(name, {{"resolution", resolution}});
  }
  return sheet;
}

bool soak(const std::string& name, const Options& options) {
  FoldSession session(surfaceOfSize(name, options.triangles));
  const Sheet& initial = session.initial();
  const SheetReport before = measure(initial);
  const double size = before.size;
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : initial.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::dvec3 centre = 0.5 * (lo + hi), extent = 0.75 * (hi - lo) + glm::dvec3(0.01 * size);
  std::mt19937_64 random(options.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int folds = 0, cancels = 0, undos = 0, redos = 0;
  double worstError = 0.0, thinnest = before.minRelativeHeight;
  int refused = 0;

  for (int step = 0; step < options.steps; ++step) {
    // Redo only exists right after undos, so it is likelier there.
    const double action = unit(random), redoChance = session.canRedo() ? 0.4 : 0.0;
    std::string what;
    if (action < 0.06) {
      what = "undo";
      undos += session.undo();
    } else if (action < 0.06 + redoChance) {
      what = "redo";
      redos += session.redo();
    } else {
      // Grab a random point of the current sheet, drag through a few random targets.
      const Sheet& fixed = session.fixed();
      const auto t = static_cast<TriangleIndex>(random() % fixed.triangleCount());
      double a = unit(random), b = unit(random);
      if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
      session.beginDrag({t, {1.0 - a - b, a, b}});
      const int updates = 1 + static_cast<int>(random() % 3);
      for (int u = 0; u < updates; ++u)
        session.updateDrag(centre + extent * glm::dvec3(2 * unit(random) - 1, 2 * unit(random) - 1,
                                                        2 * unit(random) - 1));
      if (unit(random) < 0.1) {
        what = "cancel";
        session.cancel();
        ++cancels;
      } else {
        what = "fold";
        const bool kept = session.commit();
        folds += kept;
        refused += !kept && !session.refusal().empty();
      }
    }
    const Sheet& sheet = session.current();
    const SheetReport now = measure(sheet);
    worstError = std::max(worstError, now.maxEdgeLengthError);
    thinnest = std::min(thinnest, now.minRelativeHeight);
    std::string problem = now.firstProblem;
    if (problem.empty() && now.eulerCharacteristic != before.eulerCharacteristic)
      problem = "Euler characteristic changed";
    if (problem.empty() && now.boundaryLoopCount != before.boundaryLoopCount)
      problem = "boundary loop count changed";
    if (problem.empty() && now.maxEdgeLengthError > 1e-9 * size)
      problem = "edge-length error above 1e-9 of the size";
    if (!problem.empty()) {
      std::fprintf(stderr, "%s: step %d (%s, seed %llu): %s\n", name.c_str(), step + 1,
                   what.c_str(), static_cast<unsigned long long>(options.seed), problem.c_str());
      return false;
    }
  }
  const std::size_t grown = session.fixed().triangleCount() - initial.triangleCount();
  std::printf(
      "%-14s %7zu -> %7zu triangles, %4zu folds kept (%d committed, %d cancelled, %d undone, %d "
      "redone, %d refused), %.1f triangles per kept fold, worst edge error %.2g and thinnest "
      "triangle %.2g of the size\n",
      name.c_str(), initial.triangleCount(), session.fixed().triangleCount(), session.foldCount(),
      folds, cancels, undos, redos, refused,
      session.foldCount() ? double(grown) / session.foldCount() : 0.0, worstError / size, thinnest);
  return true;
}

}  // namespace
}  // namespace curvefold

int main(int argc, char** argv) {
  curvefold::Options options;
  // Options come in pairs: --name value.
  for (int i = 1; i < argc; i += 2) {
    const std::string arg = argv[i];
    const char* value = i + 1 < argc ? argv[i + 1] : nullptr;
    if (!value) {
      std::fprintf(stderr, "curvefold_soak: %s needs a value\n", arg.c_str());
      return 2;
    }
    if (arg == "--steps")
      options.steps = std::atoi(value);
    else if (arg == "--triangles")
      options.triangles = std::strtoull(value, nullptr, 10);
    else if (arg == "--seed")
      options.seed = std::strtoull(value, nullptr, 10);
    else if (arg == "--surface")
      options.surface = value;
    else {
      std::fprintf(stderr, "curvefold_soak: unknown option %s\n", arg.c_str());
      return 2;
    }
  }
  bool ok = true;
  for (const curvefold::SurfaceInfo& surface : curvefold::surfaceCatalog())
    if (options.surface.empty() || options.surface == surface.name)
      ok &= curvefold::soak(surface.name, options);
  return ok ? 0 : 1;
}
