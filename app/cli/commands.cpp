#include "app/cli/commands.hpp"
#include "app/session/design_check.hpp"
#include "app/session/document.hpp"
#include "app/session/printed_cover.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>
#include <string_view>
#include <variant>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "engine/fabrication/crease_pattern_pdf.hpp"
#include "engine/fabrication/cutter_svg.hpp"
#include "engine/fabrication/svg_crease_pattern.hpp"
#include "engine/geometry/creases.hpp"
#include "engine/geometry/development_overlap.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/io/crease_pattern_reader.hpp"
#include "engine/io/design_document.hpp"
#include "engine/io/fold_format.hpp"
#include "engine/io/gltf_writer.hpp"
#include "engine/io/input_limits.hpp"
#include "engine/io/obj_writer.hpp"
#include "engine/io/output_set.hpp"
#include "engine/io/sheet_cache.hpp"
#include "engine/surfaces/obj_surface.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "engine/text/decimal.hpp"
#include "engine/text/excerpt.hpp"
#include "engine/text/input_path.hpp"

namespace curvefold::cli {

namespace fs = std::filesystem;
namespace {

// "X,Y,Z" with three finite decimal numbers.
glm::dvec3 parsePoint(const std::string& text, const std::string& option) {
  const std::string_view all = text;
  const std::size_t first = all.find(','), second = all.find(',', first + 1);
  glm::dvec3 p;
  if (first == std::string_view::npos || second == std::string_view::npos ||
      !readDecimal(all.substr(0, first), p.x) ||
      !readDecimal(all.substr(first + 1, second - first - 1), p.y) ||
      !readDecimal(all.substr(second + 1), p.z) || !std::isfinite(p.x) || !std::isfinite(p.y) ||
      !std::isfinite(p.z))
    throw UsageError(option + ": expected X,Y,Z (three finite numbers in metres), got " +
                     quotedExcerpt(text));
  return p;
}

// Six digits; a coordinate below a nanometre is rounding (a cosine's 3.06e-18) and printed as 0.
std::string formatPoint(const glm::dvec3& p) {
  auto shown = [](double x) { return std::abs(x) < 1e-9 ? 0.0 : x; };
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%.6g,%.6g,%.6g", shown(p.x), shown(p.y), shown(p.z));
  return buffer;
}

// N of "rotational:N" or "rotational:N:axis" written as parseSymmetry reads it, else nothing.
std::optional<int> rotationOrder(const std::string& symmetry) {
  static const std::regex rotation("rotational:([1-9][0-9]{0,2})(:[xyz])?");
  std::smatch match;
  if (!std::regex_match(symmetry, match, rotation)) return std::nullopt;
  return std::stoi(match[1].str());
}

bool hasParameter(const std::string& surface, const std::string& parameter) {
  for (const SurfaceInfo& info : surfaceCatalog())
    if (info.name == surface)
      for (const SurfaceParameter& p : info.parameters)
        if (p.name == parameter) return true;
  return false;
}

}  // namespace

void requireDecimalNumbers(CLI::App& app) {
  const CLI::Validator decimal(
      [](std::string& text) -> std::string {
        double value = 0.0;
        if (readDecimal(text, value)) return "";
        return "expected a decimal number (no sign +, hex or spaces), got " + quotedExcerpt(text);
      },
      "", "decimal");
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; }))
    for (CLI::Option* option : command->get_options()) {
      // "UINT", or "UINT:INT in [1 - 64]" with a range check.
      const std::string full = option->get_type_name(), type = full.substr(0, full.find(':'));
      // First, before any range check reads the text its own way.
      if (type == "INT" || type == "UINT" || type == "FLOAT") option->transform(decimal);
    }
}

void requireAnOutput(const std::string& command,
                     std::initializer_list<const CLI::Option*> outputs) {
  std::string names;
  for (const CLI::Option* output : outputs) {
    if (output->count() > 0) return;
    names += (names.empty() ? "" : ", ") + output->get_name();
  }
  throw UsageError(command + ": name at least one of " + names);
}

