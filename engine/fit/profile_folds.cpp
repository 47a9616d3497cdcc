#include "engine/fit/profile_folds.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include <Eigen/Dense>
#include <glm/geometric.hpp>
#include <memory>

#include <tbb/parallel_for.h>

#include "engine/fit/eigen_glm.hpp"
#include "engine/fit/lobed_saddle.hpp"
#include "engine/fit/subplex.hpp"
#include "engine/fit/unit_draw.hpp"
#include "engine/geometry/principal_moments.hpp"
#include "engine/geometry/self_intersection.hpp"

namespace curvefold {
namespace {

constexpr int kBins = 24;
// A sample whose normal lies this close to the axis (18 degrees) is on a cap across it (a closed
// bottom, a level shoulder), which holds every radius at one height.
constexpr double kAcrossAxis = 0.95;
// The caps set aside from the spread by height only while they hold under this share of the
// samples (a bottle's bottom 0.07; a saddle's middle, normal to its short axis, about 0.3, so a
// saddle is measured whole as before).
constexpr double kMostCapped = 0.25;
// Sheet samples a ring is previewed on, rings refined per step, and evaluations each.
constexpr std::size_t kPreviewSamples = 800;
constexpr std::size_t kRefinedRings = 4;
constexpr std::size_t kRingRefineEvaluations = 60;
// Principal variances within this ratio leave their axes to the samples' chance (revolutionAxis
// polishes them), and the evaluations a polish gets (each a pass over the samples).
constexpr double kSwungVariances = 1.25;
constexpr int kAxisPolishEvaluations = 200;

// A unit vector perpendicular to `a`.
glm::dvec3 perpendicular(const glm::dvec3& a) {
  const glm::dvec3 other = std::abs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return glm::normalize(glm::cross(other, a));
}

// Height along the axis and distance from it.
glm::dvec2 heightAndRadius(const glm::dvec3& p, const RevolutionAxis& axis) {
  const glm::dvec3 d = p - axis.point;
  const double t = glm::dot(d, axis.direction);
  return {t, glm::length(d - t * axis.direction)};
}

// The root mean square deviation of `value` within bins of `key`, over the mean radius.
double spreadWithin(const std::vector<glm::dvec2>& profile, bool byHeight, double meanRadius) {
  double lo = 1e300, hi = -1e300;
  for (const glm::dvec2& p : profile) {
    const double key = byHeight ? p.x : p.y;
    lo = std::min(lo, key);
    hi = std::max(hi, key);
  }
  if (!(hi > lo)) return 0.0;  // every sample at one key: constant within its one bin? measured
  std::array<double, kBins> sum{}, sumSquares{};
  std::array<int, kBins> count{};
  auto bin = [&](double key) {
    return std::clamp(static_cast<int>((key - lo) / (hi - lo) * kBins), 0, kBins - 1);
  };
  for (const glm::dvec2& p : profile) {
    const int b = bin(byHeight ? p.x : p.y);
    const double value = byHeight ? p.y : p.x;
    sum[b] += value;
    sumSquares[b] += value * value;
    ++count[b];
  }
  double squares = 0.0;
  int counted = 0;
  for (int b = 0; b < kBins; ++b) {
    if (count[b] < 3) continue;
    const double mean = sum[b] / count[b];
    squares += std::max(0.0, sumSquares[b] - count[b] * mean * mean);
    counted += count[b];
  }
  if (counted == 0) return 1e300;
  return std::sqrt(squares / counted) / meanRadius;
}

// The same spread with each sample's distance from the axis divided by the target's reach in
// its direction about the axis (the farthest sample of kBins turns, smoothed over three, over
// their mean): an oval cup's rim, 1.36 times wider one way, spreads its radius by 0.13 of the
// mean at each height, its shape along the turn by 0.07. 1e300 where a turn holds no sample.
double ovalSpreadWithin(std::vector<glm::dvec2> profile, const std::vector<SurfaceSample>& samples,
                        const RevolutionAxis& axis) {
  const glm::dvec3 u = perpendicular(axis.direction);
  const glm::dvec3 v = glm::cross(axis.direction, u);
  std::vector<int> turnOf(samples.size());
  std::array<double, kBins> reach{};
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const glm::dvec3 d = samples[i].position - axis.point;
    const double angle = std::atan2(glm::dot(d, v), glm::dot(d, u));
    turnOf[i] =
        std::clamp(static_cast<int>((angle + std::numbers::pi) / (2.0 * std::numbers::pi) * kBins),
                   0, kBins - 1);
    reach[static_cast<std::size_t>(turnOf[i])] =
        std::max(reach[static_cast<std::size_t>(turnOf[i])], profile[i].y);
  }
  std::array<double, kBins> scale{};
  double mean = 0.0;
  for (int b = 0; b < kBins; ++b) {
    for (int j = -1; j <= 1; ++j) {
      const double r = reach[static_cast<std::size_t>((b + j + kBins) % kBins)];
      if (!(r > 0.0)) return 1e300;
      scale[static_cast<std::size_t>(b)] += r / 3.0;
    }
    mean += scale[static_cast<std::size_t>(b)] / kBins;
  }
  double meanRadius = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    profile[i].y *= mean / scale[static_cast<std::size_t>(turnOf[i])];
    meanRadius += profile[i].y / static_cast<double>(samples.size());
  }
  if (!(meanRadius > 0.0)) return 1e300;
  return std::min(spreadWithin(profile, true, meanRadius),
                  spreadWithin(profile, false, meanRadius));
}

