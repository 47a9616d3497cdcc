// The renderer, headless on whatever Vulkan device the loader finds (lavapipe on a machine
// without a GPU) with the Khronos validation layer on: any validation message fails the test.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/geometry/creases.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/reflection.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/render/color_legend.hpp"
#include "engine/render/color_map.hpp"
#include "engine/render/field_picture.hpp"
#include "engine/render/gpu_resources.hpp"
#include "engine/render/headless_renderer.hpp"
#include "engine/render/image_barrier.hpp"
#include "engine/render/scene_builder.hpp"
#include "engine/render/scope_fail.hpp"
#include "engine/render/sheet_tracker.hpp"
#include "engine/render/sheet_view.hpp"
#include "engine/render/vulkan_objects.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "tests/sheet_fixtures.hpp"

namespace curvefold {
namespace {

constexpr std::uint32_t kSize = 256;

std::size_t countPixels(const RgbaImage& image, const auto& predicate) {
  std::size_t count = 0;
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x)
      if (predicate(image.at(x, y))) ++count;
  return count;
}

bool isBlue(const std::uint8_t* p) {
  return p[2] > 150 && p[0] < 100 && p[1] < 130;
}
bool isRed(const std::uint8_t* p) {
  return p[0] > 150 && p[1] < 100 && p[2] < 100;
}

// What any picture of a scene must show, derived from the scene: its background colour in the
// top-left corner (the view is framed around the sheet), the sheet's own pixels (where the same
// scene drawn without its sheet and creases differs) over a good part of the picture, and, when
// the sheet has creases, crease-coloured pixels. A black, empty or sheetless picture fails.
// `renderer` draws the comparison (its sheet is marked replaced afterwards).
void expectSceneDrawn(HeadlessRenderer& renderer, const RgbaImage& image, const Scene& scene,
                      bool creases) {
  const std::uint8_t* corner = image.at(1, 1);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(corner[c], std::lround(scene.colors.background[c] * 255.0f), 2) << "channel " << c;
  Scene without = scene;
  without.sheet.sheet = nullptr;
  without.creases.clear();
  renderer.sceneRenderer().markSheetReplaced();
  const RgbaImage empty = renderer.render(without);
  renderer.sceneRenderer().markSheetReplaced();
  std::size_t sheet = 0;
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const std::uint8_t *a = image.at(x, y), *b = empty.at(x, y);
      for (int c = 0; c < 3; ++c)
        if (std::abs(int(a[c]) - int(b[c])) > 30) {
          ++sheet;
          break;
        }
    }
  EXPECT_GT(sheet, std::size_t(image.width) * image.height / 50);  // over 2% of the picture
  if (creases) {
    EXPECT_GT(countPixels(image, [](const std::uint8_t* p) { return isRed(p) || isBlue(p); }), 10u);
  }
}

// One renderer for the whole suite (instance creation with validation takes a while); every test
// checks that no validation message arrived during it.
class Render : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    HeadlessOptions options;
    options.width = kSize;
    options.height = kSize;
    options.validation = true;
    renderer_ = std::make_unique<HeadlessRenderer>(options);
  }
  static void TearDownTestSuite() { renderer_.reset(); }

  void SetUp() override {
    messagesBefore_ = renderer_->context().validationMessageCount();
    renderer_->sceneRenderer().markSheetReplaced();
  }
  void TearDown() override {
    const VulkanContext& context = renderer_->context();
    EXPECT_EQ(context.validationMessageCount(), messagesBefore_) << [&] {
      std::string all;
      for (const std::string& m : context.validationMessages()) all += m + "\n";
      return all;
    }();
  }

  static std::unique_ptr<HeadlessRenderer> renderer_;
  std::size_t messagesBefore_ = 0;
};
std::unique_ptr<HeadlessRenderer> Render::renderer_;

// A half-made object's cleanup (engine/render/scope_fail.hpp) runs when an exception leaves the
// constructor's scope, and only then: not when the scope ends normally, even while another
// exception unwinds through it (a destructor's scope).
TEST(ScopeFail, CleansUpOnlyWhenAnExceptionLeavesTheScope) {
  int cleanups = 0;
  {
    const ScopeFail cleanup([&] { ++cleanups; });
  }
  EXPECT_EQ(cleanups, 0);
  EXPECT_THROW(
      {
        const ScopeFail cleanup([&] { ++cleanups; });
        throw VulkanError("vkCreateImage failed");
      },
      VulkanError);
  EXPECT_EQ(cleanups, 1);
  struct EndsNormallyWhileUnwinding {
    int& cleanups;
    ~EndsNormallyWhileUnwinding() {
      const ScopeFail cleanup([&] { ++cleanups; });
    }
  };
  EXPECT_THROW(
      {
        const EndsNormallyWhileUnwinding unwinding{cleanups};
        throw VulkanError("vkAllocateMemory failed");
      },
      VulkanError);
  EXPECT_EQ(cleanups, 1);
}