std::ostream& statusFor(std::initializer_list<std::string_view> outputs) {
  for (std::string_view output : outputs)
    if (output == "-") return std::cerr;
  return std::cout;
}

void addSurfacesCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand("surfaces", "List the initial surfaces and parameters");
  command->callback([] {
    for (const SurfaceInfo& surface : surfaceCatalog()) {
      std::cout << surface.name << ": " << surface.description << "\n";
      for (const SurfaceParameter& p : surface.parameters) {
        std::cout << "  --" << p.name << " (default " << p.defaultValue << ", " << p.min << " to "
                  << p.max << (p.integer ? ", whole number" : "") << "): " << p.description << "\n";
      }
      // What `new --symmetry` takes, at the default parameters (a rotation's order: any divisor).
      std::string symmetries;
      for (const std::string& name : symmetriesOf(makeSurface(surface.name)))
        symmetries += (symmetries.empty() ? "" : ", ") + name;
      std::cout << "  symmetries: " << (symmetries.empty() ? "none" : symmetries) << "\n";
    }
    std::cout << "any .obj file: a developable triangle mesh (with vt as its development, or "
                 "unfolded when it has none)\n";
  });
}

void addSessionFileOptions(CLI::App* command, std::string& record, std::string& autosave,
                           std::string& target, const std::string& autosaveWhen) {
  command->add_option("--record", record, "Record the session's input (*.jsonl)");
  command->add_option(
      "--autosave", autosave,
      "Design saved " + autosaveWhen + " (default: <name>.autosave.curvefold.json)");
  command->add_option("--target", target,
                      "A target shape (OBJ, in the sheet's frame) to fold toward: shown as a ghost "
                      "with its distance, and the panel's Suggest proposes the next fold");
}

void addSurfaceOptions(CLI::App* command, SurfaceOptions& options) {
  // Every parameter of every surface is an option; makeSurface refuses one the chosen surface
  // does not have.
  // A parameter whole in every surface that has it is shown as INT (read as a number all the
  // same: makeSurface says when a value is not whole).
  std::map<std::string, std::pair<std::string, bool>> help;
  for (const SurfaceInfo& surface : surfaceCatalog())
    for (const SurfaceParameter& p : surface.parameters) {
      const auto [at, added] = help.try_emplace(p.name, p.description, p.integer);
      at->second.second = at->second.second && p.integer;
    }
  for (const auto& [name, about] : help)
    command->add_option("--" + name, options.values[name], about.first)
        ->type_name(about.second ? "INT" : "FLOAT");
  command->add_option("--symmetry", options.symmetry,
                      "mirror:x|y|z or rotational:N[:x|y|z] through the surface's centre: every "
                      "fold is followed by its images (see `surfaces`)");
}

Design designFromSurfaceOptions(const SurfaceOptions& options, const CLI::App* command,
                                Sheet* sheet) {
  Design design;
  // The initial sheet, made once: a large one (a star of 10,000 m: 14.7 million triangles) took
  // seconds to mesh, and was meshed again by the symmetry's check and by the caller.
  Sheet initial;
  if (hasExtension(options.surface, ".obj")) {
    for (const auto& [name, value] : options.values)
      if (command->get_option("--" + name)->count() > 0)
        throw UsageError("--" + name + " does not apply to an OBJ surface");
    design.surface = readObjSurface(options.surface);
    initial = std::get<Sheet>(design.surface);
  } else {
    GeneratedSurface generated{options.surface, {}};
    for (const auto& [name, value] : options.values)
      if (command->get_option("--" + name)->count() > 0) generated.parameters[name] = value;
    // Refuses bad parameters now; initialSheet(design) makes this very sheet.
    initial = makeSurface(generated.generator, generated.parameters);
    design.surface = generated;
  }
  // Given is given: `--symmetry ""` is refused, not read as none.
  if (command->get_option("--symmetry")->count() > 0) {
    try {
      design.symmetry = parseSymmetry(options.symmetry, initial).name();
    } catch (const InvalidSymmetry& e) {
      // A disk has every rotation and a star one by each divisor of its points: a rotation the
      // default mesh lacks is meshed for (its "rotations"), unless the user chose them.
      auto* generated = std::get_if<GeneratedSurface>(&design.surface);
      const std::optional<int> order = rotationOrder(options.symmetry);
      if (!generated || !order || generated->parameters.count("rotations") > 0 ||
          !hasParameter(generated->generator, "rotations"))
        throw UsageError("--symmetry " + session::symmetryProblem(e));
      GeneratedSurface meshed = *generated;
      meshed.parameters["rotations"] = *order;
      try {
        Sheet remeshed = makeSurface(meshed.generator, meshed.parameters);
        design.symmetry = parseSymmetry(options.symmetry, remeshed).name();
        initial = std::move(remeshed);
      } catch (const std::invalid_argument&) {
        throw UsageError("--symmetry " + session::symmetryProblem(e));
      }
      design.surface = meshed;
    }
  }
  if (sheet) *sheet = std::move(initial);
  return design;
}

