#include "engine/fit/start_surface.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "engine/fit/crease_planes.hpp"
#include "engine/fit/nested_rings.hpp"
#include "engine/fit/placed_start.hpp"
#include "engine/fit/profile_folds.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/fit/target_units.hpp"
#include "engine/fit/tube_reach.hpp"
#include "engine/fit/unfolded_sheet.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/unfold.hpp"
#include "engine/text/distance_text.hpp"

namespace curvefold {
namespace {

constexpr std::size_t kChoiceSamples = 4000;
// Edges of a gridded smooth shape bend a few degrees; a reflection fold's crease, far more.
constexpr double kSmoothBendDegrees = 12.0;
// A fold's creases are a few curves: a target with more of its edge length bent so is a noisy scan.
constexpr double kNoisySharpShare = 0.2;
// Or its sharp edges scatter: the plane holding the most holds under this share of them (a
// folded target's longest crease holds far more; a scan's noise puts a few edges in any plane).
constexpr double kScatteredCreaseShare = 0.02;
// Or the plane holding most of its sharp edges has under this share of its edges sharp (a
// fold's crease is bent all along; noise bends a few edges of a row of a scan's grid).
constexpr double kNoisyCreaseShare = 0.5;
// A sheet folded by reflections is isometric to its development: every interior vertex's angle
// defect is zero, to the 1e-5 rad an OBJ's six digits leave. A coarse grid of a curved shape (a
// hemisphere of 7 rings bends each ring's edges as much as a crease) has one at most vertices:
// over this share of its interior vertices with a defect above kCurvedDefect makes it smooth.
constexpr double kCurvedDefect = 1e-3;  // radians
constexpr double kCurvedVertexShare = 0.25;
// Edges within this much of the diagonal of a plane lie in it (crease_planes.hpp's tolerance).
constexpr double kCreaseTolerance = 1e-4;
// A placed sheet replaces one in the catalogue's frame when this much nearer (Chamfer).
constexpr double kPlacedGain = 0.95;
// A principal axis within about 3 degrees of the axis a target turns about is that axis: its tube
// and cone are placed already.
constexpr double kAxisAgrees = 0.9986;
// A developable target whose area is a kind's at its defaults within this share was folded from
// it: every fold keeps the area (to rounding), a shape made from a formula seldom has it.
constexpr double kSameArea = 1e-5;
// How much a placed sheet's Hausdorff distance counts beside its Chamfer distance.
constexpr double kPlacedHausdorffWeight = 0.2;
// Without a kind asked for, the disk placed across a bowl's axis is the start when the nested
// rings' profile fit from it (nested_rings.hpp) scores within this share of the nearest sheet's
// distance, both as the goal weighs them (the mean, or Chamfer, plus a quarter of the farthest,
// or Hausdorff): the rings fold the disk farther than their model says (the corner paper), but
// a placed cone is near at once and folds little closer, and leaves a cup's bottom or a bowl's
// rim standing off (docs/performance.md, cups13: by the Chamfer distance alone, with 0.2, every
// cup and most bowls kept the cone).
constexpr double kRingsGain = 0.75;
constexpr std::size_t kRingsCreases = 3;
constexpr std::size_t kRingsProfilePoints = 300;

// The score in the meridian (the mean two-sided distance plus a quarter of the farthest profile
// point's) that the nested rings' profile fit reaches from `disk` toward the samples about `axis`
// (1 to kRingsCreases creases), or none where the disk does not lie flat across it. Seeded: the
// same target gives the same choice.
std::optional<double> ringsReach(const Sheet& disk, const std::vector<SurfaceSample>& samples,
                                 const RevolutionAxis& axis) {
  // About the axis the rings would fold it about (the sheet's own normal where it lies within a
  // few degrees of the target's axis: nested_rings.hpp).
  const std::optional<RevolutionAxis> across = ringsAxis(disk, axis);
  if (!across || disk.positions.empty()) return std::nullopt;
  const glm::dvec3 centre = across->point, direction = across->direction;
  double radius = 0.0;
  for (const glm::dvec3& p : disk.positions) {
    const glm::dvec3 d = p - centre;
    radius = std::max(radius, glm::length(d - glm::dot(d, direction) * direction));
  }
  const std::vector<glm::dvec2> profile =
      meridianProfile(samples, centre, *across, kRingsProfilePoints);
  std::mt19937_64 random(38);
  std::optional<ProfileCreases> fit;
  double best = 1e300;
  for (std::size_t k = 1; k <= kRingsCreases; ++k) {
    fit = fitProfileCreases(profile, radius, k, fit ? &*fit : nullptr, random);
    best = std::min(best, fit->score);
  }
  return best;
}

// Without a kind asked for, the tube as wide as a vase's belly replaces a tube about its axis
// (a placed cone) where its rings' reach (tube_reach.hpp) is under this share of that tube's:
// the model ranks the two, it does not foretell either fit, so a near tie keeps the start
// measured nearer (judge19's vase_0: its cone ended at 1.04% Chamfer, the widest tube 1.27%;
// at 0.70, make_implicit_shapes.py's vase_march traded Hausdorff for Chamfer, 3.91% / 1.84% ->
// 8.57% / 1.08%; judge20's vase, at 0.48, came closer by both: docs/performance.md, vase21).
constexpr double kTubeRingsGain = 0.6;
// The tube's rings narrow it toward both ends of a belly: the rule is for a profile whose ends
// both lie between these shares of its widest radius. Under the first a shape narrows to its
// axis (a bowl's bottom, a cup's: no tube's rings reach there); over the second one end is as
// wide as the belly (a lampshade: the cone through its profile has that end already, and the
// tube's rings cut the whole taper: stranger lampshade_0 1.06% / 3.47% -> 1.49% / 5.84%,
// Chamfer / Hausdorff, docs/performance.md, vase21).
// A start the rule ranked below its choice is a runner-up (StartChoice::runnersUp) where the
// model's ratio of the two lies within this factor of the rule's threshold either way: the
// steep cups' disks were chosen at ratios 0.55-0.70 (kRingsGain 0.75), of which the cone's fit
// ended nearer by both measures on the tumbler (0.70) and the marched beaker (0.55), farther on
// the deep cup (0.67) and the marched mug (0.58); bowls' disks lie at 0.13-0.39, clear of it
// (docs/performance.md, portfolio24).
constexpr double kRunnerUpMargin = 1.5;
// `--from cylinder`: the alternative tube's radius, as a share of the widest.
constexpr double kNarrowerTube = 0.9;
constexpr double kEndNarrowest = 0.35;
constexpr double kEndBelly = 0.85;

bool bellyBetweenEnds(const std::vector<SurfaceSample>& samples, const RevolutionAxis& axis) {
  const std::optional<HeightBands> bands = heightBands(samples, axis.point, axis.direction);
  if (!bands) return false;
  double widest = 0.0;
  for (const glm::dvec2& p : bands->profile) widest = std::max(widest, p.y);
  const double low = std::min(bands->profile.front().y, bands->profile.back().y);
  const double high = std::max(bands->profile.front().y, bands->profile.back().y);
  return low >= kEndNarrowest * widest && high <= kEndBelly * widest;
}

// Where the target lies about the y axis: mean radius overall and over the lowest and highest
// tenth of its extent along y.
struct Revolution {
  double radius = 0.0, bottomRadius = 0.0, topRadius = 0.0, height = 0.0;
};

Revolution revolutionOf(const std::vector<SurfaceSample>& samples) {
  double lo = 1e300, hi = -1e300;
  for (const SurfaceSample& s : samples) {
    lo = std::min(lo, s.position.y);
    hi = std::max(hi, s.position.y);
  }
  Revolution r;
  r.height = hi - lo;
  double sum = 0.0, bottom = 0.0, top = 0.0;
  std::size_t nBottom = 0, nTop = 0;
  for (const SurfaceSample& s : samples) {
    const double radius = std::hypot(s.position.x, s.position.z);
    sum += radius;
    if (s.position.y <= lo + 0.1 * r.height) bottom += radius, ++nBottom;
    if (s.position.y >= hi - 0.1 * r.height) top += radius, ++nTop;
  }
  r.radius = sum / static_cast<double>(std::max<std::size_t>(1, samples.size()));
  r.bottomRadius = nBottom ? bottom / static_cast<double>(nBottom) : r.radius;
  r.topRadius = nTop ? top / static_cast<double>(nTop) : r.radius;
  return r;
}

StartChoice choice(const std::string& surface, SurfaceParameters parameters) {
  StartChoice out;
  out.surface = surface;
  out.parameters = std::move(parameters);
  return out;
}

std::vector<StartChoice> candidatesFor(const TriangleMesh& target, const std::string& kind) {
  const double area = surfaceArea(target);
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : target.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const Revolution rev = revolutionOf(sampleSurface(target, kChoiceSamples, 3));
  std::vector<StartChoice> out;
  auto want = [&](const char* name) { return kind.empty() || kind == name; };
  if (want("square")) out.push_back(choice("square", {{"size", std::sqrt(area)}}));
  if (want("disk")) out.push_back(choice("disk", {{"radius", std::sqrt(area / std::numbers::pi)}}));
  if (want("rectangle")) {
    const double aspect = std::clamp((hi.x - lo.x) / std::max(1e-12, hi.y - lo.y), 0.2, 5.0);
    out.push_back(choice(
        "rectangle", {{"width", std::sqrt(area * aspect)}, {"height", std::sqrt(area / aspect)}}));
  }
  if (want("cylinder"))
    out.push_back(choice("cylinder", {{"radius", rev.radius}, {"height", rev.height}}));
  if (want("half_cylinder"))
    out.push_back(choice("half_cylinder", {{"radius", rev.radius}, {"height", rev.height}}));
  if (want("cone"))
    out.push_back(choice("cone", {{"base_radius", std::max(rev.bottomRadius, rev.topRadius)},
                                  {"top_radius", std::min(rev.bottomRadius, rev.topRadius)},
                                  {"height", rev.height}}));
  // Each kind at its defaults too: a sized sheet is kept only where it starts closer.
  const std::size_t sized = out.size();
  for (std::size_t i = 0; i < sized; ++i) out.push_back(choice(out[i].surface, {}));
  if (out.empty()) out.push_back(choice(kind, {}));  // a kind the rule does not size: its defaults
  return out;
}

// Whether the target carries creases a sheet of this kind would not have: a fold's (a plane
// holds 3% of the diagonal of sharp edges).
bool creasedFor(const TriangleMesh& target, const Sheet& sheet, double floorDegrees = 0.0) {
  CreasePlaneOptions options;
  options.minDihedralDegrees = std::max(floorDegrees, sharpEdgeThreshold(meshOf(sheet)));
  options.minSupport = 0.03 * boundingDiagonal(target);
  options.maxPlanes = 1;
  options.hypotheses = 200;
  return !findCreasePlanes(target, options).empty();
}

// The total length of the target's edges between two triangles.
double edgeLength(const TriangleMesh& target) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> faces;
  for (const auto& t : target.triangles)
    for (int k = 0; k < 3; ++k) ++faces[std::minmax(t[k], t[(k + 1) % 3])];
  double length = 0.0;
  for (const auto& [edge, count] : faces)
    if (count >= 2)
      length += glm::distance(target.positions[edge.first], target.positions[edge.second]);
  return length;
}

// The share of the target's edge length bent more than `degrees` between its two triangles, of
// its edges lying in `plane` when given (within `tolerance`, metres).
double sharpShare(const TriangleMesh& target, double degrees,
                  const ReflectionPlane* plane = nullptr, double tolerance = 0.0) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, glm::dvec3> firstNormal;
  const double cosine = std::cos(degrees * std::numbers::pi / 180.0);
  double all = 0.0, sharp = 0.0;
  for (const auto& t : target.triangles) {
    const glm::dvec3 a = target.positions[t[0]], b = target.positions[t[1]],
                     c = target.positions[t[2]];
    const glm::dvec3 cross = glm::cross(b - a, c - a);
    if (!(glm::length(cross) > 0.0)) continue;
    const glm::dvec3 normal = glm::normalize(cross);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = t[k], v = t[(k + 1) % 3];
      const auto key = std::minmax(u, v);
      const auto [found, added] = firstNormal.emplace(key, normal);
      if (added) continue;
      if (plane && !(std::abs(plane->signedDistance(target.positions[u])) <= tolerance &&
                     std::abs(plane->signedDistance(target.positions[v])) <= tolerance))
        continue;
      const double length = glm::distance(target.positions[u], target.positions[v]);
      all += length;
      if (glm::dot(found->second, normal) < cosine) sharp += length;
    }
  }
  return all > 0.0 ? sharp / all : 0.0;
}

