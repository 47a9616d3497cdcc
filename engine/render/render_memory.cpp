#include "engine/render/render_memory.hpp"

#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <thread>

#include "engine/render/vulkan_error.hpp"

namespace curvefold {

namespace {

constexpr std::uint64_t kMiB = 1u << 20;
// Measured (Mesa 22.3's lavapipe, LLVM 15, two CPUs): with up to about 420 MiB of address space
// left the driver crashed in vkCreateDevice (SIGSEGV) or aborted; from about 600 MiB it failed
// cleanly (VK_ERROR_OUT_OF_DEVICE_MEMORY) or rendered. Past the crashes, with a margin.
constexpr std::uint64_t kDriverBytes = 512 * kMiB;
constexpr std::uint64_t kMaxDriverThreads = 32;

std::uint64_t stackBytes() {
  rlimit stack{};
  if (getrlimit(RLIMIT_STACK, &stack) != 0 || stack.rlim_cur == RLIM_INFINITY) return 8 * kMiB;
  return std::max<std::uint64_t>(stack.rlim_cur, kMiB);
}

// The address space the process maps now (/proc/self/statm), or 0 when it cannot be told.
std::uint64_t mappedBytes() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  statm >> pages;
  return pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

}  // namespace

std::uint64_t renderMemoryEstimate(std::uint32_t width, std::uint32_t height,
                                   std::uint32_t samples) {
  const std::uint64_t threads =
      std::clamp<std::uint64_t>(std::thread::hardware_concurrency(), 1, kMaxDriverThreads);
  const std::uint64_t pixels = std::uint64_t(width) * height;
  // Colour and depth per sample, a resolve and a readback image: two frames in flight.
  const std::uint64_t images = 2 * pixels * (8 * std::max<std::uint32_t>(samples, 1) + 8);
  return kDriverBytes + threads * stackBytes() + images;
}

void checkRenderMemory(std::uint32_t width, std::uint32_t height, std::uint32_t samples) {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return;
  const std::uint64_t needed = renderMemoryEstimate(width, height, samples);
  void* trial =
      mmap(nullptr, needed, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (trial != MAP_FAILED) {
    munmap(trial, needed);
    return;
  }
  const std::uint64_t mapped = mappedBytes();
  const std::uint64_t left = limit.rlim_cur > mapped ? limit.rlim_cur - mapped : 0;
  throw VulkanError("not enough memory to render " + std::to_string(width) + "x" +
                    std::to_string(height) + ": about " + std::to_string(needed / kMiB) +
                    " MiB more is needed, and the address-space limit (ulimit -v) leaves " +
                    std::to_string(left / kMiB) + " MiB");
}

}  // namespace curvefold
