// Targets that reflection folds reach by construction, made in several unlike ways (issue 38, 1),
// to measure `curvefold fit` on designs it was not tuned on: each recipe grabs, drags and
// accepts folds by rules of its own, a target is kept only when its design passes `check` whole,
// and it reaches the fitter as a user's file would: written by `export --obj` with its `vt`
// lines (the development) removed, read back as a plain mesh.
//
// Recipes (foldTargetRecipes()):
//  - anywhere-long: any vertex grabbed, dragged 15-60% of the diagonal in a uniform direction;
//  - outer-short: a vertex in the outer third of the folded form (from its bounding box's centre),
//    dragged 10-35%;
//  - crossing: as anywhere-long, but every fold after the first cuts an earlier crease;
//  - symmetric: as outer-short, on a design with one of the surface's symmetries (its images
//    follow each fold).
// Deterministic for a seed. Test and benchmark code, not part of the product.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/geometry/sheet.hpp"
#include "engine/geometry/triangle_mesh.hpp"
#include "engine/io/design_document.hpp"

namespace curvefold::testing {

struct FoldTargetRecipe {
  std::string name;
  bool outerThird = false;  // grab only where the folded form reaches its outer third
  double dragMin = 0.15;    // drag length, fraction of the initial sheet's diagonal
  double dragMax = 0.60;
  bool cutEarlier = false;  // each fold after the first cuts an earlier crease
  bool symmetric = false;   // the design takes one of the surface's symmetries
};

const std::vector<FoldTargetRecipe>& foldTargetRecipes();

struct FoldTarget {
  Design design;          // what `check` passed (surface at its defaults, folds, symmetry)
  Sheet initial, sheet;   // before and after the folds
  TriangleMesh exported;  // `export --obj` less its vt lines, as `fit` reads it
};

// A target folded `folds` times (counting a fold and its images once) from the catalogue surface
// at its default parameters; nothing when the recipe found no such folds in its tries or the
// design fails `check` (try another seed).
std::optional<FoldTarget> makeFoldTarget(const FoldTargetRecipe& recipe, const std::string& surface,
                                         std::size_t folds, std::uint64_t seed);

// The sheet as `export --obj` writes it, read back without its vt lines.
TriangleMesh exportedWithoutDevelopment(const Sheet& sheet);

}  // namespace curvefold::testing
