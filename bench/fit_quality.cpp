// How well `curvefold fit` reaches targets (issues 27, 38): the quality tables of the README and
// docs/performance.md.
//
//   build/bench/fit_quality [--recipes a,b] [--buckets 1-2,3-4,5-8] [--per-bucket K]
//                           [--seconds S] [--seed-offset K] [--shapes | --shapes-only]
//                           [--shape-folds N] [--shape-evaluations E]
//                           [--shape-file OBJ[:KIND]]... [--no-symmetry] [--any-start]
//                           [--no-own-shapes] [--write-targets DIR]
//
// Reachable targets, per recipe of tests/support/fold_target_generators.hpp and per bucket of fold
// counts: K targets (the catalogue's surfaces in turn, at their defaults, each design passing
// `check`), exported as `export --obj` less its vt lines, fitted from the same surface (and
// symmetry) with `--folds N --time S`; the table counts the fits whose two-sided Hausdorff distance
// (surface_distance.hpp) is at most 1% and 3% of the target's diagonal. Shapes no reflection
// sequence reaches (--shapes): the distance after each fold, against a random search given the
// same time (random drags of random samples, each kept when it brings the sheet closer).
// --any-start: the benchmark's own shapes start from any kind (as `fit` without --from), not the
// kind each names; --no-own-shapes: only the --shape-file shapes. --shape-evaluations E: each
// shape's fit stops after E candidate folds scored (`fit --evaluations`: the same design on a
// loaded machine as on an idle one, while --seconds is not reached); the random search then gets
// the fit's own wall time.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "engine/fit/crease_planes.hpp"
#include "engine/fit/fit_start.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/start_surface.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/fit/target_unfolding.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/surfaces/obj_surface.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "tests/support/fold_target_generators.hpp"