// Whether over kCurvedVertexShare of the target's interior vertices are curved (see above).
bool curvedAtMostVertices(const TriangleMesh& target) {
  std::vector<Triangle> triangles;
  triangles.reserve(target.triangles.size());
  for (const auto& t : target.triangles)
    triangles.push_back({VertexIndex(t[0]), VertexIndex(t[1]), VertexIndex(t[2])});
  std::size_t interior = 0, curved = 0;
  for (const double defect : angleDefects(target.positions, triangles)) {
    if (std::isnan(defect)) continue;
    ++interior;
    if (std::abs(defect) > kCurvedDefect) ++curved;
  }
  return interior > 0 && static_cast<double>(curved) > kCurvedVertexShare * interior;
}

}  // namespace

bool isCurved(const TriangleMesh& target) {
  return curvedAtMostVertices(target);
}

bool isSmoothOrScanned(const TriangleMesh& target) {
  // Noise (many sharp edges) or curvature at most vertices decide it alone, at a few passes over
  // the edges: tested first, so that a large scan (100k triangles of noise: seconds of plane
  // hypotheses, before any deadline) never reaches the plane search. The same answer either way.
  const double sharp = sharpShare(target, kSmoothBendDegrees);
  if (sharp > kNoisySharpShare || curvedAtMostVertices(target)) return true;
  CreasePlaneOptions options;
  options.minDihedralDegrees = kSmoothBendDegrees;
  options.minSupport = 0.03 * boundingDiagonal(target);
  options.maxPlanes = 1;
  options.hypotheses = 200;
  const std::vector<CreasePlane> planes = findCreasePlanes(target, options);
  if (planes.empty()) return true;
  // A fold's crease holds a good share of the sharp edges, and along it every edge is bent.
  // Noise scatters sharp edges, a few per plane, and where it bends some edges of a row of a
  // depth scan's grid (a plane of edges), most edges of that row are not bent.
  const double tolerance = kCreaseTolerance * boundingDiagonal(target);
  return planes.front().support < kScatteredCreaseShare * sharp * edgeLength(target) ||
         sharpShare(target, kSmoothBendDegrees, &planes.front().plane, tolerance) <
             kNoisyCreaseShare;
}