// The spread about `axis` by height (caps across the axis left out while they are few: a
// bottle's closed bottom holds its radii 0 to R in one bin, 0.24 R deviation; the meridian
// bottle read 0.103 with them) or by radius (a disk, a shallow dish, whose radius runs over its
// whole range within a thin band of heights), the lesser; `profile` gets every sample's (height,
// radius), `byHeight` (when given) the spread by height alone. -1 where the samples lie on the
// axis.
double plainSpread(const std::vector<SurfaceSample>& samples, const RevolutionAxis& axis,
                   std::vector<glm::dvec2>& profile, double* byHeight = nullptr) {
  profile.clear();
  std::vector<glm::dvec2> walls;
  double meanRadius = 0.0;
  for (const SurfaceSample& s : samples) {
    profile.push_back(heightAndRadius(s.position, axis));
    meanRadius += profile.back().y;
    if (std::abs(glm::dot(s.normal, axis.direction)) < kAcrossAxis) walls.push_back(profile.back());
  }
  meanRadius /= static_cast<double>(samples.size());
  if (!(meanRadius > 0.0)) return -1.0;
  const bool capped = walls.size() < profile.size() &&
                      static_cast<double>(walls.size()) >=
                          (1.0 - kMostCapped) * static_cast<double>(profile.size());
  const double height = spreadWithin(capped ? walls : profile, true, meanRadius);
  if (byHeight) *byHeight = height;
  return std::min(height, spreadWithin(profile, false, meanRadius));
}