namespace curvefold {
namespace {

struct Case {
  const char* surface;
  SurfaceParameters parameters;
};

void writeObj(const TriangleMesh& mesh, const std::filesystem::path& path) {
  std::ofstream out(path);
  out.precision(9);
  for (const glm::dvec3& p : mesh.positions) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
  for (const auto& t : mesh.triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

// A grid of (u, v) in [0, 1]^2 mapped by f, two triangles a cell.
template <typename F>
TriangleMesh gridMesh(int nu, int nv, F f) {
  TriangleMesh mesh;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) mesh.positions.push_back(f(double(i) / nu, double(j) / nv));
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

struct Shape {
  const char* name;
  Case from;
  TriangleMesh mesh;
};

Shape shapeOf(const char* name, const char* surface, double resolution, TriangleMesh mesh) {
  Shape shape{name, {surface, {}}, std::move(mesh)};
  shape.from.parameters["resolution"] = resolution;
  return shape;
}

std::vector<Shape> unreachableShapes() {
  using std::numbers::pi;
  std::vector<Shape> shapes;
  // A hemisphere bowl of radius 7 cm (its area near the 10 cm disk's), opening up.
  shapes.push_back(shapeOf("bowl", "disk", 32, gridMesh(48, 16, [](double u, double v) {
                             const double theta = 2 * pi * u, phi = 0.5 * pi * v;
                             return glm::dvec3(0.07 * std::sin(phi) * std::cos(theta),
                                               0.07 * std::sin(phi) * std::sin(theta),
                                               -0.07 * std::cos(phi) + 0.035);
                           })));
  // A vase about the y axis, 21 cm tall: a waist and a lip around the default cylinder's 4.5 cm.
  shapes.push_back(shapeOf("vase", "cylinder", 40, gridMesh(48, 24, [](double u, double v) {
                             const double theta = 2 * pi * u, y = 0.21 * (v - 0.5);
                             const double r = 0.045 * (1.0 + 0.25 * std::cos(2 * pi * v) - 0.1 * v);
                             return glm::dvec3(r * std::sin(theta), y, r * std::cos(theta));
                           })));
  // A saddle z = (x^2 - y^2) / 0.3 over the 20 cm square.
  shapes.push_back(shapeOf("saddle", "square", 30, gridMesh(30, 30, [](double u, double v) {
                             const double x = 0.2 * (u - 0.5), y = 0.2 * (v - 0.5);
                             return glm::dvec3(x, y, (x * x - y * y) / 0.3);
                           })));
  return shapes;
}

// Random drags for `seconds`, each kept when it lowers the approximate distance: the baseline.
double randomSearch(const Sheet& initial, const std::string& symmetry, const FoldFitter& fitter,
                    double seconds, std::size_t folds, std::uint64_t seed) {
  FoldSession session(initial);
  if (!symmetry.empty()) session.setSymmetry(parseSymmetry(symmetry, initial));
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const TriangleMesh& target = fitter.target();
  double best = fitter.approximateDistance(session.fixed());
  const Deadline deadline = Deadline::in(seconds);
  while (!deadline.passed() && session.foldCount() < folds) {
    const Sheet& sheet = session.fixed();
    const auto v = static_cast<VertexIndex>(unit(random) * (sheet.vertexCount() - 1));
    const glm::dvec3 drop =
        target.positions[static_cast<std::size_t>(unit(random) * (target.positions.size() - 1))];
    session.beginDragAtDevelopment(sheet.development[v]);
    session.updateDrag(drop);
    if (!session.commit()) continue;
    const double score = fitter.approximateDistance(session.fixed());
    if (score < best && findSelfIntersections(session.fixed()).intersections.empty())
      best = score;
    else
      session.undo();
  }
  return surfaceDistance(meshOf(session.fixed()), target).chamfer;
}

// Sorted copy's middle.
double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

struct Bucket {
  std::size_t lo, hi;
};

// Reachable targets by recipe (tests/support/fold_target_generators.hpp) and fold count: each
// target made on the catalogue surfaces in turn at their defaults, exported as `export --obj`
// without vt, fitted as `fit TARGET --from SURFACE [--symmetry S] --folds N --time T` would, and
// measured by the project's two-sided Hausdorff distance (surface_distance.hpp).
void reachableTable(const std::vector<std::string>& recipes, const std::vector<Bucket>& buckets,
                    std::size_t perBucket, double seconds, const std::string& writeTargets,
                    std::uint64_t seedOffset) {
  std::vector<std::string> surfaces;
  for (const SurfaceInfo& info : surfaceCatalog()) surfaces.push_back(info.name);
  std::printf(
      "| recipe | folds | targets | Hausdorff <= 1%% | <= 3%% | unfolded | median Hausdorff | "
      "median time |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const testing::FoldTargetRecipe& recipe : testing::foldTargetRecipes()) {
    if (!recipes.empty() && std::find(recipes.begin(), recipes.end(), recipe.name) == recipes.end())
      continue;
    for (std::size_t b = 0; b < buckets.size(); ++b) {
      const Bucket bucket = buckets[b];
      std::vector<double> distances, times;
      std::size_t unfolded = 0;
      for (std::size_t k = 0, made = 0; made < perBucket && k < 8 * perBucket + 8; ++k) {
        const std::size_t n = bucket.lo + made % (bucket.hi - bucket.lo + 1);
        const std::string& surface =
            surfaces[(made * 4 + b + recipe.name.size()) % surfaces.size()];
        const std::uint64_t seed = 7919 * (b + 1) + 104729 * k + recipe.name.size() + seedOffset;
        std::optional<testing::FoldTarget> target;
        try {
          target = testing::makeFoldTarget(recipe, surface, n, seed);
        } catch (const std::exception& e) {
          std::fprintf(stderr, "%s %s seed %llu: %s\n", recipe.name.c_str(), surface.c_str(),
                       static_cast<unsigned long long>(seed), e.what());
        }
        if (!target) continue;
        ++made;
        const std::string name =
            recipe.name + "-" + surface + "-" + std::to_string(n) + "folds-" + std::to_string(seed);
        if (!writeTargets.empty())
          writeObj(target->exported, std::filesystem::path(writeTargets) / (name + ".obj"));
        const FoldFitter fitter(target->exported);
        FoldSession session(target->initial);
        if (!target->design.symmetry.empty())
          session.setSymmetry(parseSymmetry(target->design.symmetry, target->initial));
        FitOptions options;
        options.maxFolds = n;
        options.seconds = seconds;
        const auto begun = std::chrono::steady_clock::now();
        const FitResult result = fitFolds(session, fitter, options);
        times.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count());
        const SurfaceDistance d = surfaceDistance(meshOf(session.fixed()), target->exported);
        distances.push_back(d.relativeHausdorff());
        unfolded += result.stopReason.rfind("the target unfolded", 0) == 0;
        // What the unfolding alone reads (for finding why a fit missed).
        const TargetUnfolding plan = unfoldTarget(target->exported, meshOf(target->initial),
                                                  sharpEdgeThreshold(meshOf(target->initial)), n);
        std::fprintf(stderr,
                     "%s: %zu folds kept, Hausdorff %.3g%%, %.1f s (%s); unfolding read %zu, "
                     "%.3g diagonals of crease left\n",
                     name.c_str(), result.steps.size() - 1, 100 * distances.back(), times.back(),
                     result.stopReason.c_str(), plan.folds.size(),
                     plan.sharpLengthLeft / d.diagonal);
      }
      std::size_t within1 = 0, within3 = 0;
      for (double d : distances) {
        within1 += d <= 0.01;
        within3 += d <= 0.03;
      }
      const double count = std::max<double>(1.0, distances.size());
      std::printf("| %s | %zu-%zu | %zu | %zu (%.0f%%) | %zu (%.0f%%) | %zu | %.3g%% | %.1f s |\n",
                  recipe.name.c_str(), bucket.lo, bucket.hi, distances.size(), within1,
                  100.0 * within1 / count, within3, 100.0 * within3 / count, unfolded,
                  100 * median(distances), median(times));
      std::fflush(stdout);
    }
  }
}

int run(int argc, char** argv) {
  std::size_t perBucket = 4, shapeFolds = 16;
  std::uint64_t seedOffset = 0, shapeEvaluations = 0;
  std::vector<std::string> shapeFiles;
  std::vector<std::string> kinds;
  kinds.reserve(64);
  double seconds = 60.0;
  std::vector<Bucket> buckets = {{1, 2}, {3, 4}, {5, 8}};
  std::vector<std::string> recipes;
  bool shapes = false, reachable = true, useSymmetry = true, anyStart = false, ownShapes = true;
  std::string writeTargets;
  auto split = [](const std::string& text) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ',');)
      if (!part.empty()) parts.push_back(part);
    return parts;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--per-bucket")
      perBucket = std::stoul(next());
    else if (arg == "--seconds")
      seconds = std::stod(next());
    else if (arg == "--buckets") {
      buckets.clear();
      for (const std::string& part : split(next())) {
        const std::size_t dash = part.find('-');
        const std::size_t lo = std::stoul(part.substr(0, dash));
        buckets.push_back({lo, dash == std::string::npos ? lo : std::stoul(part.substr(dash + 1))});
        if (buckets.back().hi < lo) throw std::runtime_error("--buckets: " + part);
      }
    } else if (arg == "--recipes")
      recipes = split(next());
    else if (arg == "--seed-offset")
      seedOffset = std::stoull(next());
    else if (arg == "--no-symmetry")
      useSymmetry = false;
    else if (arg == "--any-start")
      anyStart = true;
    else if (arg == "--no-own-shapes")
      ownShapes = false;
    else if (arg == "--shape-file")
      shapeFiles.push_back(next());
    else if (arg == "--shape-folds")
      shapeFolds = std::stoul(next());
    else if (arg == "--shape-evaluations")
      shapeEvaluations = std::stoull(next());
    else if (arg == "--shapes")
      shapes = true;
    else if (arg == "--shapes-only")
      shapes = true, reachable = false;
    else if (arg == "--write-targets")
      writeTargets = next();
    else
      throw std::runtime_error("unknown option " + arg);
  }
  if (!writeTargets.empty()) std::filesystem::create_directories(writeTargets);
  if (reachable) reachableTable(recipes, buckets, perBucket, seconds, writeTargets, seedOffset);
  if (shapes) {
    // Each shape from the start `fit --from KIND` sizes to it (start_surface.hpp), with the
    // target's rotational symmetry, against random drags from the same start in the same time.
    std::printf(
        "\n| shape | from | symmetry | start Chamfer | Chamfer after each fold kept | fit "
        "Chamfer | fit Hausdorff | start / fit | random search Chamfer (same time) | random / "
        "fit |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
    std::vector<Shape> all = ownShapes ? unreachableShapes() : std::vector<Shape>{};
    if (anyStart)
      for (Shape& shape : all) shape.from.surface = "";
    std::vector<std::string> names;  // Shape holds a name's pointer
    names.reserve(shapeFiles.size());
    for (const std::string& file : shapeFiles) {
      const std::size_t colon = file.find(':');
      names.push_back(std::filesystem::path(file.substr(0, colon)).stem().string());
      Shape shape{};
      shape.name = names.back().c_str();
      shape.mesh = readObjMesh(file.substr(0, colon));
      if (colon != std::string::npos)
        kinds.push_back(file.substr(colon + 1));
      else
        kinds.emplace_back();
      shape.from.surface = kinds.back().c_str();
      all.push_back(std::move(shape));
    }
    for (const Shape& shape : all) {
      if (!writeTargets.empty())
        writeObj(shape.mesh,
                 std::filesystem::path(writeTargets) / (std::string(shape.name) + ".obj"));
      const FoldFitter fitter(shape.mesh);
      // The start `fit --from KIND --evaluations` folds (fit_start.hpp: no clock), its runners-up
      // not folded.
      const FitStart chosen = chooseFitStart(fitter, shape.from.surface, std::nullopt, {});
      const StartChoice& start = chosen.choice;
      const Sheet initial =
          start.placed ? *start.placed : makeSurface(start.surface, start.parameters);
      const std::string symmetry =
          useSymmetry ? detectRotationalSymmetry(shape.mesh, initial) : std::string();
      FoldSession session(initial);
      if (!symmetry.empty()) session.setSymmetry(parseSymmetry(symmetry, initial));
      FitOptions options;
      options.maxFolds = shapeFolds;
      options.seconds = seconds;
      options.maxEvaluations = shapeEvaluations;
      options.tubeChains = chosen.tubeChains;  // as fit hands them on
      const FitResult result = fitFolds(session, fitter, options);
      std::string trail;
      for (const FitProgress& step : result.steps) {
        char text[32];
        std::snprintf(text, sizeof text, "%s%.3g", trail.empty() ? "" : ", ", 1000 * step.chamfer);
        trail += text;
      }
      const FitProgress& first = result.steps.front();
      const FitProgress& last = result.steps.back();
      const double random =
          randomSearch(initial, symmetry, fitter, last.seconds, 4 * shapeFolds, 7);
      std::printf(
          "| %s | %s | %s | %.3g%% | %s mm | %.3g%% | %.3g%% | %.2f | %.3g%% | %.2f |\n",
          shape.name, (start.surface + (start.placed ? " (placed)" : "")).c_str(),
          symmetry.empty() ? "none" : symmetry.c_str(), 100 * first.chamfer / first.diagonal,
          trail.c_str(), 100 * last.chamfer / last.diagonal, 100 * last.hausdorff / last.diagonal,
          first.chamfer / last.chamfer, 100 * random / last.diagonal, random / last.chamfer);
      std::fflush(stdout);
    }
  }
  return 0;
}

}  // namespace
}  // namespace curvefold

int main(int argc, char** argv) {
  try {
    return curvefold::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fit_quality: %s\n", e.what());
    return 1;
  }
}
