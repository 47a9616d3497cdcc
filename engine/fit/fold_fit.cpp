#include "engine/fit/fold_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <random>
#include <sstream>
#include <tuple>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <glm/geometric.hpp>
#include <glm/gtx/exterior_product.hpp>
#include <nanoflann.hpp>
#include <nlopt.hpp>

#include "engine/fit/crease_planes.hpp"
#include "engine/fit/floor_rings.hpp"
#include "engine/fit/lip_pleats.hpp"
#include "engine/fit/nested_rings.hpp"
#include "engine/fit/pleat_folds.hpp"
#include "engine/fit/profile_folds.hpp"
#include "engine/fit/replayed_motion.hpp"
#include "engine/fit/ring_folds.hpp"
#include "engine/fit/snapped_plane.hpp"
#include "engine/fit/start_surface.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/fit/target_unfolding.hpp"
#include "engine/fit/target_units.hpp"
#include "engine/fit/tuck_folds.hpp"
#include "engine/fit/unit_draw.hpp"
#include "engine/fit/whole_sheet_folds.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/surface_point.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/tolerances.hpp"
#include "engine/geometry/topology.hpp"

namespace curvefold {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Seeds tried on each side of a crease plane: parts the plane leaves apart are each a fold.
constexpr std::size_t kSeedsPerCreasePlane = 6;
// Crease planes mirrored through each other: of the best this many (at most n(n-1) more planes).
constexpr std::size_t kMirroredCreasePlanes = 6;
// How much farther a fold through a crease plane may leave the sheet and still be offered: the
// target's first fold, moved on by its later ones, can match little of it on its own.
constexpr double kCreaseSlack = 1.1;
// An unfolded target's folds that bring the sheet this close (Hausdorff, of the target's
// diagonal) end the fit.
constexpr double kUnfoldedCloseEnough = 1e-3;
// A sequence whose last fold brings the sheet this close (Hausdorff, of the diagonal) is kept
// whole, whatever its folds on the way (FitRun::measure).
constexpr double kKeptWhole = 1e-3;
// An unfolding that ends with less crease than this (of the diagonal) is smooth: a rigid copy of
// the sheet where folds that left no crease moved it whole.
constexpr double kSmoothLeft = 0.01;
// How close (of the diagonal) the sheet must lie on that copy, both ways, once moved onto it.
constexpr double kWholeSheetTolerance = 1e-4;
// Where no way lies within that: a sheet read from the unfolding lies on it only as near as the
// reading's polish (unfolded_sheet.cpp's kLiesOn, 1e-3 of the diagonal on average: a helix's
// ruling read 0.1 mm off on 353 mm), and an unfolding counted smooth may keep a short crease
// (0.6 mm on 300): the ways within this instead, the folds made on them measured as any.
constexpr double kLooseWholeSheetTolerance = 5e-3;
// At most this many ways the sheet lies on that copy are tried (a star of 7 points mirrored: 14).
constexpr std::size_t kMostRegistrations = 24;
// How far a replayed sheet may lie from the target, after the motion left, in target diagonals.
constexpr double kRestTolerance = 1e-3;
// How near (radians, and of the diagonal) a motion left is taken for one of one or two planes.
constexpr double kRestSnap = 1e-3;
// How near (radians, and of the diagonal) a registered way times a symmetry of the sheet is taken
// for a motion of fewer planes (registration carries the crease planes' errors, 1.6e-5 seen).
constexpr double kKindSnap = 1e-4;
// Ways so made (whole_sheet_folds.hpp: sheetSymmetries) offered, at most, beyond those registered.
constexpr std::size_t kMostSymmetricWays = 8;
// Whole-sheet folds made and measured, at most, before the unfolding gives way to the search.
constexpr std::size_t kWholeSheetTries = 6;
// Seeds spread over the sheet that the last fold read is made from, each its own images.
constexpr std::size_t kLastSeeds = 16;
// Folds read made from their other side, at most, where the whole-sheet folds take too many.
constexpr std::size_t kFlipTries = 8;
// Ways whose whole-sheet folds are placed among the folds read (each a replay to find where the
// sheet lies after each fold read), and placements made and measured.
constexpr std::size_t kPlacedWays = 12;
constexpr std::size_t kPlacedTries = 6;
// Ways whose motion starts the sheet placed (FitOptions::mayPlaceStart), at most: each a replay.
constexpr std::size_t kPlacedStartWays = 2;
// Seeds tried for a fold read on a symmetric design, beyond the one the unfolding names.
constexpr std::size_t kOtherSeeds = 12;
// Toward a smooth target, a fold kept leaves the exact Hausdorff distance at most this much above
// the start's or the fold before's (FitRun::measure).
constexpr double kHausdorffSlack = 1.1;
// A smooth target within this share of the sheet's area may be the sheet moved whole
// (FoldFitter::readsCreasesFrom): a catalogue sheet at another resolution differs by about 1%.
constexpr double kSameArea = 0.05;
// A fit within this much of the diagonal (Hausdorff) reaches the target.
constexpr double kReached = 0.01;
// Tucked corners (FitRun::tuckCorners) are kept where the farthest point comes in by this share,
// the Chamfer distance rising by no more than this one.
constexpr double kTuckGain = 0.03;
constexpr double kTuckChamferSlack = 0.01;
// The share of --time the search leaves them (suggestTucks and an exact measure a round): a
// grown square chosen for its tucked corners (first_step_start.hpp) and left untucked stands
// farther out than the sized one (saddle_disk at --time 60 under load: 14.5% Hausdorff when 8%
// left no time for them, against main's 8.28%).
constexpr double kTuckShare = 0.15;
constexpr int kTuckRounds = 8;
// Steps of tucks tried in turn in a round, where the exact measure refuses the first.
constexpr std::size_t kTuckTries = 3;
// A pleat that brings the sheet this much closer (the search's distance) stands for the step
// toward a smooth target that is no surface of revolution (FitRun::beamSearch).
constexpr double kPleatEnough = 0.05;
// Nearest-point queries of a score handed to one task (Target::score): a few tens of
// microseconds of work, well above a task's cost.
constexpr std::size_t kQueriesPerTask = 128;
// A suggestion's drags are first scored on every kCoarseStride-th sample (FoldFitter::suggest);
// the best kContendersPerFinalist times as many as are refined, with distinct planes and within
// kCoarseSlack of the sheet's distance, are then scored in full.
constexpr std::size_t kCoarseStride = 3;
constexpr std::size_t kContendersPerFinalist = 4;
constexpr double kCoarseSlack = 1.2;
// Of a finalist's refinement (refineFinalists), the share in percent scored coarsely first.
constexpr std::size_t kCoarseRefinement = 60;

struct PointCloud {
  std::vector<glm::dvec3> points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t axis) const { return points[i][int(axis)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>,
                                                   PointCloud, 3, std::uint32_t>;

std::uint32_t nearest(const KdTree& tree, const glm::dvec3& p) {
  const double query[3] = {p.x, p.y, p.z};
  std::uint32_t index = 0;
  double squared = 0.0;
  tree.knnSearch(query, 1, &index, &squared);
  return index;
}

// A nearest-point search that starts from a guess: only what lies closer than the guess is
// visited, and the guess comes back when nothing does. The result is the plain search's (up to
// a tie of distances, to the last bit); a guess near the answer prunes most of the tree.
struct CloserThanGuess {
  double squared;
  std::uint32_t index;
  std::size_t size() const { return 1; }
  bool full() const { return true; }
  bool addPoint(double distance, std::uint32_t i) {
    if (distance < squared) {
      squared = distance;
      index = i;
    }
    return true;
  }
  double worstDist() const { return squared; }
};

std::uint32_t nearestFrom(const KdTree& tree, const PointCloud& cloud, const glm::dvec3& p,
                          std::uint32_t guess) {
  const double query[3] = {p.x, p.y, p.z};
  // As the tree measures (L2_Simple_Adaptor: squared differences summed in axis order).
  double squared = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double d = query[axis] - cloud.points[guess][axis];
    squared += d * d;
  }
  CloserThanGuess result{squared, guess};
  tree.findNeighbors(result, query, nanoflann::SearchParams());
  return result.index;
}

// Distance from p to a surface that holds sample s (unit normal n), its samples about `radius`
// apart: the normal part in full, the tangent part only beyond the radius, so a point on the
// surface between samples is near zero.
double nearSurface(const glm::dvec3& p, const glm::dvec3& s, const glm::dvec3& n, double radius) {
  const glm::dvec3 d = p - s;
  const double normal = glm::dot(d, n);
  const double tangent = std::max(0.0, glm::length(d - normal * n) - radius);
  return std::sqrt(normal * normal + tangent * tangent);
}

// An index drawn with probability proportional to its weight (cumulative: running sums).
std::size_t draw(const std::vector<double>& cumulative, std::mt19937_64& random) {
  const double at = unit(random) * cumulative.back();
  return std::min<std::size_t>(
      std::upper_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin(),
      cumulative.size() - 1);
}

std::vector<double> cumulativeOf(const std::vector<double>& distances, double floor) {
  std::vector<double> cumulative(distances.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < distances.size(); ++i) {
    // Squared excess over the noise floor: the farthest points lead, and a sheet that already
    // fits still proposes something.
    const double excess = std::max(0.0, distances[i] - floor);
    sum += excess * excess + 1e-30;
    cumulative[i] = sum;
  }
  return cumulative;
}

// The sheet as the search reads it: samples made vertices, each with its normal.
struct EvaluationCopy {
  Sheet sheet;
  SheetAdjacency adjacency;
  double epsilon = 0.0;
  double size = 0.0;
  std::vector<VertexIndex> samples;
  std::vector<glm::dvec3> normals;
  double radius = 0.0;      // half the samples' spacing
  std::size_t dropped = 0;  // samples that could not be placed (FitResult::droppedSamples)
};

EvaluationCopy makeEvaluationCopy(const Sheet& sheet, std::size_t count, std::uint64_t seed) {
  // Area-uniform in the development is area-uniform on the surface (an isometry).
  TriangleMesh flat;
  flat.positions.reserve(sheet.vertexCount());
  for (const glm::dvec2& p : sheet.development) flat.positions.emplace_back(p.x, p.y, 0.0);
  flat.triangles = meshOf(sheet).triangles;
  const std::vector<SurfaceSample> samples = sampleSurface(flat, count, seed);
  EvaluationCopy copy;
  copy.sheet = sheet;
  copy.size = sheetSize(sheet);
  for (const SurfaceSample& sample : samples) {
    const Triangle& t = sheet.triangles[sample.triangle];
    const glm::dvec3 n = glm::cross(sheet.positions[t[1]] - sheet.positions[t[0]],
                                    sheet.positions[t[2]] - sheet.positions[t[0]]);
    try {
      const VertexIndex v =
          insertVertexInPlace(copy.sheet, glm::dvec2(sample.position), nullptr,
                              InsertionHints{copy.size, sample.triangle, nullptr});
      copy.samples.push_back(v);
      copy.normals.push_back(glm::normalize(n));
    } catch (const InvalidSheet&) {
      // A sample on the development's very edge that rounding puts outside: one fewer, counted.
      ++copy.dropped;
    }
  }
  copy.adjacency = buildAdjacency(copy.sheet);
  copy.epsilon = sheetEpsilon(copy.sheet);
  double area = 0.0;
  for (const Triangle& t : sheet.triangles) {
    const glm::dvec2 a = sheet.development[t[1]] - sheet.development[t[0]];
    const glm::dvec2 b = sheet.development[t[2]] - sheet.development[t[0]];
    area += 0.5 * std::abs(glm::cross(a, b));
  }
  copy.radius = 0.5 * std::sqrt(area / std::max<std::size_t>(1, copy.samples.size()));
  return copy;
}

// A drag of the search: a sample of the evaluation copy dropped at a point.
struct Drag {
  std::uint32_t sample = 0;
  glm::dvec3 drop{0.0};
  double score = kInfinity;
  // Through a plane of the target's creases: exact already, and left so (a refinement would
  // trade the part it lays exactly for a compromise across parts a later fold completes).
  bool crease = false;
};

// Where a score found each nearest point, as guesses for the next score (Target::score): each
// sheet sample's dense target point, each target query's sheet sample. The search's drags, a
// refinement's above all, move the sheet little from one score to the next.
struct NearestGuesses {
  std::vector<std::uint32_t> onTarget;
  std::vector<std::uint32_t> onSheet;
};

// One thread's scratch: the copy's folded form and the sheet samples' tree.
struct Worker {
  bool ready = false;  // `out` and `watch` are set up on the evaluation copy
  Sheet out;
  ReflectionWorkspace workspace;
  DragIntersectionWatch watch;  // a drag that passes the sheet through itself scores nothing
  Sheet withImages;             // a symmetric design's: `out` with the fold's images
  std::vector<TriangleIndex> reflected;
  PointCloud cloud;
  std::vector<glm::dvec3> normals;
  NearestGuesses guesses;  // the last drag's nearest points (Target::score)
};

bool samePlane(const ReflectionPlane& a, const ReflectionPlane& b, double size) {
  return glm::dot(a.normal, b.normal) > std::cos(5.0 * std::numbers::pi / 180.0) &&
         std::abs(glm::dot(a.point - b.point, a.normal)) < 0.02 * size;
}

// The best `count` of candidates sorted best first, then the best `count` of the rest that are
// through crease planes.
template <typename Candidate>
std::vector<Candidate> bestAndCrease(std::vector<Candidate> sorted, std::size_t count) {
  std::vector<Candidate> kept;
  std::size_t creases = 0;
  for (std::size_t i = 0; i < sorted.size(); ++i)
    if (i < count || (sorted[i].crease && creases++ < count)) kept.push_back(std::move(sorted[i]));
  return kept;
}

}  // namespace

// A sheet's samples and the nearest dense target point of each (Target::score).
struct KnownNearest {
  std::vector<glm::dvec3> points;
  std::vector<std::uint32_t> nearest;
};

struct FoldFitter::Target {
  TriangleMesh mesh;
  double diagonal = 0.0;
  glm::dvec3 centre{0.0};
  PointCloud dense;
  std::vector<glm::dvec3> denseNormals;
  double denseRadius = 0.0;
  std::vector<SurfaceSample> queries;
  std::unique_ptr<KdTree> tree;
  double robust = kInfinity;           // metres: where a distance stops counting in full
  std::optional<RevolutionAxis> axis;  // a surface of revolution's (profile_folds.hpp)
  bool smooth = false;                 // isSmoothOrScanned (start_surface.hpp)
  bool curved = false;                 // isCurved (start_surface.hpp)
  double area = 0.0;
  // Toward a smooth shape with no axis (a saddle), the target's side counted in full (score).
  bool coverInFull = false;
  // The exact measures' target (its tree: a tenth of a second at 100k triangles), made once.
  std::once_flag measuredOnce;
  std::unique_ptr<MeasuredSurface> measured;