// Whether the target's height along `axis` swings with the turn about it, as a saddle's does and
// no surface of revolution's: read by radius (the samples binned by distance from the axis, only
// the bins the target covers all around), the height's harmonics of order 2 to 6 in the turn
// (order 1 is a tilt of the axis) stand out farther than the bins' mean heights rise from the
// innermost's, and hold most of the height's spread within the bins. A monkey saddle over a
// triangle whose corners lie on its falling lobes (bench/make_lattice_saddles.py) holds nearly one
// height at each radius past the triangle's inner circle, so its spread by radius (0.075 of the
// mean radius) passed as a dish's; inside that circle its height is 0.8 r^3 / R^2 cos(3 t): mean
// zero, all swing. An oval bowl's height swings at order 2 too, but by a fraction of its rise
// (0.3 of it where the footprint is 1.36 times longer one way); a tube's heights within a bin
// are scattered along its length, no harmonic holds them. Asked only where the axis holds by radius
// alone (its spread by height above the bound): a mug's handle swings a cup's heights by radius,
// but its walls keep one radius at each height.
// `order` and `share`, when given: the order whose harmonic holds most of the swing's mean square
// (summed over the bins as weighted), and its share of it.
bool swingsWithTurn(const std::vector<SurfaceSample>& samples, const RevolutionAxis& axis,
                    int* order = nullptr, double* share = nullptr) {
  constexpr int kOrders = 6;
  constexpr int kTerms = 2 * kOrders + 1;
  constexpr int kSectors = 12;              // the turn's sectors a bin must cover, all but one
  constexpr int kLeastPerBin = 4 * kTerms;  // samples a bin's fit needs
  const glm::dvec3 u = perpendicular(axis.direction);
  const glm::dvec3 v = glm::cross(axis.direction, u);
  std::vector<glm::dvec3> polar;  // (radius, height, angle)
  polar.reserve(samples.size());
  double most = 0.0;
  for (const SurfaceSample& s : samples) {
    const glm::dvec3 d = s.position - axis.point;
    const double h = glm::dot(d, axis.direction);
    const glm::dvec3 across = d - h * axis.direction;
    polar.emplace_back(glm::length(across), h,
                       std::atan2(glm::dot(across, v), glm::dot(across, u)));
    most = std::max(most, polar.back().x);
  }
  if (!(most > 0.0)) return false;
  std::array<std::vector<int>, kBins> bins;
  for (std::size_t i = 0; i < polar.size(); ++i)
    bins[static_cast<std::size_t>(
             std::clamp(static_cast<int>(polar[i].x / most * kBins), 0, kBins - 1))]
        .push_back(static_cast<int>(i));
  double swing = 0.0, rise = 0.0, swingSquares = 0.0, restSquares = 0.0, counted = 0.0;
  std::array<double, kOrders + 1> byOrder{};  // each order's mean square, weighted
  std::optional<double> innermost;
  for (const std::vector<int>& bin : bins) {
    if (static_cast<int>(bin.size()) < kLeastPerBin) continue;
    std::array<bool, kSectors> covered{};
    Eigen::Matrix<double, kTerms, kTerms> normal = Eigen::Matrix<double, kTerms, kTerms>::Zero();
    Eigen::Matrix<double, kTerms, 1> right = Eigen::Matrix<double, kTerms, 1>::Zero();
    auto terms = [](double angle) {
      Eigen::Matrix<double, kTerms, 1> t;
      t(0) = 1.0;
      for (int k = 1; k <= kOrders; ++k) {
        t(2 * k - 1) = std::cos(k * angle);
        t(2 * k) = std::sin(k * angle);
      }
      return t;
    };
    for (const int i : bin) {
      const double angle = polar[static_cast<std::size_t>(i)].z;
      covered[static_cast<std::size_t>(std::clamp(
          static_cast<int>((angle + std::numbers::pi) / (2.0 * std::numbers::pi) * kSectors), 0,
          kSectors - 1))] = true;
      const Eigen::Matrix<double, kTerms, 1> t = terms(angle);
      normal += t * t.transpose();
      right += t * polar[static_cast<std::size_t>(i)].y;
    }
    if (std::count(covered.begin(), covered.end(), true) < kSectors - 1) continue;
    const Eigen::Matrix<double, kTerms, 1> c = normal.ldlt().solve(right);
    double harmonic = 0.0;  // the mean square of the orders 2 to 6 over the turn
    for (int j = 3; j < kTerms; ++j) harmonic += 0.5 * c(j) * c(j);
    double rest = 0.0;
    for (const int i : bin) {
      const double r =
          polar[static_cast<std::size_t>(i)].y - terms(polar[static_cast<std::size_t>(i)].z).dot(c);
      rest += r * r;
    }
    const double n = static_cast<double>(bin.size());
    if (!innermost) innermost = c(0);
    swing += n * std::sqrt(harmonic);
    rise += n * std::abs(c(0) - *innermost);
    swingSquares += n * harmonic;
    for (int k = 2; k <= kOrders; ++k)
      byOrder[static_cast<std::size_t>(k)] +=
          n * 0.5 * (c(2 * k - 1) * c(2 * k - 1) + c(2 * k) * c(2 * k));
    counted += n;
    restSquares += rest;
  }
  const auto leading = std::max_element(byOrder.begin() + 2, byOrder.end());
  if (order) *order = static_cast<int>(leading - byOrder.begin());
  if (share) *share = swingSquares > 0.0 ? *leading / swingSquares : 0.0;
  // Measurably (a flat sheet's heights differ by rounding alone): a thousandth of the reach.
  return innermost && swing > rise && swingSquares > restSquares && swing > 1e-3 * most * counted;
}

// `start` (its spread set) turned through its point (the centroid, which a surface of
// revolution's axis holds) to the direction of least plain spread within about 45 degrees
// (Subplex over the tangent of the tilt both ways across it), with that spread; `start` where no
// direction spreads less.
RevolutionAxis polishedAxis(const std::vector<SurfaceSample>& samples,
                            const RevolutionAxis& start) {
  const glm::dvec3 u = perpendicular(start.direction);
  const glm::dvec3 w = glm::cross(start.direction, u);
  std::vector<glm::dvec2> profile;
  auto at = [&](const std::vector<double>& x) {
    RevolutionAxis axis = start;
    axis.direction = glm::normalize(start.direction + x[0] * u + x[1] * w);
    return axis;
  };
  auto spread = [&](const RevolutionAxis& axis) {
    const double value = plainSpread(samples, axis, profile);
    return value < 0.0 ? 1e300 : value;
  };
  RevolutionAxis best = start;
  std::vector<double> x{0.0, 0.0};
  const SubplexBounds bounds{{-1.0, -1.0}, {1.0, 1.0}};
  minimizeSubplex(
      x, {0.15, 0.15}, kAxisPolishEvaluations,
      [&](const std::vector<double>& y) {
        RevolutionAxis axis = at(y);
        axis.spread = spread(axis);
        if (axis.spread < best.spread) best = axis;
        return axis.spread;
      },
      nullptr, &bounds);
  return best;
}

