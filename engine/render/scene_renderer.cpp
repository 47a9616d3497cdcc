#include "engine/render/scene_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "engine/render/pipeline_builder.hpp"
#include "engine/render/scope_fail.hpp"
#include "engine/render/vulkan_objects.hpp"
#include "shaders/line.frag.h"
#include "shaders/line.frag.multiview.h"
#include "shaders/line.vert.h"
#include "shaders/line.vert.multiview.h"
#include "shaders/marker.frag.h"
#include "shaders/marker.frag.multiview.h"
#include "shaders/marker.vert.h"
#include "shaders/marker.vert.multiview.h"
#include "shaders/panel.frag.h"
#include "shaders/panel.frag.multiview.h"
#include "shaders/panel.vert.h"
#include "shaders/panel.vert.multiview.h"
#include "shaders/sheet.frag.h"
#include "shaders/sheet.frag.multiview.h"
#include "shaders/sheet.vert.h"
#include "shaders/sheet.vert.multiview.h"
#include "shaders/sheet_colored.frag.h"
#include "shaders/sheet_colored.frag.multiview.h"
#include "shaders/sheet_colored.vert.h"
#include "shaders/sheet_colored.vert.multiview.h"
#include "shaders/translucent.frag.h"
#include "shaders/translucent.frag.multiview.h"
#include "shaders/translucent.vert.h"
#include "shaders/translucent.vert.multiview.h"

namespace curvefold {
namespace {

// std140 mirror of the shaders' Frame block.
// Two views: a multiview pass's eyes (an ordinary pass uses the first).
struct FrameUniforms {
  glm::mat4 viewProj[2];
  glm::mat4 view[2];
  glm::mat4 proj[2];
  glm::mat4 model;
  glm::mat4 panelProj;
  glm::vec4 eye[2];
  glm::vec4 lightDir;
  glm::vec4 frontColor;
  glm::vec4 backColor;
  glm::vec4 tintColor;
  glm::vec4 viewport;
};

struct LinePush {
  glm::vec2 viewportSize;
  float widthPixels;
  float towardEye;
  std::uint32_t space;
};

struct LineInstance {
  glm::vec3 a, b;
  glm::vec4 color;
};
struct MarkerInstance {
  glm::vec4 centreRadius;
  glm::vec4 color;
};
struct ColoredVertex {
  glm::vec3 position;
  glm::vec4 color;
};
static_assert(sizeof(ColoredVertex) == sizeof(TranslucentVertex));
struct PanelVertex {
  glm::vec3 position;
  glm::vec2 uv;
};

constexpr std::uint32_t kDiskSegments = 72;
// Dirty runs closer than this many clean elements are copied as one.
constexpr std::uint32_t kRunGap = 8;
// How far toward the eye crease ribbons and other world lines are pulled (fraction of distance).
constexpr float kCreaseTowardEye = 0.003f;
constexpr float kLineTowardEye = 0.001f;

// A shader's SPIR-V: its multiview variant for a multiview pass.
template <std::size_t N, std::size_t M>
std::span<const std::uint32_t> code(bool multiview, const std::uint32_t (&words)[N],
                                    const std::uint32_t (&multiviewWords)[M]) {
  if (multiview) return {multiviewWords, M};
  return {words, N};
}

// Where the 3D view and the panel go in the image.
struct Layout {
  VkRect2D view;
  VkRect2D panel;
};

Layout layoutFor(const Scene& scene, VkExtent2D extent) {
  Layout layout{{{0, 0}, extent}, {{0, 0}, {0, 0}}};
  if (scene.panel.enabled) {
    const auto panelWidth = static_cast<std::uint32_t>(
        std::clamp(scene.panel.widthFraction, 0.05f, 0.9f) * float(extent.width));
    layout.view.extent.width = extent.width - panelWidth;
    layout.panel = {{static_cast<std::int32_t>(extent.width - panelWidth), 0},
                    {panelWidth, extent.height}};
  }
  return layout;
}

// Development -> panel clip space: fits the bounds (with a margin) keeping their aspect; y up.
glm::mat4 panelProjection(const CreasePatternPanel& panel, VkExtent2D size) {
  const glm::vec2 span = glm::max(panel.max - panel.min, glm::vec2(1e-6f));
  const glm::vec2 centre = 0.5f * (panel.min + panel.max);
  const float w = float(std::max(size.width, 1u)), h = float(std::max(size.height, 1u));
  const float pixelsPerMetre = 0.88f * std::min(w / span.x, h / span.y);
  glm::mat4 m(0.0f);
  m[0][0] = 2.0f * pixelsPerMetre / w;
  m[1][1] = -2.0f * pixelsPerMetre / h;
  m[3][0] = -centre.x * m[0][0];
  m[3][1] = -centre.y * m[1][1];
  m[3][2] = 0.5f;
  m[3][3] = 1.0f;
  return m;
}

void setViewport(VkCommandBuffer commands, const VkRect2D& rect) {
  VkViewport viewport{float(rect.offset.x),
                      float(rect.offset.y),
                      float(rect.extent.width),
                      float(rect.extent.height),
                      0.0f,
                      1.0f};
  vkCmdSetViewport(commands, 0, 1, &viewport);
  vkCmdSetScissor(commands, 0, 1, &rect);
}

}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> DirtyRanges::runs(std::uint32_t limit,
                                                                       std::uint32_t gap) const {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> sorted;
  sorted.reserve(ranges_.size());
  for (auto [begin, end] : ranges_) {
    end = std::min(end, limit);
    if (begin < end) sorted.emplace_back(begin, end);
  }
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::pair<std::uint32_t, std::uint32_t>> merged;
  for (const auto& range : sorted) {
    if (!merged.empty() && range.first <= merged.back().second + gap)
      merged.back().second = std::max(merged.back().second, range.second);
    else
      merged.push_back(range);
  }
  return merged;
}

// The translucent pass's polygon offset, in depth units and per unit of depth slope: a few units
// settle the tie of two surfaces that coincide and move nothing visibly.
constexpr float kTranslucentDepthBias = -4.0f;

// Everything one frame in flight owns.
struct SceneRenderer::Slot {
  HostBuffer uniforms;
  VkDescriptorSet set = VK_NULL_HANDLE;