void addNewCommand(CLI::App& app) {
  CLI::App* command =
      app.add_subcommand("new", "Start a design from an initial surface (or an OBJ file)");
  struct Options {
    SurfaceOptions surface;
    std::string output;
  };
  auto options = std::make_shared<Options>();
  command
      ->add_option("SURFACE", options->surface.surface,
                   "Surface name (see `surfaces`) or an .obj file")
      ->required();
  command->add_option("-o,--output", options->output, "Design file to write (*.curvefold.json)")
      ->required();
  addSurfaceOptions(command, options->surface);

  command->callback([options, command] {
    // An OBJ surface is read; the design must not replace it.
    refuseOutputsOverInputs(
        {options->output},
        {{hasExtension(options->surface.surface, ".obj") ? options->surface.surface : "",
          "the surface read"}});
    Sheet sheet;
    const Design design = designFromSurfaceOptions(options->surface, command, &sheet);
    saveDesign(design, options->output);
    // A sheet may have several pieces (an OBJ of separate parts): each is its own piece of
    // paper, laid side by side in the development and printed on one crease pattern.
    const std::size_t pieces = connectedComponentCount(sheet, buildEdgeTopology(sheet));
    statusFor({options->output}) << "wrote " << options->output << " ("
                                 << session::surfaceName(design)
                                 << (design.symmetry.empty() ? "" : ", " + design.symmetry) << ", "
                                 << sheet.triangleCount() << " triangles"
                                 << (pieces > 1 ? ", " + std::to_string(pieces) + " pieces" : "")
                                 << ")\n";
  });
}

void addFoldCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "fold", "Add one fold: drag the surface point nearest one point to another");
  struct Options {
    std::string design, output, near, to;
  };
  auto options = std::make_shared<Options>();
  command->add_option("DESIGN", options->design, "Design file to fold")->required();
  command->add_option("--vertex-near", options->near, "X,Y,Z: grab the surface point nearest this")
      ->required();
  command->add_option("--to", options->to, "X,Y,Z: where the grabbed point goes")->required();
  command->add_option("-o,--output", options->output, "Design file to write")->required();
  command->callback([options] {
    const glm::dvec3 near = parsePoint(options->near, "--vertex-near");
    const glm::dvec3 to = parsePoint(options->to, "--to");
    Design design = loadDesign(options->design);
    // The folded sheet from the cache when this history was folded before: one fold per call.
    const Sheet before = buildSheetCached(design, options->design);
    FoldSession session(before);
    const glm::dvec3 grabbed = session.beginDragNear(near);
    session.updateDrag(to);
    if (session.commit()) {
      const std::size_t number = design.folds.size() + 1;
      FoldRecord fold = session.folds().back();
      Sheet sheet = session.fixed();
      std::string images;
      if (!design.symmetry.empty()) {
        // The fold's images under the design's symmetry follow it, one group.
        const Sheet initial = initialSheet(design, options->design);
        const SymmetricFolder folder(initial, parseSymmetry(design.symmetry, initial));
        const SymmetricFolder::Result result = folder.applyImages(before, sheet, fold);
        std::uint32_t group = 0;
        for (const FoldRecord& earlier : design.folds) group = std::max(group, earlier.group);
        fold.group = group + 1;
        design.folds.push_back(fold);
        for (FoldRecord image : result.applied) {
          image.group = fold.group;
          design.folds.push_back(image);
        }
        images = " and " + std::to_string(result.applied.size()) + " images" +
                 imageNotes(result.skipped, result.overlapping);
      } else {
        design.folds.push_back(fold);
      }
      ValidationOptions tolerance;
      tolerance.relativeLengthTolerance =
          session::isometryTolerance(initialSheet(design, options->design)) / sheetSize(sheet);
      validate(sheet, tolerance);
      saveDesign(design, options->output);
      storeCachedSheet(design, sheet);
      statusFor({options->output})
          << "fold " << number << images << ": grabbed " << formatPoint(grabbed) << " -> "
          << formatPoint(to) << ", " << sheet.triangleCount() << " triangles; wrote "
          << options->output << "\n";
      // Paper cannot pass through itself: say so now, not first at `check`.
      if (const std::size_t pairs = findSelfIntersections(sheet).intersections.size(); pairs > 0)
        std::cerr << "curvefold: warning: fold " << number << " passes the sheet through itself ("
                  << pairs << " triangle pairs; `check` fails it)\n";
    } else {
      saveDesign(design, options->output);
      statusFor({options->output})
          << "target lies within " << session.minimumDrag() << " m of the grabbed point "
          << formatPoint(grabbed) << " (the shortest drag that folds): no fold added; wrote "
          << options->output << "\n";
    }
  });
}

void addExportCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "export",
      "Write the folded design as FOLD, SVG crease pattern, cutter SVG, PDF, OBJ and/or glTF");
  struct Options {
    std::string design, fold, svg, cutSvg, perforate, pdf, paper = "a4", obj, gltf;
    bool angles = false;
  };
  auto options = std::make_shared<Options>();
  command->add_option("DESIGN", options->design, "Design file")->required();
  CLI::Option* fold = command->add_option("--fold", options->fold, "FOLD 1.2 file (.fold)");
  CLI::Option* svg =
      command->add_option("--svg", options->svg, "SVG crease pattern at real size (.svg)");
  CLI::Option* cutSvg = command->add_option(
      "--cut-svg", options->cutSvg,
      "SVG for laser cutters and cutting plotters: layers cut (red), mountain score (blue), "
      "valley score (green), in mm");
  command->add_option("--perforate", options->perforate,
                      "With --cut-svg: CUT,GAP in mm: the scores become cuts of CUT with GAP "
                      "between, to fold by hand, in a layer perforation (magenta)");
  CLI::Option* pdf = command->add_option(
      "--pdf", options->pdf,
      "PDF to print: the crease pattern at real size, tiled across pages, after a cover page");
  command
      ->add_option("--paper", options->paper,
                   "With --pdf: a4, letter or a3 (tiled at real size), or fit (one A4 page)")
      ->check(CLI::IsMember({"a4", "letter", "a3", "fit"}));
  command->add_flag("--angles", options->angles, "With --pdf: label each crease with its angle");
  CLI::Option* obj = command->add_option("--obj", options->obj, "OBJ with the development as vt");
  CLI::Option* gltf = command->add_option("--gltf", options->gltf, "glTF 2.0 binary (.glb)");
  command->callback([options, fold, svg, cutSvg, pdf, obj, gltf] {
    requireAnOutput("export", {fold, svg, cutSvg, pdf, obj, gltf});
    std::optional<Perforation> perforation;
    if (!options->perforate.empty()) {
      Perforation p;
      const std::string_view text = options->perforate;
      const std::size_t comma = text.find(',');
      if (comma == std::string_view::npos || !readDecimal(text.substr(0, comma), p.cutMm) ||
          !readDecimal(text.substr(comma + 1), p.gapMm) || !(p.cutMm >= kMinPerforationMm) ||
          !(p.gapMm >= kMinPerforationMm) || !std::isfinite(p.cutMm) || !std::isfinite(p.gapMm))
        throw UsageError("--perforate: expected CUT,GAP in millimetres, each at least 0.1, got " +
                         quotedExcerpt(options->perforate));
      perforation = p;
    }
    refuseOutputsOverInputs(
        {options->fold, options->svg, options->cutSvg, options->pdf, options->obj, options->gltf},
        {{options->design, "the design being exported"}});
    const Design design = loadDesign(options->design);
    const Sheet sheet = buildSheetCached(design, options->design);
    PdfOptions print;
    if (pdf->count()) {
      print.paper = *parsePaper(options->paper);
      // Counted before anything is drawn: a sheet metres wide would take hours and gigabytes.
      if (const double pages = pdfPageCount(sheet, print.paper); pages > kMaxPdfPages)
        throw UsageError("--pdf: the crease pattern would print on " +
                         std::to_string(std::llround(pages)) + " pages at real size (at most " +
                         std::to_string(std::llround(kMaxPdfPages)) +
                         "); --paper fit prints it on one page");
      print.angles = options->angles;
      print.title = session::designName(options->design);  // "vase", not "vase.curvefold.json"
      print.facts = session::coverFacts(design);
      std::string noPicture;
      print.picture = session::renderFoldedForm(sheet, noPicture);
      if (!print.picture)
        std::cerr << "curvefold: the PDF goes without the picture of the folded form: " << noPicture
                  << "\n";
    }
    // All named files or none: a failing OBJ leaves the SVG as it was.
    OutputSet outputs;
    if (fold->count()) outputs.add(options->fold, [&](const auto& at) { writeFold(sheet, at); });
    if (svg->count())
      outputs.add(options->svg, [&](const auto& at) { writeSvgCreasePattern(sheet, at); });
    if (cutSvg->count())
      outputs.add(options->cutSvg, [&](const auto& at) { writeCutterSvg(sheet, at, perforation); });
    if (pdf->count())
      outputs.add(options->pdf, [&](const auto& at) { writeCreasePatternPdf(sheet, at, print); });
    if (obj->count()) outputs.add(options->obj, [&](const auto& at) { writeObj(sheet, at); });
    if (gltf->count()) outputs.add(options->gltf, [&](const auto& at) { writeGlb(sheet, at); });
    outputs.write();
    for (const std::string* path : {&options->fold, &options->svg, &options->cutSvg, &options->pdf,
                                    &options->obj, &options->gltf})
      if (!path->empty())
        statusFor({options->fold, options->svg, options->cutSvg, options->pdf, options->obj,
                   options->gltf})
            << "wrote " << *path << "\n";
  });
}