// revolutionAxis's reading; `lobed`, when given, set to the least spread of the axes refused
// for their swing alone (lobedSaddleAxis's, its order not yet asked).
std::optional<RevolutionAxis> readAxis(const std::vector<SurfaceSample>& samples, double maxSpread,
                                       std::optional<LobedAxis>* lobed) {
  if (samples.size() < 50) return {};
  std::vector<glm::dvec3> positions;
  positions.reserve(samples.size());
  for (const SurfaceSample& s : samples) positions.push_back(s.position);
  const PointMoments moments = pointMoments(positions);
  const glm::dvec3 centroid = moments.centre;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(eigenOf(moments.scatter));
  // A squat target (a lampshade or a pot about as tall as it is wide) has principal variances
  // nearly equal, and the samples swing those eigenvectors: bench/make_implicit_shapes.py's
  // lampshade_march (variances within 1.13 of each other) had its axis 14 degrees off the
  // nearest one, spread 0.109 there (no axis) against 0.0096 about its own. A principal axis
  // whose variance is near another's is polished on the spread (the others are kept as they are).
  const Eigen::Vector3d variances = solver.eigenvalues();
  auto swung = [&](int i) {
    for (int j = 0; j < 3; ++j)
      if (j != i && std::max(variances(i), variances(j)) <
                        kSwungVariances * std::min(variances(i), variances(j)))
        return true;
    return false;
  };
  std::optional<RevolutionAxis> best, oval;
  std::vector<glm::dvec2> profile;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d v = solver.eigenvectors().col(i);
    RevolutionAxis axis{centroid, glm::normalize(glm::dvec3(v.x(), v.y(), v.z())), 0.0};
    double byHeight = 0.0;
    axis.spread = plainSpread(samples, axis, profile, &byHeight);
    if (axis.spread < 0.0) continue;
    // A saddle's axis, no revolution's: held by radius alone, its heights swing with the turn.
    const auto saddle = [&](const RevolutionAxis& a, double heightSpread) {
      LobedAxis read;
      read.axis = a;
      if (!(heightSpread > maxSpread && swingsWithTurn(samples, a, &read.order, &read.share)))
        return false;
      if (lobed && a.spread <= maxSpread && (!*lobed || a.spread < (*lobed)->axis.spread))
        *lobed = read;
      return true;
    };
    if (saddle(axis, byHeight)) continue;
    RevolutionAxis turned = axis;
    turned.spread = ovalSpreadWithin(profile, samples, axis);
    if (!oval || turned.spread < oval->spread) oval = turned;
    if (swung(i)) {
      axis = polishedAxis(samples, axis);
      plainSpread(samples, axis, profile, &byHeight);
      if (saddle(axis, byHeight)) continue;
    }
    if (!best || axis.spread < best->spread) best = axis;
  }
  if (best && best->spread <= maxSpread) return best;
  // An oval cup or bowl (its cross-sections alike ovals, not circles): the axis about which its
  // shape along the turn spreads least (the nested rings follow its reach each way).
  if (oval && oval->spread <= maxSpread) return oval;
  return {};
}

}  // namespace

std::optional<RevolutionAxis> revolutionAxis(const std::vector<SurfaceSample>& samples,
                                             double maxSpread) {
  return readAxis(samples, maxSpread, nullptr);
}

std::optional<LobedAxis> lobedSaddleAxis(const std::vector<SurfaceSample>& samples,
                                         double maxSpread) {
  std::optional<LobedAxis> lobed;
  if (readAxis(samples, maxSpread, &lobed)) return {};
  if (lobed && lobed->order >= kLeastLobes && lobed->share >= kLobedOrderShare) return lobed;
  return {};
}