  // The sheet as this slot's buffers hold it.
  HostBuffer vertices, flags, indices;  // flags: one byte per vertex, the reflected tint
  HostBuffer colors;                    // the scene's vertexColors, when it has them
  bool colored = false;                 // this frame draws them
  std::uint32_t vertexCapacity = 0, triangleCapacity = 0;
  std::uint32_t vertexCount = 0, triangleCount = 0;
  bool dirtyAll = true;
  DirtyRanges dirtyVertices, dirtyTriangles;

  // Lines, markers and disk vertices, rewritten every frame.
  HostBuffer stream;
  std::uint32_t gridFirst = 0, gridCount = 0, creaseFirst = 0, creaseCount = 0, lineFirst = 0,
                lineCount = 0, panelFirst = 0, panelCount = 0;
  VkDeviceSize markerOffset = 0, diskOffset = 0, panelOffset = 0;
  std::uint32_t markerCount = 0, diskVertexCount = 0, panelVertexCount = 0;
  std::uint32_t drawTriangles = 0;
};

SceneRenderer::SceneRenderer(const VulkanContext& context, const RenderTarget& target,
                             std::uint32_t framesInFlight)
    : context_(context),
      format_(target.format()),
      renderPass_(target.renderPass()),
      slots_(framesInFlight) {
  const VkDevice device = context.device();
  const ScopeFail cleanup([this] { destroy(); });
  VkDescriptorSetLayoutBinding bindings[1]{};
  bindings[0].binding = 0;
  bindings[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  bindings[0].descriptorCount = 1;
  bindings[0].stageFlags = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = 1;
  setInfo.pBindings = bindings;
  vkCheck(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout_),
          "vkCreateDescriptorSetLayout");
  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(LinePush)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout_;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &push;
  vkCheck(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout_), "vkCreatePipelineLayout");

  pool_ = createDescriptorPool(device, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, framesInFlight);

