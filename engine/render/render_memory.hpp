// Whether a headless render fits in the memory the process may still map. A CPU Vulkan driver
// (lavapipe) maps LLVM, a stack per rasteriser thread and every image in the process's own
// address space, and under an address-space limit (`ulimit -v`) it crashed inside vkCreateDevice
// (SIGSEGV) or aborted instead of failing. The need is estimated and the space tried (mapped
// without access and unmapped again) before any Vulkan object is made.
#pragma once

#include <cstdint>

namespace curvefold {

// Bytes a headless render of width x height at `samples` needs beyond what the process holds:
// the driver (512 MiB: lavapipe crashed with 420 MiB left; LLVM, its pools), one stack per CPU (at
// most 32 threads), and the colour, depth, resolve and readback images of two frames.
std::uint64_t renderMemoryEstimate(std::uint32_t width, std::uint32_t height,
                                   std::uint32_t samples);

// Throws VulkanError "not enough memory to render WxH: about N MiB more is needed, and the
// address-space limit (ulimit -v) leaves M MiB" when the estimate cannot be mapped now. Without a
// limit it only asks the system, which may overcommit, so it passes.
void checkRenderMemory(std::uint32_t width, std::uint32_t height, std::uint32_t samples);

}  // namespace curvefold
