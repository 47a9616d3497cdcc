// `curvefold simulate`: folds a design's flat sheet (or a crease pattern) with the bar-and-hinge
// simulation (engine/simulation) to a fold amount or through a sequence of them, and writes the
// folded state as OBJ, FOLD, glTF and PNG, a folder of frames or an animated GIF of the folding.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "app/cli/commands.hpp"
#include "app/session/printed_cover.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/crease_pattern.hpp"
#include "engine/io/crease_pattern_reader.hpp"
#include "engine/io/design_document.hpp"
#include "engine/io/fold_crease_pattern.hpp"
#include "engine/io/fold_format.hpp"
#include "engine/io/gltf_writer.hpp"
#include "engine/io/obj_writer.hpp"
#include "engine/io/output_set.hpp"
#include "engine/io/svg_crease_pattern.hpp"
#include "engine/render/color_legend.hpp"
#include "engine/render/gif_animation.hpp"
#include "engine/render/headless_renderer.hpp"
#include "engine/render/image.hpp"
#include "engine/render/scene_builder.hpp"
#include "engine/simulation/bar_hinge_model.hpp"
#include "engine/simulation/contact.hpp"
#include "engine/simulation/design_input.hpp"
#include "engine/simulation/dynamic_solver.hpp"
#include "engine/simulation/folding_motion.hpp"
#include "engine/simulation/simulate_options.hpp"
#include "engine/simulation/state_report.hpp"
#include "engine/simulation/static_solver.hpp"
#include "engine/simulation_vk/gpu_dynamic_solver.hpp"
#include "engine/text/decimal.hpp"
#include "engine/text/environment_choice.hpp"
#include "engine/text/excerpt.hpp"
#include "engine/text/input_path.hpp"

