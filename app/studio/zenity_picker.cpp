#include "app/studio/zenity_picker.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <utility>
#include <vector>

extern char** environ;

namespace curvefold::studio {

namespace {

// A path is at most this long: more output is not a path.
constexpr std::size_t kMaxOutput = 64 * 1024;

bool isExecutableFile(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
         ::access(path.c_str(), X_OK) == 0;
}

// On the worker: reads the chosen path until zenity closes its output, then reaps it; `cancel`
// becoming readable ends it first.
FilePicker::Picked waitForZenity(pid_t child, int output, int cancel) {
  std::string text;
  bool cancelled = false;
  int pollError = 0;  // waiting failed: the dialog is ended as if cancelled, and that is said
  pollfd watched[2] = {{output, POLLIN, 0}, {cancel, POLLIN, 0}};
  for (;;) {
    if (::poll(watched, 2, -1) < 0) {
      if (errno == EINTR) continue;
      pollError = errno;
      cancelled = true;
      break;
    }
    if (watched[1].revents != 0) {
      cancelled = true;
      break;
    }
    char buffer[4096];
    const ssize_t n = ::read(output, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (text.size() < kMaxOutput) text.append(buffer, std::size_t(n));
  }
  ::close(output);
  // Reaped only here, so the group is still there to signal. A program that closed its output
  // but goes on is waited for until cancelled; one that ignores SIGTERM is killed a second later.
  using Clock = std::chrono::steady_clock;
  Clock::time_point deadline = Clock::now() + std::chrono::seconds(1);
  if (cancelled) ::kill(-child, SIGTERM);
  int status = 0;
  pid_t reaped = 0;
  while ((reaped = ::waitpid(child, &status, WNOHANG)) == 0) {
    if (!cancelled) {
      pollfd stop = {cancel, POLLIN, 0};
      if (::poll(&stop, 1, 20) > 0) {
        cancelled = true;
        ::kill(-child, SIGTERM);
        deadline = Clock::now() + std::chrono::seconds(1);
      }
    } else {
      if (Clock::now() > deadline) ::kill(-child, SIGKILL);
      ::usleep(20000);
    }
  }
  FilePicker::Picked picked;
  const bool exited = reaped == child && WIFEXITED(status);
  if (pollError != 0) {
    picked.error = std::string("cannot wait for the file picker (zenity): ") +
                   std::strerror(pollError) + "; type the path instead";
  } else if (cancelled) {
    // The window is closing: nobody reads this.
  } else if (exited && WEXITSTATUS(status) == 0) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    if (text.empty() || text.find('\n') != std::string::npos || text.size() >= kMaxOutput)
      picked.error = "the file picker gave no single path; type the path instead";
    else
      picked.path = text;
  } else if (!(exited && WEXITSTATUS(status) == 1)) {
    // zenity exits 1 when the person cancels; anything else is a failure.
    picked.error = std::string("the file picker (zenity) failed") +
                   (exited ? " with exit status " + std::to_string(WEXITSTATUS(status))
                           : std::string(reaped == child ? " on a signal" : "")) +
                   "; type the path instead";
  }
  return picked;
}

}  // namespace

std::string ZenityPicker::find() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return "";
  const std::string all = path;
  for (std::size_t begin = 0; begin <= all.size();) {
    const std::size_t end = std::min(all.find(':', begin), all.size());
    // An empty entry is the working directory: not where a desktop's picker lives.
    if (end > begin) {
      const std::string candidate = all.substr(begin, end - begin) + "/zenity";
      if (isExecutableFile(candidate)) return candidate;
    }
    begin = end + 1;
  }
  return "";
}

void ZenityPicker::start(bool save, const std::string& current) {
  if (busy()) return;
  std::vector<std::string> arguments = {
      program_, "--file-selection", save ? "--title=Save the design as" : "--title=Open a design",
      "--file-filter=Designs | *.curvefold.json *.json", "--file-filter=All files | *"};
  if (save) {
    arguments.push_back("--save");
    arguments.push_back("--confirm-overwrite");  // zenity 4 always asks, and ignores it
  }
  if (!current.empty()) arguments.push_back("--filename=" + current);
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);

  int output[2];
  if (::pipe2(output, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("cannot start the file picker: ") + std::strerror(errno));
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&files, output[1], 1);
  // GTK's warnings would fill the terminal; a failure is told by the exit status.
  posix_spawn_file_actions_addopen(&files, 2, "/dev/null", O_WRONLY, 0);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  // Its own process group, so that ending the dialog ends whatever it started too.
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  pid_t child = 0;
  const int failed =
      ::posix_spawn(&child, program_.c_str(), &files, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  posix_spawnattr_destroy(&attributes);
  ::close(output[1]);
  if (failed != 0) {
    ::close(output[0]);
    throw std::runtime_error(std::string("cannot start the file picker (zenity): ") +
                             std::strerror(failed));
  }
  try {
    launch([child, out = output[0]](int cancel) { return waitForZenity(child, out, cancel); });
  } catch (...) {
    ::close(output[0]);
    ::kill(-child, SIGKILL);
    ::waitpid(child, nullptr, 0);
    throw;
  }
}

}  // namespace curvefold::studio