  // What the search lowers, for sheet samples (points, normals, spaced 2 * radius): the mean
  // two-sided distance, each distance cut at `robust` and a tenth of it kept beyond, so a fold
  // that lays part of the sheet exactly onto the target counts for more than one that brings
  // all of it somewhat closer (the inlier count of RANSAC and robust ICP); each side's plain
  // distances when asked for. Toward a smooth shape with no axis (a saddle, which no sheet
  // reaches, so nothing lies on it exactly) the target's side is not cut: a rim the sheet leaves
  // uncovered costs its whole distance, as in the exact Chamfer distance that keeps a step, and a
  // pleat that turns an end over it scores as it measures (cut, a hypar's rim 5-10% of the
  // diagonal off the sheet cost little more than 1%, and no step toward it was kept).
  // Surfaces of revolution keep the cut: their rings and nested rings are tuned to it.
  //
  // known: the samples of the sheet before a fold and their nearest dense points; a sample the
  // fold left exactly in place has the same nearest point, so it is not searched again (the
  // score is the same, bit for bit). guesses: where the last score found the nearest points,
  // searched from (when of this score's sizes) and replaced by this score's (the same score).
  // stride: every stride-th sample of each side only (a coarse score, for ranking many drags;
  // the distances asked for are then left out).
  double score(const PointCloud& points, const std::vector<glm::dvec3>& normals, double radius,
               std::vector<double>* fromSheet = nullptr, std::vector<double>* fromTarget = nullptr,
               const KnownNearest* known = nullptr, NearestGuesses* guesses = nullptr,
               std::size_t stride = 1) const {
    if (points.points.empty()) return kInfinity;
    auto cost = [&](double d) { return std::min(d, robust) + 0.1 * d; };
    auto targetCost = [&](double d) { return coverInFull ? d : cost(d); };
    const std::size_t n = points.points.size();
    const std::size_t sheetCount = (n + stride - 1) / stride;
    const std::size_t targetCount = (queries.size() + stride - 1) / stride;
    if (stride != 1) fromSheet = fromTarget = nullptr;
    if (fromSheet) fromSheet->resize(n);
    const bool reuse = known && known->points.size() == n;
    const bool guessOnTarget = guesses && guesses->onTarget.size() == n;
    const bool guessOnSheet = guesses && guesses->onSheet.size() == queries.size();
    if (guesses) guesses->onTarget.resize(n);
    if (guesses) guesses->onSheet.resize(queries.size());
    // The nearest-point queries run on the idle cores (a suggestion refines fewer drags than
    // there are cores); each cost lands in its slot and the sums run in index order after, so
    // the score is the same bit for bit however the work was split. Isolated: a thread waiting
    // here takes no other drag, whose scratch (Worker) it may share.
    std::vector<double> costs(std::max(sheetCount, targetCount));
    tbb::this_task_arena::isolate([&] {
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(0, sheetCount, kQueriesPerTask), [&](const auto& r) {
            for (std::size_t m = r.begin(); m != r.end(); ++m) {
              const std::size_t i = m * stride;
              const std::uint32_t j =
                  reuse && known->points[i] == points.points[i] ? known->nearest[i]
                  : guessOnTarget
                      ? nearestFrom(*tree, dense, points.points[i], guesses->onTarget[i])
                      : nearest(*tree, points.points[i]);
              if (guesses) guesses->onTarget[i] = j;
              const double d =
                  nearSurface(points.points[i], dense.points[j], denseNormals[j], denseRadius);
              costs[m] = cost(d);
              if (fromSheet) (*fromSheet)[i] = d;
            }
          });
    });
    double sheetSum = 0.0, targetSum = 0.0;
    for (std::size_t m = 0; m < sheetCount; ++m) sheetSum += costs[m];
    const KdTree sheetTree(3, points, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    if (fromTarget) fromTarget->resize(queries.size());
    tbb::this_task_arena::isolate([&] {
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(0, targetCount, kQueriesPerTask), [&](const auto& r) {
            for (std::size_t m = r.begin(); m != r.end(); ++m) {
              const std::size_t k = m * stride;
              const std::uint32_t i =
                  guessOnSheet
                      ? nearestFrom(sheetTree, points, queries[k].position, guesses->onSheet[k])
                      : nearest(sheetTree, queries[k].position);
              if (guesses) guesses->onSheet[k] = i;
              const double d =
                  nearSurface(queries[k].position, points.points[i], normals[i], radius);
              costs[m] = targetCost(d);
              if (fromTarget) (*fromTarget)[k] = d;
            }
          });
    });
    for (std::size_t m = 0; m < targetCount; ++m) targetSum += costs[m];
    return 0.5 * (sheetSum / static_cast<double>(sheetCount) +
                  targetSum / static_cast<double>(targetCount));
  }
};

FoldFitter::FoldFitter(TriangleMesh target, const FitSettings& settings)
    : target_(std::make_unique<Target>()), settings_(settings) {
  Target& t = *target_;
  t.mesh = std::move(target);
  checkTarget(t.mesh);
  const double area = surfaceArea(t.mesh);
  t.diagonal = boundingDiagonal(t.mesh);
  glm::dvec3 low(kInfinity), high(-kInfinity);
  for (const auto& tri : t.mesh.triangles)
    for (std::uint32_t v : tri) {
      low = glm::min(low, t.mesh.positions[v]);
      high = glm::max(high, t.mesh.positions[v]);
    }
  t.centre = 0.5 * (low + high);
  for (const SurfaceSample& s : sampleSurface(t.mesh, settings.denseTargetSamples, settings.seed)) {
    t.dense.points.push_back(s.position);
    t.denseNormals.push_back(s.normal);
  }
  t.denseRadius = 0.5 * std::sqrt(area / static_cast<double>(t.dense.points.size()));
  t.queries = sampleSurface(t.mesh, settings.targetSamples, settings.seed + 1);
  t.tree = std::make_unique<KdTree>(3, t.dense, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  t.robust = settings.robustDistance * t.diagonal;
  // Rings and pleats are for shapes reflections do not reach; a folded tube is no vase.
  t.smooth = isSmoothOrScanned(t.mesh);
  t.curved = t.smooth && isCurved(t.mesh);
  t.area = area;
  // The axis decides the score too, with rings or without (the studio's one-drag offers).
  const std::optional<RevolutionAxis> axis =
      t.smooth ? revolutionAxis(t.queries) : std::optional<RevolutionAxis>();
  if (settings.rings > 0) t.axis = axis;
  t.coverInFull = t.smooth && !axis;
}

FoldFitter::~FoldFitter() = default;

const TriangleMesh& FoldFitter::target() const {
  return target_->mesh;
}

const MeasuredSurface& FoldFitter::measuredTarget() const {
  Target& t = *target_;
  std::call_once(t.measuredOnce,
                 [&] { t.measured = std::make_unique<MeasuredSurface>(t.mesh, "target"); });
  return *t.measured;
}

bool FoldFitter::smoothTarget() const {
  return target_->smooth;
}

bool FoldFitter::revolutionTarget() const {
  return target_->axis.has_value();
}

bool FoldFitter::readsCreasesFrom(const Sheet& initial) const {
  if (!settings_.useCreases) return false;
  const Target& t = *target_;
  if (!t.smooth) return true;
  const double sheetArea = surfaceArea(meshOf(initial));
  return !t.curved && std::abs(t.area - sheetArea) <= kSameArea * sheetArea;
}

double FoldFitter::targetDiagonal() const {
  return target_->diagonal;
}

void checkTarget(const TriangleMesh& target) {
  if (target.triangles.empty()) throw InvalidTarget("the target has no triangles");
  // Before its area: a vertex at 1e300 makes the area infinite, not zero.
  if (const std::optional<std::string> why = unmeasurableVertex(target))
    throw InvalidTarget("the target's " + *why);
  const double area = surfaceArea(target), diagonal = boundingDiagonal(target);
  if (!(area > 1e-12 * diagonal * diagonal) || !std::isfinite(area))
    throw InvalidTarget("the target is degenerate: its triangles have no area");
}

namespace {

// The centre of the bounding box of the vertices triangles use.
glm::dvec3 boxCentre(const TriangleMesh& mesh) {
  glm::dvec3 low(kInfinity), high(-kInfinity);
  for (const auto& tri : mesh.triangles)
    for (std::uint32_t v : tri) {
      low = glm::min(low, mesh.positions[v]);
      high = glm::max(high, mesh.positions[v]);
    }
  return 0.5 * (low + high);
}

}  // namespace

void checkTargetAgainst(const TriangleMesh& target, const Sheet& sheet) {
  const TriangleMesh mesh = meshOf(sheet);
  const double size = boundingDiagonal(mesh), targetSize = boundingDiagonal(target);
  const double apart = glm::distance(boxCentre(mesh), boxCentre(target));
  const double ratio = targetSize / size;
  std::ostringstream text;
  text.precision(3);
  if (!sameUnits(targetSize, size)) {
    text << "the target is " << ratio << " times the sheet's size (" << targetSize
         << " m across against " << size << " m): are its units metres?";
    throw InvalidTarget(text.str());
  }
  if (apart > 10.0 * std::max(size, targetSize)) {
    text << "the target lies " << apart << " m from the sheet (centre to centre), far beyond both ("
         << size << " m across): give it in the sheet's frame";
    throw InvalidTarget(text.str());
  }
}

void FoldFitter::checkAgainst(const Sheet& sheet) const {
  checkTargetAgainst(target_->mesh, sheet);
}

const std::vector<ReflectionPlane>& FoldFitter::creasePlanesAbove(double degrees) const {
  const std::lock_guard lock(creaseMutex_);
  auto [it, added] = creasePlanes_.try_emplace(degrees);
  if (added) {
    CreasePlaneOptions options;
    options.minDihedralDegrees = degrees;
    options.seed = settings_.seed;
    std::vector<ReflectionPlane>& planes = it->second;
    for (const CreasePlane& found : findCreasePlanes(target_->mesh, options))
      planes.push_back(found.plane);
    // A crease a later fold moved lies in the image of its fold's plane under that fold: each
    // plane mirrored through another names such a fold (of the best few, each once).
    const std::size_t found = std::min<std::size_t>(planes.size(), kMirroredCreasePlanes);
    for (std::size_t i = 0; i < found; ++i)
      for (std::size_t j = 0; j < found; ++j) {
        if (i == j) continue;
        const ReflectionPlane& mirror = planes[i];
        const glm::dvec3 n = planes[j].normal;
        const ReflectionPlane image{mirror.reflect(planes[j].point),
                                    n - 2.0 * glm::dot(n, mirror.normal) * mirror.normal};
        auto same = [&](const ReflectionPlane& p) {
          return std::abs(glm::dot(p.normal, image.normal)) >
                     std::cos(2.0 * std::numbers::pi / 180) &&
                 std::abs(p.signedDistance(image.point)) < 1e-3 * target_->diagonal;
        };
        if (std::none_of(planes.begin(), planes.end(), same)) planes.push_back(image);
      }
  }
  return it->second;
}

namespace {

// A sheet's samples as the search scores them: area-uniform points, their normals, and the radius
// each stands for.
struct ScoredSamples {
  PointCloud points;
  std::vector<glm::dvec3> normals;
  double radius = 0.0;
};

ScoredSamples scoredSamples(const Sheet& sheet, std::size_t count, std::uint64_t seed) {
  const TriangleMesh mesh = meshOf(sheet);
  const std::vector<SurfaceSample> samples = sampleSurface(mesh, count, seed);
  ScoredSamples out;
  for (const SurfaceSample& s : samples) {
    out.points.points.push_back(s.position);
    out.normals.push_back(s.normal);
  }
  out.radius = 0.5 * std::sqrt(surfaceArea(mesh) / std::max<std::size_t>(1, samples.size()));
  return out;
}

}  // namespace

double FoldFitter::approximateDistance(const Sheet& sheet) const {
  const ScoredSamples s = scoredSamples(sheet, settings_.sheetSamples, settings_.seed + 2);
  return target_->score(s.points, s.normals, s.radius);
}

SurfaceDistance FoldFitter::approximateMeasure(const Sheet& sheet) const {
  const ScoredSamples s = scoredSamples(sheet, settings_.sheetSamples, settings_.seed + 2);
  std::vector<double> fromSheet, fromTarget;
  target_->score(s.points, s.normals, s.radius, &fromSheet, &fromTarget);
  SurfaceDistance d;
  d.diagonal = target_->diagonal;
  if (fromSheet.empty() || fromTarget.empty()) return d;
  d.fromAMax = *std::max_element(fromSheet.begin(), fromSheet.end());
  d.fromBMax = *std::max_element(fromTarget.begin(), fromTarget.end());
  d.fromAMean = std::accumulate(fromSheet.begin(), fromSheet.end(), 0.0) /
                static_cast<double>(fromSheet.size());
  d.fromBMean = std::accumulate(fromTarget.begin(), fromTarget.end(), 0.0) /
                static_cast<double>(fromTarget.size());
  d.hausdorff = std::max(d.fromAMax, d.fromBMax);
  d.chamfer = 0.5 * (d.fromAMean + d.fromBMean);
  return d;
}

double FoldFitter::approximateDistance(const std::vector<glm::dvec3>& points,
                                       const std::vector<glm::dvec3>& normals,
                                       double radius) const {
  return target_->score(PointCloud{points}, normals, radius);
}

namespace {

// The best few drags with distinct planes: the best crease-plane drags first (a fold that lays
// one part exactly may score below one that brings all of it somewhat closer, and still be the
// one the next fold completes), then the best of all. The first `creaseDrags` are through crease
// planes; only drags scoring below `current` count (crease-plane ones: kCreaseSlack times it).
std::vector<Drag> chooseFinalists(const std::vector<Drag>& drags, std::size_t creaseDrags,
                                  double current, const EvaluationCopy& copy, std::size_t most) {
  std::vector<std::size_t> order(drags.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return drags[a].score < drags[b].score; });
  std::vector<Drag> finalists;
  std::vector<ReflectionPlane> finalistPlanes;
  auto choose = [&](std::size_t upTo, bool creaseOnly) {
    for (std::size_t i : order) {
      if (finalists.size() >= upTo) break;
      if (creaseOnly && i >= creaseDrags) continue;
      if (!(drags[i].score < (drags[i].crease ? kCreaseSlack : 1.0) * current)) continue;
      const ReflectionPlane plane =
          bisectorPlane(copy.sheet.positions[copy.samples[drags[i].sample]], drags[i].drop);
      if (std::any_of(finalistPlanes.begin(), finalistPlanes.end(),
                      [&](const auto& p) { return samePlane(p, plane, copy.size); }))
        continue;
      finalists.push_back(drags[i]);
      finalistPlanes.push_back(plane);
    }
  };
  choose(most / 2, true);
  choose(most, false);
  return finalists;
}

// Each drag's drop point refined by NLopt's Subplex (crease-plane drags are exact already, and
// left so), on all cores; the finalists come back best first. Coarse to fine: the first part of
// the evaluations scores every kCoarseStride-th sample, the rest score them all from the best
// drop the coarse part found (its scores are the full ones).
template <typename Evaluate>
void refineFinalists(std::vector<Drag>& finalists, tbb::enumerable_thread_specific<Worker>& workers,
                     const Evaluate& evaluate, const Deadline& deadline, const EvaluationCopy& copy,
                     std::size_t evaluations) {
  const std::size_t coarse = evaluations * kCoarseRefinement / 100;
  tbb::parallel_for(std::size_t(0), finalists.size(), [&](std::size_t k) {
    Worker& worker = workers.local();
    Drag& best = finalists[k];
    if (best.crease) return;
    const glm::dvec3 grab = copy.sheet.positions[copy.samples[best.sample]];
    const double initialStep = std::max(0.1 * glm::distance(grab, best.drop), 0.005 * copy.size);
    struct Objective {
      Drag* best;
      Worker* worker;
      const Deadline* deadline;
      const Evaluate* score;
      nlopt::opt* optimizer;
      std::size_t stride;
    };
    for (const auto& [stride, stageEvaluations] :
         {std::pair{kCoarseStride, coarse}, std::pair{std::size_t(1), evaluations - coarse}}) {
      if (stageEvaluations == 0) continue;
      // The scores of one stage compare with each other only.
      best.score = kInfinity;
      nlopt::opt optimizer(nlopt::LN_SBPLX, 3);
      Objective objective{&best, &worker, &deadline, &evaluate, &optimizer, stride};
      optimizer.set_min_objective(
          [](const std::vector<double>& x, std::vector<double>&, void* data) {
            auto& o = *static_cast<Objective*>(data);
            if (o.deadline->passed()) o.optimizer->force_stop();
            const glm::dvec3 drop(x[0], x[1], x[2]);
            const double score = (*o.score)(*o.worker, o.best->sample, drop, o.stride);
            if (score < o.best->score) {
              o.best->score = score;
              o.best->drop = drop;
            }
            return std::isfinite(score) ? score : 1e30;
          },
          &objective);
      optimizer.set_initial_step(initialStep);
      optimizer.set_maxeval(static_cast<int>(stageEvaluations));
      optimizer.set_xtol_abs(1e-6 * copy.size);
      std::vector<double> x{best.drop.x, best.drop.y, best.drop.z};
      double value = 0.0;
      try {
        optimizer.optimize(x, value);
      } catch (const nlopt::forced_stop&) {
        // The deadline: the best drag seen is kept. Out of memory and the rest go on up.
      } catch (const nlopt::roundoff_limited&) {
        // As close as rounding lets it get: the best drag seen is kept.
      }
    }
  });
  std::stable_sort(finalists.begin(), finalists.end(),
                   [](const Drag& a, const Drag& b) { return a.score < b.score; });
}

// Each drag made on the real sheet, as a designer's would be (a sliver refused, a symmetric
// design's images following), checked for self-intersection, scored again and taken back: the
// ones that bring the sheet closer.
std::vector<FoldSuggestion> makeSuggestions(FoldSession& session, const std::vector<Drag>& drags,
                                            const EvaluationCopy& copy, const FoldFitter& fitter,
                                            const Deadline& deadline) {
  const bool allowCrossing = fitter.settings().allowSelfIntersection;
  const double before = fitter.approximateDistance(session.fixed());
  std::size_t crossingsBefore = 0;
  if (!allowCrossing) crossingsBefore = findSelfIntersections(session.fixed()).intersections.size();
  std::vector<FoldSuggestion> suggestions;
  for (const Drag& drag : drags) {
    if (deadline.givesUp() || (deadline.passed() && !suggestions.empty())) break;
    const std::size_t foldsBefore = session.foldCount();
    session.beginDragAtDevelopment(copy.sheet.development[copy.samples[drag.sample]]);
    session.updateDrag(drag.drop);
    if (!session.commit()) continue;
    FoldSuggestion suggestion;
    suggestion.folds.assign(
        session.folds().begin() + static_cast<std::ptrdiff_t>(foldsBefore),
        session.folds().begin() + static_cast<std::ptrdiff_t>(session.foldCount()));
    const bool crosses =
        !allowCrossing &&
        findSelfIntersections(session.fixed()).intersections.size() > crossingsBefore;
    if (!crosses) {
      suggestion.crease = drag.crease;
      suggestion.sheet = session.fixed();
      suggestion.before = before;
      suggestion.after = fitter.approximateDistance(suggestion.sheet);
    }
    session.undo();
    if (crosses || !(suggestion.after < (drag.crease ? kCreaseSlack : 1.0) * before)) continue;
    suggestions.push_back(std::move(suggestion));
  }
  return suggestions;
}

// What folding the evaluation copy by a drag needs.
struct DragFolding {
  const EvaluationCopy& copy;
  const SymmetricFolder* symmetric;  // a symmetric design's, or null
  double minimumDrag = 0.0;
  bool allowCrossing = false;
};

// The copy folded by one drag in the worker's scratch, its samples and their normals left in
// worker.cloud and worker.normals (the copy itself restored); false when the drag folds nothing
// or, unless allowed, passes the sheet through itself.
bool foldCopy(const DragFolding& folding, Worker& worker, std::uint32_t sample,
              const glm::dvec3& drop) {
  const EvaluationCopy& copy = folding.copy;
  if (!worker.ready) {
    worker.out = copy.sheet;
    worker.workspace.clear();
    worker.ready = true;
    worker.cloud.points.resize(copy.samples.size());
    worker.normals.resize(copy.samples.size());
    if (!folding.allowCrossing) worker.watch.begin(copy.sheet);
  }
  const VertexIndex seed = copy.samples[sample];
  const glm::dvec3 grab = copy.sheet.positions[seed];
  if (!(glm::distance(grab, drop) > folding.minimumDrag)) return false;
  const ReflectionPlane plane = bisectorPlane(grab, drop);
  worker.workspace.apply(copy.sheet, copy.adjacency, seed, plane, copy.epsilon, worker.out);
  if (!folding.allowCrossing) {
    worker.watch.update(worker.out, worker.workspace.changes(), plane,
                        worker.workspace.reflectedTriangles(copy.adjacency));
    if (worker.watch.pairCount() > 0) {
      worker.workspace.restore(copy.sheet, worker.out);
      return false;
    }
  }
  // A symmetric design's fold brings its images (previewed on the copy as a display previews
  // them; a sample they move keeps its normal, near enough for the distance).
  const Sheet* folded = &worker.out;
  if (folding.symmetric) {
    worker.withImages = worker.out;
    FoldRecord fold;
    fold.seed = copy.sheet.development[seed];
    fold.plane = plane;
    fold.grabbed = grab;
    fold.target = drop;
    worker.reflected.clear();
    folding.symmetric->previewImages(copy.sheet, worker.withImages, fold, worker.reflected);
    folded = &worker.withImages;
  }
  for (std::size_t i = 0; i < copy.samples.size(); ++i) {
    const glm::dvec3& y = folded->positions[copy.samples[i]];
    glm::dvec3 n = copy.normals[i];
    if (worker.out.positions[copy.samples[i]] != copy.sheet.positions[copy.samples[i]])
      n -= 2.0 * glm::dot(n, plane.normal) * plane.normal;
    worker.cloud.points[i] = y;
    worker.normals[i] = n;
  }
  worker.workspace.restore(copy.sheet, worker.out);
  return true;
}

}  // namespace