namespace {

// A folded state written with its flat sheet (simulate --obj or --fold, export --obj or --fold):
// the sheet read back, positions folded, development flat. A FOLD file's key frame is the flat
// sheet and its first file_frames entry the folded coordinates (as fold_format.hpp writes them).
Sheet readFoldedState(const std::string& path) {
  if (hasExtension(path, ".obj")) {
    try {
      return readObjState(path);
    } catch (const ObjError& e) {
      throw UsageError(e.what());
    }
  }
  const CreasePattern pattern = readCreasePattern(path);
  const nlohmann::json fold =
      nlohmann::json::parse(readWholeFile(path, kMaxCreasePatternBytes, "crease pattern"));
  const auto noFrame = [&](const std::string& why) {
    return UsageError(path + ": no folded state to check: " + why +
                      " (file_frames[0].vertices_coords, 3D, one per vertex, as simulate --fold "
                      "writes)");
  };
  if (!fold.contains("file_frames") || !fold["file_frames"].is_array() ||
      fold["file_frames"].empty() || !fold["file_frames"][0].is_object() ||
      !fold["file_frames"][0].contains("vertices_coords"))
    throw noFrame("it has no frame with vertex coordinates");
  const nlohmann::json& coords = fold["file_frames"][0]["vertices_coords"];
  if (!coords.is_array() || coords.size() != pattern.vertices.size())
    throw noFrame("its frame has " + std::to_string(coords.is_array() ? coords.size() : 0) +
                  " vertices, the crease pattern " + std::to_string(pattern.vertices.size()));
  Sheet sheet;
  sheet.development = pattern.vertices;
  for (const nlohmann::json& c : coords) {
    if (!c.is_array() || c.size() != 3 || !c[0].is_number() || !c[1].is_number() ||
        !c[2].is_number())
      throw noFrame("a vertex of its frame is not three numbers");
    const glm::dvec3 p(c[0].get<double>(), c[1].get<double>(), c[2].get<double>());
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw noFrame("a vertex of its frame is not finite");
    sheet.positions.push_back(p);
  }
  for (const auto& t : pattern.triangles) sheet.triangles.push_back({t[0], t[1], t[2]});
  return sheet;
}

// `check` of a simulated state (issue 39, 3): its largest strain (how much an edge's length
// differs from the flat sheet's; paper hardly stretches) and whether it passes through itself.
void checkFoldedState(const std::string& path, bool allowSelfIntersection) {
  const Sheet sheet = readFoldedState(path);
  double largest = 0.0;
  glm::dvec3 where(0.0);
  for (const Triangle& t : sheet.triangles)
    for (int i = 0; i < 3; ++i) {
      const VertexIndex a = t[i], b = t[(i + 1) % 3];
      const double flat = glm::distance(sheet.development[a], sheet.development[b]);
      const double strain =
          std::abs(glm::distance(sheet.positions[a], sheet.positions[b]) - flat) / flat;
      if (!(flat > 0.0) || !std::isfinite(strain))
        throw UsageError(path + ": an edge has no length on the flat sheet");
      if (strain > largest) {
        largest = strain;
        where = 0.5 * (sheet.positions[a] + sheet.positions[b]);
      }
    }
  const SelfIntersectionReport report = findSelfIntersections(sheet);
  std::cout << path << ": a folded state, " << sheet.vertexCount() << " vertices, "
            << sheet.triangleCount() << " triangles\n";
  char line[200];
  std::snprintf(line, sizeof line,
                "  info  largest strain %.3g%% (an edge's length change), at (%.4g, %.4g, %.4g)\n",
                100.0 * largest, where.x, where.y, where.z);
  std::cout << line;
  const std::size_t crossing = report.intersections.size();
  if (crossing == 0) {
    std::cout << "  ok    no self-intersection\n";
    return;
  }
  const glm::dvec3& p = report.firstPoint;
  std::snprintf(line, sizeof line,
                "self-intersection: %zu pairs of triangles cross, the first at (%.4g, %.4g, %.4g)",
                crossing, p.x, p.y, p.z);
  std::cout << (allowSelfIntersection ? "  info  " : "  FAIL  ") << line << "\n";
  if (!allowSelfIntersection) throw std::runtime_error(std::string("check failed: ") + line);
}

}  // namespace

