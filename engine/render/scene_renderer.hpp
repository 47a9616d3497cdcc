// Draws a Scene into any RenderTarget's render pass: the two-sided sheet, crease ribbons, ground
// grid, markers, the translucent plane disk and the crease-pattern panel (docs/design.md 7).
//
// Incremental upload. The sheet lives in host-visible buffers, one set per frame in flight
// (positions as float3 and a tint byte per vertex, triangles as uint32x3). A slot
// is written only in prepare(), after its fence, so the GPU never reads a buffer being written.
// The caller says what changed in the sheet (markSheetChanged with a fold's ReflectionChanges, or
// markSheetReplaced); every slot accumulates those dirty vertex and triangle indices until it is
// next prepared, so a slot that skipped a frame still catches up. prepare() sorts them into runs
// (nearby runs joined), converts just those vertices to float and copies just those triangles.
// Vertices and triangles beyond what a slot last held are always uploaded (appended by a split).
// The reflected tint is a per-vertex byte (set for vertices that only reflected triangles use, so
// the tint stops at the crease); it is recomputed on the CPU from the scene's reflected triangles
// and the vertices whose byte changed join the dirty set. For a drag, SessionSheetTracker
// (sheet_tracker.hpp) turns a FoldSession's state into these calls.
#pragma once

#include <functional>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "engine/geometry/reflection.hpp"
#include "engine/render/frames.hpp"
#include "engine/render/gpu_resources.hpp"
#include "engine/render/render_target.hpp"
#include "engine/render/scene.hpp"

namespace curvefold {

// Indices that changed, kept as half-open ranges and merged on demand.
class DirtyRanges {
 public:
  void add(std::uint32_t begin, std::uint32_t end) {
    if (begin < end) ranges_.emplace_back(begin, end);
  }
  // Any range of indices (vertex, triangle or plain integers).
  template <typename Range>
  void addIndices(const Range& indices) {
    for (const auto index : indices) {
      const std::uint32_t i = index;
      ranges_.emplace_back(i, i + 1);
    }
  }
  void clear() { ranges_.clear(); }
  bool empty() const { return ranges_.empty(); }
  // Sorted, disjoint runs clipped to `limit`; runs separated by fewer than `gap` clean indices are
  // joined (one copy beats many tiny ones).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> runs(std::uint32_t limit,
                                                            std::uint32_t gap) const;

 private:
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges_;
};

struct UploadStats {
  std::size_t sheetBytes = 0;      // sheet bytes written in the last prepare()
  std::size_t sheetRuns = 0;       // contiguous copies they took
  std::size_t fullSheetBytes = 0;  // what rewriting the whole sheet would have written
  std::size_t dynamicBytes = 0;    // lines, markers, disk and uniforms (rewritten every frame)
};

class SceneRenderer {
 public:
  // Pipelines are built for the target's render pass; any target with the same PassFormat works.
  SceneRenderer(const VulkanContext& context, const RenderTarget& target,
                std::uint32_t framesInFlight = kFramesInFlight);
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // The next scene's sheet may differ everywhere (a new sheet, commit, undo, cancel).
  void markSheetReplaced();
  // The next scene's sheet has the same triangles, every vertex moved (a simulated sheet).
  void markSheetMoved();
  // The next scene's sheet differs from the previous one only in these vertices and triangles
  // (and in what is appended). A cleared record (firstNewVertex == 0, nothing moved) marks nothing.
  void markSheetChanged(const ReflectionChanges& changes);
  void markSheetChanged(std::span<const VertexIndex> vertices,
                        std::span<const TriangleIndex> triangles);

  // Before the render pass, after the frame's fence: writes the frame slot's buffers.
  void prepare(const Frame& frame, const Scene& scene, VkExtent2D extent);
  // Inside the render pass begun on the target's framebuffer.
  void record(const Frame& frame, const Scene& scene, VkExtent2D extent) const;

  // The picture a scene's worldPanel shows: a sampled image view in SHADER_READ_ONLY_OPTIMAL
  // when drawn, and its sampler (both the caller's, outliving the renderer's use). Set it before
  // the first frame that shows a world panel, or with no frame in flight, while the target the
  // renderer was made for exists (its render pass makes the panel's pipeline).
  void setWorldPanelTexture(VkImageView view, VkSampler sampler);

  const UploadStats& lastUpload() const { return stats_; }
  // The clear colour of the scene for a target of that format (the render pass clears with it).
  static VkClearColorValue clearColor(const Scene& scene, const PassFormat& format);

 private:
  struct Slot;
  struct Pipelines;
  void uploadSheet(Slot& slot, const Scene& scene);
  void updateFlags(const Sheet& sheet, std::span<const TriangleIndex> reflected);
  void writeDescriptors(Slot& slot);
  void createPanelPipeline();
  void destroy();

  const VulkanContext& context_;
  PassFormat format_;
  VkRenderPass renderPass_;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkPipeline sheetPipeline_ = VK_NULL_HANDLE;
  VkPipeline coloredSheetPipeline_ = VK_NULL_HANDLE;  // SceneSheet::vertexColors
  VkPipeline linePipeline_ = VK_NULL_HANDLE;
  VkPipeline markerPipeline_ = VK_NULL_HANDLE;
  VkPipeline translucentPipeline_ = VK_NULL_HANDLE;
  std::vector<Slot> slots_;
  // The world panel's picture: its own set (set 1) and pipeline, made when first given.
  VkDescriptorSetLayout panelSetLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout panelLayout_ = VK_NULL_HANDLE;
  VkDescriptorPool panelPool_ = VK_NULL_HANDLE;
  VkDescriptorSet panelSet_ = VK_NULL_HANDLE;
  VkPipeline panelPipeline_ = VK_NULL_HANDLE;

  // The per-vertex tint bytes as last seen, the list they came from, and scratch.
  std::vector<std::uint8_t> flags_;
  std::vector<TriangleIndex> flagged_;
  std::vector<std::uint8_t> triangleFlags_, newFlags_;
  UploadStats stats_;
};

// Records extra drawing into the scene's render pass after the scene (a GUI panel, say).
using PassOverlay = std::function<void(VkCommandBuffer)>;

// One frame of `scene` into `target`: begin the next slot, prepare, `beforePass` (when given:
// commands outside the render pass, such as drawing a world panel's picture), render pass (with
// `overlay` last, when given), submit, present. Returns the frame (wait on it before reading a
// readback), or nullptr when the target had no image this time.
Frame* drawFrame(FrameRing& frames, RenderTarget& target, SceneRenderer& renderer,
                 const Scene& scene, const PassOverlay& overlay = {},
                 const PassOverlay& beforePass = {});

}  // namespace curvefold
