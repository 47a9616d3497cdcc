// `render` and `replay --frames`: headless Vulkan renders to PNG (docs/design.md 7). The renderer
// takes a plain Scene; the interaction state of a replayed frame (hands, hover, grab, plane) is
// turned into markers and a plane disk here, so the render library knows nothing of interaction.
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "app/cli/commands.hpp"
#include "app/desktop/interaction_scene.hpp"
#include "app/session/printed_cover.hpp"
#include "app/studio/studio_replay.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/design_document.hpp"
#include "engine/io/output_set.hpp"
#include "engine/render/field_picture.hpp"
#include "engine/render/headless_renderer.hpp"
#include "engine/render/scene_builder.hpp"
#include "engine/render/sheet_tracker.hpp"
#include "engine/surfaces/obj_surface.hpp"
#include "engine/text/decimal.hpp"
#include "engine/text/excerpt.hpp"
#include "engine/text/input_path.hpp"
#include "sim_input/player.hpp"
#include "sim_input/recording.hpp"

namespace curvefold::cli {

namespace fs = std::filesystem;

struct RenderSize {
  std::uint32_t width = 1280;
  std::uint32_t height = 720;
};

namespace {

constexpr std::uint32_t kMaxRenderSide = 16384;

// "WxH" with whole numbers from 1 to kMaxRenderSide.
RenderSize parseSize(const std::string& text) {
  RenderSize size;
  if (!readSize<std::uint32_t>(text, 1, kMaxRenderSide, size.width, size.height))
    throw UsageError("--size: expected WxH with whole numbers from 1 to " +
                     std::to_string(kMaxRenderSide) + ", got " + quotedExcerpt(text));
  return size;
}

ViewPreset parseView(const std::string& text) {
  const std::optional<ViewPreset> view = parseViewPreset(text);
  if (!view)
    throw UsageError("--view: unknown view " + quotedExcerpt(text) + " (one of " +
                     std::string(kViewPresetNames) + ")");
  return *view;
}

// Two images of one height side by side.
RgbaImage besideEachOther(const RgbaImage& left, const RgbaImage& right) {
  RgbaImage image{left.width + right.width, left.height, {}};
  image.pixels.reserve(std::size_t(image.width) * image.height * 4);
  for (std::uint32_t y = 0; y < image.height; ++y) {
    image.pixels.insert(image.pixels.end(), left.at(0, y), left.at(0, y) + left.width * 4);
    image.pixels.insert(image.pixels.end(), right.at(0, y), right.at(0, y) + right.width * 4);
  }
  return image;
}

void writePng(const fs::path& path, const RgbaImage& image) {
  writeFileAtomically(path, encodePng(image));
}

}  // namespace

std::unique_ptr<HeadlessRenderer> makePictureRenderer() {
  HeadlessOptions options;
  options.width = 1280;
  options.height = 720;
  return std::make_unique<HeadlessRenderer>(options);
}

std::string fieldPng(HeadlessRenderer& renderer, const Sheet& sheet,
                     const std::vector<double>& vertexValues, const ColorLegend& legend) {
  const RgbaImage image = renderFieldPicture(renderer, sheet, vertexValues, legend);
  session::checkValidation(renderer.context());
  return encodePng(image);
}

void writeFieldPng(HeadlessRenderer& renderer, const Sheet& sheet,
                   const std::vector<double>& vertexValues, const ColorLegend& legend,
                   const std::string& at) {
  writeFileAtomically(at, fieldPng(renderer, sheet, vertexValues, legend));
}

// Replays a recording and writes frame_NNNNNN.png every N frames. The renderer is made first, so
// a machine without Vulkan fails before anything is written; the frames are rendered into a hidden
// staging folder next to DIR and moved into DIR only by commit(), after the replay's other
// outputs have been written, so a failure anywhere leaves DIR and the outputs as they were.
class ReplayFrameWriter {
 public:
  ReplayFrameWriter(fs::path dir, std::size_t every, RenderSize size, bool panel)
      : dir_(std::move(dir)), every_(every), panel_(panel) {
    if (dir_.empty()) throw UsageError("--frames: needs a folder");
    // Refused before any work: found at commit, the replay's other outputs were already written.
    std::error_code error;
    if (fs::exists(dir_, error) && !fs::is_directory(dir_, error))
      throw UsageError("--frames: " + dir_.string() + " is a file; name a folder");
    stage_ = stagingPathFor(dir_.filename().empty() ? dir_.parent_path() : dir_);
    if (every_ == 0) throw UsageError("--every: must be at least 1");
    HeadlessOptions options;
    options.width = size.width;
    options.height = size.height;
    renderer_ = std::make_unique<HeadlessRenderer>(options);
    aspect_ = float(size.width) / float(size.height);
  }