  const bool multiview = format_.views > 1;
  PipelineBuilder builder{device,
                          layout_,
                          target.renderPass(),
                          format_.samples,
                          code(multiview, sheet_vert_spv, sheet_vert_multiview_spv),
                          code(multiview, sheet_frag_spv, sheet_frag_multiview_spv)};
  builder.srgbTarget = isSrgbFormat(format_.color) ? VK_TRUE : VK_FALSE;
  builder.bindings = {{0, sizeof(glm::vec3), VK_VERTEX_INPUT_RATE_VERTEX},
                      {1, 1, VK_VERTEX_INPUT_RATE_VERTEX}};
  builder.attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}, {1, 1, VK_FORMAT_R8_UNORM, 0}};
  sheetPipeline_ = builder.build();
  builder.vertexCode = code(multiview, sheet_colored_vert_spv, sheet_colored_vert_multiview_spv);
  builder.fragmentCode = code(multiview, sheet_colored_frag_spv, sheet_colored_frag_multiview_spv);
  builder.bindings = {{0, sizeof(glm::vec3), VK_VERTEX_INPUT_RATE_VERTEX},
                      {1, sizeof(glm::u8vec4), VK_VERTEX_INPUT_RATE_VERTEX}};
  builder.attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}, {1, 1, VK_FORMAT_R8G8B8A8_UNORM, 0}};
  coloredSheetPipeline_ = builder.build();
  // The other pipelines: lines and translucent surfaces blend and write no depth, markers are
  // opaque like the sheet.
  const auto build = [&builder](bool blended) {
    builder.depthWrite = !blended;
    builder.blend = blended;
    return builder.build();
  };

  builder.vertexCode = code(multiview, line_vert_spv, line_vert_multiview_spv);
  builder.fragmentCode = code(multiview, line_frag_spv, line_frag_multiview_spv);
  builder.bindings = {{0, sizeof(LineInstance), VK_VERTEX_INPUT_RATE_INSTANCE}};
  builder.attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(LineInstance, a)},
                        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(LineInstance, b)},
                        {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(LineInstance, color)}};
  linePipeline_ = build(true);

  builder.vertexCode = code(multiview, marker_vert_spv, marker_vert_multiview_spv);
  builder.fragmentCode = code(multiview, marker_frag_spv, marker_frag_multiview_spv);
  builder.bindings = {{0, sizeof(MarkerInstance), VK_VERTEX_INPUT_RATE_INSTANCE}};
  builder.attributes = {
      {0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(MarkerInstance, centreRadius)},
      {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(MarkerInstance, color)}};
  markerPipeline_ = build(false);

  builder.vertexCode = code(multiview, translucent_vert_spv, translucent_vert_multiview_spv);
  builder.fragmentCode = code(multiview, translucent_frag_spv, translucent_frag_multiview_spv);
  builder.bindings = {{0, sizeof(ColoredVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  builder.attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(ColoredVertex, position)},
                        {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(ColoredVertex, color)}};
  // Tested against the scene, hides nothing; drawn a little toward the eye, so a target's ghost
  // lying on the sheet tints it evenly rather than speckling where their depths tie (issue 38, 4).
  builder.depthBiasConstant = kTranslucentDepthBias;
  builder.depthBiasSlope = kTranslucentDepthBias;
  translucentPipeline_ = build(true);
  builder.depthBiasConstant = builder.depthBiasSlope = 0.0f;

  for (Slot& slot : slots_) {
    slot.uniforms = HostBuffer(context, sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    slot.set = allocateDescriptorSet(device, pool_, setLayout_);
    slot.vertices = HostBuffer(context, 16 * sizeof(glm::vec3), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    slot.indices = HostBuffer(context, 16 * sizeof(Triangle), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    slot.flags = HostBuffer(context, 16, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    slot.vertexCapacity = 16;
    slot.triangleCapacity = 16;
    writeDescriptors(slot);
  }
}

SceneRenderer::~SceneRenderer() {
  destroy();
}

void SceneRenderer::createPanelPipeline() {
  const VkDevice device = context_.device();
  VkDescriptorSetLayoutBinding binding{};
  binding.binding = 0;
  binding.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  binding.descriptorCount = 1;
  binding.stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = 1;
  setInfo.pBindings = &binding;
  vkCheck(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &panelSetLayout_),
          "vkCreateDescriptorSetLayout");
  const VkDescriptorSetLayout sets[2] = {setLayout_, panelSetLayout_};
  // The push constants as the scene's layout has them, so binding set 1 keeps set 0 bound.
  const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(LinePush)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 2;
  layoutInfo.pSetLayouts = sets;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &push;
  vkCheck(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &panelLayout_),
          "vkCreatePipelineLayout");
  panelPool_ = createDescriptorPool(device, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1);
  panelSet_ = allocateDescriptorSet(device, panelPool_, panelSetLayout_);
  const bool multiview = format_.views > 1;
  PipelineBuilder builder{device,
                          panelLayout_,
                          renderPass_,
                          format_.samples,
                          code(multiview, panel_vert_spv, panel_vert_multiview_spv),
                          code(multiview, panel_frag_spv, panel_frag_multiview_spv)};
  builder.srgbTarget = isSrgbFormat(format_.color) ? VK_TRUE : VK_FALSE;
  builder.bindings = {{0, sizeof(PanelVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  builder.attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(PanelVertex, position)},
                        {1, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(PanelVertex, uv)}};
  panelPipeline_ = builder.build();
}

void SceneRenderer::setWorldPanelTexture(VkImageView view, VkSampler sampler) {
  const VkDevice device = context_.device();
  if (!panelPipeline_) createPanelPipeline();
  VkDescriptorImageInfo image{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = panelSet_;
  write.dstBinding = 0;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = &image;
  vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

void SceneRenderer::destroy() {
  const VkDevice device = context_.device();
  vkDeviceWaitIdle(device);
  slots_.clear();
  destroyHandle(device, panelPipeline_, vkDestroyPipeline);
  destroyHandle(device, panelPool_, vkDestroyDescriptorPool);  // frees panelSet_
  destroyHandle(device, panelLayout_, vkDestroyPipelineLayout);
  destroyHandle(device, panelSetLayout_, vkDestroyDescriptorSetLayout);
  panelSet_ = VK_NULL_HANDLE;
  for (VkPipeline* pipeline : {&sheetPipeline_, &coloredSheetPipeline_, &linePipeline_,
                               &markerPipeline_, &translucentPipeline_})
    destroyHandle(device, *pipeline, vkDestroyPipeline);
  destroyHandle(device, pool_, vkDestroyDescriptorPool);
  destroyHandle(device, layout_, vkDestroyPipelineLayout);
  destroyHandle(device, setLayout_, vkDestroyDescriptorSetLayout);
}

void SceneRenderer::writeDescriptors(Slot& slot) {
  VkDescriptorBufferInfo uniforms{slot.uniforms.buffer(), 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet writes[1]{};
  writes[0].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
  writes[0].dstSet = slot.set;
  writes[0].dstBinding = 0;
  writes[0].descriptorCount = 1;
  writes[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  writes[0].pBufferInfo = &uniforms;
  vkUpdateDescriptorSets(context_.device(), 1, writes, 0, nullptr);
}

void SceneRenderer::markSheetReplaced() {
  for (Slot& slot : slots_) {
    slot.dirtyAll = true;
    slot.dirtyVertices.clear();
    slot.dirtyTriangles.clear();
  }
}

void SceneRenderer::markSheetMoved() {
  for (Slot& slot : slots_)
    if (!slot.dirtyAll) slot.dirtyVertices.add(0, kNoIndex);
}

void SceneRenderer::markSheetChanged(const ReflectionChanges& changes) {
  const bool cleared = changes.firstNewVertex == 0 && changes.firstNewTriangle == 0 &&
                       changes.movedVertices.empty() && changes.rewrittenTriangles.empty();
  if (cleared) return;
  markSheetChanged(changes.movedVertices, changes.rewrittenTriangles);
  for (Slot& slot : slots_) {
    if (slot.dirtyAll) continue;
    // Appended elements: up to whatever the sheet holds when the slot is next prepared.
    slot.dirtyVertices.add(static_cast<std::uint32_t>(changes.firstNewVertex), kNoIndex);
    slot.dirtyTriangles.add(static_cast<std::uint32_t>(changes.firstNewTriangle), kNoIndex);
  }
}

void SceneRenderer::markSheetChanged(std::span<const VertexIndex> vertices,
                                     std::span<const TriangleIndex> triangles) {
  for (Slot& slot : slots_) {
    if (slot.dirtyAll) continue;
    slot.dirtyVertices.addIndices(vertices);
    slot.dirtyTriangles.addIndices(triangles);
  }
}

void SceneRenderer::updateFlags(const Sheet& sheet, std::span<const TriangleIndex> reflected) {
  const std::size_t vertexCount = sheet.vertexCount(), triangleCount = sheet.triangleCount();
  if (flags_.size() < vertexCount) flags_.resize(vertexCount, 0);
  if (reflected.empty() && flagged_.empty()) return;  // nothing tinted now or before
  // A vertex is flagged when reflected triangles use it and no other triangle does.
  triangleFlags_.assign(triangleCount, 0);
  newFlags_.assign(vertexCount, 0);
  for (TriangleIndex t : reflected) {
    if (t >= triangleCount) continue;
    triangleFlags_[t] = 1;
    for (VertexIndex v : sheet.triangles[t]) newFlags_[v] = 1;
  }
  if (!reflected.empty())
    for (TriangleIndex t = 0; t < triangleCount; ++t)
      if (!triangleFlags_[t])
        for (VertexIndex v : sheet.triangles[t]) newFlags_[v] = 0;
  std::vector<VertexIndex> changed;
  for (VertexIndex v = 0; v < vertexCount; ++v)
    if (newFlags_[v] != flags_[v]) {
      flags_[v] = newFlags_[v];
      changed.push_back(v);
    }
  std::fill(flags_.begin() + vertexCount, flags_.end(), 0);
  flagged_.assign(reflected.begin(), reflected.end());
  if (!changed.empty()) markSheetChanged(changed, {});
}

void SceneRenderer::uploadSheet(Slot& slot, const Scene& scene) {
  const Sheet& sheet = *scene.sheet.sheet;
  const auto vertexCount = static_cast<std::uint32_t>(sheet.vertexCount());
  const auto triangleCount = static_cast<std::uint32_t>(sheet.triangleCount());
  stats_.fullSheetBytes = std::size_t(vertexCount) * sizeof(glm::vec3) + std::size_t(vertexCount) +
                          std::size_t(triangleCount) * sizeof(Triangle);

  // Grow by half again so a growing drag does not reallocate every frame; the slot's previous
  // submission has finished, so its old buffers can go now.
  if (vertexCount > slot.vertexCapacity) {
    slot.vertexCapacity = std::max(vertexCount, slot.vertexCapacity + slot.vertexCapacity / 2);
    slot.vertices = HostBuffer(context_, VkDeviceSize(slot.vertexCapacity) * sizeof(glm::vec3),
                               VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    slot.flags = HostBuffer(context_, slot.vertexCapacity, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    slot.dirtyAll = true;
  }
  if (triangleCount > slot.triangleCapacity) {
    slot.triangleCapacity =
        std::max(triangleCount, slot.triangleCapacity + slot.triangleCapacity / 2);
    slot.indices = HostBuffer(context_, VkDeviceSize(slot.triangleCapacity) * sizeof(Triangle),
                              VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    slot.dirtyAll = true;
  }
  // Whatever lies beyond what the slot last held is new to it.
  slot.dirtyVertices.add(slot.vertexCount, vertexCount);
  slot.dirtyTriangles.add(slot.triangleCount, triangleCount);

  using Runs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
  const Runs vertexRuns =
      slot.dirtyAll ? Runs{{0, vertexCount}} : slot.dirtyVertices.runs(vertexCount, kRunGap);
  const Runs triangleRuns =
      slot.dirtyAll ? Runs{{0, triangleCount}} : slot.dirtyTriangles.runs(triangleCount, kRunGap);
  auto* positions = reinterpret_cast<glm::vec3*>(slot.vertices.data());
  auto* flags = reinterpret_cast<std::uint8_t*>(slot.flags.data());
  for (const auto& [begin, end] : vertexRuns) {
    for (std::uint32_t v = begin; v < end; ++v) positions[v] = glm::vec3(sheet.positions[v]);
    std::memcpy(flags + begin, flags_.data() + begin, end - begin);
    stats_.sheetBytes += std::size_t(end - begin) * (sizeof(glm::vec3) + 1);
  }
  auto* indices = reinterpret_cast<Triangle*>(slot.indices.data());
  for (const auto& [begin, end] : triangleRuns) {
    std::memcpy(indices + begin, sheet.triangles.data() + begin,
                std::size_t(end - begin) * sizeof(Triangle));
    stats_.sheetBytes += std::size_t(end - begin) * sizeof(Triangle);
  }
  stats_.sheetRuns += vertexRuns.size() + triangleRuns.size();
  // A coloured sheet's colours, whole: they come with pictures, not with a drag's frames.
  slot.colored = !scene.sheet.vertexColors.empty() &&
                 scene.sheet.vertexColors.size() == std::size_t(vertexCount) && vertexCount > 0;
  if (slot.colored) {
    const VkDeviceSize bytes = VkDeviceSize(vertexCount) * sizeof(glm::u8vec4);
    if (slot.colors.size() < bytes)
      slot.colors = HostBuffer(context_, VkDeviceSize(slot.vertexCapacity) * sizeof(glm::u8vec4),
                               VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    std::memcpy(slot.colors.data(), scene.sheet.vertexColors.data(), bytes);
    stats_.sheetBytes += bytes;
  }
  slot.dirtyAll = false;
  slot.dirtyVertices.clear();
  slot.dirtyTriangles.clear();
  slot.vertexCount = vertexCount;
  slot.triangleCount = triangleCount;
}

void SceneRenderer::prepare(const Frame& frame, const Scene& scene, VkExtent2D extent) {
  Slot& slot = slots_.at(frame.slot);
  stats_ = UploadStats{};
  const Layout layout = layoutFor(scene, extent);

  // --- the sheet ---
  slot.drawTriangles = 0;
  if (scene.sheet.sheet) {
    updateFlags(*scene.sheet.sheet, scene.sheet.reflectedTriangles);
    uploadSheet(slot, scene);
    slot.drawTriangles = slot.triangleCount;
  }

  // --- uniforms ---
  const float aspect =
      float(layout.view.extent.width) / float(std::max(layout.view.extent.height, 1u));
  FrameUniforms u{};
  for (int view = 0; view < 2; ++view) {
    const Camera& camera = view == 1 && scene.secondView ? *scene.secondView : scene.camera;
    u.view[view] = camera.view();
    u.proj[view] = camera.projection(aspect);
    u.viewProj[view] = u.proj[view] * u.view[view];
    u.eye[view] = glm::vec4(camera.eye, 1.0f);
  }
  u.model = scene.sheet.worldFromSheet;
  u.panelProj = panelProjection(scene.panel, layout.panel.extent);
  u.lightDir = glm::vec4(glm::normalize(scene.light.direction), scene.light.ambient);
  u.frontColor = glm::vec4(scene.colors.front, 1.0f);
  u.backColor = glm::vec4(scene.colors.back, 1.0f);
  u.tintColor = scene.colors.reflectedTint;
  u.viewport = glm::vec4(float(extent.width), float(extent.height), 0.0f, 0.0f);
  std::memcpy(slot.uniforms.data(), &u, sizeof u);
  stats_.dynamicBytes += sizeof u;

  // --- lines, markers, disk ---
  std::vector<LineInstance> lines;
  auto addLine = [&](const LineSegment& s) { lines.push_back({s.a, s.b, s.color}); };
  slot.gridFirst = 0;
  if (scene.ground.enabled) {
    const Ground& g = scene.ground;
    const float half = g.spacing * float(g.halfCount);
    for (int i = -g.halfCount; i <= g.halfCount; ++i) {
      const float offset = g.spacing * float(i);
      addLine({{g.centre.x + offset, g.height, g.centre.y - half},
               {g.centre.x + offset, g.height, g.centre.y + half},
               scene.colors.grid});
      addLine({{g.centre.x - half, g.height, g.centre.y + offset},
               {g.centre.x + half, g.height, g.centre.y + offset},
               scene.colors.grid});
    }
  }
  slot.gridCount = static_cast<std::uint32_t>(lines.size());
  slot.creaseFirst = static_cast<std::uint32_t>(lines.size());
  for (const LineSegment& s : scene.creases) addLine(s);
  slot.creaseCount = static_cast<std::uint32_t>(lines.size()) - slot.creaseFirst;
  slot.lineFirst = static_cast<std::uint32_t>(lines.size());
  for (const LineSegment& s : scene.lines) addLine(s);
  std::vector<ColoredVertex> disk;
  if (scene.plane) {
    // A fan around the centre, and its rim as lines.
    const PlaneDisk& p = *scene.plane;
    const glm::vec3 n = glm::normalize(p.normal);
    const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 e1 = glm::normalize(glm::cross(n, helper));
    const glm::vec3 e2 = glm::cross(n, e1);
    auto rim = [&](std::uint32_t i) {
      const float angle = 2.0f * std::numbers::pi_v<float> * float(i) / float(kDiskSegments);
      return p.centre + p.radius * (std::cos(angle) * e1 + std::sin(angle) * e2);
    };
    const glm::vec4 rimColor(glm::vec3(p.color) * 0.8f, std::min(1.0f, p.color.a * 2.5f));
    for (std::uint32_t i = 0; i < kDiskSegments; ++i) {
      disk.push_back({p.centre, p.color});
      disk.push_back({rim(i), p.color});
      disk.push_back({rim(i + 1), p.color});
      addLine({rim(i), rim(i + 1), rimColor});
    }
  }
  for (const TranslucentVertex& v : scene.translucent) disk.push_back({v.position, v.color});
  slot.lineCount = static_cast<std::uint32_t>(lines.size()) - slot.lineFirst;
  slot.panelFirst = static_cast<std::uint32_t>(lines.size());
  if (scene.panel.enabled)
    for (const LineSegment& s : scene.panel.lines) addLine(s);
  slot.panelCount = static_cast<std::uint32_t>(lines.size()) - slot.panelFirst;
  std::vector<MarkerInstance> markers;
  for (const Marker& m : scene.markers)
    markers.push_back({glm::vec4(m.position, m.radius), m.color});

  const VkDeviceSize lineBytes = lines.size() * sizeof(LineInstance);
  const VkDeviceSize markerBytes = markers.size() * sizeof(MarkerInstance);
  const VkDeviceSize diskBytes = disk.size() * sizeof(ColoredVertex);
  // The world panel's two triangles.
  std::vector<PanelVertex> panel;
  if (scene.worldPanel) {
    const glm::vec3* c = scene.worldPanel->corners;
    const glm::vec2 uv[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    for (int corner : {0, 1, 2, 0, 2, 3}) panel.push_back({c[corner], uv[corner]});
  }
  const VkDeviceSize panelBytes = panel.size() * sizeof(PanelVertex);
  slot.markerOffset = (lineBytes + 15) / 16 * 16;
  slot.diskOffset = (slot.markerOffset + markerBytes + 15) / 16 * 16;
  slot.panelOffset = (slot.diskOffset + diskBytes + 15) / 16 * 16;
  const VkDeviceSize total = std::max<VkDeviceSize>(slot.panelOffset + panelBytes, 64);
  if (slot.stream.size() < total)
    slot.stream = HostBuffer(context_, std::max(total, slot.stream.size() * 3 / 2),
                             VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  if (lineBytes) std::memcpy(slot.stream.data(), lines.data(), lineBytes);
  if (markerBytes) std::memcpy(slot.stream.data() + slot.markerOffset, markers.data(), markerBytes);
  if (diskBytes) std::memcpy(slot.stream.data() + slot.diskOffset, disk.data(), diskBytes);
  if (panelBytes) std::memcpy(slot.stream.data() + slot.panelOffset, panel.data(), panelBytes);
  slot.panelVertexCount = static_cast<std::uint32_t>(panel.size());
  slot.markerCount = static_cast<std::uint32_t>(markers.size());
  slot.diskVertexCount = static_cast<std::uint32_t>(disk.size());
  stats_.dynamicBytes += lineBytes + markerBytes + diskBytes + panelBytes;
}

void SceneRenderer::record(const Frame& frame, const Scene& scene, VkExtent2D extent) const {
  const Slot& slot = slots_.at(frame.slot);
  const VkCommandBuffer commands = frame.commands;
  const Layout layout = layoutFor(scene, extent);
  setViewport(commands, layout.view);
  vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &slot.set, 0,
                          nullptr);
  const VkDeviceSize zero = 0;
  if (slot.drawTriangles > 0) {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS,
                      slot.colored ? coloredSheetPipeline_ : sheetPipeline_);
    const VkBuffer vertexBuffers[2] = {slot.vertices.buffer(),
                                       slot.colored ? slot.colors.buffer() : slot.flags.buffer()};
    const VkDeviceSize offsets[2] = {0, 0};
    vkCmdBindVertexBuffers(commands, 0, 2, vertexBuffers, offsets);
    vkCmdBindIndexBuffer(commands, slot.indices.buffer(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(commands, slot.drawTriangles * 3, 1, 0, 0, 0);
  }
  const VkBuffer stream = slot.stream.buffer();
  if (slot.markerCount > 0) {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, markerPipeline_);
    vkCmdBindVertexBuffers(commands, 0, 1, &stream, &slot.markerOffset);
    vkCmdDraw(commands, 6, slot.markerCount, 0, 0);
  }
  // The world panel: opaque, before the lines (which do not write depth) so those in front of it
  // stay seen.
  if (slot.panelVertexCount > 0 && panelPipeline_) {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, panelPipeline_);
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, panelLayout_, 1, 1,
                            &panelSet_, 0, nullptr);
    vkCmdBindVertexBuffers(commands, 0, 1, &stream, &slot.panelOffset);
    vkCmdDraw(commands, slot.panelVertexCount, 1, 0, 0);
  }
  const glm::vec2 viewSize(float(layout.view.extent.width), float(layout.view.extent.height));
  auto drawLines = [&](std::uint32_t first, std::uint32_t count, const LinePush& push) {
    if (count == 0) return;
    vkCmdPushConstants(commands, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, &push);
    vkCmdDraw(commands, 6, count, 0, first);
  };
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, linePipeline_);
  vkCmdBindVertexBuffers(commands, 0, 1, &stream, &zero);
  drawLines(slot.gridFirst, slot.gridCount, {viewSize, 1.0f, 0.0f, 0});
  drawLines(slot.creaseFirst, slot.creaseCount,
            {viewSize, scene.creaseWidthPixels, kCreaseTowardEye, 0});
  drawLines(slot.lineFirst, slot.lineCount, {viewSize, scene.lineWidthPixels, kLineTowardEye, 0});
  if (slot.diskVertexCount > 0) {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, translucentPipeline_);
    vkCmdBindVertexBuffers(commands, 0, 1, &stream, &slot.diskOffset);
    vkCmdDraw(commands, slot.diskVertexCount, 1, 0, 0);
  }
  if (scene.panel.enabled && layout.panel.extent.width > 0) {
    // The panel is its own little 2D view: cleared, then lines in development coordinates.
    setViewport(commands, layout.panel);
    VkClearAttachment clears[2]{};
    clears[0].aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
    clears[0].colorAttachment = 0;
    const glm::vec4 bg = targetColor(glm::vec4(scene.colors.panelBackground, 1.0f), format_);
    clears[0].clearValue.color = {{bg.r, bg.g, bg.b, bg.a}};
    clears[1].aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
    clears[1].clearValue.depthStencil = {1.0f, 0};
    VkClearRect rect{layout.panel, 0, 1};
    vkCmdClearAttachments(commands, 2, clears, 1, &rect);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, linePipeline_);
    vkCmdBindVertexBuffers(commands, 0, 1, &stream, &zero);
    const glm::vec2 panelSize(float(layout.panel.extent.width), float(layout.panel.extent.height));
    drawLines(slot.panelFirst, slot.panelCount, {panelSize, scene.lineWidthPixels, 0.0f, 1});
  }
}

VkClearColorValue SceneRenderer::clearColor(const Scene& scene, const PassFormat& format) {
  const glm::vec4 c = targetColor(glm::vec4(scene.colors.background, 1.0f), format);
  return {{c.r, c.g, c.b, c.a}};
}

Frame* drawFrame(FrameRing& frames, RenderTarget& target, SceneRenderer& renderer,
                 const Scene& scene, const PassOverlay& overlay, const PassOverlay& beforePass) {
  Frame& frame = frames.begin();
  const VkFramebuffer framebuffer = target.acquire(frame);
  if (framebuffer == VK_NULL_HANDLE) {
    // Nothing to draw into: submit the empty command buffer so the slot's fence still signals.
    frames.submit(frame);
    return nullptr;
  }
  const VkExtent2D extent = target.extent();
  renderer.prepare(frame, scene, extent);
  if (beforePass) beforePass(frame.commands);
  VkClearValue clears[3]{};
  clears[0].color = SceneRenderer::clearColor(scene, target.format());
  clears[1].depthStencil = {1.0f, 0};
  clears[2].color = clears[0].color;
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = target.renderPass();
  begin.framebuffer = framebuffer;
  begin.renderArea = {{0, 0}, extent};
  begin.clearValueCount = target.format().samples == VK_SAMPLE_COUNT_1_BIT ? 2 : 3;
  begin.pClearValues = clears;
  vkCmdBeginRenderPass(frame.commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
  renderer.record(frame, scene, extent);
  if (overlay) overlay(frame.commands);
  vkCmdEndRenderPass(frame.commands);
  target.recordAfterPass(frame);
  frames.submit(frame, target.acquireSemaphore(frame),
                VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, target.presentSemaphore(frame));
  target.present(frame);
  return &frame;
}

}  // namespace curvefold