// With VK_INSTANCE_LAYERS naming the validation layer too (as a developer's shell often does), the
// loader says it adds the layer: a general note, not a validation message, so nothing is counted
// and `--validation` runs still pass.
TEST(Validation, TheLoadersOwnNoteIsNotAValidationMessage) {
  const char* was = std::getenv("VK_INSTANCE_LAYERS");
  const std::optional<std::string> before = was ? std::optional<std::string>(was) : std::nullopt;
  ASSERT_EQ(setenv("VK_INSTANCE_LAYERS", "VK_LAYER_KHRONOS_validation", 1), 0);
  std::size_t counted = 0;
  std::string messages;
  {
    HeadlessOptions options;
    options.width = options.height = 64;
    options.validation = true;
    HeadlessRenderer renderer(options);
    const Sheet sheet = testing::flatGrid(4, 4, 0.05);
    renderer.render(sceneForSheet(sheet, ViewPreset::Iso, 1.0f, false));
    counted = renderer.context().validationMessageCount();
    for (const std::string& m : renderer.context().validationMessages()) messages += m + "\n";
  }
  if (before)
    setenv("VK_INSTANCE_LAYERS", before->c_str(), 1);
  else
    unsetenv("VK_INSTANCE_LAYERS");
  EXPECT_EQ(counted, 0u) << messages;
}

// A real validation error is still counted: a buffer of size 0
// (VUID-VkBufferCreateInfo-size-00912).
TEST(Validation, ARealValidationErrorIsCounted) {
  ContextOptions options;
  options.instance.validation = true;
  VulkanContext context(options);
  ASSERT_EQ(context.validationMessageCount(), 0u);
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = 0;
  info.usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  vkCreateBuffer(context.device(), &info, nullptr, &buffer);
  if (buffer != VK_NULL_HANDLE) vkDestroyBuffer(context.device(), buffer, nullptr);
  ASSERT_GE(context.validationMessageCount(), 1u);
  EXPECT_NE(context.validationMessages().front().find("VUID-VkBufferCreateInfo-size-00912"),
            std::string::npos)
      << context.validationMessages().front();
}

// A 0.2 m square of 4x4 cells in z = 0, front facing +z.
Sheet square() {
  return testing::flatGrid(4, 4, 0.05);
}

// The square with its right half folded up toward the front (a valley along x = 0.1).
Sheet foldedSquare() {
  const Sheet flat = square();
  const VertexIndex seed = 4 + 2 * 5;  // (0.2, 0.1)
  const ReflectionPlane plane = bisectorPlane({0.2, 0.1, 0.0}, {0.1, 0.1, 0.1});
  return reflect(flat, seed, plane).sheet;
}

TEST_F(Render, FlatSquareFromTheFrontFillsItsProjectedBox) {
  const Sheet sheet = square();
  Scene scene = sceneForSheet(sheet, ViewPreset::Front, 1.0f, false);
  scene.ground.enabled = false;
  const RgbaImage image = renderer_->render(scene);
  ASSERT_EQ(image.width, kSize);

  // Where the corners land, by the scene's own matrices.
  const glm::mat4 clip = scene.camera.projection(1.0f) * scene.camera.view();
  float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
  for (glm::vec3 corner :
       {glm::vec3(0, 0, 0), glm::vec3(0.2, 0, 0), glm::vec3(0, 0.2, 0), glm::vec3(0.2, 0.2, 0)}) {
    const glm::vec4 c = clip * glm::vec4(corner, 1.0f);
    const float px = (c.x / c.w * 0.5f + 0.5f) * kSize, py = (c.y / c.w * 0.5f + 0.5f) * kSize;
    x0 = std::min(x0, px), x1 = std::max(x1, px), y0 = std::min(y0, py), y1 = std::max(y1, py);
  }
  ASSERT_GT(x1 - x0, kSize * 0.5f);  // the camera frames the sheet
  const std::uint8_t* background = image.at(1, 1);
  std::size_t inside = 0, paperInside = 0, paperOutside = 0;
  for (std::uint32_t y = 0; y < kSize; ++y)
    for (std::uint32_t x = 0; x < kSize; ++x) {
      const std::uint8_t* p = image.at(x, y);
      const bool paper = !std::equal(p, p + 3, background);
      const float cx = x + 0.5f, cy = y + 0.5f;
      if (cx > x0 + 1 && cx < x1 - 1 && cy > y0 + 1 && cy < y1 - 1) {
        ++inside;
        paperInside += paper;
      } else if (cx < x0 - 1 || cx > x1 + 1 || cy < y0 - 1 || cy > y1 + 1) {
        paperOutside += paper;
      }
    }
  EXPECT_EQ(paperInside, inside);
  EXPECT_EQ(paperOutside, 0u);
  // The front is paper white (shaded), not the back's orange.
  const std::uint8_t* centre = image.at(kSize / 2, kSize / 2);
  EXPECT_GT(centre[0], 150);
  EXPECT_LT(std::abs(int(centre[0]) - int(centre[2])), 30);
}