std::vector<RingShape> ringProposals(const std::vector<SurfaceSample>& sheetSamples,
                                     const std::vector<SurfaceSample>& targetSamples,
                                     const RevolutionAxis& axis, std::size_t count,
                                     std::mt19937_64& random) {
  std::vector<RingShape> rings;
  if (sheetSamples.empty() || targetSamples.empty() || count == 0) return rings;
  std::vector<glm::dvec2> sheet, target;
  double lo = 1e300, hi = -1e300;
  for (const SurfaceSample& s : sheetSamples) sheet.push_back(heightAndRadius(s.position, axis));
  for (const SurfaceSample& s : targetSamples) target.push_back(heightAndRadius(s.position, axis));
  for (const auto* profile : {&sheet, &target})
    for (const glm::dvec2& p : *profile) {
      lo = std::min(lo, p.x);
      hi = std::max(hi, p.x);
    }
  // A flat sheet across the axis lies at one height: its bins still span a little.
  const double span = std::max(hi - lo, 1e-9);
  auto bin = [&](double t) {
    return std::clamp(static_cast<int>((t - lo) / span * kBins), 0, kBins - 1);
  };
  std::array<double, kBins> sheetSum{}, sheetMax{}, targetSum{};
  std::array<int, kBins> sheetCount{}, targetCount{};
  for (const glm::dvec2& p : sheet) {
    const int b = bin(p.x);
    sheetSum[b] += p.y;
    sheetMax[b] = std::max(sheetMax[b], p.y);
    ++sheetCount[b];
  }
  for (const glm::dvec2& p : target) {
    const int b = bin(p.x);
    targetSum[b] += p.y;
    ++targetCount[b];
  }
  // Each bin where the sheet lies, weighted by how far its radius is from the target's there;
  // a target's bin the sheet does not reach adds its radius to the nearest bin the sheet does.
  std::array<double, kBins> weight{};
  double meanRadius = 0.0;
  for (const glm::dvec2& p : sheet) meanRadius += p.y;
  meanRadius /= static_cast<double>(sheet.size());
  for (int b = 0; b < kBins; ++b) {
    if (sheetCount[b] < 2) continue;
    const double sheetRadius = sheetSum[b] / sheetCount[b];
    weight[b] =
        0.05 * meanRadius +
        (targetCount[b] > 0 ? std::abs(targetSum[b] / targetCount[b] - sheetRadius) : sheetRadius);
  }
  for (int b = 0; b < kBins; ++b) {
    if (sheetCount[b] >= 2 || targetCount[b] == 0) continue;
    int nearest = -1;
    for (int c = 0; c < kBins; ++c)
      if (sheetCount[c] >= 2 && (nearest < 0 || std::abs(c - b) < std::abs(nearest - b)))
        nearest = c;
    if (nearest >= 0) weight[nearest] += targetSum[b] / targetCount[b];
  }
  std::array<double, kBins> cumulative{};
  double total = 0.0;
  for (int b = 0; b < kBins; ++b) cumulative[b] = total += weight[b];
  if (!(total > 0.0)) return rings;

  constexpr std::array<int, 6> kOrders{4, 6, 8, 10, 12, 16};
  for (std::size_t r = 0; r < count; ++r) {
    const double at = unit(random) * total;
    const int b = static_cast<int>(std::min<std::ptrdiff_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin(),
        kBins - 1));
    RingShape shape;
    shape.height = lo + span * (b + unit(random)) / kBins;
    shape.radius = sheetMax[b] * (0.3 + 0.75 * unit(random));
    const bool across = unit(random) < 0.1;  // a single plane across the axis
    shape.tilt = across ? (unit(random) < 0.5 ? 0.5 : -0.5) * std::numbers::pi
                        : (unit(random) - 0.5) * (160.0 / 180.0) * std::numbers::pi;
    shape.order = across ? 1 : kOrders[static_cast<std::size_t>(unit(random) * kOrders.size())];
    shape.turn = unit(random) * 2.0 * std::numbers::pi / shape.order;
    // A plane across the axis anywhere over both: one past the sheet's end moves it whole along
    // the axis (a disk placed at a bowl's centroid, lowered toward its bottom).
    if (across) shape.height = lo + span * unit(random);
    rings.push_back(shape);
  }
  return rings;
}

double ringCutRadius(double q, int order) {
  const double half = std::numbers::pi / std::max(order, 2);
  q = std::clamp(q, std::cos(half), 1.0);
  // A wedge |theta| < w of the circle reflected across its chord: at theta its distance from
  // the axis is |(2q - cos theta, sin theta)|; the rest of [0, half] keeps radius 1. Simpson.
  const double w = std::acos(q);
  constexpr int kSteps = 32;
  double integral = 0.0;
  for (int i = 0; i <= kSteps; ++i) {
    const double t = w * i / kSteps;
    const double f = std::sqrt(std::max(0.0, 4.0 * q * q - 4.0 * q * std::cos(t) + 1.0));
    integral += f * (i == 0 || i == kSteps ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0));
  }
  integral *= w / (3.0 * kSteps);
  return ((half - w) + integral) / half;
}