  ~ReplayFrameWriter() {
    std::error_code ignored;
    if (staged_) fs::remove_all(stage_, ignored);
  }

  std::size_t write(const Recording& recording) {
    std::error_code error;
    if (!stage_.parent_path().empty()) fs::create_directories(stage_.parent_path(), error);
    // A replay killed while rendering left its staging folder; its process is gone.
    removeStaleTemporaries(dir_.filename().empty() ? dir_.parent_path() : dir_);
    fs::remove_all(stage_, error);
    if (!error) fs::create_directory(stage_, error);
    if (error) throw FileError("cannot create " + dir_.string() + ": " + error.message());
    staged_ = true;
    if (recording.header.studio)
      throw UsageError(
          "--frames cannot yet draw a studio recording (a headset session with its panel); "
          "replay it without --frames, or watch it with `curvefold xr`");
    Player player(recording);
    // One camera for the whole replay, framing the sheet where it starts and every hand position.
    Bounds bounds =
        worldBounds(player.session().current(), desktop::matrixOf(recording.header.sheetFrame));
    for (const InputFrame& frame : recording.frames) {
      if (frame.pointHand.tracked) bounds.add(glm::vec3(frame.pointHand.position));
      if (frame.sheetHand.tracked) bounds.add(glm::vec3(frame.sheetHand.pose.position));
    }
    const Camera camera = frameBounds(bounds, ViewPreset::Iso, panel_ ? aspect_ * 0.66f : aspect_);
    const Ground ground = groundBelow(bounds);
    desktop::InteractionSheetTracker tracker;
    desktop::CreasePatternCache panelCache;
    std::size_t written = 0;
    while (!player.done()) {
      const std::size_t index = player.nextFrame();
      const InputFrame& input = player.step();
      if (index % every_ != 0 && !player.done()) continue;
      tracker.update(player.core(), renderer_->sceneRenderer());
      Scene scene = desktop::sceneForInteraction(player.core(), input, camera, ground,
                                                 {panel_, /*handMarkers=*/true, &panelCache});
      tracker.describe(player.core(), scene.sheet);
      char name[32];
      std::snprintf(name, sizeof name, "frame_%06zu.png", index);
      const RgbaImage image = renderer_->render(scene);
      session::checkValidation(renderer_->context());
      try {
        writePng(stage_ / name, image);
      } catch (const FileError& e) {
        throw FileError("cannot write " + (dir_ / name).string() + ": " +
                        std::string(e.what()).substr(std::string(e.what()).rfind(": ") + 2));
      }
      ++written;
    }
    return written;
  }

  // Moves the rendered frames into DIR (made when missing; other files in it are kept).
  void commit() {
    std::error_code error;
    if (!fs::exists(dir_, error)) {
      fs::rename(stage_, dir_, error);
      if (!error) {
        staged_ = false;
        return;
      }
    }
    fs::create_directories(dir_, error);
    if (error) throw FileError("cannot create " + dir_.string() + ": " + error.message());
    for (const fs::directory_entry& entry : fs::directory_iterator(stage_)) {
      fs::rename(entry.path(), dir_ / entry.path().filename(), error);
      if (error)
        throw FileError("cannot write " + (dir_ / entry.path().filename()).string() + ": " +
                        error.message());
    }
  }