StartChoice chooseStart(const TriangleMesh& target, const std::string& kind,
                        const std::string& symmetry, const Deadline& deadline) {
  return chooseStart(MeasuredSurface(target, "target"), kind, symmetry, deadline);
}

StartChoice chooseStart(const MeasuredSurface& measured, const std::string& kind,
                        const std::string& symmetry, const Deadline& deadline) {
  const TriangleMesh& target = measured.mesh();
  StartChoice best;
  bool any = false;
  std::string lastError;
  // Whether a sheet has the symmetry asked for; text that is no symmetry is refused at once.
  std::optional<InvalidSymmetry> lacked;
  auto keeps = [&](const Sheet& sheet) {
    if (symmetry.empty()) return true;
    try {
      parseSymmetry(symmetry, sheet);
      return true;
    } catch (const InvalidSymmetry& e) {
      if (!e.surfaceLacksIt()) throw;
      lacked = e;
      return false;
    }
  };
  bool sizedDropped = false;            // a sized or placed sheet lacked the symmetry
  bool sizedKept = false;               // a sheet sized in the catalogue's frame had it
  std::map<std::string, bool> creased;  // per kind, at its defaults
  auto creasedKind = [&](const std::string& surface) {
    const auto found = creased.find(surface);
    if (found != creased.end()) return found->second;
    bool result = false;
    try {
      result = creasedFor(target, makeSurface(surface));
    } catch (const SurfaceError&) {
    }
    return creased[surface] = result;
  };
  // A smooth target's grid bends are no creases, though a flat sheet's threshold reads them so.
  const bool smooth = isSmoothOrScanned(target);
  // Folds that left short creases only (a corner turned: under the 3% a crease plane needs) or
  // none (their planes missed the sheet: the sheet moved whole) read as smooth, and a sheet sized
  // or placed on the target then starts nearer than the one it was folded from, which the
  // unfolding cannot read back onto. Its area and its flatness name that sheet.
  const double area = surfaceArea(target);
  const bool developable = !isCurved(target);
  std::map<std::string, bool> foldedFrom;  // per kind: the target has its defaults' area
  auto foldedFromKind = [&](const std::string& surface) {
    const auto found = foldedFrom.find(surface);
    if (found != foldedFrom.end()) return found->second;
    bool result = false;
    try {
      result = developable &&
               std::abs(surfaceArea(meshOf(makeSurface(surface))) - area) <= kSameArea * area;
    } catch (const SurfaceError&) {
    }
    return foldedFrom[surface] = result;
  };
  bool anyFoldedFrom = false, bestFrom = false;
  double candidateHausdorff = 0.0, bestHausdorff = 0.0;  // of the sheet measured last, of best
  bool cutShort = false;
  // Once one sheet is measured, the rest only while the deadline allows.
  auto outOfTime = [&] { return any && (cutShort = cutShort || deadline.passed()); };
  // The kind asked for at the parameters its unfolding lies on, where a target folded from it
  // (creased, or flat enough to be: short creases read as smooth) has another area than its
  // defaults (unfolded_sheet.hpp): read once. Found, it is the sheet, as the defaults are below.
  std::optional<std::optional<SurfaceParameters>> unfoldedParameters;
  auto unfoldedFor = [&](const std::string& surface) -> const std::optional<SurfaceParameters>& {
    static const std::optional<SurfaceParameters> none;
    if (surface != kind || !developable || foldedFromKind(surface)) return none;
    if (!unfoldedParameters) unfoldedParameters = parametersFromUnfolding(target, kind, deadline);
    return *unfoldedParameters;
  };
  for (StartChoice& candidate : candidatesFor(target, kind)) {
    if (outOfTime()) break;
    // A folded design was folded from the sheet as the catalogue makes it.
    if ((!smooth && creasedKind(candidate.surface)) || foldedFromKind(candidate.surface)) {
      candidate.parameters.clear();
      candidate.creased = true;
      anyFoldedFrom = anyFoldedFrom || foldedFromKind(candidate.surface);
    }
    if (const std::optional<SurfaceParameters>& unfolded = unfoldedFor(candidate.surface)) {
      candidate.parameters = *unfolded;
      candidate.creased = true;
      anyFoldedFrom = true;  // no sheet placed on it: the unfolding lies on this one
    }
    try {
      const Sheet sheet = makeSurface(candidate.surface, candidate.parameters);
      if (!keeps(sheet)) {
        sizedDropped = sizedDropped || !candidate.parameters.empty();
        continue;
      }
      sizedKept = sizedKept || !candidate.parameters.empty();
      const SurfaceDistance distance = surfaceDistance(meshOf(sheet), measured, kChoiceSamples);
      candidate.chamfer = distance.chamfer;
      candidateHausdorff = distance.hausdorff;
    } catch (const SurfaceError& e) {
      lastError = e.what();
      continue;
    }
    // The kind it was folded from first, however far its defaults lie.
    const bool from = foldedFromKind(candidate.surface);
    if (!any || (from && !bestFrom) || (from == bestFrom && candidate.chamfer < best.chamfer)) {
      best = candidate;
      bestHausdorff = candidateHausdorff;
      bestFrom = from;
    }
    any = true;
  }
  // Sheets moved onto the target: only for a smooth or noisy one (isSmoothOrScanned; a creased
  // target was folded from the catalogue's sheet where it lies). At least one is measured when
  // the clock has cut the catalogue's sheets short: those lie in the catalogue's frame, often far
  // from a smooth target (a scan kept a default cylinder 177% of its diagonal off at --time 2).
  const std::vector<SurfaceSample> samples = sampleSurface(target, kChoiceSamples, 3);
  std::optional<PlacedStart> nearest, disk, ellipse;
  double nearestChamfer = 0.0, nearestHausdorff = 0.0, nearestScore = 0.0, diskChamfer = 0.0,
         ellipseChamfer = 0.0;
  // The disk stretched to an oval footprint is for a bowl, whose nested rings fold it
  // (nested_rings.hpp): kept only where it lies flat across the target's axis.
  std::optional<std::optional<RevolutionAxis>> bowlAxis;
  const auto acrossAxis = [&](const Sheet& sheet) {
    if (!bowlAxis) bowlAxis = revolutionAxis(samples);
    return *bowlAxis && liesFlatAcross(sheet, **bowlAxis);
  };
  const auto flatRound = [](const std::string& surface) {
    return surface == "disk" || surface == "ellipse";
  };
  std::vector<PlacedStart> placedSheets = smooth && !anyFoldedFrom
                                              ? placedStarts(samples, surfaceArea(target), kind)
                                              : std::vector<PlacedStart>{};
  // The tube and the cone about the axis the target turns about, where no principal axis is it:
  // a scanned vase (judge19's, 2.5 radii tall, four holes) had its placed tube 14 degrees off and
  // started 2.5 times farther than `--from cylinder` (docs/performance.md).
  if (smooth && !anyFoldedFrom && (kind.empty() || kind == "cylinder" || kind == "cone"))
    if (const std::optional<RevolutionAxis> axis = revolutionAxis(samples)) {
      const PrincipalAxes principal = principalAxes(samples);
      const bool missed = std::none_of(
          std::begin(principal.axes), std::end(principal.axes), [&](const glm::dvec3& a) {
            return std::abs(glm::dot(a, axis->direction)) > kAxisAgrees;
          });
      if (missed)
        for (PlacedStart& extra : revolutionStarts(samples, axis->point, axis->direction, kind))
          placedSheets.push_back(std::move(extra));
    }
  for (PlacedStart& placed : placedSheets) {
    // Past the clock the flat round sheets are still measured (one measure each, milliseconds on
    // a bowl): they come last, and a loaded machine kept a cup's placed cone for want of them.
    if (nearest && outOfTime() && !flatRound(placed.surface)) continue;
    if (placed.surface == "ellipse" && !acrossAxis(placed.sheet)) continue;
    if (!keeps(placed.sheet)) {
      sizedDropped = true;
      continue;
    }
    // Among placed sheets, the farthest point counts too: of two as near on average, the one
    // that covers the whole target (a cone down to a bowl's bottom) folds to it better.
    const SurfaceDistance distance =
        surfaceDistance(meshOf(placed.sheet), measured, kChoiceSamples);
    const double score = distance.chamfer + kPlacedHausdorffWeight * distance.hausdorff;
    if (placed.surface == "disk" && !disk) {
      disk = placed;
      diskChamfer = distance.chamfer;
    }
    if (placed.surface == "ellipse" && !ellipse) {
      ellipse = placed;
      ellipseChamfer = distance.chamfer;
    }
    if (nearest && !(score < nearestScore)) continue;
    nearestChamfer = distance.chamfer;
    nearestHausdorff = distance.hausdorff;
    nearestScore = score;
    nearest = std::move(placed);
  }
  // Kept only where clearly nearer: a sheet in the catalogue's frame keeps its symmetries.
  const bool nearestPlaced = nearest && (!any || nearestChamfer < kPlacedGain * best.chamfer);
  // Without a kind asked for, a bowl's disk whose rings reach far closer than the nearest sheet
  // is (a placed cone: near at once, folded little closer) is the start.
  // Not skipped past the clock: the profile fits cost a fraction of a second, and without them a
  // loaded machine starts a bowl from the cone its rings from the disk would beat.
  bool ringsDisk = false;
  const bool metres = lengthsInMetres(boundingDiagonal(target));
  // A sheet the rule ranked close below its choice (kRunnerUpMargin), `why` its numbers.
  std::vector<RunnerUpStart> runnersUp;
  auto runnerUp = [&](const std::string& surface, const SurfaceParameters& parameters,
                      std::optional<Sheet> sheet, const std::string& placement,
                      const std::string& why) {
    if (!keeps(sheet ? *sheet : makeSurface(surface, parameters))) return;
    runnersUp.push_back({surface, parameters, std::move(sheet), placement, why});
  };
  if (kind.empty() && disk &&
      !(nearestPlaced ? flatRound(nearest->surface) : best.surface == "disk")) {
    const double nearestNow = nearestPlaced ? nearestChamfer + kProfileFarthest * nearestHausdorff
                                            : best.chamfer + kProfileFarthest * bestHausdorff;
    const std::optional<RevolutionAxis> axis = revolutionAxis(samples);
    // No reach (the disk does not lie across the axis): infinite, neither taken nor close.
    const double reach = axis ? ringsReach(disk->sheet, samples, *axis)
                                    .value_or(std::numeric_limits<double>::infinity())
                              : std::numeric_limits<double>::infinity();
    const std::string nearestName = nearestPlaced ? nearest->surface : best.surface;
    const std::string numbers = "the disk's nested rings' profile " + lengthText(reach, metres) +
                                ", the " + nearestName + " " + lengthText(nearestNow, metres);
    if (reach < kRingsGain * nearestNow) {
      const std::string text =
          "; its nested rings' profile comes within " + lengthText(reach, metres) +
          " of the target's (mean + farthest / 4), the nearest sheet (" + nearestName + ") " +
          lengthText(nearestNow, metres) + " (Chamfer + Hausdorff / 4)";
      // Close to the rule's threshold: the sheet it passed over is fitted too.
      if (reach >= kRingsGain / kRunnerUpMargin * nearestNow) {
        if (nearestPlaced)
          runnerUp(nearest->surface, nearest->parameters, nearest->sheet, nearest->placement,
                   numbers);
        else
          runnerUp(best.surface, best.parameters, std::nullopt, "", numbers);
      }
      // An oval bowl's rings fold the disk stretched to its footprint (the round disk's reach
      // stands for it: the rings follow an oblong target's reach either way).
      const bool oval = ellipse.has_value();
      nearest = std::move(oval ? ellipse : disk);
      nearest->placement += text;
      nearestChamfer = oval ? ellipseChamfer : diskChamfer;
      ringsDisk = true;
    } else if (reach < kRingsGain * kRunnerUpMargin * nearestNow) {
      const PlacedStart& flat = ellipse ? *ellipse : *disk;
      runnerUp(flat.surface, flat.parameters, flat.sheet, flat.placement, numbers);
    }
  }
  if (nearest && (ringsDisk || nearestPlaced)) {
    best.surface = nearest->surface;
    best.parameters = nearest->parameters;
    best.chamfer = nearestChamfer;
    best.placement = nearest->placement;
    best.creased = false;
    best.placed = std::move(nearest->sheet);
    any = true;
  }
  // Without a kind asked for, a vase's start that is a tube about its axis (a placed cone, near
  // at once) gives way to the tube as wide as its belly where that tube's rings could come far
  // closer (tube_reach.hpp): rings only narrow, so a belly standing outside the cone stays off
  // (judge20's vase: cone 6.36% Hausdorff, the widest tube 3.36%). Only toward a belly between
  // narrower ends (bellyBetweenEnds: not a bowl, a cup or a lampshade).
  if (kind.empty() && smooth && !anyFoldedFrom && !ringsDisk && any)
    if (const std::optional<RevolutionAxis> axis = revolutionAxis(samples)) {
      const Sheet now = best.placed ? *best.placed : makeSurface(best.surface, best.parameters);
      std::optional<PlacedStart> tube = widestCylinder(samples, axis->point, axis->direction);
      // No reach: infinite, so neither taken nor close.
      constexpr double kNone = std::numeric_limits<double>::infinity();
      const double reachNow = tubeRingsReach(now, samples, *axis).value_or(kNone);
      double reachTube = kNone;
      if (tube && bellyBetweenEnds(samples, *axis) && keeps(tube->sheet))
        reachTube = tubeRingsReach(tube->sheet, samples, *axis).value_or(kNone);
      const bool ranked = reachNow < kNone && reachTube < kNone;
      const std::string numbers = ranked ? "the widest tube's rings " +
                                               lengthText(reachTube, metres) + ", the " +
                                               best.surface + "'s " + lengthText(reachNow, metres)
                                         : std::string();
      if (ranked && reachTube < kTubeRingsGain * reachNow) {
        const std::string text = "; its rings could come within " + lengthText(reachTube, metres) +
                                 " of the target's profile (mean + farthest / 4), the " +
                                 best.surface + "'s " + lengthText(reachNow, metres);
        if (reachTube >= kTubeRingsGain / kRunnerUpMargin * reachNow)
          runnerUp(best.surface, best.parameters, best.placed, best.placement, numbers);
        best.surface = tube->surface;
        best.parameters = tube->parameters;
        best.chamfer = surfaceDistance(meshOf(tube->sheet), measured, kChoiceSamples).chamfer;
        best.placement = tube->placement + text;
        best.creased = false;
        best.placed = std::move(tube->sheet);
        best.widestTube = true;
      } else if (ranked && reachTube < kTubeRingsGain * kRunnerUpMargin * reachNow) {
        runnerUp(tube->surface, tube->parameters, tube->sheet, tube->placement, numbers);
      } else if (ranked) {
        // Ranked by hulls whose ends may stand level (a lip flared above a neck cut in), the
        // tube a runner-up where it reaches: kept only where its fit ends nearer by both
        // (as the rule's model it traded Hausdorff for Chamfer on four vases, open25).
        const double trimmedNow =
            tubeRingsReach(now, samples, *axis, TubeHull::EndsMayStandLevel).value_or(kNone);
        const double trimmedTube =
            tubeRingsReach(tube->sheet, samples, *axis, TubeHull::EndsMayStandLevel)
                .value_or(kNone);
        if (trimmedTube < kTubeRingsGain * trimmedNow)
          runnerUp(tube->surface, tube->parameters, tube->sheet, tube->placement,
                   "the widest tube's rings " + lengthText(trimmedTube, metres) + ", the " +
                       best.surface + "'s " + lengthText(trimmedNow, metres) +
                       ", their hulls' ends standing level");
      }
    }
  // A tube toward a smooth target of revolution is as wide as its belly: the rings that fold
  // it toward the target only narrow it (ring_folds.hpp).
  if (kind == "cylinder" && smooth && !anyFoldedFrom && !outOfTime()) {
    const std::optional<RevolutionAxis> axis = revolutionAxis(samples);
    std::optional<PlacedStart> tube =
        axis ? widestCylinder(samples, axis->point, axis->direction) : std::nullopt;
    if (tube && keeps(tube->sheet)) {
      best.surface = tube->surface;
      best.parameters = tube->parameters;
      best.chamfer = surfaceDistance(meshOf(tube->sheet), measured, kChoiceSamples).chamfer;
      best.placement = tube->placement;
      best.creased = false;
      best.placed = std::move(tube->sheet);
      any = true;
      // The tube's radius has an alternative: a narrower one lowers a neck's corners.
      if (std::optional<PlacedStart> narrower =
              widestCylinder(samples, axis->point, axis->direction, kNarrowerTube))
        runnerUp(narrower->surface, narrower->parameters, narrower->sheet, narrower->placement,
                 "the tube's radius, a share of the widest");
    } else if (tube) {
      sizedDropped = true;
    }
  }
  // Every sheet of the kind lacks the symmetry, its defaults too: the surface does not have it.
  if (!any && lacked) throw *lacked;
  if (!any) throw SurfaceError(lastError);
  best.cutShort = cutShort;
  best.runnersUp = std::move(runnersUp);
  best.symmetryDefaults = sizedDropped && !sizedKept && best.parameters.empty() && !best.placed;
  return best;
}