// Issue 14: an sRGB target (what the headset's swapchain now is) is given linear colour and shows
// what the UNORM target shows: the same picture within rounding, with blending and MSAA resolve
// done on linear values the only other difference (a few levels at edges and on the disk).
TEST_F(Render, AnSrgbTargetShowsWhatAUnormTargetShows) {
  HeadlessOptions options;
  options.width = kSize;
  options.height = kSize;
  options.validation = true;
  options.color = VK_FORMAT_R8G8B8A8_SRGB;
  HeadlessRenderer srgb(options);
  const Sheet sheet = foldedSquare();  // the scene points at it
  Scene scene = sceneForSheet(sheet, ViewPreset::Iso, 1.0f, true);
  scene.markers.push_back({{0.1f, 0.1f, 0.05f}, 0.01f, {0.9f, 0.3f, 0.2f, 1.0f}});
  const RgbaImage unorm = renderer_->render(scene);
  const RgbaImage linear = srgb.render(scene);
  ASSERT_EQ(linear.width, unorm.width);
  double sum = 0.0;
  int largest = 0;
  for (std::uint32_t y = 0; y < kSize; ++y)
    for (std::uint32_t x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c) {
        const int d = std::abs(int(unorm.at(x, y)[c]) - int(linear.at(x, y)[c]));
        largest = std::max(largest, d);
        sum += d;
      }
  // The background, the paper and the marker match to rounding: not encoded twice (which lifts
  // the background (219,224,232) to about (238,241,245)).
  const glm::vec4 marker = scene.camera.projection(1.0f) * scene.camera.view() *
                           glm::vec4(scene.markers.back().position, 1.0f);
  const auto mx = std::uint32_t((marker.x / marker.w * 0.5f + 0.5f) * kSize),
             my = std::uint32_t((marker.y / marker.w * 0.5f + 0.5f) * kSize);
  for (const auto& [x, y] : {std::pair{1u, 1u}, std::pair{kSize / 2, kSize / 2}, std::pair{mx, my}})
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(int(unorm.at(x, y)[c]), int(linear.at(x, y)[c]), 1) << x << "," << y << ":" << c;
  // Thin anti-aliased lines blend on linear values: a few pixels differ by more.
  EXPECT_LT(sum / (3.0 * kSize * kSize), 1.5) << "largest difference " << largest;
  EXPECT_EQ(srgb.context().validationMessageCount(), 0u);
}

TEST_F(Render, BackColourShowsWhenTheSheetIsTurned) {
  const Sheet sheet = square();
  Scene scene = sceneForSheet(sheet, ViewPreset::Back, 1.0f, false);
  const RgbaImage back = renderer_->render(scene);
  const std::uint8_t* centre = back.at(kSize / 2, kSize / 2);
  EXPECT_GT(int(centre[0]) - int(centre[2]), 60) << int(centre[0]) << "," << int(centre[2]);
}

TEST_F(Render, CreasePixelsAppearExactlyWhenThereAreCreases) {
  const Sheet flat = square();
  const RgbaImage unfolded = renderer_->render(sceneForSheet(flat, ViewPreset::Iso, 1.0f, false));
  EXPECT_EQ(countPixels(unfolded, isBlue), 0u);
  EXPECT_EQ(countPixels(unfolded, isRed), 0u);

  const Sheet folded = foldedSquare();
  const std::vector<CreaseEdge> creases = creaseEdges(folded, buildEdgeTopology(folded));
  ASSERT_FALSE(creases.empty());
  for (const CreaseEdge& c : creases) ASSERT_EQ(c.assignment, Assignment::Valley);
  renderer_->sceneRenderer().markSheetReplaced();
  const RgbaImage image = renderer_->render(sceneForSheet(folded, ViewPreset::Iso, 1.0f, false));
  EXPECT_GT(countPixels(image, isBlue), 100u);  // a 0.2 m crease, 3 px wide
  EXPECT_EQ(countPixels(image, isRed), 0u);
}

