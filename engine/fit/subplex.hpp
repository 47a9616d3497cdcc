// NLopt's Subplex (T. Rowan, "Functional stability analysis of numerical algorithms", 1990;
// NLopt's LN_SBPLX) as the fit's local refinements call it: the ring refinement of
// profile_folds.hpp and the profile creases of nested_rings.hpp (each wrote the same NLopt set-up
// and error handling out before).
//
// minimizeSubplex: `objective` minimized from `x` (left at the point NLopt ends on) with initial
// steps `steps`, at most `maxEvaluations` evaluations, within `bounds` when given; it stops at its
// next evaluation once `deadline` (when given) has passed. A value that is not finite reads as
// 1e30 (a point the objective cannot score). NLopt's forced stop, round-off limit and failures
// end the search quietly: the caller keeps what it recorded. Known limits: derivative-free and
// local; the caller keeps its own best point (NLopt's x after a forced stop is its last).
#pragma once

#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include <nlopt.hpp>

#include "engine/fit/deadline.hpp"

namespace curvefold {

struct SubplexBounds {
  std::vector<double> lower, upper;
};

inline void minimizeSubplex(std::vector<double>& x, const std::vector<double>& steps,
                            int maxEvaluations,
                            const std::function<double(const std::vector<double>&)>& objective,
                            const Deadline* deadline = nullptr,
                            const SubplexBounds* bounds = nullptr) {
  nlopt::opt optimizer(nlopt::LN_SBPLX, static_cast<unsigned>(x.size()));
  struct Data {
    const std::function<double(const std::vector<double>&)>* objective;
    const Deadline* deadline;
    nlopt::opt* optimizer;
  } data{&objective, deadline, &optimizer};
  optimizer.set_min_objective(
      [](const std::vector<double>& y, std::vector<double>&, void* p) {
        auto& d = *static_cast<Data*>(p);
        if (d.deadline && d.deadline->passed()) d.optimizer->force_stop();
        const double value = (*d.objective)(y);
        return std::isfinite(value) ? value : 1e30;
      },
      &data);
  if (bounds) {
    optimizer.set_lower_bounds(bounds->lower);
    optimizer.set_upper_bounds(bounds->upper);
  }
  optimizer.set_initial_step(steps);
  optimizer.set_maxeval(maxEvaluations);
  double value = 0.0;
  try {
    optimizer.optimize(x, value);
  } catch (const std::runtime_error&) {  // forced_stop, roundoff_limited, a failure
  }
}

}  // namespace curvefold