 private:
  fs::path dir_;
  fs::path stage_;  // .DIR.staged-PID next to DIR
  bool staged_ = false;
  std::size_t every_;
  bool panel_;
  float aspect_ = 1.0f;
  std::unique_ptr<HeadlessRenderer> renderer_;
};

std::shared_ptr<ReplayFrameWriter> makeReplayFrameWriter(const std::string& dir, std::size_t every,
                                                         const std::string& size, bool panel) {
  return std::make_shared<ReplayFrameWriter>(dir, every, parseSize(size), panel);
}

std::size_t writeReplayFrames(ReplayFrameWriter& writer, const Recording& recording) {
  return writer.write(recording);
}

void commitReplayFrames(ReplayFrameWriter& writer) {
  writer.commit();
}

void addRenderCommand(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "render", "Render a design or a recording's result to PNG (headless Vulkan)");
  struct Options {
    std::string input, png, size = "1280x720", view = "iso", target;
    bool panel = false;
  };
  auto options = std::make_shared<Options>();
  command->add_option("INPUT", options->input, "Design (*.curvefold.json) or recording (*.jsonl)")
      ->required();
  command->add_option("--png", options->png, "PNG file to write")->required();
  command->add_option("--size", options->size, "Image size WxH (default 1280x720)");
  command->add_option("--view", options->view,
                      "Camera: " + std::string(kViewPresetNames) + " (default iso)");
  command->add_flag("--crease-pattern-panel", options->panel,
                    "Show the 2D crease pattern in a panel at the right");
  command->add_option("--target", options->target,
                      "A target shape (OBJ) drawn in grey on the left half, the design on the "
                      "right, both seen by one camera");
  command->callback([options] {
    const RenderSize size = parseSize(options->size);
    const ViewPreset view = parseView(options->view);
    const fs::path input = options->input;
    refuseOutputsOverInputs({options->png},
                            {{input, "the input being rendered"}, {options->target, "the target"}});
    Sheet sheet;
    if (hasExtension(input, ".jsonl")) {
      sheet = studio::replayAnyRecording(readRecording(input)).sheet;
    } else {
      sheet = buildSheet(loadDesign(input), input.string());
    }
    std::optional<Sheet> target;
    if (!options->target.empty()) {
      if (options->panel)
        throw UsageError("--target: not with --crease-pattern-panel (the halves are views)");
      if (size.width < 2)
        throw UsageError("--size: a target beside the design needs a width of 2 or more");
      // The check `fit` and the studio's --target make: no millimetre-scale, flat or faraway one.
      const TriangleMesh mesh = readObjMesh(options->target);
      try {
        checkTarget(mesh);
        checkTargetAgainst(mesh, sheet);
      } catch (const InvalidTarget& e) {
        throw UsageError(options->target + ": " + e.what());
      }
      target = meshSheet(mesh);
    }
    // With a target, the design takes the right half and the target the left.
    const std::uint32_t left = target ? size.width / 2 : 0;
    HeadlessOptions renderOptions;
    renderOptions.width = size.width - left;
    renderOptions.height = size.height;
    HeadlessRenderer renderer(renderOptions);
    const float aspect = float(renderOptions.width) / float(size.height);
    Scene scene = sceneForSheet(sheet, view, aspect, options->panel);
    RgbaImage image;
    if (target) {
      // One framing and one ground for both halves, so sizes and places compare.
      Bounds both = worldBounds(sheet);
      const Bounds targetBounds = worldBounds(*target);
      both.add(targetBounds.min);
      both.add(targetBounds.max);
      const float leftAspect = float(left) / float(size.height);
      Scene targetScene = sceneForSheet(*target, view, leftAspect, false);
      scene.camera = frameBounds(both, view, aspect);
      targetScene.camera = frameBounds(both, view, leftAspect);
      scene.ground = targetScene.ground = groundBelow(both);
      targetScene.creases.clear();  // a target's edges are no creases
      targetScene.colors.front = targetScene.colors.back = {0.62f, 0.66f, 0.74f};
      const RgbaImage design = renderer.render(scene);
      image = besideEachOther(renderSceneOnce(renderer.context(), targetScene, {left, size.height}),
                              design);
    } else {
      image = renderer.render(scene);
    }
    session::checkValidation(renderer.context());
    writePng(options->png, image);
    statusFor({options->png}) << "wrote " << options->png << " (" << size.width << "x"
                              << size.height << ", " << sheet.triangleCount() << " triangles, "
                              << renderer.context().deviceName() << ")\n";
  });
}

}  // namespace curvefold::cli