std::vector<RingShape> neckRings(const std::vector<SurfaceSample>& sheetSamples,
                                 const std::vector<SurfaceSample>& targetSamples,
                                 const RevolutionAxis& axis, double turn,
                                 std::span<const int> orders) {
  std::vector<RingShape> rings;
  if (sheetSamples.empty() || targetSamples.empty()) return rings;
  double lo = 1e300, hi = -1e300;
  std::vector<glm::dvec2> sheet, target;
  for (const SurfaceSample& s : sheetSamples) {
    sheet.push_back(heightAndRadius(s.position, axis));
    lo = std::min(lo, sheet.back().x);
    hi = std::max(hi, sheet.back().x);
  }
  if (!(hi - lo > 1e-9)) return rings;  // a sheet across the axis: no tube to narrow
  for (const SurfaceSample& s : targetSamples) target.push_back(heightAndRadius(s.position, axis));
  auto bin = [&](double t) { return static_cast<int>((t - lo) / (hi - lo) * kBins); };
  std::array<double, kBins> sheetSum{}, targetSum{};
  std::array<int, kBins> sheetCount{}, targetCount{};
  for (const glm::dvec2& p : sheet) {
    const int b = std::clamp(bin(p.x), 0, kBins - 1);
    sheetSum[b] += p.y;
    ++sheetCount[b];
  }
  for (const glm::dvec2& p : target) {
    const int b = bin(p.x);
    if (b < 0 || b >= kBins) continue;  // beyond the sheet's length: no ring reaches it
    targetSum[b] += p.y;
    ++targetCount[b];
  }
  auto centre = [&](int b) { return lo + (hi - lo) * (b + 0.5) / kBins; };
  auto sheetRadius = [&](int b) { return sheetSum[b] / std::max(sheetCount[b], 1); };
  // A tilted ring cuts from the height t0 where its planes meet the tube (rho(t0) = R) ever
  // deeper toward one end, down to q_end R there (q_end short of cos(pi / n), where the wedges
  // meet, by an eighth of the way to 1: a sheet a little off the axis, or wedges just touching,
  // would cross). Each (t0, q_end, end) is scored on the profile itself: the
  // predicted mean radius R ringCutRadius(rho(t) / R, n) against the target's, bin by bin.
  std::vector<int> used;
  for (int b = 0; b < kBins; ++b)
    if (sheetCount[b] >= 3 && targetCount[b] >= 3) used.push_back(b);
  if (used.empty()) return rings;
  auto radiusAt = [&](double t) {
    return sheetRadius(std::clamp(bin(t), used.front(), used.back()));
  };
  auto gap = [&](int order, double t0, double rhoEnd, double tEnd) {
    const double radius0 = radiusAt(t0);
    double sum = 0.0;
    for (const int b : used) {
      const double radius = sheetRadius(b), t = centre(b);
      const double rho = radius0 + (t - t0) / (tEnd - t0) * (rhoEnd - radius0);
      const double predicted = radius * ringCutRadius(rho / radius, order);
      sum += targetCount[b] * std::abs(predicted - targetSum[b] / targetCount[b]);
    }
    return sum;
  };
  double untouched = 0.0;
  for (const int b : used)
    untouched += targetCount[b] * std::abs(sheetRadius(b) - targetSum[b] / targetCount[b]);
  for (const int order : orders) {
    const double deepest = std::cos(std::numbers::pi / order);
    for (const int end : {used.front(), used.back()}) {
      const double tEnd = end == used.front() ? lo : hi, radiusEnd = sheetRadius(end);
      double best = untouched, bestT0 = 0.0, bestRho = 0.0;
      for (int e = 0; e <= kBins; ++e) {
        const double t0 = lo + (hi - lo) * e / kBins;
        if (std::abs(t0 - tEnd) < 1e-12) continue;
        for (int level = 1; level <= 8; ++level) {
          const double rhoEnd = radiusEnd * (deepest + (1.0 - deepest) * level / 8.0);
          if (const double g = gap(order, t0, rhoEnd, tEnd); g < best) {
            best = g;
            bestT0 = t0;
            bestRho = rhoEnd;
          }
        }
      }
      if (!(best < untouched)) continue;
      // The plane through (t0, R(t0)) and (tEnd, rhoEnd): rho(t) = R0 + g (t - t0).
      const double radius0 = radiusAt(bestT0);
      const double g = (bestRho - radius0) / (tEnd - bestT0);
      RingShape shape;
      shape.height = bestT0;
      shape.radius = radius0;
      shape.tilt = std::atan(-g);
      shape.turn = turn;
      shape.order = order;
      rings.push_back(shape);
    }
  }
  return rings;
}

