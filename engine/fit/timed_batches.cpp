#include "engine/fit/timed_batches.hpp"

#include <algorithm>

#include <tbb/parallel_for.h>

namespace curvefold {

bool TimedBatches::run(std::size_t from, std::size_t to, double cost,
                       const std::function<void(std::size_t)>& evaluate) {
  if (cut_) return false;
  const auto now = std::chrono::steady_clock::now();
  const double left = std::chrono::duration<double>(deadline_.at - now).count();
  if (deadline_.passed() || (ranOne_ && secondsPerUnit_ * cost > left)) {
    cut_ = true;
    return false;
  }
  if (to <= from) return true;  // nothing to time: the last batch's rate stands
  tbb::parallel_for(from, to, evaluate);
  // The dearest rate yet, not the last: one step's batches differ by 2x per unit (the solved
  // rings' and the searched shapes'), and a batch judged by a cheap one before it ran 0.3 s past
  // the fit's deadline, leaving its final measure after the limit (NestedRings, under load).
  secondsPerUnit_ =
      std::max(secondsPerUnit_,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - now).count() /
                   std::max(1.0, cost));
  ranOne_ = true;
  return true;
}

}  // namespace curvefold
