#include "engine/fit/first_step_start.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "engine/fit/bent_start.hpp"
#include "engine/fit/pleat_folds.hpp"
#include "engine/fit/profile_folds.hpp"
#include "engine/fit/ring_folds.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/fit/tuck_folds.hpp"
#include "engine/fit/wing_start.hpp"
#include "engine/geometry/fold_session.hpp"

namespace curvefold {
namespace {

constexpr std::size_t kSamples = 4000;
// Chamfer + this times Hausdorff: the goal bounds both, and at the placed starts' 0.2 a pringle's
// footprint rectangle (first step 1.19 / 12.7 mm) beat its swept parabola (2.07 / 8.46 mm), and
// its fit ended 11.2% from the target (Hausdorff) where the parabola's ended 7.46%.
constexpr double kHausdorffWeight = 0.5;
constexpr double kLeastShortfall = 0.005;
constexpr double kHalfShare = 0.5;
// A bent sheet with more paper than this many times the target's is no candidate (see below).
constexpr double kMostBentPaper = 2.0;
// The target's arc length along each end: samples, and the strip's half width (of the sheet's
// size) about the end's line.
constexpr std::size_t kArcSamples = 6000;
constexpr double kArcStrip = 0.04;

// The unit normal of a flat sheet (none when it is not flat within 1e-6 of its size).
std::optional<glm::dvec3> flatNormal(const Sheet& sheet) {
  glm::dvec3 n(0.0), lo(1e300), hi(-1e300);
  for (const Triangle& t : sheet.triangles)
    n += glm::cross(sheet.positions[t[1]] - sheet.positions[t[0]],
                    sheet.positions[t[2]] - sheet.positions[t[0]]);
  for (const glm::dvec3& p : sheet.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  if (!(glm::length(n) > 0.0)) return std::nullopt;
  n = glm::normalize(n);
  const glm::dvec3 origin = sheet.positions.front();
  for (const glm::dvec3& p : sheet.positions)
    if (std::abs(glm::dot(p - origin, n)) > 1e-6 * glm::length(hi - lo)) return std::nullopt;
  return n;
}

double reach(const std::vector<glm::dvec3>& points, const glm::dvec3& centre,
             const glm::dvec3& direction) {
  double most = -1e300;
  for (const glm::dvec3& p : points) most = std::max(most, glm::dot(p - centre, direction));
  return most;
}

// The target's arc length from `centre` out along `direction` (unit, in the sheet's plane of
// normal `normal`): its samples within a strip about that line binned by their reach, the
// polyline through each bin's mean height measured. A steep saddle's rising end is far longer
// along its surface than its reach across the sheet (saddle_mm_thin: 168 units of arc to a reach
// of 100), and a flat sheet bent there covers only its own length. 0 where the strip holds too
// few samples.
double arcLength(const std::vector<SurfaceSample>& samples, const glm::dvec3& centre,
                 const glm::dvec3& direction, const glm::dvec3& normal, double halfWidth) {
  constexpr int kBins = 24;
  const glm::dvec3 side = glm::cross(normal, direction);
  double far = 0.0;
  for (const SurfaceSample& s : samples)
    if (std::abs(glm::dot(s.position - centre, side)) < halfWidth)
      far = std::max(far, glm::dot(s.position - centre, direction));
  if (!(far > 0.0)) return 0.0;
  std::vector<double> height(kBins, 0.0);
  std::vector<int> in(kBins, 0);
  for (const SurfaceSample& s : samples) {
    const double t = glm::dot(s.position - centre, direction);
    if (t < 0.0 || std::abs(glm::dot(s.position - centre, side)) >= halfWidth) continue;
    const int b = std::min(kBins - 1, static_cast<int>(t / far * kBins));
    height[b] += glm::dot(s.position - centre, normal);
    ++in[b];
  }
  double length = 0.0, lastT = 0.0, lastH = 0.0;
  bool started = false;
  int used = 0;
  for (int b = 0; b < kBins; ++b) {
    if (in[b] == 0) continue;
    const double t = (b + 0.5) * far / kBins, h = height[b] / in[b];
    if (started)
      length += std::hypot(t - lastT, h - lastH);
    else
      length += t;  // from the centre to the first bin, as along the sheet
    lastT = t;
    lastH = h;
    started = true;
    ++used;
  }
  if (used < kBins / 2) return 0.0;
  return length + (far - lastT);
}

std::string vectorText(const glm::dvec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.3g, %.3g, %.3g)", v.x, v.y, v.z);
  return text;
}

// paperGivenBack with the target's arc samples (sampleSurface(target, kArcSamples, 5)) given:
// startByFirstStep gives each candidate's paper back twice (all, half) from one sampling.
std::optional<PlacedStart> paperGivenBackFrom(const Sheet& flat, const FoldSuggestion& step,
                                              const TriangleMesh& target,
                                              const std::vector<SurfaceSample>& samples,
                                              const std::string& kind, double share) {
  const std::optional<glm::dvec3> normal = flatNormal(flat);
  if (!normal || step.folds.empty() || flat.positions.empty()) return std::nullopt;
  glm::dvec3 centre(0.0), lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : flat.positions) {
    centre += p;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  centre /= static_cast<double>(flat.positions.size());
  const double size = glm::length(hi - lo);
  // The cross's first line: its first fold bends that line's end, so its plane's normal lies
  // along the line (tilted out of the sheet by half the bend).
  glm::dvec3 line = step.folds.front().plane.normal;
  line -= glm::dot(line, *normal) * *normal;
  if (!(glm::length(line) > 1e-6)) return std::nullopt;
  line = glm::normalize(line);
  const glm::dvec3 across = glm::cross(*normal, line);
  // Each end's reach: the flat sheet's, the sheet's after the step, the target's.
  const glm::dvec3 ends[4] = {line, -line, across, -across};
  double grown[4];
  bool any = false;
  for (int i = 0; i < 4; ++i) {
    // Short of the target's reach after the step, or of its arc length where the target rises
    // steeply (each end's bend or pleat turns it straight, so the sheet needs the arc's paper).
    const double flatReach = reach(flat.positions, centre, ends[i]);
    const double shortfall = std::max(
        {0.0,
         reach(target.positions, centre, ends[i]) - reach(step.sheet.positions, centre, ends[i]),
         arcLength(samples, centre, ends[i], *normal, kArcStrip * size) - flatReach});
    any = any || shortfall > kLeastShortfall * size;
    grown[i] = flatReach + share * shortfall;
  }
  if (!any) return std::nullopt;
  double width = grown[0] + grown[1], height = grown[2] + grown[3];
  glm::dvec3 middle =
      centre + 0.5 * (grown[0] - grown[1]) * line + 0.5 * (grown[2] - grown[3]) * across;
  const bool square = kind == "square", disk = kind == "disk";
  if (square) width = height = std::max(width, height);
  if (kind == "ellipse") {
    // An ellipse stays an ellipse: scaled about its centre (sheet and development alike) to the
    // end that fell shortest for its reach there.
    double scale = 1.0;
    for (int i = 0; i < 4; ++i) {
      const double own = reach(flat.positions, centre, ends[i]);
      if (own > 0.0) scale = std::max(scale, grown[i] / own);
    }
    PlacedStart out{"ellipse", {}, "", flat};
    for (glm::dvec3& p : out.sheet.positions) p = centre + scale * (p - centre);
    for (glm::dvec2& d : out.sheet.development) d *= scale;
    const DevelopmentBounds bounds = developmentBounds(out.sheet);
    out.parameters = {{"width", bounds.high.x - bounds.low.x},
                      {"height", bounds.high.y - bounds.low.y}};
    out.placement =
        "on the target's footprint with the paper its first step folds away given back, "
        "centred at " +
        vectorText(centre) + " normal " + vectorText(*normal);
    return out;
  }
  PlacedStart out;
  out.surface = disk ? "disk" : square ? "square" : "rectangle";
  if (disk) {
    // A disk stays round about its centre (a disk's rim moved off centre would leave one side
    // short): its radius grown to the end that fell shortest.
    middle = centre;
    out.parameters = {{"radius", *std::max_element(grown, grown + 4)}};
  } else {
    out.parameters = square ? SurfaceParameters{{"size", width}}
                            : SurfaceParameters{{"width", width}, {"height", height}};
  }
  out.placement =
      "on the target's footprint with the paper its first step folds away given back, "
      "centred at " +
      vectorText(middle) + " normal " + vectorText(*normal);
  try {
    out.sheet = makeSurface(out.surface, out.parameters);
  } catch (const SurfaceError&) {
    return std::nullopt;
  }
  for (glm::dvec3& p : out.sheet.positions) p = middle + p.x * line + p.y * across + p.z * *normal;
  return out;
}

}  // namespace

std::optional<PlacedStart> paperGivenBack(const Sheet& flat, const FoldSuggestion& step,
                                          const TriangleMesh& target, const std::string& kind,
                                          double share) {
  return paperGivenBackFrom(flat, step, target, sampleSurface(target, kArcSamples, 5), kind, share);
}

std::optional<FirstStepStart> startByFirstStep(const std::vector<PlacedStart>& candidates,
                                               const FoldFitter& fitter, const Deadline& deadline,
                                               bool square) {
  std::optional<FirstStepStart> best;
  double bestScore = 0.0;
  bool cutShort = false;
  // The target's arc samples for paperGivenBack: drawn once, at the first sheet given paper.
  std::optional<std::vector<SurfaceSample>> arcSamples;
  // The first step of `start` measured; kept when it lands nearest. Returns the step.
  auto tryStart = [&](const PlacedStart& start, bool grown) {
    FoldSession session(start.sheet);
    std::vector<FoldSuggestion> steps = suggestPleats(session, fitter, 1, deadline);
    const Sheet& landed = steps.empty() ? start.sheet : steps.front().sheet;
    SurfaceDistance distance = surfaceDistance(meshOf(landed), fitter.measuredTarget(), kSamples);
    double score = distance.chamfer + kHausdorffWeight * distance.hausdorff;
    // The corners that stand past a round rim after the step are tucked under by the fit
    // (tuck_folds.hpp, FitRun::tuckCorners, every corner that stands out): measured so too, a
    // grown square over a round saddle covers its falling ends and leaves only its corners out
    // (saddle_disk, `--from square`). Only a grown sheet's: the start's own cross leaves its ends
    // short, which no tuck mends, and the clock's share is better spent reaching the grown ones.
    // A polygon's alone (a disk or an ellipse is grown about its centre: no corners), and only
    // where the sheet's own farthest point is the farthest one: the tucks' search costs the
    // start's share of the clock (a pringle's grown ellipses: 4.8 times the CPU when counted).
    // A bent sheet's too (bent_start.hpp): its rulings are cut as long as the target's arc
    // across, so they stand out flat past the falling ends until the fit tucks them under
    // (saddle_steep_turned: Hausdorff 28.4% -> 16.3% by the fit's tucks), whether or not its
    // pleats helped first. A winged sheet's too (wing_start.hpp): its turned flaps' corners
    // stand out past the wings' rims until the fit tucks them.
    const bool bent = start.surface == "bent_square" || start.surface == "bent_rectangle" ||
                      start.surface.starts_with("winged_");
    if (((grown && !steps.empty() && distance.fromAMax >= distance.fromBMax &&
          (start.surface == "square" || start.surface == "rectangle")) ||
         bent) &&
        !deadline.passed()) {
      if (!steps.empty()) session.applyRecords(steps.front().folds);
      const std::vector<FoldSuggestion> tucks = suggestTucks(session, fitter, 1, deadline, false);
      if (!tucks.empty()) {
        const SurfaceDistance tucked =
            surfaceDistance(meshOf(tucks.front().sheet), fitter.measuredTarget(), kSamples);
        if (const double s = tucked.chamfer + kHausdorffWeight * tucked.hausdorff; s < score) {
          score = s;
          distance = tucked;
        }
      }
    }
    if (!best || score < bestScore) {
      bestScore = score;
      // The start's own distance is measured once, for the winner (below).
      best = FirstStepStart{start, distance.chamfer, distance.hausdorff, 0.0, grown, false};
    }
    return steps;
  };
  for (const PlacedStart& candidate : candidates) {
    if (best && deadline.passed()) {
      cutShort = true;
      break;
    }
    const std::vector<FoldSuggestion> steps = tryStart(candidate, false);
    if (steps.empty() || deadline.passed()) continue;
    const std::string kind = candidate.surface == "disk" || candidate.surface == "ellipse"
                                 ? candidate.surface
                             : square ? "square"
                                      : "rectangle";
    // All the paper given back, then half of it: a grown sheet's corners (a disk's sides, where
    // its cross fell short least) may stand past a rounded footprint as far as the ends fell short.
    for (const double share : {1.0, kHalfShare}) {
      if (deadline.passed()) {
        cutShort = true;
        break;
      }
      if (!arcSamples) arcSamples = sampleSurface(fitter.target(), kArcSamples, 5);
      if (const std::optional<PlacedStart> grown = paperGivenBackFrom(
              candidate.sheet, steps.front(), fitter.target(), *arcSamples, kind, share))
        tryStart(*grown, true);
    }
  }
  if (best) {
    best->cutShort = cutShort;
    best->startChamfer =
        surfaceDistance(meshOf(best->start.sheet), fitter.measuredTarget(), kSamples).chamfer;
  }
  return best;
}

std::optional<FirstStepStart> reviseByFirstStep(StartChoice& start, const FoldFitter& fitter,
                                                const std::string& kind, const Deadline& deadline) {
  // A creased start (folded from that kind at its defaults, start_surface.hpp) is read back by
  // the unfolding onto that very sheet: another sheet would lose the reading.
  if (start.creased || !fitter.smoothTarget() || fitter.revolutionTarget() ||
      !(kind.empty() || kind == "square" || kind == "rectangle" || kind == "disk"))
    return std::nullopt;
  std::vector<PlacedStart> candidates{
      {start.surface, start.parameters, start.placement,
       start.placed ? *start.placed : makeSurface(start.surface, start.parameters)}};
  // The target's samples, drawn once for the footprint, the least spread and the bent sheets.
  std::optional<std::vector<SurfaceSample>> drawn;
  auto samples = [&]() -> const std::vector<SurfaceSample>& {
    if (!drawn) drawn = sampleSurface(fitter.target(), kSamples, 3);
    return *drawn;
  };
  // A disk asked for is cut to the target's footprint too (a pringle's rim), though flat.
  std::size_t own = 0;  // the start itself among the candidates
  if ((kind.empty() && !flatNormal(candidates.front().sheet)) || kind == "disk") {
    std::vector<PlacedStart> footprint = footprintStarts(samples(), kind);
    // A round footprint's disks go first, before the start itself: under a short --time the
    // clock may leave only the first candidate measured, and a curved sheet's first step toward
    // a round saddle lands farther (hypar_disk_scan: the swept parabola's 1.98% against the
    // grown disk's 0.548% Chamfer).
    std::size_t disks = 0;
    while (kind.empty() && disks < footprint.size() &&
           (footprint[disks].surface == "disk" || footprint[disks].surface == "ellipse"))
      ++disks;
    own = disks;
    candidates.insert(candidates.begin(), std::make_move_iterator(footprint.begin()),
                      std::make_move_iterator(footprint.begin() + disks));
    candidates.insert(candidates.end(), std::make_move_iterator(footprint.begin() + disks),
                      std::make_move_iterator(footprint.end()));
  }
  // A steep saddle's sheet across its mean normal, and as the least spread laid it (on edge).
  if (kind.empty() || kind == "square" || kind == "rectangle")
    for (PlacedStart& other : leastSpreadStarts(samples(), surfaceArea(fitter.target()), kind))
      candidates.push_back(std::move(other));
  // The sheet bent along the target's curvatures (bent_start.hpp), its other direction left to
  // the pleats and its rulings' ends to the tucks: last, so that under a short --time the clock
  // keeps the flat candidates (measured right after the start itself, saddle_steep_turned at
  // --time 60 under a load of 20 was left its bent square with no time for the tucks: 0 folds,
  // 30.6% Hausdorff, against the flat square's cross at 22.5%). Not where the rectangle of its
  // arcs has over twice the target's paper (hypar_steep_mm's square along its diagonals: about
  // 3.6 times, by its arc of 512 mm a side), which its folds would mostly fold away; a square's
  // paper past that rectangle is the kind's (bent_start.hpp).
  if (kind.empty() || kind == "square" || kind == "rectangle") {
    std::vector<PlacedStart> bent = bentStarts(samples(), kind == "square" ? "square" : "rectangle",
                                               kMostBentPaper * surfaceArea(fitter.target()));
    candidates.insert(candidates.end(), std::make_move_iterator(bent.begin()),
                      std::make_move_iterator(bent.end()));
  }
  std::optional<FirstStepStart> chosen =
      startByFirstStep(candidates, fitter, deadline, kind == "square");
  // The winner, where it is a flat square or rectangle (as cut, or grown by the paper its cross
  // folds away), with a steep or lobed saddle's wings folded first (wing_start.hpp), which neither
  // its cross nor one bend follows: taken only where its own first step lands nearer still.
  if (chosen && (kind.empty() || kind == "square" || kind == "rectangle") &&
      (chosen->start.surface == "square" || chosen->start.surface == "rectangle") &&
      flatNormal(chosen->start.sheet) && !deadline.passed())
    if (const std::optional<PlacedStart> winged = wingStart(chosen->start, fitter, deadline))
      if (std::optional<FirstStepStart> landed = startByFirstStep({*winged}, fitter, deadline);
          landed && landed->chamfer + kHausdorffWeight * landed->hausdorff <
                        chosen->chamfer + kHausdorffWeight * chosen->hausdorff) {
        landed->grown = chosen->grown;
        landed->cutShort = chosen->cutShort;
        chosen = std::move(landed);
      }
  if (!chosen ||
      (!chosen->grown && chosen->start.sheet.positions == candidates[own].sheet.positions))
    return std::nullopt;
  start.surface = chosen->start.surface;
  start.parameters = chosen->start.parameters;
  start.placement = chosen->start.placement;
  start.placed = chosen->start.sheet;
  start.chamfer = chosen->startChamfer;
  start.creased = false;
  start.symmetryDefaults = false;
  return chosen;
}

std::optional<FirstStepStart> reviseTubeByFirstStep(StartChoice& start, const FoldFitter& fitter,
                                                    const std::string& kind,
                                                    const Deadline& deadline, std::size_t rings,
                                                    TubeChains* handed) {
  if (start.creased || start.widestTube || !fitter.smoothTarget() || !fitter.revolutionTarget() ||
      !(kind.empty() || kind == "cone"))
    return std::nullopt;
  const std::vector<SurfaceSample> samples = sampleSurface(fitter.target(), kSamples, 3);
  const std::optional<RevolutionAxis> axis = revolutionAxis(samples);
  if (!axis) return std::nullopt;
  const Sheet own = start.placed ? *start.placed : makeSurface(start.surface, start.parameters);
  if (!tubeAbout(own, axis->direction)) return std::nullopt;
  std::optional<PlacedStart> around =
      enclosingCone(samples, axis->point, axis->direction, kTubeRingSteepestTaper);
  if (!around || (kind == "cone" && around->surface != "cone") ||
      !tubeAbout(around->sheet, axis->direction))
    return std::nullopt;
  // Where each start's first step lands: its chains of rings, measured exactly.
  // Each start's chains are kept to hand on (the search grows the winner's on).
  TubeChains ownChains, aroundChains;
  auto landing = [&](const Sheet& sheet, TubeChains& chains) {
    FoldSession session(sheet);
    std::mt19937_64 random(fitter.settings().seed);
    const std::vector<FoldSuggestion> steps = suggestTubeRings(
        session, fitter, *axis, samples, 1, deadline, random, rings, nullptr, &chains);
    return surfaceDistance(meshOf(steps.empty() ? sheet : steps.front().sheet),
                           fitter.measuredTarget(), kSamples);
  };
  const SurfaceDistance ownLanded = landing(own, ownChains);
  if (handed) *handed = ownChains;
  if (deadline.passed()) return std::nullopt;
  const SurfaceDistance aroundLanded = landing(around->sheet, aroundChains);
  // Nearer by Chamfer, and no farther by Hausdorff: a cone around whose rings leave a lobe or
  // an end farther than the start's own rings do is not taken (the lathe vase: its two rings
  // 1.41% / 10.1% against the cone through's 1.94% / 7.06%, and its fit ended at 1.62% / 10.2%,
  // farther by Hausdorff than its start).
  if (!(aroundLanded.chamfer < ownLanded.chamfer) ||
      !(aroundLanded.hausdorff <= ownLanded.hausdorff))
    return std::nullopt;
  if (handed) *handed = std::move(aroundChains);
  FirstStepStart chosen{
      *around,
      aroundLanded.chamfer,
      aroundLanded.hausdorff,
      surfaceDistance(meshOf(around->sheet), fitter.measuredTarget(), kSamples).chamfer,
      false,
      false,
      ownLanded.chamfer,
      ownLanded.hausdorff};
  start.surface = around->surface;
  start.parameters = around->parameters;
  start.placement = around->placement;
  start.placed = around->sheet;
  start.chamfer = chosen.startChamfer;
  start.creased = false;
  start.symmetryDefaults = false;
  return chosen;
}

}  // namespace curvefold
