// Frees a half-made object when its constructor throws: C++ runs no destructor for an object whose
// constructor did not finish, so what the constructor had made would leak. Declared first in the
// constructor's body, `const ScopeFail cleanup([this] { destroy(); });` runs destroy() when an
// exception leaves the body, and nothing otherwise (std::experimental::scope_fail's rule).
#pragma once

#include <exception>
#include <utility>

namespace curvefold {

template <typename Cleanup>
class ScopeFail {
 public:
  explicit ScopeFail(Cleanup cleanup) : cleanup_(std::move(cleanup)) {}
  ~ScopeFail() {
    if (std::uncaught_exceptions() > exceptions_) cleanup_();
  }
  ScopeFail(const ScopeFail&) = delete;
  ScopeFail& operator=(const ScopeFail&) = delete;

 private:
  Cleanup cleanup_;
  int exceptions_ = std::uncaught_exceptions();
};

}  // namespace curvefold