bool FoldFitter::nestedRingsFrom(const Sheet& sheet) const {
  return target_->axis && settings_.nestedRings && liesFlatAcross(sheet, *target_->axis);
}

std::vector<FoldSuggestion> FoldFitter::suggestNestedRingsFirst(FoldSession& session,
                                                                std::size_t count,
                                                                const Deadline& deadline,
                                                                std::uint64_t step, bool& tried,
                                                                const TubeChains* handed) const {
  tried = false;
  const Target& target = *target_;
  if (count == 0 || !target.axis || !settings_.nestedRings) return {};
  std::mt19937_64 random(settings_.seed ^ (0xd1b54a32d192ed03ull * (step + 1)));
  // From a bare tube on the axis (a vase's cylinder), the rings solved together on the target's
  // profile (ring_folds.hpp) likewise come first; a symmetric design makes its own rings.
  if (!session.symmetricFolder() && tubeAbout(session.fixed(), target.axis->direction)) {
    session.cancel();
    return suggestTubeRings(session, *this, *target.axis, target.queries, count, deadline, random,
                            kTubeChainRings, handed);
  }
  if (!nestedRingsFrom(session.fixed())) return {};
  tried = true;
  session.cancel();
  return suggestNestedRings(session, *this, *target.axis, target.queries, count, deadline, random);
}

std::vector<FoldSuggestion> FoldFitter::suggest(FoldSession& session, std::size_t count,
                                                const Deadline& deadline, std::uint64_t step,
                                                bool nestedRings) const {
  session.cancel();
  if (count == 0) return {};
  const Target& target = *target_;
  if (deadline.givesUp()) return {};
  const EvaluationCopy copy = makeEvaluationCopy(session.fixed(), settings_.sheetSamples,
                                                 settings_.seed * 0x9e3779b97f4a7c15ull + step);
  deadline.countDroppedSamples(copy.dropped);
  if (copy.samples.empty() || deadline.givesUp()) return {};

  tbb::enumerable_thread_specific<Worker> workers;
  KnownNearest unfolded;  // the copy's samples before any fold (filled below, before any drag)
  NearestGuesses unfoldedGuesses;  // the same score's: each worker's first guesses
  const DragFolding folding{copy, session.symmetricFolder().get(), session.minimumDrag(),
                            settings_.allowSelfIntersection};
  // The copy folded by one drag, scored (infinity when the drag folds nothing).
  auto evaluate = [&](Worker& worker, std::uint32_t sample, const glm::dvec3& drop,
                      std::size_t stride = 1) {
    deadline.countEvaluation();
    if (!foldCopy(folding, worker, sample, drop)) return kInfinity;
    if (worker.guesses.onSheet.empty()) worker.guesses = unfoldedGuesses;
    return target.score(worker.cloud, worker.normals, copy.radius, nullptr, nullptr, &unfolded,
                        &worker.guesses, stride);
  };

  // Where the sheet and the target are apart now.
  std::vector<double> fromSheet, fromTarget;
  double current = 0.0;
  {
    PointCloud points;
    for (VertexIndex v : copy.samples) points.points.push_back(copy.sheet.positions[v]);
    current = target.score(points, copy.normals, copy.radius, &fromSheet, &fromTarget, nullptr,
                           &unfoldedGuesses);
    unfolded.points = std::move(points.points);
    unfolded.nearest = unfoldedGuesses.onTarget;
  }
  const double floor = 2.0 * std::max(copy.radius, target.denseRadius);
  const std::vector<double> grabWeights = cumulativeOf(fromSheet, floor);
  const std::vector<double> dropWeights = cumulativeOf(fromTarget, floor);

  // Proposals: the target's crease planes from samples on either side (the same plane folds
  // different parts from different sides), then drags from far sheet samples to far target points.
  std::mt19937_64 random(settings_.seed ^ (0xd1b54a32d192ed03ull * (step + 1)));
  std::vector<Drag> drags;
  const std::vector<ReflectionPlane> noPlanes;
  for (const ReflectionPlane& crease :
       readsCreasesFrom(session.initial())
           ? creasePlanesAbove(sharpEdgeThreshold(meshOf(session.initial())))
           : noPlanes) {
    for (const double side : {-1.0, 1.0}) {
      const ReflectionPlane plane{crease.point, side * crease.normal};
      std::vector<std::uint32_t> behind;
      for (std::uint32_t i = 0; i < copy.samples.size(); ++i)
        if (plane.signedDistance(copy.sheet.positions[copy.samples[i]]) < -0.01 * copy.size)
          behind.push_back(i);
      for (std::size_t k = 0; k < std::min<std::size_t>(kSeedsPerCreasePlane, behind.size()); ++k) {
        const std::uint32_t i = behind[static_cast<std::size_t>(unit(random) * behind.size())];
        drags.push_back({i, plane.reflect(copy.sheet.positions[copy.samples[i]]), kInfinity, true});
      }
    }
  }
  // Every other drag pulls its sample onto the nearest point of the target (a correspondence, as
  // in a step of ICP): small folds that bend the sheet toward a near target.
  for (std::size_t k = 0; k < settings_.proposals; ++k) {
    const auto sample = static_cast<std::uint32_t>(draw(grabWeights, random));
    const glm::dvec3& grab = copy.sheet.positions[copy.samples[sample]];
    drags.push_back({sample, k % 2 ? target.dense.points[nearest(*target.tree, grab)]
                                   : target.queries[draw(dropWeights, random)].position});
  }
  // Coarse to fine: every drag scored on a third of the samples, then the best few with distinct
  // planes (several times as many as are refined, and a little above the sheet's distance) scored
  // in full; the finalists are chosen on the full scores.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, drags.size(), 8), [&](const auto& range) {
    Worker& worker = workers.local();
    for (std::size_t i = range.begin(); i != range.end(); ++i)
      if (!deadline.passed())
        drags[i].score = evaluate(worker, drags[i].sample, drags[i].drop, kCoarseStride);
  });
  if (deadline.givesUp()) return {};  // the scores are partial: nothing to choose from
  const std::size_t creaseDrags = drags.size() - settings_.proposals;
  std::vector<Drag> contenders = chooseFinalists(drags, creaseDrags, kCoarseSlack * current, copy,
                                                 kContendersPerFinalist * settings_.refined);
  std::stable_partition(contenders.begin(), contenders.end(),
                        [](const Drag& d) { return d.crease; });
  const auto contendingCreases = static_cast<std::size_t>(
      std::count_if(contenders.begin(), contenders.end(), [](const Drag& d) { return d.crease; }));
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, contenders.size(), 1), [&](const auto& range) {
        Worker& worker = workers.local();
        for (std::size_t i = range.begin(); i != range.end(); ++i)
          if (!deadline.passed())
            contenders[i].score = evaluate(worker, contenders[i].sample, contenders[i].drop);
      });
  if (deadline.givesUp()) return {};

  // The best few with distinct planes, each refined, then made on the real sheet.
  std::vector<Drag> finalists =
      chooseFinalists(contenders, contendingCreases, current, copy, settings_.refined);
  refineFinalists(finalists, workers, evaluate, deadline, copy, settings_.refineEvaluations);
  std::vector<FoldSuggestion> suggestions =
      makeSuggestions(session, finalists, copy, *this, deadline);
  // About a surface of revolution's axis, rings of folds (a symmetric design's images are rings
  // of its own).
  if (target.axis && !folding.symmetric)
    for (FoldSuggestion& ring : suggestRings(session, *this, *target.axis, target.queries, count,
                                             settings_.rings, deadline, random))
      suggestions.push_back(std::move(ring));
  // From a flat sheet across that axis, nested rings fitted to its profile (nested_rings.hpp; on
  // a symmetric design whose rotation is about that axis, each ring is one fold and its images).
  if (target.axis && settings_.nestedRings && nestedRings)
    for (FoldSuggestion& rings :
         suggestNestedRings(session, *this, *target.axis, target.queries, count, deadline, random))
      suggestions.push_back(std::move(rings));
  std::stable_sort(suggestions.begin(), suggestions.end(),
                   [](const auto& a, const auto& b) { return a.after < b.after; });
  // Toward a cup's floor past a cone's open end, a ring that turns the band past it inward
  // (floor_rings.hpp): alone, and under the step's best as one step (a fit whose evaluations end
  // after one step keeps both).
  if (target.axis && !folding.symmetric) {
    std::vector<FoldSuggestion> floors =
        suggestFloorRing(session, *this, *target.axis, target.queries, deadline);
    if (!suggestions.empty())
      for (FoldSuggestion& closed : suggestFloorRing(session, *this, *target.axis, target.queries,
                                                     deadline, &suggestions.front()))
        floors.push_back(std::move(closed));
    if (!floors.empty()) {
      for (FoldSuggestion& floor : floors) suggestions.push_back(std::move(floor));
      std::stable_sort(suggestions.begin(), suggestions.end(),
                       [](const auto& a, const auto& b) { return a.after < b.after; });
    }
  }
  // Toward a flare standing out of a bare cone's wide end, pleats across the axis that step its
  // lip out (lip_pleats.hpp): rings only turn parts toward the axis.
  if (target.axis && !folding.symmetric) {
    std::vector<FoldSuggestion> lips =
        suggestLipPleats(session, *this, *target.axis, target.queries, deadline);
    if (!lips.empty()) {
      for (FoldSuggestion& lip : lips) suggestions.push_back(std::move(lip));
      std::stable_sort(suggestions.begin(), suggestions.end(),
                       [](const auto& a, const auto& b) { return a.after < b.after; });
    }
  }
  return bestAndCrease(std::move(suggestions), count);
}

