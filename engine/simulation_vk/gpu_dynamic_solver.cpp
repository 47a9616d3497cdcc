#include "engine/simulation_vk/gpu_dynamic_solver.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "engine/render/pipeline_builder.hpp"
#include "engine/render/scope_fail.hpp"
#include "engine/render/vulkan_objects.hpp"
#include "shaders/simulation_elements.comp.h"
#include "shaders/simulation_vertices.comp.h"

namespace curvefold {
namespace {

// Bindings of shaders/simulation_layout.glsl.
enum Binding : std::uint32_t {
  kPositions,
  kVelocities,
  kAngles,
  kSlotForces,
  kBars,
  kBarParameters,
  kHinges,
  kHingeParameters,
  kGlue,
  kVertices,
  kGatherSlots,
  kBindingCount
};

constexpr std::uint32_t kNoPull = ~0u;

// shaders/simulation_layout.glsl's push constants.
struct StepConstants {
  std::uint32_t barCount, hingeCount, glueCount, vertexCount;
  float foldAmount, timeStep, keep, dampingRatio, glueStiffness;
  std::uint32_t restLengths;
  std::uint32_t pullVertex = kNoPull;
  float pullImpulse = 0.0f;
  float pullTo[3] = {0.0f, 0.0f, 0.0f};  // the block's vec3, at offset 48 (std430: 16-aligned)
};
static_assert(sizeof(StepConstants) == 60);

constexpr std::uint32_t kWorkgroupSize = 64;     // local_size_x
constexpr std::uint32_t kMaxWorkgroups = 65535;  // every device's maxComputeWorkGroupCount[0]
// Steps recorded into one submission: long runs are split so one command buffer stays small.
constexpr std::size_t kStepsPerSubmit = 256;

std::vector<glm::vec4> toFloat4(const std::vector<glm::dvec3>& points, std::size_t count) {
  std::vector<glm::vec4> out(count, glm::vec4(0.0f));
  for (std::size_t i = 0; i < std::min(count, points.size()); ++i)
    out[i] = glm::vec4(glm::vec3(points[i]), 0.0f);
  return out;
}

// A compute pipeline of one embedded shader.
VkPipeline createComputePipeline(VkDevice device, VkPipelineLayout layout,
                                 std::span<const std::uint32_t> code) {
  VkShaderModule module = createShaderModule(device, code);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  const VkResult result =
      vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
  vkDestroyShaderModule(device, module, nullptr);
  vkCheck(result, "vkCreateComputePipelines");
  return pipeline;
}

// Compute writes before the next dispatch's reads and writes, and before transfers.
void computeBarrier(VkCommandBuffer commands) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  barrier.dstAccessMask =
      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT;
  vkCmdPipelineBarrier(commands,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1,
                       &barrier, 0, nullptr, 0, nullptr);
}

}  // namespace

