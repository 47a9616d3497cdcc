#include "app/desktop/thread_cpu.hpp"

#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace curvefold::desktop {

namespace {

bool renderThread(const std::string& name) {
  return name.rfind("llvmpipe", 0) == 0 || name.rfind("lavapipe", 0) == 0 ||
         name.rfind("lvp", 0) == 0;
}

}  // namespace

ThreadGroupCpu threadGroupCpu() {
  ThreadGroupCpu cpu;
  timespec process{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &process);
  cpu.processMs = double(process.tv_sec) * 1e3 + double(process.tv_nsec) * 1e-6;
  const std::string self = std::to_string(syscall(SYS_gettid));
  std::error_code error;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", error)) {
    std::ifstream schedstat(task.path() / "schedstat");
    double ns = 0.0;
    if (!(schedstat >> ns)) continue;  // the thread ended meanwhile
    std::string name;
    std::getline(std::ifstream(task.path() / "comm"), name);
    const double ms = ns * 1e-6;
    if (task.path().filename() == self)
      cpu.frameMs += ms;
    else if (name == "cf-search")
      cpu.searchMs += ms;
    else if (renderThread(name))
      cpu.renderMs += ms;
    else
      cpu.otherMs += ms;
  }
  return cpu;
}

std::string threadGroupCpuToken(const ThreadGroupCpu& cpu) {
  char token[160];
  std::snprintf(token, sizeof token,
                "cpu=frame:%.1f,search:%.1f,render:%.1f,other:%.1f,process:%.1f", cpu.frameMs,
                cpu.searchMs, cpu.renderMs, cpu.otherMs, cpu.processMs);
  return token;
}

}  // namespace curvefold::desktop