namespace {

// The unfolding read with fold k made from the other side of its plane: the form after it is the
// same one mirrored through that plane, so every later fold's plane is mirrored too (its seed, a
// point of the development, names the same part).
TargetUnfolding flippedAt(TargetUnfolding plan, std::size_t k) {
  const RigidMotion mirror = reflectionOf(plan.folds[k].plane);
  for (std::size_t j = k + 1; j < plan.folds.size(); ++j) {
    ReflectionPlane& plane = plan.folds[j].plane;
    plane = {mirror(plane.point), mirror.linear * plane.normal};
  }
  return plan;
}

// A fold sequence of the beam, beyond the session's own folds.
struct FoldSequence {
  std::vector<FoldRecord> folds;
  std::vector<std::size_t> groups;  // folds per group (a fold and its images)
  double score = 0.0;               // the search's distance after it
  bool crease = false;              // its last fold is through a crease plane
  bool monotone = true;             // every fold brought the sheet closer (the search's distance)
};

// One fitFolds: the session it folds, the clock, and what it has measured.
class FitRun {
 public:
  // `readCreases`: try the target's unfolding first (off for the search toward a target the
  // unfolding left unfinished, which has been read).
  FitRun(FoldSession& session, const FoldFitter& fitter, const FitOptions& options,
         bool readCreases = true)
      : readCreases_(readCreases),
        session_(session),
        fitter_(fitter),
        options_(options),
        start_(options.started.value_or(std::chrono::steady_clock::now())),
        end_(endOf(start_, options.seconds)),
        base_(session.folds().begin(),
              session.folds().begin() + static_cast<std::ptrdiff_t>(session.foldCount())) {
    deadline_.cancelled = options.cancelled;
    deadline_.evaluations = &evaluations_;
    deadline_.droppedSamples = &droppedSamples_;
  }

  FitResult run() {
    measureSamples_ = samplesWithinTime();
    result_.steps.push_back(measureNow(0));
    // What one fold kept costs at the end (its exact measure and the caller's report of it):
    // about the start's measure, twice over (the report, and a sheet grown by folds).
    foldCost_ = 2.0 * result_.steps.back().seconds - 2.0 * startedAt_;
    FoldSequence root{{}, {}, fitter_.approximateDistance(session_.fixed())};
    best_ = bestMonotone_ = root;
    result_.stopReason = "reached the most folds asked for";
    // A bowl from a flat sheet (the nested rings' start) has no creases to read: on a scan the
    // unfolding reads its noise, and took the whole time; nor has a curved shape (a vase, a
    // saddle) or one of another area than the sheet (readsCreasesFrom).
    // The start is reported after the reading, which may place it (startPlaced).
    const bool read = readCreases_ && !fitter_.nestedRingsFrom(session_.fixed()) &&
                      fitter_.readsCreasesFrom(session_.initial()) && unfoldTarget();
    announceStart();
    if (read) {
      result_.stopReason = "the target unfolded: its creases named every fold";
      readingCut_ = false;  // what it read reached the target: no run finds more
    } else {
      beamSearch(root);
    }
    commitBest();
    if (!result_.cancelled) tuckCorners();
    result_.folds.assign(
        session_.folds().begin(),
        session_.folds().begin() + static_cast<std::ptrdiff_t>(session_.foldCount()));
    result_.evaluations = evaluations_.load();
    result_.droppedSamples = droppedSamples_.load();
    result_.readingSeconds = readingEndedAt_;
    if (result_.cancelled) result_.stopReason = "interrupted";
    // The clock ended the reading: another run may read more, and find other folds.
    if (readingCut_) result_.timedOut = true;
    return std::move(result_);
  }

