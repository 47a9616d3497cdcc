#include "app/studio/file_picker.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace curvefold::studio {

FilePicker::~FilePicker() {
  if (!worker_.joinable()) return;
  const char stop = 1;
  [[maybe_unused]] const ssize_t written = ::write(cancel_[1], &stop, 1);
  worker_.join();
  for (int& end : cancel_) ::close(std::exchange(end, -1));
}

void FilePicker::launch(std::function<Picked(int cancelled)> dialog) {
  if (::pipe2(cancel_, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("cannot start the file picker: ") + std::strerror(errno));
  {
    std::lock_guard lock(mutex_);
    done_.reset();
  }
  worker_ = std::thread([this, dialog = std::move(dialog)] {
    Picked picked = dialog(cancel_[0]);
    std::lock_guard lock(mutex_);
    done_ = std::move(picked);
  });
}

std::optional<FilePicker::Picked> FilePicker::poll() {
  {
    std::lock_guard lock(mutex_);
    if (!done_) return std::nullopt;
  }
  worker_.join();  // it has set done_: it is returning
  for (int& end : cancel_) ::close(std::exchange(end, -1));
  std::lock_guard lock(mutex_);
  return std::exchange(done_, std::nullopt);
}

}  // namespace curvefold::studio
