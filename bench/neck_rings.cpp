// What rings solved on the radius profile reach from a tube (issue 38, 2; profile_folds.hpp,
// neckRings): the target's axis found (revolutionAxis), a cylinder of its mean radius and
// length placed on it (as `fit --from cylinder` sizes one), then up to N rings taken greedily,
// each the neck ring (both turns) that brings the sheet closest (the fitter's approximate
// distance) without passing it through itself. Prints the exact distance (20,000 samples a side)
// after each: what the search could keep if it chose these rings at every step. RADIUS_SCALE
// (default 1) widens the tube past the mean radius: rings only narrow it.
//
//   build/bench/neck_rings TARGET.obj [RINGS [RADIUS_SCALE]]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <numbers>
#include <optional>
#include <string>

#include <glm/geometric.hpp>

#include "engine/fit/fold_fit.hpp"
#include "engine/fit/profile_folds.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/surfaces/obj_surface.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {
namespace {

// The catalogue's cylinder (about y, centred) turned onto `axis`, its middle at height `middle`.
Sheet placedCylinder(double radius, double length, const RevolutionAxis& axis, double middle) {
  Sheet tube = makeSurface("cylinder", {{"radius", radius}, {"height", length}});
  const glm::dvec3 y(0, 1, 0), d = axis.direction;
  const glm::dvec3 k = glm::cross(y, d);
  const double s = glm::length(k), c = glm::dot(y, d);
  for (glm::dvec3& p : tube.positions) {
    glm::dvec3 q = p;
    if (s > 1e-12) {  // Rodrigues: y onto d
      const glm::dvec3 u = k / s;
      q = p * c + glm::cross(u, p) * s + u * glm::dot(u, p) * (1.0 - c);
    } else if (c < 0.0) {
      q = -p;
    }
    p = axis.point + middle * d + q;
  }
  return tube;
}

void print(const char* what, const Sheet& sheet, const TriangleMesh& target) {
  const SurfaceDistance d = surfaceDistance(meshOf(sheet), target);
  std::printf("%s: Chamfer %.3g%%, Hausdorff %.3g%% of the diagonal\n", what,
              100.0 * d.relativeChamfer(), 100.0 * d.relativeHausdorff());
}

int run(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::fprintf(stderr, "usage: neck_rings TARGET.obj [RINGS [RADIUS_SCALE]]\n");
    return 2;
  }
  const int rings = argc >= 3 ? std::atoi(argv[2]) : 3;
  // The tube's radius against the target's mean (rings only narrow a tube: a wider start leaves
  // them the belly to cut from).
  const double radiusScale = argc == 4 ? std::atof(argv[3]) : 1.0;
  const TriangleMesh target = readObjMesh(argv[1]);
  const std::vector<SurfaceSample> targetSamples = sampleSurface(target, 3000, 5);
  const std::optional<RevolutionAxis> axis = revolutionAxis(targetSamples);
  if (!axis) {
    std::fprintf(stderr, "neck_rings: the target is not a surface of revolution\n");
    return 1;
  }
  double lo = 1e300, hi = -1e300, radius = 0.0;
  for (const SurfaceSample& s : targetSamples) {
    const glm::dvec3 d = s.position - axis->point;
    const double t = glm::dot(d, axis->direction);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
    radius += glm::length(d - t * axis->direction);
  }
  radius *= radiusScale / static_cast<double>(targetSamples.size());
  const Sheet tube = placedCylinder(radius, hi - lo, *axis, 0.5 * (lo + hi));
  std::printf("cylinder: radius %.4g m, length %.4g m on the axis\n", radius, hi - lo);
  const FoldFitter fitter(target);
  FoldSession session(tube);
  print("start", session.fixed(), target);
  for (int step = 0; step < rings; ++step) {
    const std::vector<SurfaceSample> sheetSamples =
        sampleSurface(meshOf(session.fixed()), 800, 6 + static_cast<std::uint64_t>(step));
    const std::vector<FoldRecord> base(
        session.folds().begin(),
        session.folds().begin() + static_cast<std::ptrdiff_t>(session.foldCount()));
    double best = fitter.approximateDistance(session.fixed());
    std::optional<RingShape> chosen;
    for (const double turn : {0.0, 0.5})
      for (RingShape shape : neckRings(sheetSamples, targetSamples, *axis)) {
        shape.turn = turn * 2.0 * std::numbers::pi / shape.order;
        FoldSession trial(tube);
        trial.applyRecords(base);
        if (makeRing(trial, ringOf(shape, *axis)) == 0) continue;
        const double d = fitter.approximateDistance(trial.fixed());
        if (d < best && findSelfIntersections(trial.fixed()).intersections.empty()) {
          best = d;
          chosen = shape;
        }
      }
    if (!chosen) {
      std::printf("no neck ring brings it closer\n");
      break;
    }
    makeRing(session, ringOf(*chosen, *axis));
    validate(session.fixed());
    const std::string what = "ring " + std::to_string(step + 1) + " of " +
                             std::to_string(chosen->order) + " (" +
                             std::to_string(session.foldCount()) + " folds)";
    print(what.c_str(), session.fixed(), target);
  }
  return 0;
}

}  // namespace
}  // namespace curvefold

int main(int argc, char** argv) {
  try {
    return curvefold::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "neck_rings: %s\n", e.what());
    return 1;
  }
}
