// How near the fit's own distance comes to the exact one (issue 38): for a design and target OBJs,
// the search's score (FoldFitter::approximateDistance, what each step lowers), the search's
// samples read plainly (FoldFitter::approximateMeasure) and the exact measure (surfaceDistance,
// what `fit` and `distance` print), in millimetres. bench/distance_truth.py measures the same
// apart from curvefold.
//
//   build/bench/search_distance DESIGN.curvefold.json TARGET.obj...
#include <cstdio>
#include <exception>

#include "engine/fit/fold_fit.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/io/design_document.hpp"
#include "engine/surfaces/obj_surface.hpp"

namespace curvefold {
namespace {

void print(const char* what, const SurfaceDistance& d) {
  std::printf(
      "  %-7s Hausdorff %9.3f  Chamfer %8.3f  (sheet->target max %.3f mean %.3f; "
      "target->sheet max %.3f mean %.3f)\n",
      what, 1e3 * d.hausdorff, 1e3 * d.chamfer, 1e3 * d.fromAMax, 1e3 * d.fromAMean,
      1e3 * d.fromBMax, 1e3 * d.fromBMean);
}

int run(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: search_distance DESIGN.curvefold.json TARGET.obj...\n");
    return 2;
  }
  const Sheet sheet = buildSheet(loadDesign(argv[1]));
  for (int i = 2; i < argc; ++i) {
    const FoldFitter fitter(readObjMesh(argv[i]));
    std::printf("%s: search score %.3f mm\n", argv[i], 1e3 * fitter.approximateDistance(sheet));
    print("search", fitter.approximateMeasure(sheet));
    print("exact", surfaceDistance(meshOf(sheet), fitter.measuredTarget()));
  }
  return 0;
}

}  // namespace
}  // namespace curvefold

int main(int argc, char** argv) {
  try {
    return curvefold::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "search_distance: %s\n", e.what());
    return 1;
  }
}