Ring ringOf(const RingShape& shape, const RevolutionAxis& axis) {
  const glm::dvec3 u = perpendicular(axis.direction), v = glm::cross(axis.direction, u);
  const bool across = shape.order == 1;
  Ring ring;
  for (int k = 0; k < shape.order; ++k) {
    const double angle = shape.turn + 2.0 * std::numbers::pi * k / shape.order;
    const glm::dvec3 e = std::cos(angle) * u + std::sin(angle) * v;
    const glm::dvec3 normal =
        across ? (shape.tilt >= 0.0 ? 1.0 : -1.0) * axis.direction
               : glm::normalize(std::cos(shape.tilt) * e + std::sin(shape.tilt) * axis.direction);
    ring.planes.push_back(
        {axis.point + shape.height * axis.direction + (across ? 0.0 : shape.radius) * e, normal});
    if (shape.seeded)
      ring.seeds.push_back(axis.point + shape.seedHeight * axis.direction + shape.seedRadius * e);
  }
  return ring;
}

void previewRing(const Ring& ring, std::vector<glm::dvec3>& points,
                 std::vector<glm::dvec3>& normals) {
  for (const ReflectionPlane& plane : ring.planes)
    for (std::size_t i = 0; i < points.size(); ++i)
      if (plane.signedDistance(points[i]) > 0.0) {
        points[i] = plane.reflect(points[i]);
        normals[i] -= 2.0 * glm::dot(normals[i], plane.normal) * plane.normal;
      }
}

RingTrials::RingTrials(const FoldSession& session, std::optional<std::size_t> mostCrossings)
    : session_(session),
      records_(session.folds().begin(),
               session.folds().begin() + static_cast<std::ptrdiff_t>(session.foldCount())),
      mostCrossings_(mostCrossings) {}

void RingTrials::tryRing(const Ring& ring, std::size_t leastFolds,
                         const std::function<void(const FoldSession&)>& made) {
  std::unique_ptr<FoldSession>& copy = copies_.local();
  if (!copy) {
    copy = std::make_unique<FoldSession>(session_.initial());
    copy->applyRecords(records_);
  }
  if (makeRing(*copy, ring) >= leastFolds &&
      (!mostCrossings_ ||
       findSelfIntersections(copy->fixed()).intersections.size() <= *mostCrossings_))
    made(*copy);
  copy->undoTo(records_.size());
}

std::size_t makeRing(FoldSession& session, const Ring& ring) {
  session.cancel();
  std::size_t made = 0;
  const bool seeded = ring.seeds.size() == ring.planes.size();
  for (std::size_t k = 0; k < ring.planes.size(); ++k) {
    const ReflectionPlane& plane = ring.planes[k];
    const Sheet& sheet = session.fixed();
    std::size_t farthest = 0;
    double most = -1e300, nearest = 1e300;
    for (std::size_t i = 0; i < sheet.positions.size(); ++i) {
      const double d = plane.signedDistance(sheet.positions[i]);
      if (seeded) {
        // The vertex on the plane's side (clear of it) nearest the seed.
        const double gap = glm::length(sheet.positions[i] - ring.seeds[k]);
        if (d > 2.0 * session.minimumDrag() && gap < nearest) {
          nearest = gap;
          most = d;
          farthest = i;
        }
      } else if (d > most) {
        most = d;
        farthest = i;
      }
    }
    if (!(most > 2.0 * session.minimumDrag())) continue;  // the plane misses the sheet
    const glm::dvec2 seed = sheet.development[farthest];  // a copy: the drag changes the sheets
    const glm::dvec3 grabbed = session.beginDragAtDevelopment(seed);
    session.updateDrag(plane.reflect(grabbed));
    if (session.commit()) ++made;
  }
  return made;
}

