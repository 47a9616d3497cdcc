// Why a reachable target's unfolding misses (issue 38, 1): for a target OBJ and the design that
// made it, the design's fold planes, the crease planes read off the target (crease_planes.hpp) and
// which fold each names, and what the unfolding (target_unfolding.hpp) read; where it ends a
// rigid copy of the sheet, every way the sheet lies on it, each also times each of the sheet's own
// symmetries and with each fold read flipped, counted by the planes its kind takes.
//
//   build/bench/unfold_report TARGET.obj DESIGN.curvefold.json [MAX_FOLDS]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "engine/fit/crease_planes.hpp"
#include "engine/fit/replayed_motion.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/fit/target_unfolding.hpp"
#include "engine/fit/whole_sheet_folds.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/io/design_document.hpp"
#include "engine/surfaces/obj_surface.hpp"

namespace curvefold {
namespace {

bool samePlane(const ReflectionPlane& a, const ReflectionPlane& b, double size) {
  return std::abs(std::abs(glm::dot(a.normal, b.normal)) - 1.0) < 1e-4 &&
         std::abs(a.signedDistance(b.point)) < 1e-4 * size;
}

int run(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: unfold_report TARGET.obj DESIGN.curvefold.json [MAX_FOLDS]\n");
    return 2;
  }
  // As `fit --folds 8` reads (12 by default).
  const std::size_t maxFolds = argc == 4 ? std::stoul(argv[3]) : 12;
  const TriangleMesh target = readObjMesh(argv[1]);
  const Design design = loadDesign(argv[2]);
  const Sheet initial = initialSheet(design);
  const TriangleMesh sheet = meshOf(initial);
  const double size = boundingDiagonal(target);
  const double threshold = sharpEdgeThreshold(sheet);
  std::printf("target: %zu vertices, diagonal %.4f; threshold %.2f deg; %zu folds%s%s\n",
              target.positions.size(), size, threshold, design.folds.size(),
              design.symmetry.empty() ? "" : ", symmetry ", design.symmetry.c_str());
  CreasePlaneOptions options;
  options.minDihedralDegrees = threshold;
  const std::vector<CreasePlane> planes = findCreasePlanes(target, options);
  for (std::size_t f = 0; f < design.folds.size(); ++f) {
    int found = -1;
    for (std::size_t p = 0; p < planes.size(); ++p)
      if (samePlane(planes[p].plane, design.folds[f].plane, size)) found = int(p);
    std::printf("fold %zu (group %u): plane n=(%.3f %.3f %.3f) d=%.4f  crease plane %d\n", f + 1,
                design.folds[f].group, design.folds[f].plane.normal.x,
                design.folds[f].plane.normal.y, design.folds[f].plane.normal.z,
                glm::dot(design.folds[f].plane.normal, design.folds[f].plane.point), found);
  }
  // Each creasing fold's plane as the target holds it: moved by every later fold that moved the
  // whole sheet (its plane missed it), as a reading of the target finds it.
  std::vector<ReflectionPlane> seen;
  {
    std::vector<std::size_t> whole;
    for (std::size_t f = 0; f < design.folds.size(); ++f) {
      FoldSession before(initial), after(initial);
      before.applyRecords({design.folds.begin(), design.folds.begin() + std::ptrdiff_t(f)});
      after.applyRecords({design.folds.begin(), design.folds.begin() + std::ptrdiff_t(f + 1)});
      const auto& a = before.fixed().positions;
      const auto& b = after.fixed().positions;
      bool all = a.size() == b.size();
      for (std::size_t v = 0; all && v < a.size(); ++v)
        all = glm::distance(design.folds[f].plane.reflect(a[v]), b[v]) < 1e-9 * size;
      if (all) whole.push_back(f);
    }
    for (std::size_t f = 0; f < design.folds.size(); ++f) {
      ReflectionPlane p = design.folds[f].plane;
      for (std::size_t w : whole)
        if (w > f) {
          const ReflectionPlane& m = design.folds[w].plane;
          const glm::dvec3 n = p.normal - 2.0 * glm::dot(p.normal, m.normal) * m.normal;
          p = {m.reflect(p.point), n};
        }
      const bool isWhole = std::find(whole.begin(), whole.end(), f) != whole.end();
      seen.push_back(p);
      std::printf("fold %zu %s, as the target holds it: n=(%.3f %.3f %.3f) d=%.4f\n", f + 1,
                  isWhole ? "moved the whole sheet" : "creases", p.normal.x, p.normal.y, p.normal.z,
                  glm::dot(p.normal, p.point));
    }
  }
  for (std::size_t p = 0; p < planes.size(); ++p) {
    int fold = -1;
    for (std::size_t f = 0; f < design.folds.size(); ++f)
      if (samePlane(planes[p].plane, design.folds[f].plane, size)) fold = int(f) + 1;
    std::printf("crease plane %zu: support %.4f (%.2f%%), fold %d\n", p, planes[p].support,
                100 * planes[p].support / size, fold);
  }
  // A symmetric design's images, as the fit reads them (a fold's image may move the whole sheet).
  const std::vector<Isometry> images = design.symmetry.empty()
                                           ? std::vector<Isometry>{}
                                           : parseSymmetry(design.symmetry, initial).images();
  const auto unfoldingStarted = std::chrono::steady_clock::now();
  const TargetUnfolding plan = unfoldTarget(target, sheet, threshold, maxFolds, {}, images);
  const double unfoldingSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - unfoldingStarted).count();
  const TriangleMesh unfolded{plan.unfolded, target.triangles};
  std::printf(
      "unfolding (%.2f s): %zu folds, sharp left %.4f (%.2f%%), off sheet Hausdorff %.3f%%\n",
      unfoldingSeconds, plan.folds.size(), plan.sharpLengthLeft, 100 * plan.sharpLengthLeft / size,
      100 * surfaceDistance(unfolded, sheet, 5000).relativeHausdorff());
  std::printf("  forms read %zu, met %zu times; %zu unfoldings ended%s\n", plan.formsRead,
              plan.formsMet, plan.unfoldings, plan.cutShort ? " (cut short)" : "");
  for (const UnfoldedFold& u : plan.folds) {
    int fold = -1;
    for (std::size_t f = 0; f < design.folds.size(); ++f)
      if (samePlane(u.plane, design.folds[f].plane, size)) fold = int(f) + 1;
    int held = -1;
    for (std::size_t f = 0; f < seen.size(); ++f)
      if (samePlane(u.plane, seen[f], size)) held = int(f) + 1;
    std::printf("  read n=(%.3f %.3f %.3f) d=%.4f = fold %d, as held %d%s\n", u.plane.normal.x,
                u.plane.normal.y, u.plane.normal.z, glm::dot(u.plane.normal, u.plane.point), fold,
                held, u.wholeImage ? " (its image moved the whole sheet)" : "");
  }
  if (plan.sharpLengthLeft < 0.01 * size) {
    const auto registering = std::chrono::steady_clock::now();
    const std::optional<RigidMotion> motion = registerSheetOnto(sheet, unfolded, 1e-4 * size);
    std::printf(
        "rigid copy of the sheet (%.2f s): %s",
        std::chrono::duration<double>(std::chrono::steady_clock::now() - registering).count(),
        motion ? "yes" : "no");
    std::fflush(stdout);
    if (motion) {
      for (int r = 0; r < 3; ++r)
        std::printf("\n  [%.6f %.6f %.6f | %.6f]", motion->linear[0][r], motion->linear[1][r],
                    motion->linear[2][r], motion->offset[r]);
      std::printf("\n  det %.6f", glm::determinant(motion->linear));
    }
    if (motion)
      std::printf(", %zu whole-sheet folds",
                  wholeSheetReflections(*motion, initial.positions).size());
    // Every way the sheet lies on the copy (its symmetries), and the folds each takes.
    const auto started = std::chrono::steady_clock::now();
    const std::vector<RigidMotion> all = registerSheetOntoAll(sheet, unfolded, 1e-4 * size, 24);
    std::printf("\n  %zu ways (%.2f s), whole-sheet folds each (first):", all.size(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
    for (const RigidMotion& m : all)
      std::printf(" %zu", wholeSheetReflections(m, initial.positions).size());
    std::printf("\n");
    // Each way times each of the sheet's own symmetries (sheetSymmetries): the fewest planes by
    // kind, and how many such ways take one or two planes that miss the sheet.
    const std::vector<RigidMotion> symmetries = sheetSymmetries(sheet, 1e-4 * size);
    std::size_t byKind[5] = {0, 0, 0, 0, 0}, made[3] = {0, 0, 0};
    for (const RigidMotion& m : all)
      for (const RigidMotion& s : symmetries) {
        const RigidMotion way{m.linear * s.linear, m.linear * s.offset + m.offset};
        const std::size_t kind = fewestReflections(way, 1e-4, 1e-4 * size);
        ++byKind[std::min<std::size_t>(kind, 4)];
        if (kind >= 1 && kind <= 2 &&
            !wholeSheetReflections(snappedToFewPlanes(way, 1e-4, 1e-4 * size), initial.positions,
                                   kind)
                 .empty())
          ++made[kind];
      }
    std::printf(
        "  %zu symmetries of the sheet; ways times them by kind (0-4 planes): %zu %zu %zu "
        "%zu %zu; made by 1 plane: %zu, by 2: %zu\n",
        symmetries.size(), byKind[0], byKind[1], byKind[2], byKind[3], byKind[4], made[1], made[2]);
    // With one fold read made from its other side (the fit's flips): the motion left is then the
    // mirror through that plane after the way.
    std::size_t flippedKind[5] = {0, 0, 0, 0, 0};
    for (const RigidMotion& m : all)
      for (std::size_t s = 0; s <= symmetries.size(); ++s) {
        const RigidMotion way = s == symmetries.size() ? m : then(symmetries[s], m);
        for (const UnfoldedFold& u : plan.folds) {
          const RigidMotion left = then(way, reflectionOf(u.plane));
          ++flippedKind[std::min<std::size_t>(fewestReflections(left, 1e-4, 1e-4 * size), 4)];
        }
      }
    std::printf("  one fold read flipped, by kind (0-4 planes): %zu %zu %zu %zu %zu\n",
                flippedKind[0], flippedKind[1], flippedKind[2], flippedKind[3], flippedKind[4]);
    // Any set of folds read made from their other sides (the rest reflected in place of the
    // piece, read in unfolding order): the copy moves by those reflections, and the motion left
    // is that after the way. The fewest planes over every set, and the set.
    std::size_t fewest = 99, fewestSet = 0;
    const std::size_t n = plan.folds.size();
    for (std::size_t bits = 0; bits < (std::size_t(1) << n) && n <= 10; ++bits) {
      RigidMotion flips{glm::dmat3(1.0), glm::dvec3(0.0)};
      for (std::size_t u = 0; u < n; ++u) {  // unfolding order: the last fold read first
        if (!(bits >> u & 1)) continue;
        flips = then(reflectionOf(plan.folds[n - 1 - u].plane), flips);
      }
      for (const RigidMotion& m : all)
        for (std::size_t s = 0; s <= symmetries.size(); ++s) {
          const RigidMotion way = s == symmetries.size() ? m : then(symmetries[s], m);
          const RigidMotion left = then(way, flips);
          const std::size_t k = fewestReflections(left, 1e-4, 1e-4 * size);
          if (k < fewest) fewest = k, fewestSet = bits;
        }
    }
    std::printf("  any folds read flipped: fewest planes %zu, flipping (unfolding order) %zx\n",
                fewest, fewestSet);
  }
  return 0;
}

}  // namespace
}  // namespace curvefold

int main(int argc, char** argv) {
  try {
    return curvefold::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unfold_report: %s\n", e.what());
    return 1;
  }
}
