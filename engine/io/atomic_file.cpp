#include "engine/io/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <map>
#include <mutex>
#include <streambuf>
#include <string>
#include <vector>

namespace curvefold {
namespace {

std::string failure(const std::filesystem::path& path, int error) {
  return "cannot write " + path.string() + ": " + std::strerror(error);
}

// A stream buffer over a POSIX descriptor, so that the descriptor stays ours to fsync and the
// first write error's errno is kept for the message.
class DescriptorBuffer : public std::streambuf {
 public:
  explicit DescriptorBuffer(int fd) : fd_(fd) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }

  int error() const { return error_; }

  // Writes out what is buffered; false (with error() set) on failure.
  bool drain() {
    const char* data = pbase();
    std::size_t left = static_cast<std::size_t>(pptr() - pbase());
    while (left > 0 && error_ == 0) {
      const ssize_t written = ::write(fd_, data, left);
      if (written < 0) {
        if (errno != EINTR) error_ = errno;
        continue;
      }
      data += written;
      left -= static_cast<std::size_t>(written);
    }
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return error_ == 0;
  }

 protected:
  int_type overflow(int_type ch) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  int fd_;
  int error_ = 0;
  std::array<char, 1 << 16> buffer_;
};

// A name no one else uses: hidden, next to the target, unique per process and call.
std::filesystem::path temporaryPathFor(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  // Appending piece by piece avoids GCC 12's false -Wrestrict on "literal" + std::string.
  std::string name(1, '.');
  name += path.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(counter++);
  std::filesystem::path temp = path;
  temp.replace_filename(name);
  return temp;
}

std::string describe(const std::filesystem::path& path) {
  return path == "-" ? std::string("standard output") : path.string();
}

// Writes through writer into an open descriptor; returns the first errno (0 on success).
int writeThrough(int fd, const std::function<void(std::ostream&)>& writer) {
  DescriptorBuffer buffer(fd);
  std::ostream stream(&buffer);
  writer(stream);
  stream.flush();
  if (!buffer.drain() || !stream) return buffer.error() != 0 ? buffer.error() : EIO;
  return 0;
}

// A device, a FIFO or standard output: no temporary, no rename, nothing to fsync.
void writeInPlace(const std::filesystem::path& path, const std::filesystem::path& shownAs,
                  const std::function<void(std::ostream&)>& writer) {
  const bool standardOutput = path == "-";
  const int fd = standardOutput ? STDOUT_FILENO : ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) throw FileError("cannot write " + describe(shownAs) + ": " + std::strerror(errno));
  int error = 0;
  try {
    error = writeThrough(fd, writer);
  } catch (...) {
    if (!standardOutput) ::close(fd);
    throw;
  }
  if (!standardOutput && ::close(fd) != 0 && error == 0) error = errno;
  if (error != 0)
    throw FileError("cannot write " + describe(shownAs) + ": " + std::strerror(error));
}

bool processIsGone(std::string_view digits) {
  int pid = 0;
  const auto [end, problem] = std::from_chars(digits.data(), digits.data() + digits.size(), pid);
  if (problem != std::errc() || end != digits.data() + digits.size() || pid <= 0) return false;
  return ::kill(pid, 0) != 0 && errno == ESRCH;
}

// Whether `rest` (what follows ".NAME.") is "tmp-PID-N", "staged-PID" or "staged-PID.tmp-PID-N"
// with every PID gone.
bool staleSuffix(std::string_view rest) {
  auto takeTemporary = [](std::string_view text) {  // "tmp-PID-N"
    if (text.substr(0, 4) != "tmp-") return false;
    text.remove_prefix(4);
    const auto dash = text.find('-');
    if (dash == std::string_view::npos || dash + 1 >= text.size()) return false;
    for (char c : text.substr(dash + 1))
      if (c < '0' || c > '9') return false;
    return processIsGone(text.substr(0, dash));
  };
  if (takeTemporary(rest)) return true;
  if (rest.substr(0, 7) != "staged-") return false;
  rest.remove_prefix(7);
  const auto dot = rest.find('.');
  if (!processIsGone(rest.substr(0, dot))) return false;
  return dot == std::string_view::npos || takeTemporary(rest.substr(dot + 1));
}