TEST_F(Render, CreasePatternPanelShowsTheCreases) {
  const Sheet folded = foldedSquare();
  Scene scene = sceneForSheet(folded, ViewPreset::Front, 1.0f, true);
  scene.creases.clear();  // only the panel's lines
  const RgbaImage image = renderer_->render(scene);
  std::size_t panelBlue = 0, viewBlue = 0;
  for (std::uint32_t y = 0; y < kSize; ++y)
    for (std::uint32_t x = 0; x < kSize; ++x)
      (x > kSize * 0.7f ? panelBlue : viewBlue) += isBlue(image.at(x, y));
  EXPECT_GT(panelBlue, 20u);
  EXPECT_EQ(viewBlue, 0u);
}

TEST_F(Render, MarkersAndPlaneDiskAreDrawn) {
  const Sheet sheet = square();
  Scene scene = sceneForSheet(sheet, ViewPreset::Front, 1.0f, false);
  const RgbaImage plain = renderer_->render(scene);
  scene.markers.push_back({{0.1f, 0.1f, 0.0f}, 0.01f, {0.1f, 0.8f, 0.1f, 1.0f}});
  scene.plane = PlaneDisk{{0.05f, 0.05f, 0.0f}, {1.0f, 0.0f, 1.0f}, 0.05f};
  const RgbaImage marked = renderer_->render(scene);
  const std::uint8_t* centre = marked.at(kSize / 2, kSize / 2);
  EXPECT_GT(centre[1], centre[0] + 50);  // green marker over the middle
  EXPECT_NE(plain.pixels, marked.pixels);
}

// Issue 27: translucent triangles (a target's ghost, a suggestion's result) blend over the sheet in
// front of it and are hidden behind it.
TEST_F(Render, TranslucentTrianglesBlendInFrontAndHideBehind) {
  const Sheet sheet = square();
  Scene scene = sceneForSheet(sheet, ViewPreset::Front, 1.0f, false);
  const RgbaImage plain = renderer_->render(scene);
  auto triangleAt = [&](float z) {
    scene.translucent.clear();
    const glm::vec4 red(1.0f, 0.0f, 0.0f, 0.5f);
    // Within the sheet's outline, over its middle.
    for (const glm::vec3& p :
         {glm::vec3(0.05f, 0.05f, z), glm::vec3(0.15f, 0.05f, z), glm::vec3(0.1f, 0.15f, z)})
      scene.translucent.push_back({p, red});
  };
  triangleAt(-0.01f);  // behind the sheet (the front view looks from +z)
  EXPECT_EQ(renderer_->render(scene).pixels, plain.pixels);
  triangleAt(0.01f);
  const RgbaImage ghost = renderer_->render(scene);
  const std::uint8_t* under = plain.at(kSize / 2, kSize / 2);
  const std::uint8_t* over = ghost.at(kSize / 2, kSize / 2);
  EXPECT_GT(int(over[0]), int(over[1]) + 60);  // reddened
  EXPECT_GT(int(over[1]), 40);                 // the paper still shows through
  EXPECT_LT(int(over[1]), int(under[1]) - 40);
}