GpuDynamicSolver::GpuDynamicSolver(const VulkanContext& context, const BarHingeModel& model,
                                   const DynamicOptions& options)
    : context_(context),
      options_(options),
      barCount_(static_cast<std::uint32_t>(model.bars.size())),
      hingeCount_(static_cast<std::uint32_t>(model.hinges.size())),
      glueCount_(static_cast<std::uint32_t>(model.glue.size())),
      vertexCount_(static_cast<std::uint32_t>(model.vertexCount())),
      glueStiffness_(static_cast<float>(model.glueStiffness)),
      hinges_(model.hinges),
      pinned_(model.pinned.begin(), model.pinned.end()) {
  const ScopeFail cleanup([this] { destroy(); });
  timeStep_ = options.timeStep > 0.0 ? options.timeStep
              : model.timeStep > 0.0 ? model.timeStep
                                     : stableTimeStep(model);
  const VkDevice device = context.device();

  std::uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice(), &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice(), &familyCount, families.data());
  if (!(families.at(context.graphicsFamily()).queueFlags & VK_QUEUE_COMPUTE_BIT))
    throw VulkanError(context.deviceName() + "'s graphics queue cannot run compute shaders");

  // The model as the shaders read it.
  std::vector<glm::uvec2> bars(std::max<std::size_t>(barCount_, 1));
  std::vector<glm::vec4> barParameters(bars.size(), glm::vec4(0.0f));
  for (std::size_t i = 0; i < barCount_; ++i) {
    bars[i] = {model.bars[i][0], model.bars[i][1]};
    barParameters[i] = {0.0f, float(model.barStiffness[i]), float(model.barDamping[i]), 0.0f};
  }
  std::vector<glm::uvec4> hinges(std::max<std::size_t>(hingeCount_, 1));
  std::vector<glm::vec4> hingeParameters(hinges.size(), glm::vec4(0.0f));
  for (std::size_t j = 0; j < hingeCount_; ++j) {
    const Hinge& h = model.hinges[j];
    hinges[j] = {h.a, h.b, h.c, h.d};
    hingeParameters[j] = {float(model.hingeTarget[j]), model.hingeDriven[j] ? 1.0f : 0.0f,
                          float(model.hingeStiffness[j]), float(model.hingeWrongSide[j])};
  }
  std::vector<glm::uvec2> glue(std::max<std::size_t>(glueCount_, 1));
  for (std::size_t g = 0; g < glueCount_; ++g) glue[g] = {model.glue[g][0], model.glue[g][1]};
  std::vector<glm::uvec4> vertices(std::max<std::size_t>(vertexCount_, 1));
  for (std::size_t v = 0; v < vertexCount_; ++v)
    vertices[v] = {model.gatherOffsets[v], model.gatherOffsets[v + 1], model.pinned[v],
                   std::bit_cast<std::uint32_t>(float(model.mass[v]))};
  std::vector<std::uint32_t> gatherSlots = model.gatherSlots;
  if (gatherSlots.empty()) gatherSlots.push_back(0);

  // Sizes by binding (a buffer is never empty: Vulkan has no buffers of size 0).
  const std::size_t slots = std::max<std::size_t>(model.slotCount, 1);
  const std::array<VkDeviceSize, kBindingCount> sizes{sizeof(glm::vec4) * vertices.size(),
                                                      sizeof(glm::vec4) * vertices.size(),
                                                      sizeof(float) * hinges.size(),
                                                      sizeof(glm::vec4) * slots,
                                                      sizeof(glm::uvec2) * bars.size(),
                                                      sizeof(glm::vec4) * bars.size(),
                                                      sizeof(glm::uvec4) * hinges.size(),
                                                      sizeof(glm::vec4) * hinges.size(),
                                                      sizeof(glm::uvec2) * glue.size(),
                                                      sizeof(glm::uvec4) * vertices.size(),
                                                      sizeof(std::uint32_t) * gatherSlots.size()};
  for (VkDeviceSize size : sizes)
    buffers_.emplace_back(context, size,
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                              VK_BUFFER_USAGE_TRANSFER_SRC_BIT);

  // Descriptors and pipelines.
  std::array<VkDescriptorSetLayoutBinding, kBindingCount> bindings{};
  for (std::uint32_t b = 0; b < kBindingCount; ++b)
    bindings[b] = {b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = kBindingCount;
  setInfo.pBindings = bindings.data();
  vkCheck(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout_),
          "vkCreateDescriptorSetLayout");
  const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(StepConstants)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout_;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &range;
  vkCheck(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &pipelineLayout_),
          "vkCreatePipelineLayout");
  elements_ = createComputePipeline(device, pipelineLayout_, simulation_elements_comp_spv);
  vertices_ = createComputePipeline(device, pipelineLayout_, simulation_vertices_comp_spv);
  descriptorPool_ = createDescriptorPool(device, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kBindingCount);
  descriptorSet_ = allocateDescriptorSet(device, descriptorPool_, setLayout_);
  std::array<VkDescriptorBufferInfo, kBindingCount> infos{};
  std::array<VkWriteDescriptorSet, kBindingCount> writes{};
  for (std::uint32_t b = 0; b < kBindingCount; ++b) {
    infos[b] = {buffers_[b].buffer(), 0, VK_WHOLE_SIZE};
    writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[b].dstSet = descriptorSet_;
    writes[b].dstBinding = b;
    writes[b].descriptorCount = 1;
    writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[b].pBufferInfo = &infos[b];
  }
  vkUpdateDescriptorSets(device, kBindingCount, writes.data(), 0, nullptr);

  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = context.graphicsFamily();
  vkCheck(vkCreateCommandPool(device, &poolInfo, nullptr, &commandPool_), "vkCreateCommandPool");
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocate.commandPool = commandPool_;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  vkCheck(vkAllocateCommandBuffers(device, &allocate, &commands_), "vkAllocateCommandBuffers");
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  vkCheck(vkCreateFence(device, &fenceInfo, nullptr, &done_), "vkCreateFence");

  // The model, then the bars' rest lengths measured on the flat state, then the flat state.
  upload(buffers_[kBars].buffer(), bars.data(), sizes[kBars]);
  upload(buffers_[kBarParameters].buffer(), barParameters.data(), sizes[kBarParameters]);
  upload(buffers_[kHinges].buffer(), hinges.data(), sizes[kHinges]);
  upload(buffers_[kHingeParameters].buffer(), hingeParameters.data(), sizes[kHingeParameters]);
  upload(buffers_[kGlue].buffer(), glue.data(), sizes[kGlue]);
  upload(buffers_[kVertices].buffer(), vertices.data(), sizes[kVertices]);
  upload(buffers_[kGatherSlots].buffer(), gatherSlots.data(), sizes[kGatherSlots]);
  const std::vector<glm::vec4> flat = toFloat4(model.flatPositions, vertices.size());
  upload(buffers_[kPositions].buffer(), flat.data(), sizes[kPositions]);
  submitAndWait([&](VkCommandBuffer commands) {
    StepConstants constants{barCount_, hingeCount_, glueCount_, vertexCount_, 0.0f, 0.0f, 1.0f,
                            0.0f,      0.0f,        1u,         kNoPull,      0.0f, {}};
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout_, 0, 1,
                            &descriptorSet_, 0, nullptr);
    vkCmdPushConstants(commands, pipelineLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof constants,
                       &constants);
    dispatch(commands, elements_, barCount_);
  });
  setState(flatState(model));
}