namespace curvefold::cli {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxFrames = 1000;
constexpr std::size_t kMaxSteps = 10'000'000;

// What is simulated: the pattern, and for a design its sheet (tags, seams).
struct SimulationInput {
  CreasePattern pattern;
  Sheet sheet;  // positions are replaced by each simulated state
  std::vector<std::pair<std::uint32_t, std::uint32_t>> seams;
};

// The sheet a crease pattern is written as: development from the pattern, creases and cuts tagged.
Sheet sheetOfPattern(const CreasePattern& pattern) {
  Sheet sheet;
  sheet.development = pattern.vertices;
  sheet.positions.reserve(pattern.vertices.size());
  for (const glm::dvec2& p : pattern.vertices) sheet.positions.emplace_back(p, 0.0);
  for (const auto& t : pattern.triangles) sheet.triangles.push_back({t[0], t[1], t[2]});
  for (const CreasePatternEdge& e : pattern.edges) {
    const Edge edge = Edge::of(e.a, e.b);
    if (e.assignment == CreaseAssignment::Mountain || e.assignment == CreaseAssignment::Valley)
      sheet.tags.push_back({edge, EdgeKind::Crease});
    else if (e.assignment == CreaseAssignment::Cut)
      sheet.tags.push_back({edge, EdgeKind::Slit});
  }
  sheet.normalizeTags();
  return sheet;
}

// A value the engine checks (simulate_options.hpp, setPaperMode, sheetSizeMetres), whose message
// starts with the value's name: a usage error naming the option ("--pin: ...").
template <typename Check>
auto checkedOption(Check check) {
  try {
    return check();
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--") + e.what());
  }
}

// sizeMetres > 0: a crease pattern's larger side (--size).
SimulationInput readInput(const fs::path& path, double sizeMetres, std::string& sizeLine) {
  SimulationInput input;
  // A crease pattern from another tool (docs/formats.md); anything else is a curvefold design.
  if (hasExtension(path, ".fold") || hasExtension(path, ".svg")) {
    // The units as read (how they were found is said), then in metres.
    CreasePattern asRead =
        hasExtension(path, ".svg") ? readSvgCreasePattern(path) : readFoldCreasePattern(path);
    std::string source = asRead.unitSource;
    scaleToMetres(asRead);
    input.pattern = std::move(asRead);
    if (sizeMetres > 0.0) {
      scaleToSize(input.pattern, sizeMetres);
      source = "--size";
    }
    glm::dvec2 low(INFINITY), high(-INFINITY);
    for (const glm::dvec2& v : input.pattern.vertices) {
      low = glm::min(low, v);
      high = glm::max(high, v);
    }
    char line[240];
    std::snprintf(line, sizeof line, "sheet %.4g x %.4g mm (%s)\n", (high.x - low.x) * 1e3,
                  (high.y - low.y) * 1e3, source.c_str());
    sizeLine = line;
    input.sheet = sheetOfPattern(input.pattern);
    return input;
  }
  if (sizeMetres > 0.0)
    throw UsageError("--size: sizes a crease pattern (.fold, .svg); a design is in metres already");
  input.sheet = buildSheet(loadDesign(path), path.string());
  DesignPattern design = designPattern(input.sheet);
  input.pattern = std::move(design.pattern);
  input.seams = std::move(design.seams);
  return input;
}

// "P" or "FROM:TO:N" (N fold amounts from FROM to TO, both included), percent.
std::vector<double> parsePercents(const std::string& text) {
  const auto bad = [&] {
    return UsageError(
        "--percent: expected P or FROM:TO:N with percents from 0 to 100 and N from "
        "2 to " +
        std::to_string(kMaxFrames) + ", got " + quotedExcerpt(text));
  };
  const auto percent = [&](std::string_view part) {
    double value = 0.0;
    if (!readDecimal(part, value) || !(value >= 0.0 && value <= 100.0)) throw bad();
    return value;
  };
  const std::size_t first = text.find(':');
  if (first == std::string::npos) return {percent(text)};
  const std::size_t second = text.find(':', first + 1);
  if (second == std::string::npos) throw bad();
  const double from = percent(std::string_view(text).substr(0, first));
  const double to = percent(std::string_view(text).substr(first + 1, second - first - 1));
  std::size_t count = 0;
  if (!readDecimal(std::string_view(text).substr(second + 1), count) || count < 2 ||
      count > kMaxFrames)
    throw bad();
  std::vector<double> percents;
  for (std::size_t i = 0; i < count; ++i)
    percents.push_back(from +
                       (to - from) * static_cast<double>(i) / static_cast<double>(count - 1));
  return percents;
}

double largestMagnitude(const std::vector<double>& values) {
  double largest = 0.0;
  for (double v : values) largest = std::max(largest, std::abs(v));
  return largest;
}

// What --color paints on the sheet.
enum class StateColor { None, Strain, AngleError };

StateColor parseStateColor(const std::string& text) {
  if (text == "strain") return StateColor::Strain;
  if (text == "angle-error") return StateColor::AngleError;
  throw UsageError("--color: expected strain or angle-error, got " + quotedExcerpt(text));
}

// A per-edge value at the vertices, for a picture: each vertex takes the value of largest
// magnitude among its edges (sign kept), so a strained bar or a lagging crease shows at both ends.
std::vector<double> vertexField(const BarHingeModel& model, const std::vector<double>& edgeValues) {
  std::vector<double> field(model.vertexCount(), 0.0);
  for (std::size_t e = 0; e < model.bars.size(); ++e)
    for (std::uint32_t v : model.bars[e])
      if (std::abs(edgeValues[e]) > std::abs(field[v])) field[v] = edgeValues[e];
  return field;
}

// The state's --color field at its vertices: strain in percent (magnitude), or the crease angle
// error in degrees (signed: positive folded past its target).
std::vector<double> stateField(StateColor color, const BarHingeModel& model,
                               const SimulationState& state, double amount) {
  if (color == StateColor::Strain) {
    std::vector<double> strain = edgeStrain(model, state.positions);
    for (double& s : strain) s = 100.0 * std::abs(s);
    return vertexField(model, strain);
  }
  return vertexField(model, creaseAngleError(model, state.positions, amount, state.hingeAngles));
}

// The legend of --color pictures, one scale for every picture of a run so frames compare.
ColorLegend stateLegend(StateColor color, const std::vector<std::vector<double>>& fields) {
  double largest = 0.0;
  for (const std::vector<double>& field : fields)
    largest = std::max(largest, largestMagnitude(field));
  largest = std::max(largest, 1e-9);
  if (color == StateColor::Strain)
    return {ColorMap::Viridis, 0.0, largest, "strain (edge length change)", "%"};
  return {ColorMap::CoolWarm, -largest, largest, "crease angle error (+: past its target)",
          "degrees"};
}

// A picture of one state. The renderer keeps what it last uploaded of a sheet unless told it was
// replaced: each state is a new sheet to it (without this, frames after the first two showed
// stale states).
RgbaImage renderState(const Sheet& sheet, HeadlessRenderer& renderer, float aspect,
                      const std::optional<Bounds>& framing = std::nullopt) {
  Scene scene = sceneForSheet(sheet, ViewPreset::Iso, aspect, false);
  if (framing) {
    scene.camera = frameBounds(*framing, ViewPreset::Iso, aspect);
    scene.ground = groundBelow(*framing);
  }
  renderer.sceneRenderer().markSheetReplaced();
  return renderer.render(scene);
}

void writePng(const Sheet& sheet, const fs::path& path, HeadlessRenderer& renderer, float aspect) {
  writeFileAtomically(path, encodePng(renderState(sheet, renderer, aspect)));
}

// The GIF of the folding: every state rendered by one still camera (framing all states), at half
// the PNG's size, 10 states a second and the last held a second.
void writeGif(Sheet sheet, const std::vector<std::vector<glm::dvec3>>& states, const fs::path& path,
              HeadlessRenderer& renderer, float aspect) {
  constexpr unsigned kFrameCentiseconds = 10, kLastFrameCentiseconds = 100;
  Bounds framing;
  for (const std::vector<glm::dvec3>& positions : states) {
    sheet.positions = positions;
    const Bounds bounds = worldBounds(sheet);
    framing.add(bounds.min);
    framing.add(bounds.max);
  }
  GifAnimation gif;
  for (std::size_t i = 0; i < states.size(); ++i) {
    sheet.positions = states[i];
    const RgbaImage image = renderState(sheet, renderer, aspect, framing);
    gif.addFrame(resizedImage(image, image.width / 2, image.height / 2),
                 i + 1 < states.size() ? kFrameCentiseconds : kLastFrameCentiseconds);
  }
  writeFileAtomically(path, gif.finish());
}

}  // namespace

void addSimulateCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "simulate",
      "Fold the flat sheet of a design with the bar-and-hinge simulation and write the state");
  struct Options {
    std::string input, percent, obj, fold, gltf, png, frames, color, gif, stiffness;
    bool settle = false, verbose = false, gpu = false, motion = false, noContact = false;
    double paperMm = 0.0, modulusGpa = kDefaultPaperModulusGpa, sizeMm = 0.0;
    double creaseSide = ModelOptions{}.wrongSideScale;
    std::size_t steps = 2000;
    std::vector<std::string> pins, glue;
  };
  auto options = std::make_shared<Options>();
  command
      ->add_option("INPUT", options->input,
                   "Design (*.curvefold.json) or crease pattern (.fold, .svg)")
      ->required();
  command
      ->add_option("--percent", options->percent,
                   "Fold amount in percent, P, or a sequence FROM:TO:N (N states, both ends)")
      ->required();
  command->add_flag("--settle", options->settle,
                    "Solve each state to equilibrium (static solver) instead of --steps steps of "
                    "the damped dynamic solver");
  command->add_flag("--verbose", options->verbose,
                    "With --settle: a line per static iteration (stage, energy, its change, "
                    "residual)");
  command->add_option("--steps", options->steps,
                      "Dynamic steps per state without --settle (default 2000)");
  command->add_flag("--gpu", options->gpu,
                    "Take the dynamic steps in Vulkan compute shaders (single precision) on the "
                    "Vulkan device instead of on the CPU (double)");
  command->add_flag("--motion", options->motion,
                    "Targets along the pattern's folding motion (for patterns whose creases do not "
                    "fold in proportion, as a waterbomb's), not scaled with --percent");
  CLI::Option* paper = command->add_option(
      "--paper", options->paperMm,
      "Paper mode: only creases are driven and the sheet bends as paper THICKNESS mm thick");
  CLI::Option* stiffness = command->add_option(
      "--stiffness", options->stiffness,
      "Design mode's stiffnesses: `curvefold` (default: stiff bars and facets, soft creases) or "
      "`origami-simulator` (Origami Simulator's: axial 20, crease 0.7, facet 0.7)");
  command->add_option("--crease-side", options->creaseSide,
                      "Stiffness that keeps each crease on its side of flat and short of "
                      "passing flat-folded, times a facet's (default 10; 0: off, the "
                      "symmetric crease energy alone)");
  CLI::Option* size = command->add_option(
      "--size", options->sizeMm,
      "A crease pattern's larger side in mm (default: as its file states; an SVG's px at 96 per "
      "inch, a FOLD file's by its frame_unit, else metres)");
  command->add_flag("--no-contact", options->noContact,
                    "With --paper: let the sheet pass through itself (no self-contact; by default "
                    "layers keep the paper's thickness apart)");
  command->add_option("--modulus", options->modulusGpa,
                      "With --paper: the paper's Young's modulus in GPa (default 4)");
  command->add_option(
      "--pin", options->pins,
      "X,Y: hold the vertex nearest this flat-sheet point (metres) where it starts; "
      "repeatable");
  command->add_option("--glue", options->glue,
                      "X1,Y1:X2,Y2: pull the vertices nearest these two flat-sheet points "
                      "together, or `slits`: glue every slit of the design shut; repeatable");
  CLI::Option* obj = command->add_option("--obj", options->obj, "OBJ of the (last) state");
  CLI::Option* fold =
      command->add_option("--fold", options->fold, "FOLD 1.2 of the (last) state (3D frame)");
  CLI::Option* gltf = command->add_option("--gltf", options->gltf, "glTF 2.0 binary (.glb)");
  CLI::Option* png = command->add_option("--png", options->png, "PNG picture (headless Vulkan)");
  CLI::Option* frames = command->add_option("--frames", options->frames,
                                            "Folder for frame_NNNN.png and .obj, one per state");
  CLI::Option* colorOption = command->add_option(
      "--color", options->color,
      "Colour the pictures (--png, --frames) by `strain` (each edge's length change) or "
      "`angle-error` (each crease's fold angle minus its target), with a legend");
  CLI::Option* gif = command->add_option(
      "--gif", options->gif,
      "Animated GIF of the folding: one frame per state of --percent FROM:TO:N (headless Vulkan)");
  // CLI11 gives an option still short of its value the next word even when that is another
  // option (`--color --png x.png` set the colour to "--png", then refused x.png as an extra
  // argument without naming --color): such a value is refused here, naming the option.
  const CLI::Validator notAnOption(
      [](std::string& text) -> std::string {
        if (text.starts_with("--"))
          return "expected a value, got the option " + quotedExcerpt(text);
        return "";
      },
      "", "value");
  for (CLI::Option* option : command->get_options())
    if (option->get_expected_min() > 0) option->check(notAnOption);
  command->callback([options, paper, size, stiffness, obj, fold, gltf, png, frames, colorOption,
                     gif] {
    const std::vector<double> percents = parsePercents(options->percent);
    const StateColor color =
        colorOption->count() ? parseStateColor(options->color) : StateColor::None;
    if (color != StateColor::None && png->count() + frames->count() == 0)
      throw UsageError("--color: colours a picture; name --png or --frames too");
    requireAnOutput("simulate", {obj, fold, gltf, png, frames, gif});
    if (gif->count() && percents.size() < 2)
      throw UsageError("--gif: an animation needs a sequence of states, --percent FROM:TO:N; got " +
                       quotedExcerpt(options->percent));
    if (options->gpu && options->settle)
      throw UsageError("--gpu: takes dynamic steps; --settle solves on the CPU, name one");
    if (options->gpu && options->motion)
      throw UsageError(
          "--gpu: scales the targets with --percent; --motion follows the pattern's "
          "motion on the CPU, name one");
    if (options->steps == 0 || options->steps > kMaxSteps)
      throw UsageError("--steps: must be from 1 to " + std::to_string(kMaxSteps));
    ModelOptions modelOptions;
    if (stiffness->count())
      checkedOption(
          [&] { setStiffnessPreset(modelOptions, options->stiffness, paper->count() > 0); });
    if (!(options->creaseSide >= 0.0 && options->creaseSide <= 1e4))
      throw UsageError("--crease-side: must be from 0 to 10000");
    modelOptions.wrongSideScale = options->creaseSide;
    if (paper->count()) {
      // The compute shaders have no contact: the GPU path folds through itself, as it says.
      checkedOption([&] {
        setPaperMode(modelOptions, options->paperMm, options->modulusGpa,
                     !options->noContact && !options->gpu);
      });
    } else if (options->noContact) {
      throw UsageError("--no-contact: only paper mode (--paper) has self-contact");
    }
    for (const std::string* output :
         {&options->obj, &options->fold, &options->gltf, &options->png, &options->gif})
      if (!output->empty() && *output != "-" && sameFile(*output, options->input))
        throw UsageError("simulate: " + *output + " is the input; write to another file");

    const double sizeMetres =
        size->count() ? checkedOption([&] { return sheetSizeMetres(options->sizeMm); }) : 0.0;
    std::string sizeLine;
    SimulationInput input = readInput(options->input, sizeMetres, sizeLine);
    if (!sizeLine.empty())
      statusFor({options->obj, options->fold, options->gltf, options->png, options->gif})
          << sizeLine;
    // What the reader read but did not use, or read otherwise than written (docs/formats.md).
    for (const std::string& note : input.pattern.notes) std::cerr << "note: " << note << "\n";
    for (const std::string& pin : options->pins)
      checkedOption([&] { addPin(modelOptions, input.pattern, parseSheetPoint(pin, "pin")); });
    for (const std::string& glue : options->glue)
      checkedOption([&] { addGlueText(modelOptions, input.pattern, input.seams, glue); });
    BarHingeModel model;
    try {
      model = buildModel(input.pattern, modelOptions);
    } catch (const SimulationInputError& e) {
      throw UsageError("simulate: " + fs::path(options->input).filename().string() + ": " +
                       e.what());
    }

    if (options->motion) {
      const FoldingMotion motion = checkedOption([&] { return followFoldingMotion(model); });
      char line[160];
      std::snprintf(line, sizeof line, "folding motion: %zu states, followed to %.1f%%%s\n",
                    motion.amounts.size(), 100.0 * motion.amounts[motion.amounts.size() - 2],
                    motion.reachedFull ? " (the 100% angles)" : ", then linear to 100%");
      statusFor({options->obj, options->fold, options->gltf, options->png, options->gif}) << line;
    }

    if (paper->count()) {
      char line[160];
      if (model.contact.enabled)
        std::snprintf(line, sizeof line, "self-contact: layers kept %.3g mm apart\n",
                      model.contact.thickness * 1e3);
      else
        std::snprintf(line, sizeof line, "self-contact: off%s\n",
                      options->gpu ? " (not on the GPU path)" : "");
      statusFor({options->obj, options->fold, options->gltf, options->png, options->gif}) << line;
    }

    // The renderer first: a machine without Vulkan fails before any work.
    std::unique_ptr<HeadlessRenderer> renderer;
    constexpr std::uint32_t kWidth = 1280, kHeight = 720;
    if (png->count() || frames->count() || gif->count()) {
      HeadlessOptions renderOptions;
      renderOptions.width = kWidth;
      renderOptions.height = kHeight;
      renderer = std::make_unique<HeadlessRenderer>(renderOptions);
    }
    const float aspect = float(kWidth) / float(kHeight);

    // The compute path on the renderer's device, or a context of its own.
    std::unique_ptr<VulkanContext> gpuContext;
    std::unique_ptr<GpuDynamicSolver> gpuSolver;
    if (options->gpu) {
      if (!renderer) {
        ContextOptions contextOptions;
        contextOptions.instance.validation = vulkanValidationAsked();
        gpuContext = std::make_unique<VulkanContext>(contextOptions);
      }
      gpuSolver =
          std::make_unique<GpuDynamicSolver>(renderer ? renderer->context() : *gpuContext, model);
    }

    SimulationState state = flatState(model);
    std::vector<Sheet> frameSheets;
    frameSheets.reserve(frames->count() ? percents.size() : 0);
    std::vector<std::vector<double>> fields;  // --color's, one per state kept
    std::vector<std::vector<glm::dvec3>> gifStates;
    gifStates.reserve(gif->count() ? percents.size() : 0);
    Sheet sheet = input.sheet;
    for (std::size_t i = 0; i < percents.size(); ++i) {
      const double amount = percents[i] / 100.0;
      std::string solved;
      if (options->settle) {
        const StaticResult result = settle(model, amount, state);
        // Whether the energy rose in any iteration (issue 39: it never should) is in the
        // summary, from each iteration's change as the solver measured it (energyRises).
        if (options->verbose)
          for (const StaticIteration& it : result.history) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "  stage %zu: energy %.17g, change %.3e, residual %.3e\n", it.stage,
                          it.energy, it.energyChange, it.residual);
            statusFor({options->obj, options->fold, options->gltf, options->png, options->gif})
                << text;
          }
        solved = settleSummary(result);
      } else if (gpuSolver) {
        gpuSolver->step(amount, options->steps);
        gpuSolver->state(state);
        solved = std::to_string(options->steps) + " dynamic steps on the GPU";
      } else {
        stepDynamic(model, amount, state, options->steps);
        solved = std::to_string(options->steps) + " dynamic steps";
      }
      // Its strain, crease angle error, creases on the wrong side of flat or past flat-folded,
      // and whether it passes through itself (as `check` tests it), as Python reports them.
      const StateReport report = reportState(model, state, amount);
      const std::string crossingText =
          report.crossingPairs == 0
              ? "none"
              : std::to_string(report.crossingPairs) + " triangle pairs cross";
      std::string wrongWayText = report.wrongSideCreases == 0
                                     ? ""
                                     : ", " + std::to_string(report.wrongSideCreases) +
                                           " creases on the wrong side of flat";
      if (report.pastFlatCreases > 0)
        wrongWayText += ", " + std::to_string(report.pastFlatCreases) + " creases past flat-folded";
      char line[384];
      std::snprintf(line, sizeof line,
                    "%g%%: %s, largest strain %.2e, largest crease angle error %.2f degrees "
                    "(mean %.2f)%s, self-intersection: %s\n",
                    percents[i], solved.c_str(), report.largestStrain, report.largestAngleError,
                    report.meanAngleError, wrongWayText.c_str(), crossingText.c_str());
      statusFor({options->obj, options->fold, options->gltf, options->png, options->gif}) << line;
      sheet.positions = state.positions;
      if (frames->count()) frameSheets.push_back(sheet);
      if (color != StateColor::None && (frames->count() || i + 1 == percents.size()))
        fields.push_back(stateField(color, model, state, amount));
      if (gif->count()) gifStates.push_back(state.positions);
    }
    if (gpuSolver) session::checkValidation(renderer ? renderer->context() : *gpuContext);
    const ColorLegend legend =
        color == StateColor::None ? ColorLegend{} : stateLegend(color, fields);

    OutputSet outputs;
    if (obj->count()) outputs.add(options->obj, [&](const auto& at) { writeObj(sheet, at); });
    if (fold->count()) outputs.add(options->fold, [&](const auto& at) { writeFold(sheet, at); });
    if (gltf->count()) outputs.add(options->gltf, [&](const auto& at) { writeGlb(sheet, at); });
    if (png->count())
      outputs.add(options->png, [&](const auto& at) {
        if (color == StateColor::None)
          writePng(sheet, at, *renderer, aspect);
        else
          writeFieldPng(*renderer, sheet, fields.back(), legend, at);
      });
    if (gif->count())
      outputs.add(options->gif,
                  [&](const auto& at) { writeGif(sheet, gifStates, at, *renderer, aspect); });
    const fs::path folder = options->frames;
    for (std::size_t i = 0; i < frameSheets.size(); ++i) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%04zu", i);
      const Sheet* frameSheet = &frameSheets[i];
      outputs.add(folder / (std::string(name) + ".obj"),
                  [frameSheet](const auto& at) { writeObj(*frameSheet, at); });
      outputs.add(folder / (std::string(name) + ".png"), [&, frameSheet, i](const auto& at) {
        if (color == StateColor::None)
          writePng(*frameSheet, at, *renderer, aspect);
        else
          writeFieldPng(*renderer, *frameSheet, fields[i], legend, at);
      });
    }
    outputs.write(frames->count() ? folder : fs::path());
    for (const std::string* path : {&options->obj, &options->fold, &options->gltf, &options->png,
                                    &options->frames, &options->gif})
      if (!path->empty())
        statusFor({options->obj, options->fold, options->gltf, options->png, options->gif})
            << "wrote " << *path << "\n";
  });
}

}  // namespace curvefold::cli
