// `curvefold fit` and `curvefold distance` (issue 27): folding toward a target shape, and how far
// two shapes lie apart.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "app/commands.hpp"
#include "app/document.hpp"
#include "app/studio_target.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/design_document.hpp"
#include "engine/io/output_set.hpp"
#include "engine/io/sheet_cache.hpp"
#include "engine/surfaces/obj_surface.hpp"
#include "engine/text/input_path.hpp"
#include "sim_input/player.hpp"

namespace curvefold::cli {
namespace {

namespace fs = std::filesystem;

// A seed: a whole number from 0 to 2^64 - 1, digits only.
std::uint64_t parseSeed(const std::string& text) {
  std::uint64_t seed = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seed);
  if (text.empty() || error != std::errc() || end != text.data() + text.size())
    throw UsageError("--seed: expected a whole number from 0 to 18446744073709551615, got '" +
                     text.substr(0, 40) + (text.size() > 40 ? "...'" : "'"));
  return seed;
}

// A shape to measure: an OBJ, or a design's folded form.
TriangleMesh shapeOf(const std::string& path) {
  if (hasExtension(path, ".obj")) return readObjMesh(path);
  const Design design = loadDesign(path);
  return meshOf(buildSheetCached(design, path));
}

}  // namespace

void addFitCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "fit", "Find reflection folds that bring a surface close to a target shape (an OBJ)");
  struct Options {
    std::string target, output, log;
    SurfaceOptions from;
    std::size_t folds = 6;
    double seconds = 60.0;
    std::string seed = "1";
    bool allowSelfIntersection = false;
  };
  auto options = std::make_shared<Options>();
  command->add_option("TARGET", options->target, "The shape to fold toward: a triangle mesh (.obj)")
      ->required();
  command
      ->add_option("--from", options->from.surface,
                   "The surface to fold: a name (see `surfaces`) or an .obj file")
      ->required();
  addSurfaceOptions(command, options->from);
  command->add_option("--folds", options->folds, "At most this many folds (each must help)")
      ->check(CLI::Range(1, 64));
  command->add_option("--time", options->seconds, "Stop within this many seconds")
      ->check(CLI::Range(0.1, 86400.0));
  command->add_option("--seed", options->seed,
                      "Seed of the search (the same seed, the same folds)");
  command->add_flag("--allow-self-intersection", options->allowSelfIntersection,
                    "Let a fold pass the sheet through itself");
  command->add_option("--log", options->log,
                      "Per-fold log (JSON lines) with each fold's distance to the target");
  command->add_option("-o,--output", options->output, "Design file to write (*.curvefold.json)")
      ->required();
  command->callback([options, command] {
    // Everything that can be refused is refused before the search (a NaN passes a range check).
    if (!(options->seconds >= 0.1 && options->seconds <= 86400.0))
      throw UsageError("--time: expected seconds from 0.1 to 86400, got " +
                       std::to_string(options->seconds));
    refuseOutputsOverInputs(
        {options->output, options->log},
        {{options->target, "the target"},
         {hasExtension(options->from.surface, ".obj") ? options->from.surface : "",
          "the surface read (--from)"}});
    Design design = designFromSurfaceOptions(options->from, command, options->output);
    TriangleMesh target = readObjMesh(options->target);
    FitSettings settings;
    settings.seed = parseSeed(options->seed);
    settings.allowSelfIntersection = options->allowSelfIntersection;
    std::unique_ptr<FoldFitter> fitter;
    try {
      fitter = std::make_unique<FoldFitter>(std::move(target), settings);
    } catch (const InvalidTarget& e) {
      throw UsageError(options->target + ": " + e.what());
    }
    const Sheet initial = initialSheet(design, options->output);
    FoldSession session(initial);
    if (!design.symmetry.empty()) session.setSymmetry(parseSymmetry(design.symmetry, initial));
    try {
      fitter->checkAgainst(initial);
    } catch (const InvalidTarget& e) {
      throw UsageError(options->target + ": " + e.what());
    }

    std::vector<FoldLogEntry> log;
    std::size_t trianglesBefore = initial.triangleCount();
    FitOptions fit;
    fit.maxFolds = options->folds;
    fit.seconds = options->seconds;
    fit.progress = [&](const FitProgress& step) {
      if (step.fold == 0) {
        std::cout << "start: " << studio::distanceText(step.hausdorff, step.chamfer, step.diagonal)
                  << " of the target's " << step.diagonal << " m diagonal" << std::endl;
        return;
      }
      // The group just committed: the fold and its images.
      const std::vector<FoldRecord>& folds = session.folds();
      std::size_t first = session.foldCount() - 1;
      while (first > 0 && folds[first].group != 0 && folds[first - 1].group == folds[first].group)
        --first;
      const Sheet& sheet = session.fixed();
      FoldLogEntry entry;
      entry.time = step.seconds;
      entry.fold = first + 1;
      entry.foldCount = session.foldCount();
      entry.plane = folds[first].plane;
      entry.trianglesBefore = trianglesBefore;
      entry.trianglesAfter = trianglesBefore = sheet.triangleCount();
      entry.maxEdgeLengthError = maxEdgeLengthError(sheet);
      entry.selfIntersections = findSelfIntersections(sheet).intersections.size();
      entry.images = session.foldCount() - first - 1;
      entry.hausdorff = step.hausdorff;
      entry.chamfer = step.chamfer;
      entry.targetDiagonal = step.diagonal;
      log.push_back(entry);
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%.1f s", step.seconds);
      std::cout << "fold " << step.fold
                << (entry.images ? " (+" + std::to_string(entry.images) + " images)" : "") << ", "
                << seconds << ": "
                << studio::distanceText(step.hausdorff, step.chamfer, step.diagonal) << std::endl;
    };
    fit.searching = [](std::size_t depth, double distance, double seconds) {
      char text[96];
      std::snprintf(text, sizeof text, "searching: %zu folds, best %s (approximate), %.1f s", depth,
                    studio::millimetresText(distance).c_str(), seconds);
      std::cout << text << std::endl;
    };
    // The outputs, checked before the search: a path that cannot be written fails now.
    OutputSet outputs;
    outputs.add(options->output, [&](const fs::path& at) { saveDesign(design, at); });
    if (!options->log.empty())
      outputs.add(options->log, [&](const fs::path& at) {
        std::string text;
        for (const FoldLogEntry& entry : log) text += foldLogLine(entry) + "\n";
        writeFileAtomically(at, text);
      });
    outputs.checkWritable();
    const FitResult result = fitFolds(session, *fitter, fit);
    design.folds = result.folds;

    outputs.write();
    const FitProgress& last = result.steps.back();
    std::cout << "stopped: " << result.stopReason << "\n"
              << "wrote " << options->output << " (" << log.size() << " folds"
              << (design.folds.size() > log.size()
                      ? ", " + std::to_string(design.folds.size()) + " with images"
                      : "")
              << "; " << studio::distanceText(last.hausdorff, last.chamfer, last.diagonal) << ")\n";
    if (!options->log.empty()) std::cout << "wrote " << options->log << "\n";
  });
}

void addDistanceCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "distance",
      "How far two shapes (designs or OBJs) lie apart: Hausdorff and Chamfer distances");
  struct Options {
    std::string a, b;
    std::size_t samples = kDefaultDistanceSamples;
    std::string seed = "1";
  };
  auto options = std::make_shared<Options>();
  command->add_option("A", options->a, "A design (*.curvefold.json, its folded form) or an .obj")
      ->required();
  command->add_option("B", options->b, "The reference shape (a target): a design or an .obj")
      ->required();
  command->add_option("--samples", options->samples, "Area-uniform samples on each surface")
      ->check(CLI::Range(100, 10'000'000));
  command->add_option("--seed", options->seed, "Seed of the samples");
  command->callback([options] {
    parseSeed(options->seed);  // refused before the shapes are read
    const TriangleMesh a = shapeOf(options->a);
    const TriangleMesh b = shapeOf(options->b);
    SurfaceDistance d;
    try {
      d = surfaceDistance(a, b, options->samples, parseSeed(options->seed));
    } catch (const DegenerateMesh& e) {
      throw UsageError(
          std::string(e.what()) + " (" +
          (std::string(e.what()).find("first") != std::string::npos ? options->a : options->b) +
          ")");
    }
    std::cout << "A -> B: max " << studio::millimetresText(d.fromAMax) << ", mean "
              << studio::millimetresText(d.fromAMean) << "\n"
              << "B -> A: max " << studio::millimetresText(d.fromBMax) << ", mean "
              << studio::millimetresText(d.fromBMean) << "\n"
              << "Hausdorff (two-sided): " << studio::millimetresText(d.hausdorff) << " ("
              << studio::percentText(d.relativeHausdorff()) << " of B's diagonal, " << d.diagonal
              << " m)\n"
              << "Chamfer (mean two-sided): " << studio::millimetresText(d.chamfer) << " ("
              << studio::percentText(d.relativeChamfer()) << ")\n";
  });
}

}  // namespace curvefold::cli
