// Deferred destruction (as in vulkan-guide): objects are pushed with the function that destroys
// them and destroyed in reverse order, either at shutdown or once the frame that last used them
// has finished on the GPU.
#pragma once

#include <functional>
#include <utility>
#include <vector>

namespace curvefold {

class DeletionQueue {
 public:
  DeletionQueue() = default;
  DeletionQueue(const DeletionQueue&) = delete;
  DeletionQueue& operator=(const DeletionQueue&) = delete;
  ~DeletionQueue() { flush(); }

  void push(std::function<void()> destroy) { pending_.push_back(std::move(destroy)); }
  void flush() {
    while (!pending_.empty()) {
      std::function<void()> destroy = std::move(pending_.back());
      pending_.pop_back();
      destroy();
    }
  }
  bool empty() const { return pending_.empty(); }

 private:
  std::vector<std::function<void()>> pending_;
};

}  // namespace curvefold
