// CPU time, for the tests whose claim is about work: a step that stops soon after its deadline
// or a cancel does little work after it. The wall clock measures that only on an idle machine (a
// loaded one stretches every step), but the CPU a process spends after the moment is the same
// under load; a step that ignores its deadline spends seconds of it.
#pragma once

#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "engine/fit/deadline.hpp"

namespace curvefold::testing {

// The nice of each of this process's threads (/proc/self/task/*/stat, the 19th field): who
// yields the cores to whom.
inline std::vector<int> threadNices() {
  std::vector<int> nices;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::string stat;
    try {
      std::ifstream in(task.path() / "stat");
      stat.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    } catch (const std::ios_base::failure&) {
      // A thread that ended between the listing and the read (ESRCH: libstdc++'s filebuf throws
      // on a read error): it has no nice left to count.
      continue;
    }
    const std::size_t afterName = stat.rfind(')');
    if (afterName == std::string::npos) continue;
    std::istringstream fields(stat.substr(afterName + 1));
    std::string field;
    for (int k = 3; k <= 19 && fields >> field; ++k)
      if (k == 19) nices.push_back(std::stoi(field));
  }
  return nices;
}

// Seconds of CPU this process has used so far, all its threads together: the engine's clock
// (deadline.hpp), which the fit's share of work reads too.
using curvefold::processCpuSeconds;

// Seconds of CPU of the children this process has waited for (std::system's commands and theirs),
// user and system together.
inline double childrenCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// The CPU this process spends after a moment: a thread sleeps until `at`, reads the process's
// CPU time, then runs `then` (a cancel, say). A thread woken late under load reads later, which
// counts less, never more.
class CpuAfter {
 public:
  explicit CpuAfter(std::chrono::steady_clock::time_point at, std::function<void()> then = {})
      : thread_([this, at, then = std::move(then)] {
          std::this_thread::sleep_until(at);
          atMoment_ = processCpuSeconds();
          if (then) then();
        }) {}
  CpuAfter(const CpuAfter&) = delete;
  CpuAfter& operator=(const CpuAfter&) = delete;
  ~CpuAfter() {
    if (thread_.joinable()) thread_.join();
  }

  // Seconds of CPU since the moment (waits for it when it has not come: then about 0).
  double seconds() {
    if (thread_.joinable()) thread_.join();
    return processCpuSeconds() - atMoment_;
  }

 private:
  double atMoment_ = 0.0;
  std::thread thread_;
};

// Runs `run` (a search given `limit` seconds from now): what it returned, the wall seconds it
// took, and the CPU the process spent after the limit (CpuAfter).
template <class Run>
auto runPastLimit(double limit, Run&& run) {
  struct Timed {
    decltype(run()) result;
    double seconds, cpuAfterLimit;
  };
  const auto start = std::chrono::steady_clock::now();
  CpuAfter afterLimit(start + std::chrono::duration_cast<std::chrono::nanoseconds>(
                                  std::chrono::duration<double>(limit)));
  auto result = run();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Timed{std::move(result), seconds, afterLimit.seconds()};
}

}  // namespace curvefold::testing