// Issue 38, 4: a target's ghost lying on the sheet (where the design already matches it) tints
// the sheet evenly; without a polygon offset their depths tie and the ghost speckles (seen as
// grey and orange on a headset). The ghost here is the sheet itself, a curved one seen at a
// slant, placed on the CPU as the studio places a target.
TEST_F(Render, AGhostOnTheSheetTintsItEvenly) {
  const Sheet sheet = makeSurface("cylinder");
  Scene scene = sceneForSheet(sheet, ViewPreset::Iso, 1.0f, false);
  scene.ground.enabled = false;  // only the sheet differs from the background
  // Held somewhere in a room (a headset's sheet frame), the camera moved with it: the sheet is
  // placed by the GPU in floats, the ghost by the CPU in doubles (InteractionCore::worldOf).
  const glm::dmat4 place =
      glm::translate(glm::dmat4(1.0), glm::dvec3(0.31, 1.13, -0.47)) *
      glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(0.3, 1.0, 0.2)));
  scene.sheet.worldFromSheet = glm::mat4(place) * scene.sheet.worldFromSheet;
  scene.camera.eye = glm::vec3(place * glm::dvec4(glm::dvec3(scene.camera.eye), 1.0));
  scene.camera.target = glm::vec3(place * glm::dvec4(glm::dvec3(scene.camera.target), 1.0));
  scene.camera.up = glm::vec3(place * glm::dvec4(glm::dvec3(scene.camera.up), 0.0));
  const RgbaImage plain = renderer_->render(scene);
  const glm::vec4 tint(1.0f, 0.0f, 0.0f, 0.5f);
  const glm::dmat4 model(scene.sheet.worldFromSheet);
  for (const Triangle& t : sheet.triangles)
    for (const VertexIndex v : t)
      scene.translucent.push_back({glm::vec3(model * glm::dvec4(sheet.positions[v], 1.0)), tint});
  const RgbaImage ghost = renderer_->render(scene);
  const std::uint8_t* corner = plain.at(0, 0);
  std::size_t paper = 0, untinted = 0;
  for (std::uint32_t y = 1; y + 1 < kSize; ++y)
    for (std::uint32_t x = 1; x + 1 < kSize; ++x) {
      // The sheet's inside: this pixel and its neighbours differ from the background.
      bool inside = true;
      for (const auto& [dx, dy] : {std::pair{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const std::uint8_t* p = plain.at(x + dx, y + dy);
        inside = inside && std::abs(int(p[0]) - int(corner[0])) +
                                   std::abs(int(p[1]) - int(corner[1])) +
                                   std::abs(int(p[2]) - int(corner[2])) >
                               30;
      }
      if (!inside) continue;
      ++paper;
      const std::uint8_t* over = ghost.at(x, y);
      untinted += int(over[0]) < int(over[1]) + 30;
    }
  ASSERT_GT(paper, std::size_t(kSize * kSize / 20));
  EXPECT_LT(untinted, paper / 200) << untinted << " of " << paper << " pixels of the sheet speckle";
}

// Issue 14: a picture on a quad in the world (the headset's panel) shows its texture and hides
// what is behind it, lines included, while lines in front of it stay visible.
TEST_F(Render, AWorldPanelShowsItsPictureAndHidesWhatIsBehindIt) {
  const VulkanContext& context = renderer_->context();
  GpuImage picture(context, {8, 8}, VK_FORMAT_R8G8B8A8_UNORM, VK_SAMPLE_COUNT_1_BIT,
                   VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                   VK_IMAGE_ASPECT_COLOR_BIT);
  {
    // Solid green, left ready to sample.
    FrameRing once(context, 1);
    Frame& frame = once.begin();
    const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    const ImageUse transfer{VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                            VK_ACCESS_TRANSFER_WRITE_BIT};
    imageBarrier(frame.commands, picture.image(), VK_IMAGE_ASPECT_COLOR_BIT, {}, transfer);
    const VkClearColorValue green{{0.1f, 0.8f, 0.2f, 1.0f}};
    vkCmdClearColorImage(frame.commands, picture.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         &green, 1, &all);
    imageBarrier(frame.commands, picture.image(), VK_IMAGE_ASPECT_COLOR_BIT, transfer,
                 {VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                  VK_ACCESS_SHADER_READ_BIT});
    once.submit(frame);
    once.wait(frame);
  }
  const VkSampler sampler =
      createSampler(context.device(), VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_REPEAT);
  renderer_->sceneRenderer().setWorldPanelTexture(picture.view(), sampler);

  const Sheet sheet = square();  // 0.2 m, z = 0, seen from the front
  Scene scene = sceneForSheet(sheet, ViewPreset::Front, 1.0f, false);
  scene.ground.enabled = false;
  // The panel over the left half, a little in front of the sheet; a red line behind it and a
  // blue one in front of it, both across the whole sheet.
  WorldPanel panel;
  panel.corners[0] = {0.0f, 0.2f, 0.02f};
  panel.corners[1] = {0.1f, 0.2f, 0.02f};
  panel.corners[2] = {0.1f, 0.0f, 0.02f};
  panel.corners[3] = {0.0f, 0.0f, 0.02f};
  scene.worldPanel = panel;
  scene.lines.push_back({{-0.05f, 0.08f, -0.03f}, {0.25f, 0.08f, -0.03f}, {0.9f, 0.05f, 0.05f, 1}});
  scene.lines.push_back({{-0.05f, 0.12f, 0.05f}, {0.25f, 0.12f, 0.05f}, {0.05f, 0.1f, 0.9f, 1}});
  const RgbaImage image = renderer_->render(scene);
  vkDestroySampler(context.device(), sampler, nullptr);

  // Where the panel and the sheet are on screen: project their corners.
  const glm::mat4 viewProj = scene.camera.projection(1.0f) * scene.camera.view();
  auto pixel = [&](const glm::vec3& p) {
    const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
    return glm::vec2((clip.x / clip.w * 0.5f + 0.5f) * kSize,
                     (clip.y / clip.w * 0.5f + 0.5f) * kSize);
  };
  const glm::vec2 panelLow = pixel(panel.corners[0]), panelHigh = pixel(panel.corners[2]);
  auto insidePanel = [&](std::uint32_t x, std::uint32_t y) {
    return x > panelLow.x + 2 && x < panelHigh.x - 2 && y > panelLow.y + 2 && y < panelHigh.y - 2;
  };
  std::size_t green = 0, redInside = 0, redOutside = 0, blueInside = 0;
  for (std::uint32_t y = 0; y < kSize; ++y)
    for (std::uint32_t x = 0; x < kSize; ++x) {
      const std::uint8_t* p = image.at(x, y);
      const bool inside = insidePanel(x, y);
      if (inside && p[1] > 150 && p[0] < 80 && p[2] < 100) ++green;
      if (isRed(p)) ++(inside ? redInside : redOutside);
      if (inside && isBlue(p)) ++blueInside;
    }
  EXPECT_GT(green, 1000u);
  EXPECT_EQ(redInside, 0u);    // behind the panel: hidden
  EXPECT_GT(redOutside, 50u);  // beside it: seen
  EXPECT_GT(blueInside, 50u);  // in front of it: seen
}

TEST_F(Render, SameDesignRendersBitIdenticallyTwice) {
  const Sheet folded = foldedSquare();
  const Scene scene = sceneForSheet(folded, ViewPreset::Iso, 1.0f, true);
  const RgbaImage first = renderer_->render(scene);
  renderer_->sceneRenderer().markSheetReplaced();
  const RgbaImage second = renderer_->render(scene);
  EXPECT_EQ(first.pixels, second.pixels);
  expectSceneDrawn(*renderer_, first, scene, /*creases=*/true);
}

// A drag rendered frame by frame with incremental upload gives the images of a full upload every
// frame, while writing fewer bytes; drawn with every triangle (simplify false) or as the designer
// draws it (the display session's merged planar regions, a few dozen triangles here, so most of
// it changes with every update and no bytes are saved). In a symmetric design the display sheet
// previews the images, remade whole at every update.
void expectIncrementalUploadMatchesFullUpload(HeadlessRenderer& renderer, bool simplify,
                                              bool symmetric = false) {
  HeadlessOptions options;
  options.width = options.height = kSize;
  options.validation = true;
  HeadlessRenderer full(options);

  FoldSession session(makeSurface("cylinder", {{"resolution", 24}}));
  if (symmetric) session.setSymmetry(parseSymmetry("rotational:6", session.initial()));
  SessionSheetTracker tracker(simplify);
  std::size_t incrementalBytes = 0, fullBytes = 0;
  auto frame = [&] {
    tracker.update(session, renderer.sceneRenderer());
    full.sceneRenderer().markSheetReplaced();
    Scene scene = sceneForSheet(session.current(), ViewPreset::Iso, 1.0f, false);
    scene.camera = frameBounds(worldBounds(session.initial()), ViewPreset::Iso, 1.0f);
    tracker.describe(scene.sheet);
    const RgbaImage a = renderer.render(scene);
    incrementalBytes += renderer.sceneRenderer().lastUpload().sheetBytes;
    const RgbaImage b = full.render(scene);
    fullBytes += full.sceneRenderer().lastUpload().sheetBytes;
    expectSceneDrawn(full, b, scene, /*creases=*/false);
    return a.pixels == b.pixels;
  };
  EXPECT_TRUE(frame());
  session.beginDragNear({0.03, 0.105, 0.03});
  EXPECT_TRUE(frame());
  const std::size_t bytesBeforeDrag = incrementalBytes;
  const std::size_t fullBeforeDrag = fullBytes;
  for (int step = 1; step <= 8; ++step) {
    session.updateDrag({0.03 - 0.002 * step, 0.105 - 0.006 * step, 0.03 + 0.001 * step});
    // Two updates between some frames: the tracker must still catch up.
    if (step % 3 == 0)
      session.updateDrag({0.03 - 0.002 * step, 0.104 - 0.006 * step, 0.03 + 0.001 * step});
    EXPECT_TRUE(frame()) << "step " << step;
  }
  if (!simplify) {
    EXPECT_LT(incrementalBytes - bytesBeforeDrag, (fullBytes - fullBeforeDrag) / 2);
  }
  EXPECT_EQ(tracker.display().shownSession().previewingImages(), symmetric);
  session.commit();
  EXPECT_TRUE(frame());
  session.undo();
  EXPECT_TRUE(frame());
  EXPECT_EQ(full.context().validationMessageCount(), 0u);
  EXPECT_EQ(&tracker.display().sheet() == &session.current(), !simplify);
}

TEST_F(Render, IncrementalUploadMatchesFullUpload) {
  expectIncrementalUploadMatchesFullUpload(*renderer_, false);
}

TEST_F(Render, IncrementalUploadOfTheDisplaySheetMatchesFullUpload) {
  expectIncrementalUploadMatchesFullUpload(*renderer_, true);
}

TEST_F(Render, IncrementalUploadOfASymmetricPreviewMatchesFullUpload) {
  expectIncrementalUploadMatchesFullUpload(*renderer_, true, true);
}

TEST(DirtyRanges, JoinsNearbyRunsAndClips) {
  DirtyRanges ranges;
  const std::uint32_t indices[] = {9, 3, 4, 5, 40};
  ranges.addIndices(indices);
  ranges.add(100, 200);
  const auto runs = ranges.runs(150, 4);
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0], std::make_pair(3u, 10u));
  EXPECT_EQ(runs[1], std::make_pair(40u, 41u));
  EXPECT_EQ(runs[2], std::make_pair(100u, 150u));
}