 private:
  static std::chrono::steady_clock::time_point endOf(std::chrono::steady_clock::time_point start,
                                                     double seconds) {
    if (!(seconds < 1e9)) return std::chrono::steady_clock::time_point::max();  // no clock
    return start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                       std::chrono::duration<double>(std::max(0.0, seconds)));
  }

  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  // The search's deadline with `groups` folds to measure and report at the end: it stops early
  // enough for them (and 5% of the time for the rest), whatever the deadline says.
  // The final phase is estimated from the largest design the search has found (finalCost), for
  // as many groups as the sequence would have.
  Deadline searchDeadline(std::size_t groups) const {
    if (end_ == std::chrono::steady_clock::time_point::max()) return deadline_;
    const double final = std::max(
        foldCost_ * static_cast<double>(groups + 1),
        finalGroups_ == 0 ? 0.0
                          : finalCost_ * static_cast<double>(std::max(groups, finalGroups_)) /
                                static_cast<double>(finalGroups_));
    const double reserve =
        0.05 * options_.seconds + final + (tucksAtEnd() ? kTuckShare * options_.seconds : 0.0);
    return deadline_.notAfter(end_ -
                              std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                  std::chrono::duration<double>(reserve)));
  }

  // The reading's deadline (the unfolding, and the motion of the whole sheet): a share of the
  // search's time left, so that the search after it, from what it read, has the rest. A reading
  // within a reading (readPlain's) takes that share again of what the first left: the readings
  // take at most 84% of the search's time. A fresh share is worth more than the search's time: a
  // mirrored square of 5 folds, its reading with images cut at the end of its share, landed read
  // plain 2 s later (sym-mirror-5-8-00-square, bench/make_symmetric_targets.py --seed 8, --time
  // 20); with the readings held to one share together it ended 38% away.
  Deadline readingDeadline() const {
    const Deadline search = searchDeadline(1);
    const auto now = std::chrono::steady_clock::now();
    if (end_ == std::chrono::steady_clock::time_point::max() || search.at <= now) return search;
    return search.notAfter(now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                     kReadingShare * (search.at - now)));
  }

  // Whether the clock (or a cancel) cut the search short: said in the result.
  void noteCut(const Deadline& deadline) {
    if (deadline.isCancelled()) {
      result_.cancelled = true;
    } else {
      result_.timedOut = true;
      result_.stopReason = "reached the time limit";
    }
  }

  // The final phase of a design the search found, `groups` groups whose sheet took `replay`
  // seconds to fold and `check` to check for self-intersection: folded twice (measured, then
  // committed), and measured and reported group by group (an exact measure, whose samples do not
  // grow with the sheet, as the start's: foldCost_; the report's self-intersection check, which
  // does). The largest seen is kept for searchDeadline. On the example bowl's 65 rings' folds
  // (18,332 triangles) at a load of 25: folding 0.35 s, measuring 0.29 s, the report 0.08 s.
  void noteFinalCost(std::size_t groups, double replay, double check) {
    const double cost = 2.0 * replay + static_cast<double>(groups) * (foldCost_ + check);
    if (groups > 0 && cost > finalCost_) {
      finalCost_ = cost;
      finalGroups_ = groups;
    }
  }

  // The samples of every exact measure of this fit: all of distanceSamples, unless the start's
  // measure with them would take more than a tenth of the time left (a large or far target under
  // a short --time), judged by a measure of a few samples first; then as many as that tenth
  // allows. With no clock, always all, so a fit by evaluations repeats bit for bit.
  std::size_t samplesWithinTime() const {
    const std::size_t all = options_.distanceSamples;
    const std::size_t probe = std::min(all, kProbeSamples);
    if (end_ == std::chrono::steady_clock::time_point::max() || probe == all) return all;
    const auto before = std::chrono::steady_clock::now();
    surfaceDistance(meshOf(session_.fixed()), fitter_.measuredTarget(), probe);
    const auto after = std::chrono::steady_clock::now();
    const double cost = std::chrono::duration<double>(after - before).count();
    // A deadline already passed leaves no share (a negative count cast to size_t is undefined).
    const double share =
        kStartShare * std::max(0.0, std::chrono::duration<double>(end_ - after).count());
    // The probe's cost holds the sheet's tree and vertices, and at a fit's first measure the
    // target's tree and samples (made once, FoldFitter::measuredTarget), which fewer samples do
    // not cut: the estimate errs long.
    const double allowed = static_cast<double>(probe) * share / std::max(cost, 1e-9);
    if (allowed >= static_cast<double>(all)) return all;
    return std::max(probe, static_cast<std::size_t>(allowed));
  }

  // The exact measure of `sheet` (the session's, unless given) as the step after `folds` folds.
  // The start's progress (result_.steps.front()) said once, then the search lines held back
  // until it (the reading's offers come before the start is known: it may be placed).
  void announceStart() {
    if (startAnnounced_) return;
    startAnnounced_ = true;
    if (options_.progress) options_.progress(result_.steps.front());
    if (options_.searching)
      for (const auto& [depth, distance, at] : heldSearching_)
        options_.searching(depth, distance, at);
    heldSearching_.clear();
  }

  void reportSearching(std::size_t depth, double distance, double at) {
    if (!options_.searching) return;
    if (startAnnounced_)
      options_.searching(depth, distance, at);
    else
      heldSearching_.emplace_back(depth, distance, at);
  }

  FitProgress measureNow(std::size_t folds, const Sheet* sheet = nullptr) {
    if (folds == 0) startedAt_ = seconds();
    const SurfaceDistance d = surfaceDistance(meshOf(sheet ? *sheet : session_.fixed()),
                                              fitter_.measuredTarget(), measureSamples_);
    return FitProgress{folds, d.hausdorff, d.chamfer, d.diagonal, seconds()};
  }

  // A session of its own holding the session's folds and the sequence's.
  std::unique_ptr<FoldSession> sessionFor(const FoldSequence& sequence) const {
    auto branch = std::make_unique<FoldSession>(session_.initial());
    if (session_.symmetry()) branch->setSymmetry(*session_.symmetry());
    std::vector<FoldRecord> folds = base_;
    folds.insert(folds.end(), sequence.folds.begin(), sequence.folds.end());
    branch->applyRecords(folds);
    return branch;
  }

  // The folds the target's own creases name, read by unfolding it. A symmetric design's fold
  // brings its images, which the unfolding reads as folds of their own: a fold read whose plane
  // an image already made is skipped. True when they reach the target (a search could only
  // polish it).
  bool unfoldTarget() {
    if (!fitter_.settings().useCreases) return false;
    const Symmetry* symmetry = session_.symmetry();
    const std::size_t perFold = symmetry ? static_cast<std::size_t>(symmetry->order) : 1;
    // Room for one fold's measure after it (its own check and measure below); the folds it
    // names are measured within the time at the end, or not kept.
    const Deadline deadline = searchDeadline(1);
    const Deadline reading = readingDeadline();
    auto unfold = [&](bool withImages) {
      return curvefold::unfoldTarget(
          fitter_.target(), meshOf(session_.initial()),
          sharpEdgeThreshold(meshOf(session_.initial())),
          std::min(options_.maxFolds * perFold, std::max<std::size_t>(options_.maxFolds, 12)),
          reading, withImages && symmetry ? symmetry->images() : std::vector<Isometry>{});
    };
    // Each reading's end noted, for FitResult::readingSeconds.
    const auto unfoldNoted = [&](bool withImages) {
      TargetUnfolding read = unfold(withImages);
      readingEndedAt_ = std::max(readingEndedAt_, seconds());
      return read;
    };
    TargetUnfolding plan = unfoldNoted(true);
    FoldSequence planned;
    // The unfolding, its folds made and offered: true when they reach the target; false with
    // the cut noted when the deadline came first.
    bool cut = false;
    auto tryPlan = [&] {
      // Cut short by its share of the time, the unfolding still names the folds it read (as far
      // as it got): made, and searched on from, like those of an unfolding that stopped short.
      if (plan.cutShort) {
        if (deadline.passed()) {
          cut = true;
          return false;
        }
        readingCut_ = true;
      }
      const std::unique_ptr<FoldSession> branch = sessionFor({});
      planned = replay(plan, *branch, session_.initial(), deadline);
      if (deadline.passed()) {
        cut = true;
        return false;
      }
      return offer(planned, *branch);
    };
    if (tryPlan()) return true;
    // A fold whose image moved the whole sheet that does not reach the target (a fold's image
    // read as a fold of its own beside it): the unfolding read without images, as it was.
    if (!cut && !reading.passed() &&
        std::any_of(plan.folds.begin(), plan.folds.end(),
                    [](const UnfoldedFold& f) { return f.wholeImage.has_value(); })) {
      plan = unfoldNoted(false);
      if (tryPlan()) return true;
    }
    if (cut) {
      noteCut(deadline);
      return false;
    }
    // Where the unfolding stopped short of the sheet (a crease it could not read, or an
    // unfolding that ends off it), what it read is used still: the search folds the sheet
    // toward where the unfolding stopped, and the folds read follow.
    const TriangleMesh unfolded{plan.unfolded, fitter_.target().triangles};
    if (planned.groups.size() >= options_.maxFolds ||
        surfaceDistance(unfolded, meshOf(session_.initial()), measureSamples_)
                .relativeHausdorff() <= kUnfoldedCloseEnough)
      return readPlain();
    // Smooth but off the sheet: folds that left no crease (their planes missed the sheet) moved
    // it whole. That motion, as such folds, then the folds read.
    if (plan.sharpLengthLeft <= kSmoothLeft * fitter_.targetDiagonal() && base_.empty() &&
        foldWholeSheetFirst(plan, unfolded, reading, deadline))
      return true;
    if (deadline.passed()) return false;
    // Before the search from what was read: a symmetric design read as plain folds.
    if (readPlain()) return true;
    if (plan.folds.empty() || deadline.passed() || !searchUnfolded_) return false;
    return searchTowardUnfolded(plan, unfolded, planned.groups.size());
  }

  // A symmetric design whose reading with images did not reach the target (a fold or an image
  // moved the whole sheet, and the images of a whole-sheet fold made about the sheet's centre
  // reach none of its ways), read as a design without symmetry: its folds and their images each a
  // fold of its own, with the flips, the placed planes and (mayPlaceStart) the placed start that
  // only a plain design is offered. Without --symmetry such targets were read exactly (judge17).
  // Kept only where it reaches the target; the folds then have no group (FitResult::readPlain),
  // and a placed start leaves the session without its symmetry. True when it reaches.
  bool readPlain() {
    if (!session_.symmetry()) return false;
    const Deadline deadline = searchDeadline(1);
    if (deadline.passed()) return false;
    FoldSession plain(session_.initial());
    plain.applyRecords(base_);
    FitOptions options = options_;
    options.progress = nullptr;  // the outer run reports what it keeps
    options.started = start_;    // the outer run's clock: the search after it keeps its share
    // and what is left of its budget of evaluations: the reading scores none (measured: 0 on
    // judge17's symmetric targets read so), and were it to search, the two runs together would
    // still be held to one budget, as searchTowardUnfolded's inner run is.
    if (options_.maxEvaluations > 0)
      options.maxEvaluations = std::max<std::uint64_t>(
          1, options_.maxEvaluations - std::min(options_.maxEvaluations, evaluations_.load()));
    FitRun run(plain, fitter_, options);
    run.searchUnfolded_ = false;  // a search toward the unfolded copy is the outer run's
    run.measureSamples_ = measureSamples_;
    run.foldCost_ = foldCost_;
    run.finalCost_ = finalCost_;
    run.finalGroups_ = finalGroups_;
    run.best_ = run.bestMonotone_ =
        FoldSequence{{}, {}, fitter_.approximateDistance(session_.fixed())};
    const bool reached = run.unfoldTarget();
    evaluations_ += run.evaluations_.load();
    droppedSamples_ += run.droppedSamples_.load();
    if (run.result_.cancelled) result_.cancelled = true;
    if (run.readingCut_) readingCut_ = true;
    readingEndedAt_ = std::max(readingEndedAt_, run.readingEndedAt_);
    if (!reached) return false;
    if (run.result_.placedStart) {
      session_.restartFrom(*run.result_.placedStart);
      session_.applyRecords(base_);
      result_.placedStart = std::move(run.result_.placedStart);
      measurePlacedStart();
    }
    best_ = std::move(run.best_);
    result_.readPlain = true;
    return true;
  }

  // The rigid motion from the sheet to the smooth unfolded target, made as folds of the whole
  // sheet (whole_sheet_folds.hpp), then the unfolding's folds: true when that reaches the target.
  // Found within `reading` (the reading's share of the time), made within `deadline`.
  bool foldWholeSheetFirst(const TargetUnfolding& plan, const TriangleMesh& unfolded,
                           const Deadline& reading, const Deadline& deadline) {
    // Every way the sheet lies on the copy (a symmetric sheet's symmetries): each its own motion
    // and its own count of whole-sheet folds. The first way found first, and every way (dearer:
    // each registered) only where that one takes more folds than are left.
    // Within the deadline too: a copy that lies on the sheet no way refines every start (minutes).
    double wholeSheetTolerance = kWholeSheetTolerance * fitter_.targetDiagonal();
    std::vector<RigidMotion> motions =
        registerSheetOntoAll(meshOf(session_.initial()), unfolded, wholeSheetTolerance, 1, reading);
    // Only where folds were read: with none, the copy is the whole target, and a crease too
    // short to read (a star's 0.65 mm) is what the search must fold, not a way to lie.
    if (motions.empty() && !plan.folds.empty() && !reading.passed()) {
      wholeSheetTolerance = kLooseWholeSheetTolerance * fitter_.targetDiagonal();
      motions = registerSheetOntoAll(meshOf(session_.initial()), unfolded, wholeSheetTolerance, 1,
                                     reading);
    }
    if (motions.empty()) return false;
    // The whole-sheet folds first (on the sheet), or last (on the sheet folded by the folds read,
    // moved back by the motion): whichever takes fewer, as a plane that misses the sheet at one
    // time may cut it at the other; of every motion, the fewest.
    // Fewest planes first, over every motion: one plane is cheap to try, three a search.
    const Symmetry* symmetry = session_.symmetry();
    const double tolerance = kRestTolerance * fitter_.targetDiagonal();
    // The plan moved back by `motion` (onto the sheet).
    auto movedBackBy = [&](const RigidMotion& motion) {
      const RigidMotion back{glm::inverse(motion.linear),
                             -(glm::inverse(motion.linear) * motion.offset)};
      TargetUnfolding movedBack = plan;
      for (glm::dvec3& p : movedBack.unfolded) p = back(p);
      for (UnfoldedFold& fold : movedBack.folds)
        fold.plane = {back(fold.plane.point), glm::normalize(back.linear * fold.plane.normal)};
      return movedBack;
    };
    // Where the whole-sheet folds come last: the sheet folded by the folds read (moved back by
    // a motion), and the motion left to make on it.
    struct FoldedFirst {
      std::vector<glm::dvec3> positions;
      RigidMotion rest;
      TargetUnfolding movedBack;
      std::optional<glm::dvec2> lastSeed;  // the last fold read made from this seed
      std::optional<std::size_t> flip;     // this fold read made from its other side
    };
    auto foldedFirst = [&](const RigidMotion& motion, std::optional<glm::dvec2> lastSeed,
                           std::optional<std::size_t> flip =
                               std::nullopt) -> std::optional<FoldedFirst> {
      TargetUnfolding movedBack = movedBackBy(motion);
      // Fold `flip` made from its other side leaves the form mirrored through its plane, and the
      // later folds with it: the motion left takes that mirror first (one plane more or less).
      RigidMotion left = motion;
      if (flip) {
        const RigidMotion mirror = reflectionOf(movedBack.folds[*flip].plane);
        left = {motion.linear * mirror.linear, motion.linear * mirror.offset + motion.offset};
        movedBack = flippedAt(std::move(movedBack), *flip);
      }
      const std::unique_ptr<FoldSession> lastBranch = sessionFor({});
      bool everyFoldRead = false;
      replay(movedBack, *lastBranch, session_.initial(), reading, options_.maxFolds, &everyFoldRead,
             lastSeed, flip);
      if (!everyFoldRead) return std::nullopt;
      if (!symmetry)
        return FoldedFirst{lastBranch->fixed().positions, left, std::move(movedBack), lastSeed,
                           flip};
      // A symmetric fold's image may have moved the whole sheet (its plane missed it), and the
      // replay brings it again: what is left to move is measured, not the copy's motion.
      std::vector<ReflectionPlane> read;
      for (const UnfoldedFold& fold : movedBack.folds) read.push_back(fold.plane);
      const std::optional<RigidMotion> rest =
          restOntoTarget(session_.initial(), lastBranch->fixed(), movedBack.unfolded,
                         fitter_.target(), read, tolerance);
      if (!rest) return std::nullopt;
      // Measured, it is about 1e-6 off: made exactly what one or two planes make where it lies
      // that near (the sequence made is measured before it is kept).
      return FoldedFirst{lastBranch->fixed().positions,
                         snappedToFewPlanes(*rest, kRestSnap, kRestSnap * fitter_.targetDiagonal()),
                         std::move(movedBack), lastSeed, std::nullopt};
    };
    // Each way's options: the replay itself, and (symmetric) the same folds moved by a symmetry
    // of the sheet where that leaves fewer whole-sheet folds to make (replayed_motion.hpp).
    // A seed that makes a form other than the target's leaves no motion (restOntoTarget).
    auto optionsFor = [&](const RigidMotion& motion) {
      std::vector<FoldedFirst> options;
      // The last fold read made from its own seed, then from seeds spread over the sheet: a
      // symmetric fold brings the images of its seed it does not move itself, and one whose
      // image moved the sheet whole is made again only from a seed whose images do the same
      // (the images, and the side the fold moves, make what is left to move).
      std::vector<std::optional<glm::dvec2>> seeds{std::nullopt};
      if (symmetry && !plan.folds.empty()) {
        const Sheet& initial = session_.initial();
        const std::size_t stride = 1 + initial.vertexCount() / kLastSeeds;
        for (VertexIndex v = stride / 2; v < initial.vertexCount(); v += stride)
          seeds.push_back(initial.development[v]);
      }
      for (const std::optional<glm::dvec2>& seed : seeds) {
        if (reading.passed()) break;
        std::optional<FoldedFirst> first = foldedFirst(motion, seed);
        if (!first) continue;
        const RigidMotion rest = first->rest;
        options.push_back(std::move(*first));
        if (!symmetry) continue;
        for (const FewerPlaneRest& fewer :
             fewerPlaneRests(rest, symmetry->centre, symmetry->images())) {
          if (reading.passed()) break;
          if (!isSymmetryOf(fewer.symmetry, session_.initial(), tolerance)) continue;
          const RigidMotion& s = fewer.symmetry;
          const glm::dmat3 sBack = glm::transpose(s.linear);
          // T s^-1: the folds read moved by s (the seed with them).
          const RigidMotion moved{motion.linear * sBack,
                                  motion.offset - motion.linear * (sBack * s.offset)};
          std::optional<glm::dvec2> movedSeed;
          const Sheet& initial = session_.initial();
          if (seed) {
            const std::optional<SurfacePoint> at =
                locateDevelopmentPoint(initial, *seed, 1e-6 * sheetSize(initial));
            if (!at) continue;
            movedSeed =
                developmentOf(initial, closestSurfacePoint(initial, s(positionOf(initial, *at))));
          }
          if (std::optional<FoldedFirst> other = foldedFirst(moved, movedSeed))
            options.push_back(std::move(*other));
        }
      }
      return options;
    };
    std::vector<std::optional<std::vector<FoldedFirst>>> lastAt(motions.size());
    // A symmetric design's fold brings its images, read as folds of their own: the folds read
    // take at least one group per `perFold` of them (the sequence is counted once made, below).
    const std::size_t perFold =
        session_.symmetry() ? static_cast<std::size_t>(session_.symmetry()->order) : 1;
    const std::size_t readGroups = (plan.folds.size() + perFold - 1) / perFold;
    const std::size_t most = std::min<std::size_t>(
        5, options_.maxFolds > readGroups ? options_.maxFolds - readGroups : 0);
    // Per way: whether its motion was made within the planes left (first or last). Such a way
    // missed for another reason than its count, which the flips below do not mend.
    std::vector<char> withinCount(motions.size(), 0);
    auto noted = [&](std::vector<ReflectionPlane> planes, std::size_t way) {
      if (!planes.empty() && planes.size() <= most) withinCount[way] = 1;
      return planes;
    };
    // Each way found is made and measured: one that does not reach (a symmetric design's images
    // made about the centre a first whole-sheet fold moved) leaves the next its turn.
    std::size_t tries = 0;
    auto tryPlanes = [&](const std::vector<ReflectionPlane>& planes, bool atEnd,
                         const TargetUnfolding& read, std::optional<glm::dvec2> lastSeed,
                         std::optional<std::size_t> flip = std::nullopt) {
      if (planes.empty() || planes.size() + readGroups > options_.maxFolds) return false;
      ++tries;
      return makeWholeSheetFolds(planes, atEnd, plan, read, lastSeed, deadline, flip);
    };
    // A design without symmetry whose whole-sheet folds came between its creasing folds: read
    // with every whole-sheet fold last, the motion may take more planes than are left (a turn
    // and a shift along its axis, four). Each fold read made from its other side mirrors the
    // motion through its plane, which then takes one plane fewer or more: each fold flipped in
    // turn, its motion made last with the fewest planes that allow.
    std::size_t flipTries = 0;
    auto tryFlips = [&](const RigidMotion& motion) {
      if (symmetry || plan.folds.empty()) return false;
      for (std::size_t k = 0; k < plan.folds.size() && flipTries < kFlipTries; ++k) {
        if (reading.passed() || deadline.passed()) return false;
        const std::optional<FoldedFirst> option = foldedFirst(motion, std::nullopt, k);
        if (!option) continue;
        for (std::size_t count = 1; count <= most; ++count) {
          const std::vector<ReflectionPlane> planes =
              wholeSheetReflections(option->rest, option->positions, count);
          if (planes.empty()) continue;
          ++flipTries;
          if (tryPlanes(planes, true, option->movedBack, std::nullopt, option->flip)) return true;
          break;
        }
      }
      return false;
    };
    // A design without symmetry whose whole-sheet folds came between its creasing folds
    // (C C W C C W C C) where no plane of its motion misses the sheet first or last (a turn about
    // a line through both): the motion's planes placed among the folds read, each where it
    // misses the sheet as it lies then (placedWholeSheetReflections), the fewest planes first.
    std::size_t placedWays = 0, placedTries = 0;
    auto tryPlaced = [&](const RigidMotion& motion) {
      if (symmetry || plan.folds.empty() || placedWays >= kPlacedWays ||
          placedTries >= kPlacedTries || reading.passed() || deadline.passed())
        return false;
      ++placedWays;
      const TargetUnfolding movedBack = movedBackBy(motion);
      std::vector<std::vector<glm::dvec3>> stages;
      if (!stagesOf(movedBack, stages, reading)) return false;
      for (std::size_t count = 1; count <= most; ++count) {
        if (reading.passed()) return false;
        const std::vector<PlacedPlane> placed = placedWholeSheetReflections(motion, stages, count);
        if (placed.empty()) continue;
        ++placedTries;
        return makePlacedFolds(placed, movedBack, deadline);
      }
      return false;
    };
    // A sheet with discrete symmetries (a disk's polygon's turns and flips) lies on the copy each
    // way registered times each of them, and registration's starts reach only some: those whose
    // kind takes fewer whole-sheet folds than the way itself, and no more than are left, are
    // offered too, the fewest first (the design's own way, whose folds the design made, is one of
    // them). A design's own symmetry reads its images instead (optionsFor).
    auto withSymmetricWays = [&](const std::vector<RigidMotion>& ways) {
      const double shift = kKindSnap * fitter_.targetDiagonal();
      auto planesFor = [&](const RigidMotion& m) { return fewestReflections(m, kKindSnap, shift); };
      std::vector<std::pair<std::size_t, RigidMotion>> kept;
      for (const RigidMotion& way : ways) kept.emplace_back(planesFor(way), way);
      auto seen = [&](const RigidMotion& m) {
        return std::any_of(kept.begin(), kept.end(), [&](const auto& k) {
          double linear = 0.0;
          for (int c = 0; c < 3; ++c)
            linear = std::max(linear, glm::length(k.second.linear[c] - m.linear[c]));
          return linear < kKindSnap && glm::distance(k.second.offset, m.offset) < shift;
        });
      };
      const std::vector<RigidMotion> symmetries = sheetSymmetries(
          meshOf(session_.initial()), kWholeSheetTolerance * fitter_.targetDiagonal());
      std::size_t added = 0;
      for (std::size_t w = 0; w < ways.size() && added < kMostSymmetricWays; ++w) {
        const std::size_t own = planesFor(ways[w]);
        for (const RigidMotion& s : symmetries) {
          if (added >= kMostSymmetricWays || reading.passed()) break;
          // x -> way(s(x)): the sheet moved onto itself, then onto the copy.
          const RigidMotion moved{ways[w].linear * s.linear,
                                  ways[w].linear * s.offset + ways[w].offset};
          const std::size_t planes = planesFor(moved);
          if (planes >= own || planes > most) continue;
          const RigidMotion snapped = snappedToFewPlanes(moved, kKindSnap, shift);
          if (seen(snapped)) continue;
          kept.emplace_back(planes, snapped);
          ++added;
        }
      }
      std::stable_sort(kept.begin(), kept.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
      std::vector<RigidMotion> all;
      for (const auto& k : kept) all.push_back(k.second);
      return all;
    };
    for (int pass = 0; pass < 2 && tries < kWholeSheetTries; ++pass) {
      if (pass == 1) {
        if (reading.passed()) return false;
        motions = registerSheetOntoAll(meshOf(session_.initial()), unfolded, wholeSheetTolerance,
                                       kMostRegistrations, reading);
        if (!symmetry) motions = withSymmetricWays(motions);
        lastAt.assign(motions.size(), std::nullopt);
        withinCount.assign(motions.size(), 0);
      }
      // Each count tried on the sheet for every motion, then on the sheet folded by the folds read
      // (a replay, dearer) for every motion.
      // A symmetric design lies on its copy only the ways its symmetry keeps (its folds read
      // onto their images): the first way found, if not one of them, takes more planes, and
      // those folds make images the target lacks. Every way then, past one plane.
      // With no fold read (the whole target a moved copy), any way is right: whole-sheet folds
      // move their grabs' images too and bring none.
      // Where they come last (a symmetric design's), what is left is measured on the replayed
      // sheet, which has the target's form: any count, then.
      const std::size_t upTo = pass == 0 && session_.symmetry() && !plan.folds.empty()
                                   ? std::min<std::size_t>(most, 1)
                                   : most;
      for (std::size_t count = 1; count <= most && tries < kWholeSheetTries; ++count)
        for (std::size_t k = 0; k < 2 * motions.size() && tries < kWholeSheetTries; ++k) {
          if (reading.passed() || deadline.passed()) return false;
          // A symmetric design's images are made about the sheet's own centre and axis, which
          // a whole-sheet fold made first moves: last for it, then.
          const bool last = (k >= motions.size()) != (session_.symmetry() != nullptr);
          const RigidMotion& motion = motions[k % motions.size()];
          if (!last) {
            if (count > upTo) continue;
            if (tryPlanes(noted(wholeSheetReflections(motion, session_.initial().positions, count),
                                k % motions.size()),
                          false, plan, std::nullopt))
              return true;
            continue;
          }
          std::optional<std::vector<FoldedFirst>>& options = lastAt[k % motions.size()];
          if (!options) options = optionsFor(motion);  // replays, once per motion
          for (const FoldedFirst& option : *options)
            if (tryPlanes(noted(wholeSheetReflections(option.rest, option.positions, count),
                                k % motions.size()),
                          true, option.movedBack, option.lastSeed))
              return true;
        }
      for (std::size_t way = 0; way < motions.size(); ++way)
        if (!withinCount[way] && tryFlips(motions[way])) return true;
      for (std::size_t way = 0; way < motions.size(); ++way)
        if (!withinCount[way] && tryPlaced(motions[way])) return true;
    }
    // No way made within the folds left: where the start may be placed, the sheet moved whole
    // by the motion instead, and only the folds read.
    if (options_.mayPlaceStart && !symmetry && !reading.passed())
      for (std::size_t way = 0; way < std::min(motions.size(), kPlacedStartWays); ++way)
        if (!withinCount[way] && startPlaced(motions[way], plan, deadline)) return true;
    return false;
  }

  // The start is the placed sheet: its distance is the one reported and folds must beat (the
  // time of the start's measure kept: what a measure costs, FitProgress::seconds). A run inside
  // another (readPlain) has measured no start: the outer run measures its own.
  void measurePlacedStart() {
    if (result_.steps.empty()) return;
    const double at = startedAt_;
    const FitProgress placedMeasure = measureNow(0);
    startedAt_ = at;
    result_.steps.front().hausdorff = placedMeasure.hausdorff;
    result_.steps.front().chamfer = placedMeasure.chamfer;
  }

  // The session's initial sheet moved by `motion` (onto the unfolded target) as the start, and
  // the folds read made on it: kept, with the session holding the moved sheet as its initial
  // one, only when that reaches the target; else the session and the best found are as before.
  bool startPlaced(const RigidMotion& motion, const TargetUnfolding& plan,
                   const Deadline& deadline) {
    if (deadline.passed()) return false;
    Sheet placed = session_.initial();
    for (glm::dvec3& p : placed.positions) p = motion(p);
    Sheet before = session_.initial();
    const FoldSequence bestBefore = best_;
    session_.restartFrom(placed);
    const std::unique_ptr<FoldSession> branch = sessionFor({});
    const FoldSequence made = replay(plan, *branch, session_.initial(), deadline);
    if (!deadline.passed() && made.groups.size() <= options_.maxFolds && offer(made, *branch)) {
      result_.placedStart = std::move(placed);
      measurePlacedStart();
      return true;
    }
    session_.restartFrom(std::move(before));
    best_ = bestBefore;
    return false;
  }

  // The sheet after each of the first k folds of `read` (moved back onto the sheet), k = 0 to
  // all of them: where the whole-sheet folds may go (placedWholeSheetReflections). False where a
  // fold read cannot be made or the deadline passes.
  bool stagesOf(const TargetUnfolding& read, std::vector<std::vector<glm::dvec3>>& stages,
                const Deadline& deadline) const {
    const std::unique_ptr<FoldSession> branch = sessionFor({});
    const Sheet& initial = session_.initial();
    stages.assign(1, branch->fixed().positions);
    for (std::size_t k = 0; k < read.folds.size(); ++k) {
      if (deadline.passed()) return false;
      const glm::dvec2 seed = developmentOf(
          initial, closestSurfacePoint(initial, read.unfolded[read.folds[k].seedVertex]));
      if (!makeRead(read, k, seed, *branch)) return false;
      stages.push_back(branch->fixed().positions);
    }
    return true;
  }

  // The folds read (`read`, moved back onto the sheet) with the whole-sheet folds `planes` made
  // among them where placed: each fold read after a whole-sheet fold made moved by it (its plane
  // reflected through the plane, its seed the same point of the development), so the form ends
  // moved by all of them. True when that reaches the target.
  bool makePlacedFolds(const std::vector<PlacedPlane>& planes, const TargetUnfolding& read,
                       const Deadline& deadline) {
    const std::unique_ptr<FoldSession> branch = sessionFor({});
    const Sheet& initial = session_.initial();
    TargetUnfolding moved = read;
    FoldSequence sequence;
    RigidMotion made;
    auto noteGroup = [&](std::size_t before) {
      sequence.folds.insert(
          sequence.folds.end(), branch->folds().begin() + static_cast<std::ptrdiff_t>(before),
          branch->folds().begin() + static_cast<std::ptrdiff_t>(branch->foldCount()));
      sequence.groups.push_back(branch->foldCount() - before);
    };
    std::size_t next = 0;
    for (std::size_t k = 0; k <= read.folds.size(); ++k) {
      for (; next < planes.size() && planes[next].after == k; ++next) {
        const std::size_t before = branch->foldCount();
        const glm::dvec3 grabbed = branch->beginDragAtDevelopment(branch->fixed().development[0]);
        branch->updateDrag(planes[next].plane.reflect(grabbed));
        if (!branch->commit()) return false;
        noteGroup(before);
        made = then(made, reflectionOf(planes[next].plane));
      }
      if (k == read.folds.size()) break;
      if (deadline.passed() || sequence.groups.size() >= options_.maxFolds) return false;
      const ReflectionPlane& was = read.folds[k].plane;
      moved.folds[k].plane = {made(was.point), glm::normalize(made.linear * was.normal)};
      const glm::dvec2 seed = developmentOf(
          initial, closestSurfacePoint(initial, read.unfolded[read.folds[k].seedVertex]));
      const std::size_t before = branch->foldCount();
      if (!makeRead(moved, k, seed, *branch)) return false;
      noteGroup(before);
    }
    if (sequence.groups.size() > options_.maxFolds) return false;
    return offer(std::move(sequence), *branch);
  }

  // The whole-sheet folds `planes` and the folds read (`read`, moved back onto the sheet where the
  // planes come last, its last fold from `lastSeed` where given), made and offered: true when
  // they reach.
  bool makeWholeSheetFolds(const std::vector<ReflectionPlane>& planes, bool atEnd,
                           const TargetUnfolding& plan, const TargetUnfolding& read,
                           std::optional<glm::dvec2> lastSeed, const Deadline& deadline,
                           std::optional<std::size_t> flip = std::nullopt) {
    const std::unique_ptr<FoldSession> branch = sessionFor({});
    FoldSequence sequence;
    if (atEnd) {
      const FoldSequence made =
          replay(read, *branch, session_.initial(), deadline, 0, nullptr, lastSeed, flip);
      sequence.folds = made.folds;
      sequence.groups = made.groups;
    }
    for (const ReflectionPlane& plane : planes) {
      const std::size_t before = branch->foldCount();
      const glm::dvec3 grabbed = branch->beginDragAtDevelopment(branch->fixed().development[0]);
      branch->updateDrag(plane.reflect(grabbed));
      if (!branch->commit()) return false;
      sequence.folds.insert(
          sequence.folds.end(), branch->folds().begin() + static_cast<std::ptrdiff_t>(before),
          branch->folds().begin() + static_cast<std::ptrdiff_t>(branch->foldCount()));
      sequence.groups.push_back(branch->foldCount() - before);
    }
    if (!atEnd) {
      const Sheet reached = branch->fixed();
      const FoldSequence made =
          replay(plan, *branch, reached, deadline, options_.maxFolds - sequence.groups.size());
      sequence.folds.insert(sequence.folds.end(), made.folds.begin(), made.folds.end());
      sequence.groups.insert(sequence.groups.end(), made.groups.begin(), made.groups.end());
    }
    if (sequence.groups.size() > options_.maxFolds) return false;
    return offer(std::move(sequence), *branch);
  }

  // The unfolding's folds made on `branch` (the session's folds and maybe more), each seeded at
  // the development point under where the unfolding lays its seed on `seedsOn` (the sheet the
  // unfolded target lies on, as `branch` holds it now): a point in 3D may name two (a slit's
  // sides, layers a flat fold laid together); the development names one. A symmetric design's
  // fold brings its images, which the unfolding reads as folds of their own: a fold read whose
  // plane an image already made is skipped. `everyFoldRead`, when given: whether every fold read
  // was made (or an image made it), none left for a failure, the deadline or `most`.
  // `flip`, when given: that fold is made from the other side of its plane (the part the read
  // fold kept moves instead), which leaves the form one reflection through that plane away
  // (flippedAt, where the later planes are moved to match).
  FoldSequence replay(const TargetUnfolding& plan, FoldSession& branch, const Sheet& seedsOn,
                      const Deadline& deadline, std::size_t most = 0, bool* everyFoldRead = nullptr,
                      std::optional<glm::dvec2> lastSeed = std::nullopt,
                      std::optional<std::size_t> flip = std::nullopt) const {
    if (most == 0) most = options_.maxFolds;
    const Symmetry* symmetry = session_.symmetry();
    const double size = sheetSize(session_.initial());
    const std::size_t first = branch.foldCount();
    auto madeAlready = [&](const ReflectionPlane& plane) {
      for (std::size_t f = first; f < branch.foldCount(); ++f) {
        const ReflectionPlane& made = branch.folds()[f].plane;
        if (std::abs(glm::dot(made.normal, plane.normal)) >
                std::cos(0.5 * std::numbers::pi / 180.0) &&
            std::abs(made.signedDistance(plane.point)) < 1e-4 * size)
          return true;
      }
      return false;
    };
    std::vector<glm::dvec2> seeds;
    for (const UnfoldedFold& fold : plan.folds)
      seeds.push_back(
          developmentOf(seedsOn, closestSurfacePoint(seedsOn, plan.unfolded[fold.seedVertex])));
    FoldSequence planned;
    if (everyFoldRead) *everyFoldRead = false;
    for (std::size_t k = 0; k < plan.folds.size(); ++k) {
      if (symmetry && madeAlready(plan.folds[k].plane)) continue;
      if (planned.groups.size() >= most || deadline.passed()) return planned;
      const std::size_t before = branch.foldCount();
      const bool seedGiven = lastSeed && k + 1 == plan.folds.size();
      if (flip && *flip == k) {
        const std::optional<glm::dvec2> other = otherSide(plan.folds[k].plane, seeds[k], branch);
        if (!other || !makeRead(plan, k, *other, branch, true)) return planned;
      } else if (!makeRead(plan, k, seedGiven ? *lastSeed : seeds[k], branch, seedGiven)) {
        return planned;
      }
      planned.folds.insert(
          planned.folds.end(), branch.folds().begin() + static_cast<std::ptrdiff_t>(before),
          branch.folds().begin() + static_cast<std::ptrdiff_t>(branch.foldCount()));
      planned.groups.push_back(branch.foldCount() - before);
    }
    if (everyFoldRead) *everyFoldRead = true;
    return planned;
  }

  // A seed on the other side of `plane` from `seed` as `branch` lies now: the development point
  // of the vertex farthest from the plane there (deep in the part the fold kept).
  static std::optional<glm::dvec2> otherSide(const ReflectionPlane& plane, const glm::dvec2& seed,
                                             const FoldSession& branch) {
    const Sheet& sheet = branch.fixed();
    const std::optional<SurfacePoint> at =
        locateDevelopmentPoint(sheet, seed, 1e-6 * sheetSize(sheet));
    if (!at) return std::nullopt;
    const double side = plane.signedDistance(positionOf(sheet, *at));
    std::optional<VertexIndex> farthest;
    double most = 0.0;
    for (VertexIndex v = 0; v < sheet.vertexCount(); ++v) {
      const double d = -side * plane.signedDistance(sheet.positions[v]);
      if (d > most) {
        most = d;
        farthest = v;
      }
    }
    if (!farthest) return std::nullopt;
    return sheet.development[*farthest];
  }

  // The unfolding's fold k made on `branch` from `seed`. A symmetric design's fold brings the
  // images of its seed that it does not move itself, so the seed the unfolding names may bring
  // images the target lacks (its designer grabbed elsewhere, and the fold moved the images of
  // that grab): then other seeds on the same side of the plane, nearest the symmetry's centre
  // first (their images the likeliest moved too), until every image made is a fold read.
  bool makeRead(const TargetUnfolding& plan, std::size_t k, const glm::dvec2& seed,
                FoldSession& branch, bool seedGiven = false) const {
    const ReflectionPlane& plane = plan.folds[k].plane;
    const std::size_t before = branch.foldCount();
    const Symmetry* symmetry = session_.symmetry();
    const double size = sheetSize(session_.initial());
    auto imagesRead = [&] {
      for (std::size_t f = before + 1; f < branch.foldCount(); ++f) {
        const ReflectionPlane& image = branch.folds()[f].plane;
        auto same = [&](const ReflectionPlane& p) {
          return std::abs(glm::dot(p.normal, image.normal)) >
                     std::cos(0.5 * std::numbers::pi / 180.0) &&
                 std::abs(p.signedDistance(image.point)) < 1e-3 * size;
        };
        // A fold read, or the image the unfolding found had moved the whole sheet.
        const bool read =
            std::any_of(plan.folds.begin(), plan.folds.end(), [&](const UnfoldedFold& fold) {
              return same(fold.plane) || (fold.wholeImage && same(*fold.wholeImage));
            });
        if (!read) return false;
      }
      return true;
    };
    const Sheet sheet = branch.fixed();  // before the fold
    double side = 0.0;                   // where the seed lies, of the plane
    double thinnest = 0.0;               // the last fold's thinnest cut piece
    ReflectionPlane made = plan.folds[k].plane;
    auto make = [&](const glm::dvec2& at) {
      const glm::dvec3 grabbed = branch.beginDragAtDevelopment(at);
      if (side == 0.0) side = made.signedDistance(grabbed);
      thinnest = branch.updateDrag(made.reflect(grabbed)).thinnestCut;
      return branch.commit();
    };
    const bool madeAsRead = make(seed);
    // Refused, or made with a piece thinner than a cut may leave (reflection.hpp's plane shift
    // can pass through one vertex, not two the read plane passes by a hair on either side): the
    // fold that made the crease passed through them, and a sliver left here is what a later
    // fold's cut pushes below the floor (the most-moved cone's fourth fold). The plane moved
    // through the vertices it all but meets, kept where that cuts cleaner.
    if (!madeAsRead || thinnest < kRelativeCutFeatureSize * size) {
      const std::optional<ReflectionPlane> snapped = planeThroughNearPoints(
          made, sheet.positions, kRelativeGrabSnap * size, size, 0.1 * kRelativeEpsilon * size);
      if (!snapped) return madeAsRead;
      const double thinnestAsRead = madeAsRead ? thinnest : -1.0;
      if (madeAsRead) branch.undo();
      const ReflectionPlane read = made;
      made = *snapped;
      if (!make(seed)) {
        if (!madeAsRead) return false;
        made = read;
        if (!make(seed)) return false;
      } else if (thinnest <= thinnestAsRead) {
        branch.undo();
        made = read;
        if (!make(seed)) return false;
      }
    }
    if (!symmetry || seedGiven || imagesRead()) return true;
    branch.undo();
    const Sheet& initial = session_.initial();
    std::vector<std::pair<double, VertexIndex>> others;
    for (VertexIndex v = 0; v < std::min(initial.vertexCount(), sheet.vertexCount()); ++v) {
      const double d = plane.signedDistance(sheet.positions[v]);
      if (d * side > 0.0 && std::abs(d) > 0.005 * size)
        others.emplace_back(glm::distance(initial.positions[v], symmetry->centre), v);
    }
    std::sort(others.begin(), others.end());
    for (std::size_t t = 0; t < kOtherSeeds && !others.empty(); ++t) {
      const VertexIndex v = others[t * others.size() / kOtherSeeds].second;
      if (!make(sheet.development[v])) continue;
      if (imagesRead()) return true;
      branch.undo();
    }
    return make(seed);  // the seed read, images and all: the search may mend it
  }

  // A sequence found outside the beam, made on `branch`: kept as the best when it is (and passes
  // nothing through itself unless allowed). True when it reaches the target.
  bool offer(FoldSequence sequence, const FoldSession& branch) {
    const bool crosses = !fitter_.settings().allowSelfIntersection &&
                         !findSelfIntersections(branch.fixed()).intersections.empty();
    if (sequence.groups.empty() || crosses) return false;
    sequence.score = fitter_.approximateDistance(branch.fixed());
    const bool better = sequence.score < best_.score;
    if (better) best_ = sequence;
    // Said only when it is the best so far: the line says "best".
    if (better && options_.searching)
      reportSearching(sequence.groups.size(), fitter_.approximateMeasure(branch.fixed()).chamfer,
                      seconds());
    return better &&
           surfaceDistance(meshOf(branch.fixed()), fitter_.measuredTarget(), measureSamples_)
                   .relativeHausdorff() <= kUnfoldedCloseEnough;
  }

  // The folds the unfolding did not read, searched for toward the target as far as it unfolded
  // (with half the time left), then the folds it read; true when that reaches the target.
  bool searchTowardUnfolded(const TargetUnfolding& plan, const TriangleMesh& unfolded,
                            std::size_t groupsRead) {
    std::unique_ptr<FoldFitter> toward;
    try {
      toward = std::make_unique<FoldFitter>(unfolded, fitter_.settings());
    } catch (const InvalidTarget&) {
      return false;
    }
    const std::unique_ptr<FoldSession> branch = sessionFor({});
    FitOptions inner;
    inner.maxFolds = options_.maxFolds - groupsRead;
    inner.minimumGain = options_.minimumGain;
    inner.distanceSamples = measureSamples_;
    inner.cancelled = options_.cancelled;
    inner.pleats = 0;  // toward a sheet unfolded from reflections: single folds make it
    // Half of what is left of each budget: the clock's (less the reserve for measuring at the
    // end) and the evaluations', so a fit with a count repeats bit for bit.
    const Deadline deadline = searchDeadline(groupsRead + 1);
    if (deadline.passed()) return false;
    if (end_ != std::chrono::steady_clock::time_point::max()) {
      inner.seconds =
          0.5 *
          std::chrono::duration<double>(deadline.at - std::chrono::steady_clock::now()).count();
      if (!(inner.seconds > 0.05)) return false;
    } else {
      inner.seconds = std::numeric_limits<double>::infinity();
    }
    if (options_.maxEvaluations > 0) {
      const std::uint64_t used = evaluations_.load();
      if (used >= options_.maxEvaluations) return false;
      inner.maxEvaluations = std::max<std::uint64_t>(1, (options_.maxEvaluations - used) / 2);
    }
    const FitResult innerResult = FitRun(*branch, *toward, inner, false).run();
    evaluations_ += innerResult.evaluations;
    droppedSamples_ += innerResult.droppedSamples;
    if (innerResult.cancelled) result_.cancelled = true;
    FoldSequence sequence;
    sequence.folds.assign(
        branch->folds().begin() + static_cast<std::ptrdiff_t>(base_.size()),
        branch->folds().begin() + static_cast<std::ptrdiff_t>(branch->foldCount()));
    for (std::size_t f = 0; f < sequence.folds.size(); ++f) {
      // A symmetric group: consecutive folds of one group number.
      if (f > 0 && sequence.folds[f].group != 0 &&
          sequence.folds[f].group == sequence.folds[f - 1].group)
        ++sequence.groups.back();
      else
        sequence.groups.push_back(1);
    }
    const Sheet reached = branch->fixed();
    const FoldSequence read = replay(plan, *branch, reached, deadline);
    sequence.folds.insert(sequence.folds.end(), read.folds.begin(), read.folds.end());
    sequence.groups.insert(sequence.groups.end(), read.groups.begin(), read.groups.end());
    return offer(std::move(sequence), *branch);
  }

  // A beam over fold sequences: each kept sequence grown by its best few next folds, the best few
  // sequences (and the best few ending on a crease plane) kept at each depth.
  // What the reading found (best_, when it is more than the start) grows beside the start: a
  // search after a reading that fell short goes on from it rather than from the sheet alone.
  void beamSearch(const FoldSequence& root) {
    std::vector<FoldSequence> beam{root};
    if (!best_.groups.empty() && best_.groups.size() < options_.maxFolds) {
      beam.push_back(best_);
      beam.back().monotone = false;  // not measured fold by fold
    }
    if (result_.timedOut || result_.cancelled) return;  // the unfolding took the time
    for (std::size_t depth = 0; depth < options_.maxFolds; ++depth) {
      std::vector<FoldSequence> children;
      const Deadline deadline = searchDeadline(depth + 1);
      bool outOfEvaluations = false;
      for (std::size_t k = 0; k < beam.size() && !deadline.passed(); ++k) {
        if (beam[k].groups.size() >= options_.maxFolds) continue;  // grown as far as allowed
        // The budget is checked only here, between steps, where the count is the same on every
        // run (each step scores the same candidates).
        if (options_.maxEvaluations > 0 && evaluations_.load() >= options_.maxEvaluations) {
          outOfEvaluations = true;
          break;
        }
        const std::unique_ptr<FoldSession> branch = sessionFor(beam[k]);
        // Pleats (pleat_folds.hpp): two folds as one step, the first of which alone no search
        // of single folds keeps. Only toward a smooth shape (or a scan): a target folded by
        // reflections is made by single folds, and pleats cost time. A coarse smooth grid's bends
        // may pass for shallow creases the unfolding reads; it still gets pleats. Toward a
        // smooth shape that is no surface of revolution (a saddle), where a pleat brings the
        // sheet closer by kPleatEnough, the single folds' search (tens of times dearer, and on a
        // saddle seldom better) is left out of the step, so the clock leaves room for more.
        // From a flat sheet across a bowl's axis, the nested rings first: where they bring it
        // closer they are the step, and the clock is not spent on single folds before them.
        bool ringsTried = false;
        std::vector<FoldSuggestion> nexts = fitter_.suggestNestedRingsFirst(
            *branch, options_.branching, deadline, 16 * (depth + 1) + k, ringsTried,
            options_.tubeChains.get());
        if (nexts.empty()) {
          std::vector<FoldSuggestion> pleats =
              suggestPleats(*branch, fitter_, fitter_.smoothTarget() ? options_.pleats : 0,
                            deadline, 16 * (depth + 1) + k);
          const bool pleatEnough = !pleats.empty() && !fitter_.revolutionTarget() &&
                                   pleats.front().after < (1.0 - kPleatEnough) * beam[k].score;
          if (!pleatEnough)
            nexts = fitter_.suggest(*branch, options_.branching, deadline, 16 * (depth + 1) + k,
                                    !ringsTried);
          for (FoldSuggestion& pleat : pleats) nexts.push_back(std::move(pleat));
        }
        for (FoldSuggestion& next : nexts) {
          FoldSequence child = beam[k];
          child.folds.insert(child.folds.end(), next.folds.begin(), next.folds.end());
          child.groups.push_back(next.folds.size());
          child.score = next.after;
          child.crease = next.crease;
          child.monotone = beam[k].monotone && next.after < beam[k].score;
          children.push_back(std::move(child));
        }
      }
      if (outOfEvaluations) {
        // A depth the budget cut short is dropped whole, as one the clock cuts.
        result_.outOfEvaluations = true;
        result_.stopReason = "used the evaluations allowed";
        return;
      }
      if (deadline.passed()) {
        // A depth the deadline cut short is dropped whole: what is kept does not depend on speed.
        // Except the first, when nothing else would be kept: a step made whole before the clock
        // ran out (the nested rings answer with the batches they finished, coarsest first) is
        // kept rather than no fold at all on a loaded machine.
        if (depth == 0 && best_.groups.empty() && !deadline.isCancelled())
          for (const FoldSequence& child : children) {
            if (child.score < best_.score) best_ = child;
            if (child.monotone && child.score < bestMonotone_.score) bestMonotone_ = child;
          }
        noteCut(deadline);
        return;
      }
      if (children.empty()) {
        result_.stopReason = "no fold found brings the sheet closer";
        return;
      }
      std::stable_sort(children.begin(), children.end(),
                       [](const auto& a, const auto& b) { return a.score < b.score; });
      beam = bestAndCrease(std::move(children), options_.beamWidth);
      if (beam.size() > options_.beamWidth + options_.creaseWidth)
        beam.resize(options_.beamWidth + options_.creaseWidth);
      if (beam.front().score < best_.score) best_ = beam.front();
      for (const FoldSequence& sequence : beam)
        if (sequence.monotone && sequence.score < bestMonotone_.score) bestMonotone_ = sequence;
      // The front folded again, timed: what the final phase will fold (twice) and measure.
      const double replayStart = seconds();
      const std::unique_ptr<FoldSession> front = sessionFor(beam.front());
      const double checkStart = seconds();
      findSelfIntersections(front->fixed());
      noteFinalCost(beam.front().groups.size(), checkStart - replayStart, seconds() - checkStart);
      // Reported as the Chamfer distance the search's samples measure: the score it ranks by cuts
      // far distances, so it is no distance (a sheet 25 mm off scores 4 mm).
      if (options_.searching)
        reportSearching(depth + 1, fitter_.approximateMeasure(front->fixed()).chamfer, seconds());
    }
  }

  // A sequence measured exactly after each fold, and how many of its folds to keep.
  struct Measured {
    std::vector<FitProgress> steps;
    std::vector<double> costs;  // seconds each group took to fold and measure
    std::size_t keep = 0;
  };

  // Whether `seconds` more of work end after the fit's time (never without a clock).
  bool overruns(double seconds) const {
    return end_ != std::chrono::steady_clock::time_point::max() &&
           std::chrono::steady_clock::now() +
                   std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                       std::chrono::duration<double>(seconds)) >
               end_;
  }

  // Up to where the sequence comes closest, less any last folds that gain under minimumGain each
  // (a fold on the way may gain little itself, or lose, and still be what the next one needs);
  // `strict`: only while every fold gains.
  Measured measure(const FoldSequence& sequence, bool strict) {
    Measured m;
    // On a session of its own: the fit's keeps its folds, with no undo to fold them again (an
    // undo replays up to a keyframe's worth of folds, once per fold: ~230 for 65 rings' folds).
    const std::unique_ptr<FoldSession> trialSession = sessionFor({});
    FoldSession& trial = *trialSession;
    double spent = 0.0;  // by the groups measured, which committing them costs again
    for (std::size_t g = 0, first = 0; g < sequence.groups.size(); first += sequence.groups[g++]) {
      // Within the time: this group's fold and measure, then committing and reporting it and
      // every group before it (about what each took here). A group is judged by the one before
      // it (a sheet grows by its folds: half again). A fold not measured is not kept. The first
      // is always measured: the search left time for it (finalCost), and on a machine so loaded
      // that the estimate falls short, the fit still answers what it found (dropping it left a
      // loaded bowl at --time 30 with no fold).
      if (g > 0 && overruns(spent + 3.0 * m.costs.back())) {
        result_.timedOut = true;
        result_.stopReason = "reached the time limit";
        break;
      }
      const double t0 = seconds();
      trial.applyRecords(
          {sequence.folds.begin() + static_cast<std::ptrdiff_t>(first),
           sequence.folds.begin() + static_cast<std::ptrdiff_t>(first + sequence.groups[g])});
      m.steps.push_back(measureNow(g + 1, &trial.fixed()));
      m.costs.push_back(seconds() - t0);
      spent += m.costs.back();
    }
    auto before = [&](std::size_t g) {
      return (g > 0 ? m.steps[g - 1] : result_.steps.front()).chamfer;
    };
    // Toward a smooth shape the search's robust distance may lay a flap near the target and
    // leave an end uncovered: a fold there gains only while the farthest point stays within
    // kHausdorffSlack of where the start or the fold before left it.
    auto bounded = [&](std::size_t g) {
      if (!fitter_.smoothTarget()) return true;
      const double start = result_.steps.front().hausdorff;
      return m.steps[g].hausdorff <=
             kHausdorffSlack * std::max(start, g > 0 ? m.steps[g - 1].hausdorff : start);
    };
    // A fold that brings the farthest point within reach (1% of the diagonal) from beyond it
    // gains, however little the Chamfer distance falls: a small flap read last moves a sliver of
    // the area, not of the shape.
    auto reaches = [&](std::size_t g) {
      const FitProgress& previous = g > 0 ? m.steps[g - 1] : result_.steps.front();
      return m.steps[g].hausdorff <= kReached * m.steps[g].diagonal &&
             previous.hausdorff > kReached * previous.diagonal;
    };
    auto gains = [&](std::size_t g) {  // whether group g (from 0) brings the sheet closer enough
      return (m.steps[g].chamfer < (1.0 - options_.minimumGain) * before(g) &&
              before(g) - m.steps[g].chamfer > options_.minimumAbsoluteGain * m.steps[g].diagonal &&
              bounded(g)) ||
             reaches(g);
    };
    // A sequence that reaches the target is kept whole: folds of the whole sheet (a target with
    // no crease left, which reads as smooth) may each move it farther before the last lays it on.
    if (!strict && !m.steps.empty() && m.steps.size() == sequence.groups.size() &&
        m.steps.back().hausdorff <= kKeptWhole * m.steps.back().diagonal) {
      m.keep = m.steps.size();
      return m;
    }
    if (strict) {
      while (m.keep < m.steps.size() && gains(m.keep)) ++m.keep;
    } else {
      for (std::size_t g = 0; g < m.steps.size() && bounded(g); ++g)
        if (m.steps[g].chamfer < before(m.keep)) m.keep = g + 1;
      while (m.keep > 0 && !gains(m.keep - 1)) --m.keep;
    }
    return m;
  }

  // The best sequence found, committed; where it does not reach the target (1% of the diagonal)
  // and a fold on its way brought the sheet no closer, the best sequence whose every fold does
  // instead: on a shape no sequence reaches, every fold kept brings the sheet closer.
  void commitBest() {
    const FoldSequence* chosen = &best_;
    Measured measured = measure(best_, false);
    const bool reaches =
        measured.keep > 0 && measured.steps[measured.keep - 1].hausdorff <=
                                 kReached * measured.steps[measured.keep - 1].diagonal;
    bool falls = true;
    for (std::size_t g = 0; g < measured.keep; ++g)
      falls = falls && measured.steps[g].chamfer <
                           (g > 0 ? measured.steps[g - 1] : result_.steps.front()).chamfer;
    if (!reaches && !falls) {
      Measured monotone = measure(bestMonotone_, true);
      // Toward a target folded by reflections (not smooth) the distance is the goal: a sequence
      // read off its creases that moves the sheet whole on the way (farther first) and ends
      // nearer, both ways, than every fold of the monotone one stays (a cone read 41.3% -> 15.3%
      // in 5 folds, where the monotone best kept none).
      const FitProgress& start = result_.steps.front();
      const FitProgress& end = measured.keep > 0 ? measured.steps[measured.keep - 1] : start;
      const FitProgress& monotoneEnd =
          monotone.keep > 0 ? monotone.steps[monotone.keep - 1] : start;
      const bool nearer = !fitter_.smoothTarget() && measured.keep > 0 &&
                          end.hausdorff < monotoneEnd.hausdorff &&
                          end.chamfer < monotoneEnd.chamfer;
      if (!nearer) {
        chosen = &bestMonotone_;
        measured = std::move(monotone);
      }
    }
    // A clock that cut the search is the reason it stopped, though the folds it found last gain
    // little too (a run under load said otherwise while saying the time limit cut it short).
    if (measured.keep < measured.steps.size() && !result_.timedOut)
      result_.stopReason = "the next fold found brings the sheet closer by less than " +
                           std::to_string(int(std::round(options_.minimumGain * 100))) + "%";
    for (std::size_t g = 0, first = 0; g < measured.keep; first += chosen->groups[g++]) {
      // The commit and report of a group cost about its fold and measure: one past the first
      // that would end past the time is not kept (measure judged it by an estimate).
      if (g > 0 && overruns(measured.costs[g])) {
        result_.timedOut = true;
        result_.stopReason = "reached the time limit";
        break;
      }
      session_.applyRecords(
          {chosen->folds.begin() + static_cast<std::ptrdiff_t>(first),
           chosen->folds.begin() + static_cast<std::ptrdiff_t>(first + chosen->groups[g])});
      result_.steps.push_back(measured.steps[g]);
      if (options_.progress) options_.progress(measured.steps[g]);
    }
  }

  // The corners that stand past a smooth target's rim (a square over a round saddle) tucked
  // under once the search is done (tuck_folds.hpp), kept where the exact measure says the sheet's
  // farthest point came in by kTuckGain at least and its Chamfer distance rose by no more than
  // kTuckChamferSlack. The search's robust score barely sees a corner 24 mm out (the judge's
  // saddle_disk: 1.6% lower), so it is judged here by the distance the goal bounds.
  bool tucksAtEnd() const {
    return fitter_.smoothTarget() && !fitter_.revolutionTarget() && options_.pleats > 0 &&
           !session_.symmetricFolder();
  }
  void tuckCorners() {
    if (!tucksAtEnd() || result_.steps.size() >= options_.maxFolds + 1) return;
    // Room for the tucked sheet's measure and its report.
    Deadline deadline = deadline_;
    if (end_ != std::chrono::steady_clock::time_point::max())
      deadline =
          deadline_.notAfter(end_ - std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                        std::chrono::duration<double>(1.5 * foldCost_)));
    // Rounds until no corner stands out: a round may tuck only some corners (the others' tucks
    // crossed the sheet as it was, or stood apart from the far points found), and the rest stand
    // out as far; a corner left out stays the sheet's farthest point. Where the exact measure
    // refuses a round's best step, its next ones are tried.
    for (int round = 0; round < kTuckRounds; ++round) {
      if (deadline.passed() || result_.steps.size() >= options_.maxFolds + 1) return;
      const std::vector<FoldSuggestion> tucks =
          suggestTucks(session_, fitter_, kTuckTries, deadline);
      if (tucks.empty() || deadline.passed()) return;
      bool kept = false;
      for (const FoldSuggestion& tuck : tucks) {
        if (deadline.passed()) return;
        const FitProgress before = result_.steps.back();
        session_.applyRecords(tuck.folds);
        FitProgress after = measureNow(result_.steps.size());
        after.tucked = true;
        if ((after.hausdorff < (1.0 - kTuckGain) * before.hausdorff &&
             after.chamfer <= (1.0 + kTuckChamferSlack) * before.chamfer) ||
            (after.chamfer < (1.0 - options_.minimumGain) * before.chamfer &&
             after.hausdorff <= before.hausdorff)) {
          result_.steps.push_back(after);
          if (options_.progress) options_.progress(after);
          kept = true;
          break;
        }
        session_.undo();
      }
      if (!kept) return;
    }
  }

  const bool readCreases_;
  bool searchUnfolded_ = true;  // the reading may end in a search toward the unfolded copy
  FoldSession& session_;
  const FoldFitter& fitter_;
  const FitOptions& options_;
  const std::chrono::steady_clock::time_point start_;
  const std::chrono::steady_clock::time_point end_;  // of the whole fit (max: no clock)
  Deadline deadline_;                                // the cancel and the evaluation count
  std::atomic<std::uint64_t> evaluations_{0};
  std::atomic<std::uint64_t> droppedSamples_{0};
  // The start's measure takes at most this share of the time left (samplesWithinTime), judged by
  // a measure of this many samples.
  static constexpr double kStartShare = 0.1;
  static constexpr std::size_t kProbeSamples = 1000;
  // The reading (readingDeadline) takes at most this share of the search's time.
  static constexpr double kReadingShare = 0.6;
  // Seconds from the start to the end of the last reading (0: none ran).
  double readingEndedAt_ = 0.0;
  bool readingCut_ = false;         // the reading's share of the time ran out before it ended
  std::size_t measureSamples_ = 0;  // of every exact measure (samplesWithinTime)
  double startedAt_ = 0.0;          // seconds from start_ to the start's measure
  bool startAnnounced_ = false;     // the start's progress said (announceStart)
  std::vector<std::tuple<std::size_t, double, double>> heldSearching_;  // until then
  double foldCost_ = 0.0;               // seconds one fold kept costs at the end, at the start
  double finalCost_ = 0.0;              // estimated final phase of the largest design found
  std::size_t finalGroups_ = 0;         // its groups
  const std::vector<FoldRecord> base_;  // the session's folds before the fit
  FitResult result_;
  FoldSequence best_, bestMonotone_;  // the best, and the best whose every fold gains
};

}  // namespace

FitResult fitFolds(FoldSession& session, const FoldFitter& fitter, const FitOptions& options) {
  fitter.checkAgainst(session.fixed());
  session.cancel();
  return FitRun(session, fitter, options).run();
}

}  // namespace curvefold