GpuDynamicSolver::~GpuDynamicSolver() {
  destroy();
}

void GpuDynamicSolver::destroy() {
  const VkDevice device = context_.device();
  if (done_ != VK_NULL_HANDLE) vkWaitForFences(device, 1, &done_, VK_TRUE, UINT64_MAX);
  destroyHandle(device, done_, vkDestroyFence);
  destroyHandle(device, commandPool_, vkDestroyCommandPool);  // frees commands_
  commands_ = VK_NULL_HANDLE;
  destroyHandle(device, descriptorPool_, vkDestroyDescriptorPool);  // frees the set
  descriptorSet_ = VK_NULL_HANDLE;
  destroyHandle(device, elements_, vkDestroyPipeline);
  destroyHandle(device, vertices_, vkDestroyPipeline);
  destroyHandle(device, pipelineLayout_, vkDestroyPipelineLayout);
  destroyHandle(device, setLayout_, vkDestroyDescriptorSetLayout);
  buffers_.clear();
  staging_.reset();
}

template <typename Record>
void GpuDynamicSolver::submitAndWait(const Record& record) {
  const VkDevice device = context_.device();
  vkCheck(vkResetCommandBuffer(commands_, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkCheck(vkBeginCommandBuffer(commands_, &begin), "vkBeginCommandBuffer");
  record(commands_);
  vkCheck(vkEndCommandBuffer(commands_), "vkEndCommandBuffer");
  vkCheck(vkResetFences(device, 1, &done_), "vkResetFences");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands_;
  vkCheck(vkQueueSubmit(context_.graphicsQueue(), 1, &submit, done_), "vkQueueSubmit");
  vkCheck(vkWaitForFences(device, 1, &done_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

void GpuDynamicSolver::upload(VkBuffer buffer, const void* data, VkDeviceSize bytes) {
  if (staging_.size() < bytes)
    staging_ = HostBuffer(context_, bytes,
                          VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  std::memcpy(staging_.data(), data, bytes);
  submitAndWait([&](VkCommandBuffer commands) {
    const VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(commands, staging_.buffer(), buffer, 1, &region);
    computeBarrier(commands);
  });
}

void GpuDynamicSolver::download(VkBuffer buffer, void* data, VkDeviceSize bytes) {
  if (staging_.size() < bytes)
    staging_ = HostBuffer(context_, bytes,
                          VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  submitAndWait([&](VkCommandBuffer commands) {
    const VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(commands, buffer, staging_.buffer(), 1, &region);
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &barrier, 0, nullptr, 0, nullptr);
  });
  std::memcpy(data, staging_.data(), bytes);
}

void GpuDynamicSolver::dispatch(VkCommandBuffer commands, VkPipeline pipeline,
                                std::size_t count) const {
  if (count == 0) return;
  const auto groups = static_cast<std::uint32_t>(
      std::min<std::size_t>((count + kWorkgroupSize - 1) / kWorkgroupSize, kMaxWorkgroups));
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  vkCmdDispatch(commands, groups, 1, 1);
  computeBarrier(commands);
}

void GpuDynamicSolver::setState(const SimulationState& state) {
  const std::size_t n = std::max<std::uint32_t>(vertexCount_, 1);
  const std::vector<glm::vec4> positions = toFloat4(state.positions, n);
  const std::vector<glm::vec4> velocities = toFloat4(state.velocities, n);
  std::vector<float> angles(std::max<std::uint32_t>(hingeCount_, 1), 0.0f);
  for (std::size_t j = 0; j < hingeCount_; ++j) {
    const Hinge& h = hinges_[j];
    angles[j] = state.hingeAngles.size() == hingeCount_
                    ? float(state.hingeAngles[j])
                    : float(hingeAngle(state.positions[h.a], state.positions[h.b],
                                       state.positions[h.c], state.positions[h.d]));
  }
  upload(buffers_[kPositions].buffer(), positions.data(), sizeof(glm::vec4) * n);
  upload(buffers_[kVelocities].buffer(), velocities.data(), sizeof(glm::vec4) * n);
  upload(buffers_[kAngles].buffer(), angles.data(), sizeof(float) * angles.size());
  steps_ = state.steps;
}

void GpuDynamicSolver::step(double foldAmount, std::size_t steps,
                            const std::optional<GpuPull>& pull) {
  StepConstants constants{barCount_,
                          hingeCount_,
                          glueCount_,
                          vertexCount_,
                          float(foldAmount),
                          float(timeStep_),
                          float(1.0 - options_.velocityDamping),
                          float(options_.dampingRatio),
                          glueStiffness_,
                          0u,
                          kNoPull,
                          0.0f,
                          {}};
  if (pull && pull->vertex < vertexCount_ && !pinned_[pull->vertex]) {
    constants.pullVertex = pull->vertex;
    constants.pullImpulse = float(pull->impulse);
    for (int k = 0; k < 3; ++k) constants.pullTo[k] = float(pull->to[k]);
  }
  const std::size_t elements = std::size_t(barCount_) + hingeCount_ + glueCount_;
  for (std::size_t done = 0; done < steps;) {
    const std::size_t now = std::min(kStepsPerSubmit, steps - done);
    submitAndWait([&](VkCommandBuffer commands) {
      vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout_, 0, 1,
                              &descriptorSet_, 0, nullptr);
      vkCmdPushConstants(commands, pipelineLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0,
                         sizeof constants, &constants);
      for (std::size_t s = 0; s < now; ++s) {
        dispatch(commands, elements_, elements);
        dispatch(commands, vertices_, vertexCount_);
      }
    });
    done += now;
    steps_ += now;
  }
}

void GpuDynamicSolver::positions(std::vector<glm::dvec3>& positions) {
  std::vector<glm::vec4> device(std::max<std::uint32_t>(vertexCount_, 1));
  download(buffers_[kPositions].buffer(), device.data(), sizeof(glm::vec4) * device.size());
  positions.resize(vertexCount_);
  for (std::size_t v = 0; v < vertexCount_; ++v) positions[v] = glm::dvec3(glm::vec3(device[v]));
}

void GpuDynamicSolver::state(SimulationState& state) {
  positions(state.positions);
  std::vector<glm::vec4> velocities(std::max<std::uint32_t>(vertexCount_, 1));
  download(buffers_[kVelocities].buffer(), velocities.data(),
           sizeof(glm::vec4) * velocities.size());
  state.velocities.resize(vertexCount_);
  for (std::size_t v = 0; v < vertexCount_; ++v)
    state.velocities[v] = glm::dvec3(glm::vec3(velocities[v]));
  std::vector<float> angles(std::max<std::uint32_t>(hingeCount_, 1));
  download(buffers_[kAngles].buffer(), angles.data(), sizeof(float) * angles.size());
  state.hingeAngles.assign(angles.begin(), angles.begin() + hingeCount_);
  state.steps = steps_;
}

}  // namespace curvefold