void addCheckCommand(CLI::App& app) {
  CLI::App* command =
      app.add_subcommand("check", "Print the geometry invariants; exit non-zero if one fails");
  auto design = std::make_shared<std::string>();
  auto allowSelfIntersection = std::make_shared<bool>(false);
  command
      ->add_option("DESIGN", *design,
                   "Design file, or a simulated state (.obj or .fold written by simulate)")
      ->required();
  command->add_flag("--allow-self-intersection", *allowSelfIntersection,
                    "Report a folded form that passes through itself without failing");
  command->callback([design, allowSelfIntersection] {
    if (hasExtension(*design, ".obj") || hasExtension(*design, ".fold")) {
      checkFoldedState(*design, *allowSelfIntersection);
      return;
    }
    const Design loaded = loadDesign(*design);
    const Sheet initial = initialSheet(loaded, *design);
    const Sheet sheet = buildSheet(loaded, *design);
    const session::DesignCheck check =
        session::checkDesign(loaded, *design, initial, sheet, *allowSelfIntersection);
    std::cout << check.summary << "\n";
    for (const session::CheckLine& line : check.lines)
      std::cout << (line.ok ? "  ok    " : "  FAIL  ") << line.text << "\n";
    if (!check.passed()) throw std::runtime_error("check failed: " + check.firstFailure());
  });
}

}  // namespace curvefold::cli
