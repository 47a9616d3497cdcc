#include "engine/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <streambuf>
#include <string>

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

void syncDirectory(const std::filesystem::path& path) {
  // Makes the rename itself durable; a file system that cannot fsync a directory is not an error.
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& writer) {
  if (path.empty() || !path.has_filename()) throw FileError(failure(path, EISDIR));
  std::filesystem::path temp;
  int fd = -1;
  for (int attempt = 0; fd < 0; ++attempt) {
    temp = temporaryPathFor(path);
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
    DescriptorBuffer buffer(fd);
    std::ostream stream(&buffer);
    writer(stream);
    stream.flush();
    if (!buffer.drain() || !stream) error = buffer.error() != 0 ? buffer.error() : EIO;
  } catch (...) {
    discard();
    throw;
  }
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  fd = -1;
  if (error == 0 && ::rename(temp.c_str(), path.c_str()) != 0) error = errno;
  if (error != 0) {
    discard();
    throw FileError(failure(path, error));
  }
  syncDirectory(path);
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view content) {
  writeFileAtomically(path, [content](std::ostream& out) {
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
  });
}

}  // namespace curvefold