std::string detectRotationalSymmetry(const TriangleMesh& target, const Sheet& initial) {
  return detectRotationalSymmetry(MeasuredSurface(target, "target"), initial);
}

std::string detectRotationalSymmetry(const MeasuredSurface& measured, const Sheet& initial) {
  const TriangleMesh& target = measured.mesh();
  const double diagonal = boundingDiagonal(target);
  const std::vector<SurfaceSample> samples = sampleSurface(target, 2000, 5);
  const SurfaceDistanceQuery& query = measured.query();
  std::string best;
  int bestOrder = 1;
  for (const std::string& choice : symmetryChoices(initial)) {
    if (choice.rfind("rotational:", 0) != 0) continue;
    const Symmetry symmetry = parseSymmetry(choice, initial);
    if (symmetry.order <= bestOrder) continue;
    const Isometry turn = symmetry.images().front();
    double sum = 0.0, most = 0.0;
    for (const SurfaceSample& s : samples) {
      const double d = query.distance(turn.apply(s.position));
      sum += d;
      most = std::max(most, d);
      if (most > 0.03 * diagonal) break;
    }
    if (most <= 0.03 * diagonal && sum <= 0.01 * diagonal * static_cast<double>(samples.size())) {
      best = symmetry.name();
      bestOrder = symmetry.order;
    }
  }
  return best;
}

}  // namespace curvefold