void syncDirectory(const std::filesystem::path& path) {
  // Makes the rename itself durable; a file system that cannot fsync a directory is not an error.
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

std::filesystem::path resolveOutputPath(const std::filesystem::path& path) {
  std::filesystem::path resolved = path;
  for (int hops = 0;; ++hops) {
    std::error_code error;
    if (resolved == "-" || !std::filesystem::is_symlink(resolved, error)) return resolved;
    if (hops == 40) throw FileError(failure(path, ELOOP));
    const std::filesystem::path target = std::filesystem::read_symlink(resolved, error);
    if (error) throw FileError("cannot write " + path.string() + ": " + error.message());
    resolved = target.is_absolute() ? target : resolved.parent_path() / target;
  }
}

bool writesInPlace(const std::filesystem::path& resolvedPath) {
  if (resolvedPath == "-") return true;
  struct stat info {};
  if (::stat(resolvedPath.c_str(), &info) != 0) return false;
  return !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode);
}

std::filesystem::path stagingPathFor(const std::filesystem::path& resolvedPath) {
  std::string name(1, '.');
  name += resolvedPath.filename().string();
  name += ".staged-";
  name += std::to_string(::getpid());
  std::filesystem::path staged = resolvedPath;
  staged.replace_filename(name);
  return staged;
}

void keepPermissions(const std::filesystem::path& target, const std::filesystem::path& staged) {
  struct stat info {};
  if (::stat(target.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return;
  ::chmod(staged.c_str(), info.st_mode & 07777);
}

void removeStaleTemporaries(const std::filesystem::path& resolvedPath) {
  // One listing per directory and process: a folder of thousands of frames is not listed per
  // frame. What it found is kept per target name, and each write removes its own target's.
  static std::mutex mutex;
  static std::map<std::filesystem::path, std::map<std::string, std::vector<std::filesystem::path>>>
      listed;
  const std::string name = resolvedPath.filename().string();
  if (name.empty()) return;
  const std::filesystem::path dir =
      resolvedPath.has_parent_path() ? resolvedPath.parent_path() : ".";
  std::lock_guard lock(mutex);
  auto [entry, first] = listed.try_emplace(dir);
  if (first) {
    std::error_code error;
    for (std::filesystem::directory_iterator it(dir, error), end; !error && it != end;
         it.increment(error)) {
      const std::string file = it->path().filename().string();
      if (file.size() < 2 || file[0] != '.') continue;
      // ".NAME.tmp-..." or, for a staged file's own temporary, "..NAME.staged-....tmp-...".
      const std::size_t skip = file[1] == '.' ? 2 : 1;
      for (std::size_t dot = file.find('.', skip); dot != std::string::npos;
           dot = file.find('.', dot + 1)) {
        if (staleSuffix(std::string_view(file).substr(dot + 1))) {
          entry->second[file.substr(skip, dot - skip)].push_back(it->path());
          break;
        }
      }
    }
  }
  const auto stale = entry->second.find(name);
  if (stale == entry->second.end()) return;
  for (const std::filesystem::path& file : stale->second) {
    std::error_code ignored;
    std::filesystem::remove_all(file, ignored);  // a link itself, never what it points to
  }
  entry->second.erase(stale);
}

void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& writer) {
  if (path.empty() || !path.has_filename()) throw FileError(failure(path, EISDIR));
  const std::filesystem::path target = resolveOutputPath(path);
  if (writesInPlace(target)) return writeInPlace(target, path, writer);
  removeStaleTemporaries(target);
  std::filesystem::path temp;
  int fd = -1;
  for (int attempt = 0; fd < 0; ++attempt) {
    temp = temporaryPathFor(target);
    // O_EXCL never follows or reuses someone else's file; mode 0666 lets the umask apply.
    fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && (errno != EEXIST || attempt > 100)) throw FileError(failure(path, errno));
  }
  auto discard = [&] {
    if (fd >= 0) ::close(fd);
    ::unlink(temp.c_str());
  };

  int error = 0;
  try {
    error = writeThrough(fd, writer);
  } catch (...) {
    discard();
    throw;
  }
  // Replacing a file keeps its permissions (a rename would give it the temporary's).
  struct stat info {};
  if (error == 0 && ::stat(target.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
      ::fchmod(fd, info.st_mode & 07777) != 0)
    error = errno;
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  fd = -1;
  if (error == 0 && ::rename(temp.c_str(), target.c_str()) != 0) error = errno;
  if (error != 0) {
    discard();
    throw FileError(failure(path, error));
  }
  syncDirectory(target);
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view content) {
  writeFileAtomically(path, [content](std::ostream& out) {
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
  });
}

}  // namespace curvefold
