#include "engine/fit/nested_rings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>

#include "engine/fit/farthest_points.hpp"
#include "engine/fit/subplex.hpp"
#include "engine/fit/timed_batches.hpp"
#include "engine/fit/unit_draw.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {
namespace {

constexpr std::size_t kProfilePoints = 300;  // target samples the profile is fitted to
constexpr std::size_t kPolylinePoints = 48;  // along the sheet's radius
constexpr int kRestarts = 5;                 // random starts per crease count
constexpr int kProfileEvaluations = 500;     // Subplex evaluations per start
// The fits are also made with the farthest point weighed this much (the rim's fits), their rings
// made after the others' and kept where the sheet comes nearer: on a deep cap whose corner paper
// leaves the rim unreached, fits that reach for the rim bring the sheet closer by both measures
// (a judge's 75 degree cap: Hausdorff 6.9% -> 3.8%), on others they do not (a scanned 80 degree
// cap: 6.9% -> 8.3%), and the real sheet, not the model, tells which.
constexpr double kRimFarthest = 0.5;
constexpr std::array<int, 3> kOrders{8, 12, 16};
// A fit whose wall turns steeper than this from the sheet's plane is also made with rings of
// these few planes, first (see the header: the flaps of a ring of n overlap more the more planes
// it has, and on a steep wall their overlap stands out).
constexpr double kSteepWall = 60.0 * std::numbers::pi / 180.0;
constexpr std::array<int, 3> kSteepOrders{4, 5, 6};
constexpr double kFlatSheet = 0.02;  // height spread over radius below which a sheet is flat
// A placed disk's normal is read from the target's samples (placed_start.cpp) and the target's
// axis from others (profile_folds.cpp); on a cup about as deep as wide the two estimates of one
// principal axis differ by 1-4 degrees (the axial spread near the others': 0.5-0.75 of the
// largest), and the disk's height along the axis then spanned twice the sine of the angle of its
// radius, over the 2% of kFlatSheet: no rings at all (bench/make_cup16_targets.py's tulip_cup,
// 3.7 degrees apart, 13%: 1 fold, Chamfer 9.7%). A flat sheet whose own normal lies within this
// angle of the axis gets rings about that normal.
constexpr double kAxisSlack = 6.0 * std::numbers::pi / 180.0;
constexpr double kPi = std::numbers::pi;
// A step whose farthest point stands farther than this times the sheet's before it is not
// offered: the fit keeps no step toward a smooth shape that does so (fold_fit.cpp's
// kHausdorffSlack), and a better one by the search's mean distance would hide those it keeps (on
// a steep cup, rings whose corner paper stands out past the rim).
constexpr double kFarthestSlack = 1.1;
constexpr std::size_t kFarthestSamples = 3000;
// Steps whose approximate distance lies within this share of the nearest step's are as near
// (see suggestNestedRings: the one standing out least of them is offered).
constexpr double kTiedNearest = 0.05;

// An oblong target (an oval serving bowl) is followed by rings whose planes stand off the axis in
// proportion to the target's reach in their direction: below this ratio of the farthest reach to
// the nearest (over kReachBins turns about the axis) a target is taken as round and the rings are
// round, as before.
constexpr double kOblong = 1.12;
constexpr int kReachBins = 24;

// The target's reach about the axis by azimuth, as a scale of mean 1 (see kOblong).
struct AzimuthReach {
  glm::dvec3 u{0.0}, v{0.0};
  std::vector<double> scale;  // per bin; empty where the target is round
  int binOf(const glm::dvec3& radial) const {
    const double angle = std::atan2(glm::dot(radial, v), glm::dot(radial, u));
    const int bin = static_cast<int>(std::floor((angle + kPi) / (2.0 * kPi) * kReachBins));
    return std::clamp(bin, 0, kReachBins - 1);
  }
  // Interpolated between the bins' centres, around the turn.
  double at(const glm::dvec3& radial) const {
    if (scale.empty()) return 1.0;
    const double angle = std::atan2(glm::dot(radial, v), glm::dot(radial, u));
    const double f = (angle + kPi) / (2.0 * kPi) * kReachBins - 0.5;
    const double lower = std::floor(f);
    const int a = (static_cast<int>(lower) % kReachBins + kReachBins) % kReachBins;
    const int b = (a + 1) % kReachBins;
    const double t = f - lower;
    return (1.0 - t) * scale[static_cast<std::size_t>(a)] + t * scale[static_cast<std::size_t>(b)];
  }
};

// The farthest of `points` from the axis through `centre` in each bin (0 where a bin has none).
std::vector<double> reachByBin(const AzimuthReach& frame, const std::vector<glm::dvec3>& points,
                               const glm::dvec3& centre, const glm::dvec3& direction) {
  std::vector<double> reach(kReachBins, 0.0);
  for (const glm::dvec3& p : points) {
    glm::dvec3 radial = p - centre;
    radial -= glm::dot(radial, direction) * direction;
    double& bin = reach[static_cast<std::size_t>(frame.binOf(radial))];
    bin = std::max(bin, glm::length(radial));
  }
  return reach;
}

AzimuthReach azimuthReach(const std::vector<SurfaceSample>& samples, const glm::dvec3& centre,
                          const glm::dvec3& direction) {
  AzimuthReach reach;
  const glm::dvec3 pick =
      std::abs(direction.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  reach.u = glm::normalize(pick - glm::dot(pick, direction) * direction);
  reach.v = glm::cross(direction, reach.u);
  std::vector<glm::dvec3> points;
  points.reserve(samples.size());
  for (const SurfaceSample& s : samples) points.push_back(s.position);
  const std::vector<double> raw = reachByBin(reach, points, centre, direction);
  // Smoothed over three bins (a hole or noise at the rim moves one bin's farthest sample).
  std::vector<double> smooth(kReachBins, 0.0);
  for (int i = 0; i < kReachBins; ++i) {
    double sum = 0.0, count = 0.0;
    for (int j = -1; j <= 1; ++j) {
      const double r = raw[static_cast<std::size_t>((i + j + kReachBins) % kReachBins)];
      if (r > 0.0) {
        sum += r;
        count += 1.0;
      }
    }
    if (!(count > 0.0)) return reach;  // a gap of three bins: no reach to follow
    smooth[static_cast<std::size_t>(i)] = sum / count;
  }
  const auto [least, most] = std::minmax_element(smooth.begin(), smooth.end());
  if (!(*most < kOblong * *least)) {
    double mean = 0.0;
    for (double r : smooth) mean += r;
    mean /= kReachBins;
    for (double r : smooth) reach.scale.push_back(r / mean);
  }
  return reach;
}

// The farthest either of the sheet and the target lies from the other, among samples.
double farthestApart(const Sheet& sheet, const MeasuredSurface& target) {
  const FarthestPoints far = farthestPoints(meshOf(sheet), target, kFarthestSamples, 7);
  return std::max(far.fromA, far.fromB);
}

double segmentDistance(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

// The mean two-sided distance between the polyline and the target's profile points, the
// polyline's points weighted by their distance from the centre (the area of the sheet there).
struct ProfileDistance {
  double mean = 0.0, farthest = 0.0;  // the two-sided mean; the target's farthest point
  double score(double weight) const { return mean + weight * farthest; }
};
ProfileDistance profileDistance(const std::vector<glm::dvec2>& polyline,
                                const std::vector<glm::dvec2>& target, double sheetRadius) {
  double toPolyline = 0.0, farthest = 0.0;
  for (const glm::dvec2& p : target) {
    double best = 1e300;
    for (std::size_t i = 0; i + 1 < polyline.size(); ++i)
      best = std::min(best, segmentDistance(p, polyline[i], polyline[i + 1]));
    toPolyline += best;
    farthest = std::max(farthest, best);
  }
  toPolyline /= static_cast<double>(target.size());
  // Points along the polyline by their distance s from the centre (its length is the radius).
  double toTarget = 0.0, weights = 0.0;
  std::size_t segment = 0;
  double segmentStart = 0.0;
  for (std::size_t j = 0; j < kPolylinePoints; ++j) {
    const double s = sheetRadius * (static_cast<double>(j) + 0.5) / kPolylinePoints;
    while (segment + 2 < polyline.size() &&
           s > segmentStart + glm::length(polyline[segment + 1] - polyline[segment])) {
      segmentStart += glm::length(polyline[segment + 1] - polyline[segment]);
      ++segment;
    }
    const glm::dvec2 a = polyline[segment], b = polyline[segment + 1];
    const double length = glm::length(b - a);
    const glm::dvec2 point = length > 0.0 ? a + (s - segmentStart) / length * (b - a) : a;
    double best = 1e300;
    for (const glm::dvec2& q : target) best = std::min(best, glm::dot(point - q, point - q));
    toTarget += s * std::sqrt(best);
    weights += s;
  }
  return {0.5 * (toPolyline + toTarget / weights), farthest};
}

// A fit's parameters as Subplex sees them: the shift, then the creases' distances from the
// centre as fractions of the radius, then their angles.
std::vector<double> packed(const ProfileCreases& creases, double sheetRadius) {
  std::vector<double> x{creases.shift};
  for (double s : creases.arcs) x.push_back(s / sheetRadius);
  x.insert(x.end(), creases.angles.begin(), creases.angles.end());
  return x;
}

ProfileCreases unpacked(const std::vector<double>& x, double sheetRadius) {
  const std::size_t k = (x.size() - 1) / 2;
  ProfileCreases creases;
  creases.shift = x[0];
  std::vector<std::pair<double, double>> pairs;
  for (std::size_t i = 0; i < k; ++i) pairs.emplace_back(x[1 + i], x[1 + k + i]);
  std::sort(pairs.begin(), pairs.end());
  for (const auto& [s, angle] : pairs) {
    creases.arcs.push_back(sheetRadius * s);
    creases.angles.push_back(angle);
  }
  return creases;
}

}  // namespace

std::vector<glm::dvec2> profilePolyline(const ProfileCreases& creases, double sheetRadius) {
  std::vector<glm::dvec2> polyline{{0.0, creases.shift}};
  double s = 0.0, angle = 0.0;
  for (std::size_t i = 0; i < creases.arcs.size(); ++i) {
    const double next = std::clamp(creases.arcs[i], s, sheetRadius);
    polyline.push_back(polyline.back() + (next - s) * glm::dvec2(std::cos(angle), std::sin(angle)));
    s = next;
    angle = creases.angles[i];
  }
  polyline.push_back(polyline.back() +
                     (sheetRadius - s) * glm::dvec2(std::cos(angle), std::sin(angle)));
  return polyline;
}

std::vector<glm::dvec2> meridianProfile(const std::vector<SurfaceSample>& samples,
                                        const glm::dvec3& centre, const RevolutionAxis& axis,
                                        std::size_t pointCount) {
  std::vector<glm::dvec2> profile;
  const std::size_t stride =
      std::max<std::size_t>(1, samples.size() / std::max<std::size_t>(1, pointCount));
  for (std::size_t i = 0; i < samples.size(); i += stride) {
    const glm::dvec3 d = samples[i].position - centre;
    const double h = glm::dot(d, axis.direction);
    profile.push_back({glm::length(d - h * axis.direction), h});
  }
  return profile;
}

ProfileCreases fitProfileCreases(const std::vector<glm::dvec2>& target, double sheetRadius,
                                 std::size_t creaseCount, const ProfileCreases* start,
                                 std::mt19937_64& random, double farthestWeight) {
  double low = 1e300, high = -1e300;
  for (const glm::dvec2& p : target) {
    low = std::min(low, p.y);
    high = std::max(high, p.y);
  }
  // The starts: the fit with fewer creases grown by one that turns nothing, then random ones.
  std::vector<ProfileCreases> starts;
  if (start && start->arcs.size() < creaseCount) {
    ProfileCreases grown = *start;
    while (grown.arcs.size() < creaseCount) {
      const double s = sheetRadius * (0.1 + 0.85 * unit(random));
      const auto at = std::upper_bound(grown.arcs.begin(), grown.arcs.end(), s);
      const auto i = at - grown.arcs.begin();
      const double angle = i == 0 ? 0.0 : grown.angles[static_cast<std::size_t>(i - 1)];
      grown.arcs.insert(at, s);
      grown.angles.insert(grown.angles.begin() + i, angle);
    }
    starts.push_back(grown);
  }
  for (int r = 0; r < kRestarts; ++r) {
    ProfileCreases random_start;
    random_start.shift = low + (high - low) * unit(random);
    const double side = unit(random) < 0.5 ? -1.0 : 1.0;
    for (std::size_t i = 0; i < creaseCount; ++i)
      random_start.arcs.push_back(sheetRadius * (0.05 + 0.9 * unit(random)));
    std::sort(random_start.arcs.begin(), random_start.arcs.end());
    double angle = 0.0;
    for (std::size_t i = 0; i < creaseCount; ++i) {
      angle += side * unit(random) * 0.5 * kPi / static_cast<double>(creaseCount) * 1.5;
      random_start.angles.push_back(angle);
    }
    starts.push_back(random_start);
  }

  ProfileCreases best;
  best.score = 1e300;
  for (const ProfileCreases& from : starts) {
    std::vector<double> x = packed(from, sheetRadius);
    const std::size_t k = creaseCount;
    std::vector<double> lower(x.size()), upper(x.size()), step(x.size());
    const double extent = std::max(high - low, 0.05 * sheetRadius);
    lower[0] = low - sheetRadius;
    upper[0] = high + sheetRadius;
    step[0] = 0.1 * extent;
    for (std::size_t i = 0; i < k; ++i) {
      lower[1 + i] = 0.02;
      upper[1 + i] = 0.98;
      step[1 + i] = 0.05;
      lower[1 + k + i] = -kPi;
      upper[1 + k + i] = kPi;
      step[1 + k + i] = 0.15;
    }
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::clamp(x[i], lower[i], upper[i]);
    const SubplexBounds bounds{lower, upper};
    minimizeSubplex(
        x, step, kProfileEvaluations,
        [&](const std::vector<double>& y) {
          return profileDistance(profilePolyline(unpacked(y, sheetRadius), sheetRadius), target,
                                 sheetRadius)
              .score(farthestWeight);
        },
        nullptr, &bounds);
    ProfileCreases fitted = unpacked(x, sheetRadius);
    const ProfileDistance distance =
        profileDistance(profilePolyline(fitted, sheetRadius), target, sheetRadius);
    fitted.score = distance.score(farthestWeight);
    fitted.mean = distance.mean;
    if (fitted.score < best.score) best = fitted;
  }
  return best;
}

bool outermostFirstHolds(const ProfileCreases& creases, double sheetRadius) {
  const std::vector<NestedRing> rings = nestedRingShapes(creases, 3, 0.0, sheetRadius, true);
  // The centre line's points, at height 0 (the shift moves them all alike).
  std::vector<double> arcs;
  std::vector<glm::dvec2> line;
  for (std::size_t i = 0; i <= kPolylinePoints; ++i) {
    arcs.push_back(sheetRadius * static_cast<double>(i) / kPolylinePoints);
    line.push_back({arcs.back(), 0.0});
  }
  for (const NestedRing& ring : rings) {
    if (ring.shape.order == 1) continue;
    const glm::dvec2 normal(std::cos(ring.shape.tilt), std::sin(ring.shape.tilt));
    const glm::dvec2 at(ring.shape.radius, 0.0);
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (!(arcs[i] > ring.shape.radius)) continue;
      const double side = glm::dot(normal, line[i] - at);
      if (side < -1e-9 * sheetRadius) return false;
      line[i] -= 2.0 * side * normal;
    }
  }
  return true;
}

std::vector<NestedRing> nestedRingShapes(const ProfileCreases& creases, int order, double turn,
                                         double sheetRadius, bool outerFirst) {
  std::vector<NestedRing> rings;
  // The sheet lies at height 0; a plane across the axis halfway to the shift moves it there,
  // folding the side its normal points to (the sheet's).
  if (std::abs(creases.shift) > 0.005 * sheetRadius) {
    NestedRing across;
    across.shape.height = 0.5 * creases.shift;
    across.shape.tilt = (creases.shift < 0.0 ? 0.5 : -0.5) * kPi;
    across.shape.order = 1;
    rings.push_back(across);
  }
  const std::vector<glm::dvec2> polyline = profilePolyline(creases, sheetRadius);
  std::vector<NestedRing> nested;
  double before = 0.0;
  for (std::size_t i = 0; i < creases.arcs.size(); ++i) {
    const double after = creases.angles[i];
    // Inner first, each crease turns the flap where the rings before it left it: from `before`
    // to `after`. Outer first, each is drawn on the flat sheet, turned by the same angle with the
    // sign each later (inner) ring's reflection flips: the i-th crease's flap is reflected by
    // the i - 1 rings inside it.
    const double flat = (i % 2 == 0 ? 1.0 : -1.0) * (after - before);
    const glm::dvec2 from =
        outerFirst ? glm::dvec2(1.0, 0.0) : glm::dvec2(std::cos(before), std::sin(before));
    const glm::dvec2 to = outerFirst ? glm::dvec2(std::cos(flat), std::sin(flat))
                                     : glm::dvec2(std::cos(after), std::sin(after));
    const glm::dvec2 normal = from - to;
    before = after;
    // A crease that turns nothing, or one at the centre, makes no ring.
    if (!(glm::length(normal) > 1e-3) || !(polyline[i + 1].x > 1e-6 * sheetRadius)) continue;
    const double arc = std::min(creases.arcs[i], sheetRadius);
    NestedRing ring;
    ring.shape.height = outerFirst ? creases.shift : polyline[i + 1].y;
    ring.shape.radius = outerFirst ? arc : polyline[i + 1].x;
    ring.shape.tilt = std::atan2(normal.y, normal.x);
    ring.shape.turn = turn;
    ring.shape.order = order;
    // Before this ring the sheet beyond the crease runs straight on to the rim.
    ring.flap = 0.5 * (sheetRadius - arc) * from;
    nested.push_back(ring);
  }
  if (outerFirst) std::reverse(nested.begin(), nested.end());
  rings.insert(rings.end(), nested.begin(), nested.end());
  return rings;
}

namespace {

// Each plane of `shape` folded on the session, seeded at the sheet vertex on its side nearest to
// where the flap beyond it lies (along `flap`, in the meridian: (r, z)), so the fold takes its
// own flap and not another the plane reaches. On a session whose rotation makes the ring (its
// images), only the first plane. Returns how many folds were made, images included.
std::size_t makeNestedRing(FoldSession& session, const RingShape& shape, const RevolutionAxis& axis,
                           const glm::dvec2& flap, const AzimuthReach& reach) {
  std::size_t made = 0;
  Ring ring = ringOf(shape, axis);
  if (session.symmetricFolder()) ring.planes.resize(1);
  // An oblong target's ring: each plane off the axis in proportion to its reach that way.
  if (shape.order > 1 && !reach.scale.empty())
    for (ReflectionPlane& plane : ring.planes) {
      const double h = glm::dot(plane.point - axis.point, axis.direction);
      const glm::dvec3 radial = plane.point - axis.point - h * axis.direction;
      plane.point = axis.point + h * axis.direction + reach.at(radial) * radial;
    }
  for (const ReflectionPlane& plane : ring.planes) {
    const Sheet& sheet = session.fixed();
    glm::dvec3 radial = plane.point - axis.point;
    radial -= glm::dot(radial, axis.direction) * axis.direction;
    const double r = glm::length(radial);
    const glm::dvec3 want = shape.order == 1 || !(r > 0.0)
                                ? axis.point
                                : plane.point + flap.x * (radial / r) + flap.y * axis.direction;
    std::optional<std::size_t> seed;
    double nearest = 1e300;
    for (std::size_t v = 0; v < sheet.positions.size(); ++v) {
      if (!(plane.signedDistance(sheet.positions[v]) > 2.0 * session.minimumDrag())) continue;
      const double d = glm::distance(sheet.positions[v], want);
      if (d < nearest) {
        nearest = d;
        seed = v;
      }
    }
    if (!seed) continue;                                      // the plane misses the sheet
    const glm::dvec2 development = sheet.development[*seed];  // a copy: the drag changes sheets
    const glm::dvec3 grabbed = session.beginDragAtDevelopment(development);
    session.updateDrag(plane.reflect(grabbed));
    const std::size_t before = session.foldCount();
    if (session.commit()) made += session.foldCount() - before;
  }
  return made;
}

// The sheet's centre and radius about `direction` when it lies flat across it, and that direction
// (the rings' axis).
struct FlatSheet {
  glm::dvec3 centre{0.0}, direction{0.0};
  double radius = 0.0;
};
std::optional<FlatSheet> flatAbout(const Sheet& sheet, const glm::dvec3& direction) {
  if (sheet.positions.empty()) return std::nullopt;
  FlatSheet flat;
  flat.direction = direction;
  for (const glm::dvec3& p : sheet.positions) flat.centre += p;
  flat.centre /= static_cast<double>(sheet.positions.size());
  double lowest = 1e300, highest = -1e300;
  for (const glm::dvec3& p : sheet.positions) {
    const double h = glm::dot(p - flat.centre, direction);
    lowest = std::min(lowest, h);
    highest = std::max(highest, h);
    flat.radius = std::max(flat.radius, glm::length((p - flat.centre) - h * direction));
  }
  if (!(flat.radius > 0.0) || highest - lowest > kFlatSheet * flat.radius) return std::nullopt;
  return flat;
}

// Flat across `direction`, or about its own normal where that lies within kAxisSlack of it (see
// kAxisSlack); the rings then fold about the sheet's normal.
std::optional<FlatSheet> flatSheetAcross(const Sheet& sheet, const glm::dvec3& direction) {
  if (std::optional<FlatSheet> flat = flatAbout(sheet, direction)) return flat;
  glm::dvec3 normal(0.0);  // area-weighted: a folded sheet's faces cancel, and it is not flat
  for (const Triangle& t : sheet.triangles)
    normal += glm::cross(sheet.positions[t[1]] - sheet.positions[t[0]],
                         sheet.positions[t[2]] - sheet.positions[t[0]]);
  if (!(glm::length(normal) > 0.0)) return std::nullopt;
  normal = glm::normalize(normal);
  if (glm::dot(normal, direction) < 0.0) normal = -normal;
  if (glm::dot(normal, direction) < std::cos(kAxisSlack)) return std::nullopt;
  return flatAbout(sheet, normal);
}

struct Candidate {
  ProfileCreases creases;
  int order = 8;
  bool outerFirst = false;
  bool rim = false;  // from the rim's fits
};

// The steepest turn of a fit's polyline from the sheet's plane (radians).
double steepest(const ProfileCreases& creases) {
  double most = 0.0;
  for (double angle : creases.angles) most = std::max(most, std::abs(angle));
  return most;
}

}  // namespace

bool liesFlatAcross(const Sheet& sheet, const RevolutionAxis& axis) {
  return ringsAxis(sheet, axis).has_value();
}

std::optional<RevolutionAxis> ringsAxis(const Sheet& sheet, const RevolutionAxis& axis) {
  const std::optional<FlatSheet> flat = flatSheetAcross(sheet, axis.direction);
  if (!flat) return std::nullopt;
  return RevolutionAxis{flat->centre, flat->direction, axis.spread};
}

std::vector<FoldSuggestion> suggestNestedRings(const FoldSession& session, const FoldFitter& fitter,
                                               const RevolutionAxis& axis,
                                               const std::vector<SurfaceSample>& targetSamples,
                                               std::size_t count, const Deadline& deadline,
                                               std::mt19937_64& random, std::size_t mostCreases) {
  if (count == 0 || targetSamples.empty() || deadline.givesUp()) return {};
  // The sheet: flat across the axis? Its centre is the rings' axis point.
  const Sheet& sheet = session.fixed();
  const std::optional<FlatSheet> flat = flatSheetAcross(sheet, axis.direction);
  if (!flat) return {};
  const glm::dvec3 centre = flat->centre;
  // The target's axis, or the sheet's normal within kAxisSlack of it.
  const RevolutionAxis local{centre, flat->direction, 0.0};
  // A design with a rotation of its own (--symmetry) folds each ring as one fold and its images,
  // when that rotation is about this axis through the sheet's centre; any other symmetry, none.
  std::vector<int> orders(kOrders.begin(), kOrders.end());
  if (session.symmetricFolder()) {
    const Symmetry* symmetry = session.symmetry();
    glm::dvec3 about(0.0);
    about[symmetry->axis] = 1.0;
    const glm::dvec3 off = symmetry->centre - centre;
    if (symmetry->kind != Symmetry::Kind::Rotational ||
        std::abs(glm::dot(about, axis.direction)) < 0.999 ||
        glm::length(off - glm::dot(off, about) * about) > 0.01 * flat->radius)
      return {};
    orders = {symmetry->order};
  }

  // An oblong target: its profile read with each sample's distance from the axis over the
  // target's reach that way, and the model's radius the sheet's reach over the same, on average.
  const AzimuthReach reach = session.symmetricFolder()
                                 ? AzimuthReach{}
                                 : azimuthReach(targetSamples, centre, local.direction);
  std::vector<glm::dvec2> profile = meridianProfile(targetSamples, centre, local, kProfilePoints);
  double radius = flat->radius;
  if (!reach.scale.empty()) {
    const std::size_t stride = std::max<std::size_t>(1, targetSamples.size() / kProfilePoints);
    for (std::size_t i = 0, k = 0; i < targetSamples.size() && k < profile.size();
         i += stride, ++k) {
      glm::dvec3 radial = targetSamples[i].position - centre;
      radial -= glm::dot(radial, local.direction) * local.direction;
      profile[k].x /= reach.at(radial);
    }
    const std::vector<double> sheetReach =
        reachByBin(reach, sheet.positions, centre, local.direction);
    double sum = 0.0;
    for (int b = 0; b < kReachBins; ++b)
      sum += sheetReach[static_cast<std::size_t>(b)] / reach.scale[static_cast<std::size_t>(b)];
    radius = sum / kReachBins;
  }

  // Fits with 1..mostCreases creases, each grown from the one before (the random draws made
  // here, in order, so a seed repeats).
  std::mt19937_64 rimRandom = random;  // the rim's fits (below) start from the same draws
  std::vector<ProfileCreases> fits;
  for (std::size_t k = 1; k <= mostCreases && !deadline.passed(); ++k) {
    deadline.countEvaluation();
    fits.push_back(
        fitProfileCreases(profile, radius, k, fits.empty() ? nullptr : &fits.back(), random));
  }
  // The rim's fits (kRimFarthest), from the same random starts as the fits above (a copy of the
  // generator as it was), so the fits above and the rings' turn below are drawn as before.
  std::vector<ProfileCreases> rimFits;
  for (std::size_t k = 1; k <= mostCreases && !deadline.passed(); ++k) {
    deadline.countEvaluation();
    rimFits.push_back(fitProfileCreases(
        profile, radius, k, rimFits.empty() ? nullptr : &rimFits.back(), rimRandom, kRimFarthest));
  }
  if (deadline.givesUp()) return {};
  // Coarse to fine, in batches: first the fit nearest the profile at the coarsest order (a step
  // of the fewest folds that follows the profile best), then that fit's other orders and its
  // rings drawn outermost first (with two creases or more, where the centre line allows it: see
  // the header), then each other fit by its distance to the profile. Between batches the clock
  // is read, and a batch the time left would not finish (judged by the last batch's seconds per
  // fold) is not started: the step still lands, coarser, on a loaded machine. The rim's fits
  // follow, in the same order among themselves.
  std::vector<const ProfileCreases*> byScore;
  for (const std::vector<ProfileCreases>* set : {&fits, &rimFits}) {
    const std::size_t from = byScore.size();
    for (const ProfileCreases& fit : *set) byScore.push_back(&fit);
    std::stable_sort(
        byScore.begin() + static_cast<std::ptrdiff_t>(from), byScore.end(),
        [](const ProfileCreases* a, const ProfileCreases* b) { return a->score < b->score; });
  }
  std::vector<Candidate> candidates;
  std::vector<std::size_t> batchEnds;
  for (const ProfileCreases* each : byScore) {
    const ProfileCreases& fit = *each;
    const bool rim = each >= rimFits.data() && each < rimFits.data() + rimFits.size();
    const bool outerToo = fit.arcs.size() >= 2 && outermostFirstHolds(fit, radius);
    std::vector<int> fitOrders = orders;
    if (!session.symmetricFolder() && steepest(fit) > kSteepWall)
      fitOrders.insert(fitOrders.begin(), kSteepOrders.begin(), kSteepOrders.end());
    for (int order : fitOrders) {
      candidates.push_back({fit, order, false, rim});
      if (batchEnds.empty()) batchEnds.push_back(candidates.size());  // the coarsest first
    }
    if (outerToo)
      for (int order : fitOrders) candidates.push_back({fit, order, true, rim});
    if (batchEnds.back() != candidates.size()) batchEnds.push_back(candidates.size());
  }
  const double turn = unit(random) * 2.0 * kPi;

  const std::vector<FoldRecord> base(
      session.folds().begin(),
      session.folds().begin() + static_cast<std::ptrdiff_t>(session.foldCount()));
  const double before = fitter.approximateDistance(sheet);
  const bool allowCrossing = fitter.settings().allowSelfIntersection;
  const std::size_t crossingsBefore =
      allowCrossing ? 0 : findSelfIntersections(sheet).intersections.size();
  const double farthestBefore = farthestApart(sheet, fitter.measuredTarget());
  std::vector<FoldSuggestion> made(candidates.size());
  std::vector<double> farthest(candidates.size(), 0.0);
  // Each candidate on a session made afresh at the base design: taking its folds back one undo at
  // a time replayed the sheet from a keyframe and rebuilt its adjacency for each fold, several
  // times what the folds themselves cost (the base is replayed once, and is short or empty).
  const auto foldsOf = [&](std::size_t from, std::size_t to) {
    double folds = 0.0;
    for (std::size_t c = from; c < to; ++c)
      folds += static_cast<double>(candidates[c].order * candidates[c].creases.arcs.size());
    return folds;
  };
  const auto evaluate = [&](std::size_t c) {
    if (deadline.passed()) return;
    deadline.countEvaluation();
    FoldSession own(session.initial());
    if (session.symmetricFolder()) own.setSymmetry(*session.symmetry());
    own.applyRecords(base);
    const Candidate& candidate = candidates[c];
    // Ring after ring; one that passes the sheet through itself (on a steep profile a ring's
    // planes can take the corner paper of the flaps beside their own) is taken back, and the
    // rings before it kept.
    for (const NestedRing& ring :
         nestedRingShapes(candidate.creases, candidate.order, turn / candidate.order, radius,
                          candidate.outerFirst)) {
      const std::size_t foldsBefore = own.foldCount();
      if (makeNestedRing(own, ring.shape, local, ring.flap, reach) == 0) continue;
      const auto crosses = [&] {
        return !allowCrossing &&
               findSelfIntersections(own.fixed()).intersections.size() > crossingsBefore;
      };
      if (crosses()) {
        own.undoTo(foldsBefore);
        if (candidate.outerFirst) continue;
        // On a steep cup the rings after the second met the corner paper the first two left
        // and crossed it, so every fit stopped at two rings short of the rim: such a ring is
        // drawn again turned by half a polygon side (its planes at the corners, where the
        // paper stands out), and kept where that crosses nothing.
        if (ring.shape.order > 1) {
          RingShape turned = ring.shape;
          turned.turn += kPi / turned.order;
          if (makeNestedRing(own, turned, local, ring.flap, reach) > 0 && !crosses()) continue;
          own.undoTo(foldsBefore);
        }
        break;
      }
    }
    if (own.foldCount() > base.size()) {
      made[c].folds.assign(own.folds().begin() + static_cast<std::ptrdiff_t>(base.size()),
                           own.folds().begin() + static_cast<std::ptrdiff_t>(own.foldCount()));
      made[c].sheet = own.fixed();
      made[c].before = before;
      made[c].after = fitter.approximateDistance(made[c].sheet);
      farthest[c] = farthestApart(made[c].sheet, fitter.measuredTarget());
    }
  };
  TimedBatches batches(deadline);
  for (std::size_t b = 0, from = 0; b < batchEnds.size(); from = batchEnds[b++])
    if (!batches.run(from, batchEnds[b], foldsOf(from, batchEnds[b]), evaluate)) break;
  // A cancel answers nothing; the clock, what the batches finished (each candidate is whole).
  if (deadline.isCancelled()) return {};
  std::vector<FoldSuggestion> out;
  const auto offered = [&](std::size_t c) {
    return !made[c].folds.empty() && made[c].after < before &&
           farthest[c] <= kFarthestSlack * farthestBefore;
  };
  // The rim's fits are there to bring the farthest point in: a step of theirs is offered only
  // where it stands no farther out than the usual fits' nearest step (on a steep cup one scored
  // nearer by the search's score, which cuts far distances, and stood out farther: small_cup
  // Hausdorff 8.73% -> 13.9%).
  std::optional<double> usualFarthest;
  double usualAfter = 1e300;
  for (std::size_t c = 0; c < made.size(); ++c)
    if (!candidates[c].rim && offered(c) && made[c].after < usualAfter) {
      usualAfter = made[c].after;
      usualFarthest = farthest[c];
    }
  const auto kept = [&](std::size_t c) {
    return offered(c) && !(candidates[c].rim && usualFarthest && farthest[c] > *usualFarthest);
  };
  double nearestAfter = 1e300;
  for (std::size_t c = 0; c < made.size(); ++c)
    if (kept(c)) nearestAfter = std::min(nearestAfter, made[c].after);
  // Of the steps within kTiedNearest of the nearest by the search's score, only the one standing
  // out least is offered: the score cuts far distances, and on a steep cup steps 1% apart by it
  // stood 7.4 and 12.4 mm out.
  double tiedFarthest = 1e300;
  for (std::size_t c = 0; c < made.size(); ++c)
    if (kept(c) && made[c].after <= (1.0 + kTiedNearest) * nearestAfter)
      tiedFarthest = std::min(tiedFarthest, farthest[c]);
  for (std::size_t c = 0; c < made.size(); ++c)
    if (kept(c) &&
        !(made[c].after <= (1.0 + kTiedNearest) * nearestAfter && farthest[c] > tiedFarthest))
      out.push_back(std::move(made[c]));
  std::stable_sort(out.begin(), out.end(),
                   [](const auto& a, const auto& b) { return a.after < b.after; });
  if (out.size() > count) out.resize(count);
  return out;
}

}  // namespace curvefold