// Issue 38 2d / issue 39 1: a quantity coloured on the sheet. viridis runs from dark purple to
// yellow and brightens all the way (perceptual: its lightness rises with the value); cool-warm
// is blue, grey, red with its light middle at 0.5.
TEST(ColorMaps, RunFromTheirPublishedEndsAndViridisBrightensThroughout) {
  EXPECT_EQ(colorAt(ColorMap::Viridis, 0.0), glm::u8vec4(68, 1, 84, 255));
  EXPECT_EQ(colorAt(ColorMap::Viridis, 1.0), glm::u8vec4(253, 231, 37, 255));
  EXPECT_EQ(colorAt(ColorMap::Viridis, -3.0), colorAt(ColorMap::Viridis, 0.0));
  EXPECT_EQ(colorAt(ColorMap::Viridis, std::nan("")), colorAt(ColorMap::Viridis, 0.0));
  EXPECT_EQ(colorAt(ColorMap::Viridis, 7.0), colorAt(ColorMap::Viridis, 1.0));
  double lightness = -1.0;
  for (int i = 0; i <= 100; ++i) {
    const glm::u8vec4 c = colorAt(ColorMap::Viridis, i / 100.0);
    const double y = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    EXPECT_GT(y, lightness) << "at " << i;
    lightness = y;
  }
  const glm::u8vec4 low = colorAt(ColorMap::CoolWarm, 0.0),
                    middle = colorAt(ColorMap::CoolWarm, 0.5),
                    high = colorAt(ColorMap::CoolWarm, 1.0);
  EXPECT_GT(low.b, low.r + 100);
  EXPECT_GT(high.r, high.b + 100);
  EXPECT_NEAR(middle.r, middle.b, 2);
  EXPECT_GT(middle.g, 200);
  const std::vector<double> values{-1.0, 0.0, 1.0, std::numeric_limits<double>::infinity()};
  const std::vector<glm::u8vec4> colors = colorsOf(values, -1.0, 1.0, ColorMap::CoolWarm);
  EXPECT_EQ(colors[0], low);
  EXPECT_EQ(colors[1], middle);
  EXPECT_EQ(colors[2], high);
  EXPECT_EQ(colors[3], low);
}

