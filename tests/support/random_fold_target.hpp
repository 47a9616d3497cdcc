// Targets that a sequence of reflection folds reaches by construction, for measuring the fold
// search (issue 27): a catalogue surface folded N times at random, each fold cutting a crease
// across the sheet, moving between a tenth and nine tenths of it, and passing nothing through
// itself. Deterministic for a seed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/geometry/fold_session.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {

struct RandomFoldTarget {
  Sheet initial;
  std::vector<FoldRecord> folds;
  Sheet sheet;  // the initial sheet with the folds
};

// Throws std::runtime_error when no such fold is found in many tries (a tiny sheet).
RandomFoldTarget makeRandomFoldTarget(const std::string& surface,
                                      const SurfaceParameters& parameters, std::size_t folds,
                                      std::uint64_t seed);

}  // namespace curvefold
