// Candidates scored in batches within a deadline (issue 38, 3: a step the clock cuts still
// answers), shared by the nested rings (nested_rings.hpp) and the tube rings' chains
// (ring_folds.hpp): each batch runs on all cores, and before each the clock is read; a batch the
// time left would not finish, judged by the most seconds per unit of cost of any batch run so
// far, is not started. So a caller that orders its candidates coarse to fine (cheap and likely
// first) answers with the candidates of the batches that ran, each made whole, on a loaded machine.
//
// Inputs: the deadline (a deadline that never comes runs every batch: a fit by evaluations
// repeats bit for bit); for each batch the candidates' range, its cost in any unit proportional
// to its time (the folds it makes), and what to do with one candidate. The first batch always
// starts unless the deadline has passed. Limits: the estimate is the dearest rate seen, so a
// batch dearer per unit than every one before it (or a load that rises while it runs) may still
// run past the deadline (each candidate should read the deadline itself).
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>

#include "engine/fit/deadline.hpp"

namespace curvefold {

class TimedBatches {
 public:
  explicit TimedBatches(const Deadline& deadline) : deadline_(deadline) {}

  // Runs `evaluate(c)` for c in [from, to) on all cores when the time left holds it (see above);
  // returns whether it ran. After a batch is refused, every later one is refused too.
  bool run(std::size_t from, std::size_t to, double cost,
           const std::function<void(std::size_t)>& evaluate);

  // Whether a batch was refused (the clock cut the work short).
  bool cut() const { return cut_; }

 private:
  Deadline deadline_;
  double secondsPerUnit_ = 0.0;
  bool ranOne_ = false;
  bool cut_ = false;
};

}  // namespace curvefold