bool isViridisHigh(const std::uint8_t* p) {  // yellow, shaded or not
  return p[0] > 150 && p[1] > 130 && p[2] < 80;
}
bool isViridisLow(const std::uint8_t* p) {  // dark purple
  return p[0] > 30 && p[0] < 100 && p[1] < 30 && p[2] > 45 && p[2] < 110;
}

// A flat square whose right quarter is "far" (value 1, the rest 0), seen from the front: the far
// part is drawn in the map's high colour, right of the low colour, and the legend strip at the
// right shows the bar's both ends and dark text. The same sheet drawn plain has neither colour.
TEST_F(Render, AColouredSheetShowsItsFarRegionInTheHighColour) {
  const Sheet sheet = testing::flatGrid(8, 8, 0.025);
  std::vector<double> values(sheet.vertexCount(), 0.0);
  for (VertexIndex v = 0; v < sheet.vertexCount(); ++v)
    if (sheet.positions[v].x > 0.15 + 1e-9) values[v] = 1.0;
  const ColorLegend legend{ColorMap::Viridis, 0.0, 1.0, "distance to the target", "mm"};
  const RgbaImage image = renderFieldPicture(*renderer_, sheet, values, legend, ViewPreset::Front);
  ASSERT_EQ(image.width, kSize);
  const std::uint32_t viewWidth = kSize - legendWidth(kSize);
  double highX = 0.0, lowX = 0.0;
  std::size_t high = 0, low = 0, legendHigh = 0, legendLow = 0, legendText = 0;
  for (std::uint32_t y = 0; y < kSize; ++y)
    for (std::uint32_t x = 0; x < kSize; ++x) {
      const std::uint8_t* p = image.at(x, y);
      if (x < viewWidth) {
        if (isViridisHigh(p)) ++high, highX += x;
        if (isViridisLow(p)) ++low, lowX += x;
      } else {
        legendHigh += isViridisHigh(p);
        legendLow += isViridisLow(p);
        legendText += p[0] < 60 && p[1] < 60 && p[2] < 60;
      }
    }
  // The square spans the flat view; its right quarter is about a fifth of its pixels.
  EXPECT_GT(high, std::size_t(viewWidth) * kSize / 40);
  EXPECT_GT(low, 2 * high);
  ASSERT_GT(high, 0u);
  ASSERT_GT(low, 0u);
  EXPECT_GT(highX / double(high), lowX / double(low) + 0.2 * viewWidth);
  EXPECT_GT(legendHigh, 20u);
  EXPECT_GT(legendLow, 20u);
  EXPECT_GT(legendText, 20u);

  // Plain paper: neither colour anywhere.
  Scene plain = sceneForSheet(sheet, ViewPreset::Front, 1.0f, false);
  const RgbaImage paper = renderer_->render(plain);
  EXPECT_EQ(countPixels(paper, isViridisHigh), 0u);
  EXPECT_EQ(countPixels(paper, isViridisLow), 0u);
}