std::vector<FoldSuggestion> suggestRings(const FoldSession& session, const FoldFitter& fitter,
                                         const RevolutionAxis& axis,
                                         const std::vector<SurfaceSample>& targetSamples,
                                         std::size_t count, std::size_t proposals,
                                         const Deadline& deadline, std::mt19937_64& random) {
  if (count == 0 || proposals == 0 || deadline.givesUp()) return {};
  const TriangleMesh mesh = meshOf(session.fixed());
  const std::vector<SurfaceSample> sheetSamples = sampleSurface(mesh, kPreviewSamples, random());
  if (sheetSamples.empty()) return {};
  std::vector<glm::dvec3> points, normals;
  for (const SurfaceSample& s : sheetSamples) {
    points.push_back(s.position);
    normals.push_back(s.normal);
  }
  const double spacing =
      0.5 * std::sqrt(surfaceArea(mesh) / static_cast<double>(sheetSamples.size()));
  auto preview = [&](const RingShape& shape) {
    deadline.countEvaluation();
    std::vector<glm::dvec3> p = points, n = normals;
    previewRing(ringOf(shape, axis), p, n);
    return fitter.approximateDistance(p, n, spacing);
  };
  std::vector<RingShape> shapes =
      ringProposals(sheetSamples, targetSamples, axis, proposals, random);
  // Rings solved on the radius profile (a tube's neck), at two turns: a second ring lines up with
  // a first one's wedges or falls between them.
  const std::size_t drawn = shapes.size();
  for (const double turn : {0.0, 0.5})
    for (RingShape shape : neckRings(sheetSamples, targetSamples, axis)) {
      shape.turn = turn * 2.0 * std::numbers::pi / shape.order;
      shapes.push_back(shape);
    }
  std::vector<double> scores(shapes.size(), 1e300);
  tbb::parallel_for(std::size_t(0), shapes.size(), [&](std::size_t r) {
    if (!deadline.passed()) scores[r] = preview(shapes[r]);
  });
  if (deadline.givesUp()) return {};
  std::vector<std::size_t> order(shapes.size());
  for (std::size_t r = 0; r < order.size(); ++r) order[r] = r;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return scores[a] < scores[b]; });
  // The best few of different orders (one plane across the axis, which a preview cannot tell
  // lays the sheet on itself, takes one place at most) refined by Subplex over (height, radius,
  // tilt, turn), the order kept.
  std::vector<RingShape> refined;
  for (std::size_t r : order) {
    if (refined.size() >= kRefinedRings) break;
    if (std::none_of(refined.begin(), refined.end(),
                     [&](const RingShape& kept) { return kept.order == shapes[r].order; }))
      refined.push_back(shapes[r]);
  }
  // The two solved rings that preview best are also made as solved (a drawn ring of the same
  // order may preview better and then cross itself on the sheet, leaving none of that order).
  std::vector<RingShape> solved;
  for (std::size_t r : order)
    if (r >= drawn && solved.size() < 2 && scores[r] < 1e300) solved.push_back(shapes[r]);
  const double size = glm::length(points.front() - axis.point) + spacing;
  tbb::parallel_for(std::size_t(0), refined.size(), [&](std::size_t k) {
    RingShape& best = refined[k];
    double bestScore = preview(best);
    const bool across = best.order == 1;
    std::vector<double> x{best.height}, step{0.02 * size};
    if (!across) {
      x.insert(x.end(), {best.radius, best.tilt, best.turn});
      step.insert(step.end(), {0.05 * size, 0.1, 0.5 * std::numbers::pi / best.order});
    }
    minimizeSubplex(
        x, step, static_cast<int>(kRingRefineEvaluations),
        [&](const std::vector<double>& y) {
          RingShape shape = best;
          shape.height = y[0];
          if (!across) {
            shape.radius = y[1];
            shape.tilt = y[2];
            shape.turn = y[3];
          }
          const double score = preview(shape);
          if (score < bestScore) {
            bestScore = score;
            best = shape;
          }
          return score;
        },
        &deadline);
  });
  if (deadline.givesUp()) return {};
  refined.insert(refined.end(), solved.begin(), solved.end());

  // Each refined ring made on the sheet itself (a session of each thread's own), scored, checked
  // for passing through itself, and taken back.
  const double before = fitter.approximateDistance(session.fixed());
  const bool allowCrossing = fitter.settings().allowSelfIntersection;
  const std::size_t crossingsBefore =
      allowCrossing ? 0 : findSelfIntersections(session.fixed()).intersections.size();
  std::vector<FoldSuggestion> made(refined.size());
  RingTrials trials(session, allowCrossing ? std::nullopt : std::optional(crossingsBefore));
  tbb::parallel_for(std::size_t(0), refined.size(), [&](std::size_t r) {
    if (deadline.passed()) return;
    trials.tryRing(ringOf(refined[r], axis), 1, [&](const FoldSession& copy) {
      made[r].folds.assign(copy.folds().begin() + static_cast<std::ptrdiff_t>(trials.baseFolds()),
                           copy.folds().begin() + static_cast<std::ptrdiff_t>(copy.foldCount()));
      made[r].sheet = copy.fixed();
      made[r].before = before;
      made[r].after = fitter.approximateDistance(made[r].sheet);
    });
  });
  if (deadline.givesUp()) return {};
  std::vector<FoldSuggestion> out;
  for (FoldSuggestion& ring : made)
    if (!ring.folds.empty() && ring.after < before) out.push_back(std::move(ring));
  std::stable_sort(out.begin(), out.end(),
                   [](const auto& a, const auto& b) { return a.after < b.after; });
  if (out.size() > count) out.resize(count);
  return out;
}

}  // namespace curvefold