// A 20 cm square bent into a saddle 22 mm high, in the xy plane (as the fit's square lies) and
// in the xz plane (an OBJ with y up): the chosen view lays it on the ground (its normal onto +y)
// and looks from within 36 degrees of that normal, where the fixed iso view stood it up as a wall
// or saw it from 69 degrees. A tube keeps the iso view unturned.
TEST(SheetViews, NearlyFlatSheetsAreLaidDownAndSeenFromAboveATubeAsBefore) {
  for (const bool yUp : {false, true}) {
    Sheet saddle = testing::flatGrid(20, 20, 0.01);
    glm::dvec3 normal(0.0, 0.0, 1.0);
    for (glm::dvec3& p : saddle.positions) {
      const double x = p.x - 0.1, y = p.y - 0.1, z = 0.011 * (x * x - y * y) / 0.01;
      p = yUp ? glm::dvec3(x, z, y) : glm::dvec3(x, y, z);
    }
    if (yUp) normal = {0.0, 1.0, 0.0};
    const SheetView view = viewForSheet(saddle);
    const glm::vec3 worldNormal =
        glm::normalize(glm::mat3(view.worldFromSheet) * glm::vec3(normal));
    EXPECT_GT(std::abs(worldNormal.y), std::cos(glm::radians(5.0f))) << "y up: " << yUp;
    EXPECT_NEAR(glm::length(view.direction), 1.0f, 1e-5f);
    const float fromNormal =
        glm::degrees(std::acos(std::abs(glm::dot(view.direction, worldNormal))));
    EXPECT_LT(fromNormal, 36.0f) << "y up: " << yUp;
    EXPECT_GT(fromNormal, 25.0f) << "y up: " << yUp;  // at an angle, so its heights read
    // The rotation turns about the sheet's centre: the picture frames the same sheet.
    const glm::vec3 centre = worldBounds(saddle).centre();
    EXPECT_LT(glm::length(worldBounds(saddle, view.worldFromSheet).centre() - centre), 0.02f);
  }
  // A bowl opening down (-z, or -y with y up) is turned to open upwards: its rim above its middle.
  for (const bool yUp : {false, true}) {
    Sheet bowl = testing::flatGrid(20, 20, 0.01);
    for (glm::dvec3& p : bowl.positions) {
      const double x = p.x - 0.1, y = p.y - 0.1, z = -2.0 * (x * x + y * y);
      p = yUp ? glm::dvec3(x, z, y) : glm::dvec3(x, y, z);
    }
    const glm::mat4 laid = viewForSheet(bowl).worldFromSheet;
    auto height = [&](VertexIndex v) {
      return (laid * glm::vec4(glm::vec3(bowl.positions[v]), 1.0f)).y;
    };
    EXPECT_GT(height(0), height(VertexIndex(bowl.vertexCount() / 2)) + 0.02f) << "y up: " << yUp;
  }
  const Sheet tube = makeSurface("cylinder");
  const SheetView view = viewForSheet(tube);
  EXPECT_EQ(view.worldFromSheet, glm::mat4(1.0f));
  EXPECT_LT(glm::length(view.direction - viewDirection(ViewPreset::Iso)), 1e-6f);
}

TEST(ViewPresets, ParseKnownNamesOnly) {
  EXPECT_EQ(parseViewPreset("iso"), ViewPreset::Iso);
  EXPECT_EQ(parseViewPreset("top"), ViewPreset::Top);
  EXPECT_FALSE(parseViewPreset("diagonal"));
}

}  // namespace
}  // namespace curvefold
