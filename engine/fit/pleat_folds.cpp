#include "engine/fit/pleat_folds.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <utility>

#include <Eigen/Dense>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "engine/fit/eigen_glm.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/geometry/nearest_vertex.hpp"
#include "engine/geometry/principal_moments.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/vertex_normals.hpp"

namespace curvefold {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// Bends tried at each hinge (degrees), and the flap's rise above the bend (2 eps = theta + this).
constexpr double kBends[] = {4.0, 9.0, 16.0, 25.0, 35.0};
constexpr double kFlapMargin = 4.0;
// Hinges on the way from the sheet's centre to a far point, as fractions of the way.
constexpr double kHingeAt[] = {0.25, 0.45, 0.65, 0.8};
// Far points tried, at least this far apart (of the sheet's size).
constexpr std::size_t kFarPoints = 3;
constexpr double kFarApart = 0.2;
// The pleat's width, of the target's diagonal.
constexpr double kWidth = 0.003;
// Vertices measured to the target to find where the sheet is far.
constexpr std::size_t kMeasured = 800;
// The best pleats of the grid refined.
constexpr std::size_t kRefined = 2;
constexpr double kNone = std::numeric_limits<double>::infinity();
// Solved pleats: directions tried over a half turn, hinges across each (fractions of the way from
// the centre to the sheet's end), turns kept (radians), the best few made, each at these shares
// of its solved turn (the model ignores the width a pleat folds away).
constexpr int kDirections = 8;
constexpr double kSolvedHinges[] = {-0.6, -0.45, -0.3, -0.15, 0.0, 0.1, 0.2,
                                    0.3,  0.4,   0.5,  0.6,   0.7, 0.8};
constexpr double kMostSolvedTurn = 35.0 * kDegree, kLeastSolvedTurn = 1.0 * kDegree;
constexpr std::size_t kSolvedTried = 4;
constexpr double kSolvedShares[] = {1.0, 0.7};
constexpr std::size_t kSolvedPairs = 2;
// Families of pleats: hinges along a line, the farthest hinge's place (of the way from the centre
// to the end), the families made (the best by the model) and the shares of their turns tried.
constexpr int kFamilyHinges[] = {3, 4, 5, 6, 8};
constexpr double kFamilyLast[] = {0.85, 0.7};
constexpr std::size_t kFamiliesTried = 4;
constexpr double kFamilyShares[] = {0.9, 0.65};
// Crosses (two lines' ends pleated as one step, from a flat sheet): the hinges' places (of the
// way from the centre to the end) and the crosses made, the best by the model.
constexpr double kCrossHinges[] = {0.15, 0.3, 0.45, 0.6};
constexpr std::size_t kCrossesTried = 4;
// Samples of the exact distance a family's farthest point is measured with.
constexpr std::size_t kFarthestSamples = 3000;

// A pleat solved from the target's heights: the end beyond `at` (metres from the sheet's centre
// along the unit `direction`) turned by `turn` radians toward `up` (negative: away).
struct SolvedPleat {
  glm::dvec3 direction{0.0}, up{0.0};
  double at = 0.0, turn = 0.0, gain = 0.0;
};

// For every direction in the sheet's plane (kDirections about its normal, both ways) and every
// hinge across it, the target's height over the sheet beyond the hinge (r, along the sheet's
// normal) fitted by a turn about the hinge, r = turn * (s - at) (least squares: a pleat turns
// the end rigidly, so the height it adds grows with the distance from the hinge); the gain is
// the squared height that turn removes. The best hinge of each direction, best first.
glm::dvec3 axisOf(const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& axes, int i) {
  const Eigen::Vector3d v = axes.eigenvectors().col(i);
  return glm::dvec3(v.x(), v.y(), v.z());
}

// The target's height over each point along the sheet's normal `up` (0 where a point lies on it).
std::vector<double> heightsOver(const std::vector<glm::dvec3>& points,
                                const std::vector<double>& distances,
                                const SurfaceDistanceQuery& query, const glm::dvec3& up) {
  std::vector<double> heights(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    heights[i] = distances[i] > 0.0 ? glm::dot(query.closestPoint(points[i]) - points[i], up) : 0.0;
  return heights;
}

// The target's height over each point straight along `up` (the sheet's mean normal), as a
// corrugation's turns are solved: each step moves along `up` to the plane tangent to the target
// at the closest point (exact over a tilted plane, where the closest point lies sideways and its
// height alone says too little: a saddle's steep ends). Where the closest point lies mostly
// sideways (beyond the target's rim) the height of the closest point is kept.
std::vector<double> heightsAlong(const std::vector<glm::dvec3>& points,
                                 const SurfaceDistanceQuery& query, const glm::dvec3& up) {
  std::vector<double> heights(points.size(), 0.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    double h = 0.0;
    for (int step = 0; step < 4; ++step) {
      const glm::dvec3 q = points[i] + h * up, d = query.closestPoint(q) - q;
      const double length = glm::length(d);
      if (!(length > 1e-12)) break;
      const double cosine = glm::dot(d, up) / length;
      if (std::abs(cosine) < 0.4) {
        if (step == 0) h = glm::dot(d, up);
        break;
      }
      h += length / cosine;
    }
    heights[i] = h;
  }
  return heights;
}

std::vector<SolvedPleat> solvePleats(const std::vector<glm::dvec3>& points,
                                     const std::vector<double>& heights, const glm::dvec3& centre,
                                     const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& axes,
                                     double width) {
  const glm::dvec3 up = axisOf(axes, 0), e1 = axisOf(axes, 2), e2 = axisOf(axes, 1);
  std::vector<SolvedPleat> best(2 * kDirections);
  for (int k = 0; k < 2 * kDirections; ++k) {
    const double angle = std::numbers::pi * k / kDirections;
    const glm::dvec3 direction = std::cos(angle) * e1 + std::sin(angle) * e2;
    double reach = 0.0;
    for (const glm::dvec3& p : points) reach = std::max(reach, glm::dot(p - centre, direction));
    SolvedPleat found;
    for (const double fraction : kSolvedHinges) {
      const double at = fraction * reach;
      double rs = 0.0, ss = 0.0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const double s = glm::dot(points[i] - centre, direction) - at;
        if (s < 2.0 * width) continue;  // the pleat's own width is folded away
        rs += heights[i] * s;
        ss += s * s;
      }
      if (!(ss > 0.0)) continue;
      const double turn = std::clamp(rs / ss, -kMostSolvedTurn, kMostSolvedTurn);
      const double gain = 2.0 * turn * rs - turn * turn * ss;
      if (gain > found.gain && std::abs(turn) > kLeastSolvedTurn)
        found = {direction, up, at, turn, gain};
    }
    best[k] = found;
  }
  return best;
}

// The best hinges of all directions, best first, at most kSolvedTried.
std::vector<SolvedPleat> topSolved(std::vector<SolvedPleat> solved) {
  std::erase_if(solved, [](const SolvedPleat& p) { return !(p.gain > 0.0); });
  std::stable_sort(solved.begin(), solved.end(),
                   [](const auto& a, const auto& b) { return a.gain > b.gain; });
  if (solved.size() > kSolvedTried) solved.resize(kSolvedTried);
  return solved;
}

// Pairs of pleats turning both ends of one line through the sheet (direction k and its
// opposite), as one step: a saddle's ends fall (or rise) on both sides of its middle, and a
// pleat on one end alone leaves the other end as far and tilts the balance of the sheet's height.
// Their ends do not overlap (the hinges at least `apart` apart), so the solved gains add. The
// best kSolvedPairs, best first.
std::vector<std::pair<SolvedPleat, SolvedPleat>> solvedPairs(const std::vector<SolvedPleat>& solved,
                                                             double apart) {
  std::vector<std::pair<SolvedPleat, SolvedPleat>> pairs;
  for (int k = 0; k < kDirections; ++k) {
    const SolvedPleat &a = solved[k], &b = solved[k + kDirections];
    if (a.gain > 0.0 && b.gain > 0.0 && a.at + b.at > apart) pairs.emplace_back(a, b);
  }
  std::stable_sort(pairs.begin(), pairs.end(), [](const auto& x, const auto& y) {
    return x.first.gain + x.second.gain > y.first.gain + y.second.gain;
  });
  if (pairs.size() > kSolvedPairs) pairs.resize(kSolvedPairs);
  return pairs;
}

// A family of pleats: hinges along one line through the sheet, the piece between two of them
// (the anchor) kept where it is, each hinge turning all of the sheet beyond it (away from the
// anchor) by its own turn (SolvedPleat: toward the line's positive end, or with the opposite
// direction toward its negative one), ordered from the anchor out on each side.
struct PleatFamily {
  std::vector<SolvedPleat> pleats;
  double gain = 0.0;
};

// Families solved from the target's heights as a corrugation is laid out: along each line through
// the sheet's centre (kDirections over a half turn), for each count and spread of hinges (evenly
// spaced along the line) and each piece between them kept in place, the height over the sheet
// fitted in least squares by a sum of ramps, one per hinge, r(s) = turn_j * max(0, s - at_j) on
// the anchor's positive side and turn_j * max(0, at_j - s) on its negative side (a pleat turns
// all of the sheet beyond it rigidly). A paper artist's parallel pleats toward a hypar are these.
// The anchor matters: a least-squares start lies between a saddle's high middle and its low ends,
// so keeping the middle leaves it too high; keeping a piece where the target crosses the sheet
// lets the pleats raise the middle and lower the ends. The best kFamiliesTried.
std::vector<PleatFamily> solveFamilies(const std::vector<glm::dvec3>& points,
                                       const std::vector<double>& heights, const glm::dvec3& centre,
                                       const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& axes,
                                       double width) {
  const glm::dvec3 up = axisOf(axes, 0), e1 = axisOf(axes, 2), e2 = axisOf(axes, 1);
  std::vector<PleatFamily> families;
  for (int k = 0; k < kDirections; ++k) {
    const double angle = std::numbers::pi * k / kDirections;
    const glm::dvec3 direction = std::cos(angle) * e1 + std::sin(angle) * e2;
    std::vector<double> s(points.size());
    double reachUp = 0.0, reachDown = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      s[i] = glm::dot(points[i] - centre, direction);
      reachUp = std::max(reachUp, s[i]);
      reachDown = std::max(reachDown, -s[i]);
    }
    for (const int hinges : kFamilyHinges)
      for (const double last : kFamilyLast) {
        std::vector<double> at(hinges);  // from the negative end to the positive one
        for (int j = 0; j < hinges; ++j) {
          const double fraction = -last + 2.0 * last * (j + 0.5) / hinges;
          at[j] = fraction * (fraction < 0.0 ? reachDown : reachUp);
        }
        for (int anchor = 0; anchor <= hinges; ++anchor) {  // the piece after hinge anchor - 1
          auto ramp = [&](std::size_t i, int j) {
            return j >= anchor ? std::max(0.0, s[i] - at[j]) : std::max(0.0, at[j] - s[i]);
          };
          Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(hinges, hinges);
          Eigen::VectorXd right = Eigen::VectorXd::Zero(hinges), row(hinges);
          for (std::size_t i = 0; i < points.size(); ++i) {
            for (int j = 0; j < hinges; ++j) row(j) = ramp(i, j);
            normal.noalias() += row * row.transpose();
            right += heights[i] * row;
          }
          normal.diagonal().array() += 1e-9 * (normal.trace() + 1e-30);
          Eigen::VectorXd turn = normal.ldlt().solve(right);
          for (int j = 0; j < hinges; ++j) {
            turn(j) = std::clamp(turn(j), -kMostSolvedTurn, kMostSolvedTurn);
            if (!(std::abs(turn(j)) >= kLeastSolvedTurn)) turn(j) = 0.0;  // too small to pleat
          }
          PleatFamily family;
          family.gain = 2.0 * turn.dot(right) - turn.dot(normal * turn);
          if (!(family.gain > 0.0)) continue;
          for (int j = anchor; j < hinges; ++j)  // the positive side, from the anchor out
            if (turn(j) != 0.0 && at[j] + 4.0 * width < reachUp)
              family.pleats.push_back({direction, up, at[j], turn(j), 0.0});
          for (int j = anchor - 1; j >= 0; --j)  // the negative side
            if (turn(j) != 0.0 && -at[j] + 4.0 * width < reachDown)
              family.pleats.push_back({-direction, up, -at[j], turn(j), 0.0});
          if (family.pleats.size() > 2) families.push_back(std::move(family));
        }
      }
  }
  // The best of each count of pleats, best first: the model leaves out the length each pleat folds
  // away (twice its width, more where the sheet rises across the hinge), so more pleats are not
  // always closer; the sheet says which is.
  std::stable_sort(families.begin(), families.end(),
                   [](const auto& a, const auto& b) { return a.gain > b.gain; });
  std::vector<PleatFamily> best;
  for (PleatFamily& family : families)
    if (best.size() < kFamiliesTried &&
        std::none_of(best.begin(), best.end(), [&](const PleatFamily& other) {
          return other.pleats.size() == family.pleats.size();
        }))
      best.push_back(std::move(family));
  return best;
}

// Crosses of pleats, from a flat sheet toward a shape curved both ways (a saddle, a chip): both
// ends of a line through the sheet's centre and both ends of the line across it, each end turned
// about a hinge (both ends of a line at the same share of the way to the sheet's end, of
// kCrossHinges; the line across at its own), the four turns
// solved together in least squares from the target's height over the sheet (ramps, as a family's:
// a turn adds height in proportion to the distance beyond its hinge; along two lines the ramps
// overlap at the corners, where their heights add as the pleats' turns compose). The best
// kCrossesTried (directions, hinge places), best first; each the end along +line,
// -line, +across, -across.
// The direction in the sheet's plane (normal `up`, spanned by `e1` and `e2`) along which the
// heights curve most: the principal direction of the least-squares quadric h = A u^2 + B uv +
// C v^2 + D u + E v + F over the points. A flat square's or disk's own axes spread alike, so
// its principal axes come out turned anyhow (by rounding: 22.5 degrees off a square's sides,
// whichever side faces up), and a cross's lines, laid from them, missed the target's rising and
// falling ends (a saddle turned 20 degrees: its turned-over square's first step 1.12% of the
// diagonal against 0.552% face up,
// FirstStepStart.ASaddleFoldsAlikeFromEitherSideOfItsTurnedSquare). Laid from this, they do not
// depend on how the sheet is turned or which side faces up. `e1` where the heights do not curve.
glm::dvec3 mostCurvedDirection(const std::vector<glm::dvec3>& points,
                               const std::vector<double>& heights, const glm::dvec3& centre,
                               const glm::dvec3& e1, const glm::dvec3& e2) {
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> right = Eigen::Matrix<double, 6, 1>::Zero(), row;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double u = glm::dot(points[i] - centre, e1), v = glm::dot(points[i] - centre, e2);
    row << u * u, u * v, v * v, u, v, 1.0;
    normal.noalias() += row * row.transpose();
    right += heights[i] * row;
  }
  normal.diagonal().array() += 1e-12 * (normal.trace() + 1e-30);
  const Eigen::Matrix<double, 6, 1> q = normal.ldlt().solve(right);
  Eigen::Matrix2d hessian;
  hessian << 2.0 * q(0), q(1), q(1), 2.0 * q(2);
  if (!hessian.allFinite() || !(hessian.norm() > 0.0)) return e1;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> curvature(hessian);
  const Eigen::Vector2d lo = curvature.eigenvectors().col(0), hi = curvature.eigenvectors().col(1);
  const Eigen::Vector2d most =
      std::abs(curvature.eigenvalues()(0)) > std::abs(curvature.eigenvalues()(1)) ? lo : hi;
  const glm::dvec3 direction = most(0) * e1 + most(1) * e2;
  return glm::length(direction) > 0.5 ? glm::normalize(direction) : e1;
}

std::vector<std::array<SolvedPleat, 4>> solveCrosses(
    const std::vector<glm::dvec3>& points, const std::vector<double>& heights,
    const glm::dvec3& centre, const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& axes) {
  const glm::dvec3 up = axisOf(axes, 0);
  const glm::dvec3 e1 = mostCurvedDirection(points, heights, centre, axisOf(axes, 2),
                                            axisOf(axes, 1)),
                   e2 = glm::cross(up, e1);
  struct Cross {
    std::array<SolvedPleat, 4> pleats;
    double gain = 0.0;
  };
  std::vector<Cross> crosses;
  // A full half turn: each cross twice, its lines in either order (the first line's ends are
  // bent, the second's pleated).
  for (int k = 0; k < kDirections; ++k) {
    const double angle = std::numbers::pi * k / kDirections;
    const glm::dvec3 line = std::cos(angle) * e1 + std::sin(angle) * e2;
    const glm::dvec3 across = glm::cross(up, line);
    const std::array<glm::dvec3, 4> directions{line, -line, across, -across};
    std::array<std::vector<double>, 4> s;
    std::array<double, 4> reach{};
    for (int j = 0; j < 4; ++j) {
      s[j].resize(points.size());
      for (std::size_t i = 0; i < points.size(); ++i) {
        s[j][i] = glm::dot(points[i] - centre, directions[j]);
        reach[j] = std::max(reach[j], s[j][i]);
      }
    }
    for (const double lineFraction : kCrossHinges)
      for (const double acrossFraction : kCrossHinges) {
        const std::array<double, 4> fraction{lineFraction, lineFraction, acrossFraction,
                                             acrossFraction};
        Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
        Eigen::Vector4d right = Eigen::Vector4d::Zero(), row;
        for (std::size_t i = 0; i < points.size(); ++i) {
          for (int j = 0; j < 4; ++j) row(j) = std::max(0.0, s[j][i] - fraction[j] * reach[j]);
          normal.noalias() += row * row.transpose();
          right += heights[i] * row;
        }
        normal.diagonal().array() += 1e-9 * (normal.trace() + 1e-30);
        Eigen::Vector4d turn = normal.ldlt().solve(right);
        bool usable = true;
        for (int j = 0; j < 4; ++j) {
          turn(j) = std::clamp(turn(j), -kMostSolvedTurn, kMostSolvedTurn);
          usable = usable && std::abs(turn(j)) >= kLeastSolvedTurn;
        }
        const double gain = 2.0 * turn.dot(right) - turn.dot(normal * turn);
        if (!usable || !(gain > 0.0)) continue;
        Cross cross;
        cross.gain = gain;
        for (int j = 0; j < 4; ++j)
          cross.pleats[j] = {directions[j], up, fraction[j] * reach[j], turn(j), 0.0};
        crosses.push_back(cross);
      }
  }
  std::stable_sort(crosses.begin(), crosses.end(),
                   [](const Cross& a, const Cross& b) { return a.gain > b.gain; });
  std::vector<std::array<SolvedPleat, 4>> best;
  for (const Cross& cross : crosses)
    if (best.size() < kCrossesTried) best.push_back(cross.pleats);
  return best;
}

// A rigid motion, x -> linear * x + shift: where the pleats made so far on an end have moved it.
struct Motion {
  glm::dmat3 linear{1.0};
  glm::dvec3 shift{0.0};
  glm::dvec3 operator()(const glm::dvec3& x) const { return linear * x + shift; }
  ReflectionPlane operator()(const ReflectionPlane& plane) const {
    return {(*this)(plane.point), glm::normalize(linear * plane.normal)};
  }
};

// The reflection in `plane`, then `before`.
Motion reflectedAfter(const ReflectionPlane& plane, const Motion& before) {
  const glm::dvec3 n = plane.normal;
  const glm::dmat3 mirror = glm::dmat3(1.0) - 2.0 * glm::outerProduct(n, n);
  return {mirror * before.linear, mirror * before.shift + 2.0 * glm::dot(plane.point, n) * n};
}

}  // namespace

PleatPlanes pleatPlanes(const glm::dvec3& hinge, const glm::dvec3& along,
                        const glm::dvec3& bendToward, double theta, double flapTilt, double width) {
  // In the plane of `along` (x) and `up` (z, away from the bend): the first plane's normal is
  // `along` tilted by -eps, so the end reflects back over the sheet rising at 2 eps (`flap`); the
  // second, through the flap at `width`, is the bisector of the flap's direction and the wanted
  // one (forward, turned by theta toward the bend).
  const glm::dvec3 up = -bendToward;
  const glm::dvec3 n1 = std::cos(flapTilt) * along - std::sin(flapTilt) * up;
  const glm::dvec3 flap = -std::cos(2 * flapTilt) * along + std::sin(2 * flapTilt) * up;
  const glm::dvec3 wanted = std::cos(theta) * along - std::sin(theta) * up;
  return {{hinge, n1}, {hinge + width * flap, glm::normalize(flap - wanted)}};
}

std::vector<FoldSuggestion> suggestPleats(FoldSession& session, const FoldFitter& fitter,
                                          std::size_t count, const Deadline& deadline,
                                          std::uint64_t step) {
  session.cancel();
  std::vector<FoldSuggestion> out;
  if (count == 0 || session.symmetricFolder() || deadline.passed()) return out;
  const Sheet sheet = session.fixed();
  const std::size_t n = sheet.vertexCount();
  if (n < 4) return out;
  const std::vector<glm::dvec3> normals = vertexNormals(sheet);
  glm::dvec3 centre(0.0), lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : sheet.positions) {
    centre += p;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  centre /= static_cast<double>(n);
  const double size = glm::length(hi - lo);
  const double width = kWidth * fitter.targetDiagonal();

  // Where the sheet is far from the target: a spread of its vertices measured.
  const SurfaceDistanceQuery& query = fitter.measuredTarget().query();
  const std::size_t stride = std::max<std::size_t>(1, n / kMeasured);
  std::vector<VertexIndex> measured;
  std::vector<glm::dvec3> points;
  for (std::size_t v = (step * 7919) % stride; v < n; v += stride) {
    measured.push_back(static_cast<VertexIndex>(v));
    points.push_back(sheet.positions[v]);
  }
  const std::vector<double> distances = pointDistances(points, query);
  std::vector<std::size_t> order(measured.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return distances[a] > distances[b]; });
  std::vector<glm::dvec3> far;
  for (const std::size_t i : order) {
    if (far.size() == kFarPoints) break;
    const glm::dvec3 p = points[i];
    if (std::all_of(far.begin(), far.end(),
                    [&](const glm::dvec3& q) { return glm::distance(p, q) > kFarApart * size; }))
      far.push_back(p);
  }

  const double before = fitter.approximateDistance(sheet);
  const std::size_t crossingsBefore = findSelfIntersections(sheet).intersections.size();
  const std::size_t foldsBefore = session.foldCount();
  std::uint32_t group = 1;
  for (std::size_t f = 0; f < foldsBefore; ++f)
    group = std::max(group, session.folds()[f].group + 1);
  auto undoAll = [&] { session.undoTo(foldsBefore); };
  // Directions to pleat along: toward the far point, and the sheet's own principal direction
  // nearest it (a swept sheet's rulings or profile, across which a hinge is straight).
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(
      eigenOf(pointMoments(sheet.positions, {}, centre).scatter));
  std::vector<glm::dvec3> axes;
  for (int i = 1; i < 3; ++i) {
    const Eigen::Vector3d v = solver.eigenvectors().col(i);
    axes.emplace_back(v.x(), v.y(), v.z());
  }
  // A hinge: where the pleat turns the end, given by a far point, a direction toward it and how
  // far along the way from the centre.
  struct Hinge {
    glm::dvec3 middle{0.0}, along{0.0}, bend{0.0};
    VertexIndex seed = 0;
    double reach = 0.0, spread = 0.0;
  };
  // On `on` (the sheet, or the sheet as pleats made so far left it), with its vertex normals.
  auto hingeOn = [&](const Sheet& on, const std::vector<glm::dvec3>& onNormals, const glm::dvec3& p,
                     const glm::dvec3& direction, double t) -> std::optional<Hinge> {
    const std::size_t vertices = on.vertexCount();
    const glm::dvec3 wanted = centre + t * glm::dot(p - centre, direction) * direction;
    const auto at = static_cast<VertexIndex>(nearestVertex(on.positions, wanted));
    const glm::dvec3 h = on.positions[at], m = onNormals[at];
    Hinge hinge;
    hinge.along = direction - glm::dot(direction, m) * m;
    if (!(glm::length(hinge.along) > 1e-6) || !(glm::length(m) > 0.5)) return {};
    hinge.along = glm::normalize(hinge.along);
    hinge.bend = glm::dot(query.closestPoint(p) - p, m) >= 0.0 ? m : -m;
    // The seed: the end's vertex farthest beyond the hinge (on the part both folds move).
    for (std::size_t v = 0; v < vertices; ++v)
      if (const double d = glm::dot(on.positions[v] - h, hinge.along); d > hinge.reach) {
        hinge.reach = d;
        hinge.seed = static_cast<VertexIndex>(v);
      }
    // The planes tilt about the hinge by eps and eps + theta / 2, so where the sheet rises or
    // falls along the hinge (a trough across it) the pleat is narrower or wider by that height
    // times tan(theta / 2): the planes pass at mid-height, and the pleat is widened so it is
    // nowhere narrower than `width` (else the second plane cuts the sheet under the flap).
    double low = 0.0, high = 0.0;
    for (std::size_t v = 0; v < vertices; ++v)
      if (std::abs(glm::dot(on.positions[v] - h, hinge.along)) < 0.02 * size) {
        const double height = glm::dot(on.positions[v] - h, m);
        low = std::min(low, height);
        high = std::max(high, height);
      }
    hinge.middle = h + 0.5 * (low + high) * m;
    hinge.spread = high - low;
    return hinge;
  };
  auto hingeAt = [&](const glm::dvec3& p, const glm::dvec3& direction, double t) {
    return hingeOn(sheet, normals, p, direction, t);
  };
  // Folds through `planes`, each grabbing the sheet at `seed`, made, scored, kept among the best
  // when they bring the sheet closer (as one group), and taken back.
  // `farthestWithin`: kept only where the sheet's farthest point (two-sided, exact) stays within
  // this (a family, whose pleats fold away paper its model does not see, may lay the sheet nearer
  // on the whole and leave an end short of the target's).
  // Each fold's seed is a vertex of `on`, the sheet the folds before it left.
  auto makeFolds = [&](const std::vector<std::pair<ReflectionPlane, VertexIndex>>& folds,
                       const Sheet& on) {
    for (const auto& [plane, seed] : folds) {
      const glm::dvec3 grab = session.beginDragAtDevelopment(on.development[seed]);
      session.updateDrag(plane.reflect(grab));
      if (!session.commit()) return false;
    }
    return true;
  };
  // The folds made so far scored, kept when they help, and taken back.
  auto scoreMade = [&](double farthestWithin) {
    const double after = fitter.approximateDistance(session.fixed());
    const bool keeps = after < before && (out.size() < count || after < out.back().after);
    if (keeps && findSelfIntersections(session.fixed()).intersections.size() <= crossingsBefore &&
        (farthestWithin == kNone ||
         surfaceDistance(meshOf(session.fixed()), fitter.measuredTarget(), kFarthestSamples)
                 .hausdorff <= farthestWithin)) {
      FoldSuggestion pleat;
      pleat.folds.assign(
          session.folds().begin() + static_cast<std::ptrdiff_t>(foldsBefore),
          session.folds().begin() + static_cast<std::ptrdiff_t>(session.foldCount()));
      // One group, as a symmetric fold and its images are: undo takes the pleat at once, and a
      // fit counts it as one step.
      for (FoldRecord& fold : pleat.folds) fold.group = group;
      pleat.sheet = session.fixed();
      pleat.before = before;
      pleat.after = after;
      out.push_back(std::move(pleat));
      std::stable_sort(out.begin(), out.end(),
                       [](const auto& a, const auto& b) { return a.after < b.after; });
      if (out.size() > count) out.pop_back();
    }
    undoAll();
    return after;
  };
  auto tryFolds = [&](const std::vector<std::pair<ReflectionPlane, VertexIndex>>& folds,
                      double farthestWithin = kNone) {
    deadline.countEvaluation();
    if (!makeFolds(folds, sheet)) {
      undoAll();
      return kNone;
    }
    return scoreMade(farthestWithin);
  };
  using Folds = std::vector<std::pair<ReflectionPlane, VertexIndex>>;
  // The two folds of the pleat at `hinge` turning its end by `degrees` (none where the end is
  // too short for it).
  auto pleatAt = [&](const Hinge& hinge, double degrees) {
    const double theta = degrees * kDegree, eps = 0.5 * (degrees + kFlapMargin) * kDegree;
    const double wide = width + 0.6 * hinge.spread * std::tan(0.5 * theta);
    if (!(hinge.reach > 4.0 * wide)) return Folds{};
    const PleatPlanes planes = pleatPlanes(hinge.middle, hinge.along, hinge.bend, theta, eps, wide);
    return Folds{{planes.first, hinge.seed}, {planes.second, hinge.seed}};
  };
  // The pleat at `hinge` turning its end by `degrees`, tried as above.
  auto tryPleat = [&](const Hinge& hinge, double degrees) {
    const Folds folds = pleatAt(hinge, degrees);
    return folds.empty() ? kNone : tryFolds(folds);
  };

  // Pleats placed from the target (a corrugation solved, not searched): each turns the end
  // beyond its hinge by the least-squares slope of the target's height over the sheet there.
  // `sheetFrame`: the turn about the hinge's line across the sheet's normal where the hinge lies
  // (else about the line across the sheet's mean normal, as the heights were solved: on a
  // trough, a hinge on its flank turns the end sideways about the flank's own normal).
  auto solvedFoldsOn = [&](const Sheet& on, const std::vector<glm::dvec3>& onNormals,
                           const SolvedPleat& solved, bool sheetFrame) {
    std::optional<Hinge> hinge =
        hingeOn(on, onNormals, centre + solved.at * solved.direction, solved.direction, 1.0);
    if (!hinge) return Folds{};
    if (!sheetFrame) {
      hinge->along = solved.direction;
      hinge->bend = solved.turn >= 0.0 ? solved.up : -solved.up;
    } else {
      const glm::dvec3 m = hinge->bend;
      hinge->bend = glm::dot(m, solved.up) * solved.turn >= 0.0 ? m : -m;
    }
    return pleatAt(*hinge, std::abs(solved.turn) / kDegree);
  };
  auto solvedFolds = [&](const SolvedPleat& solved, bool sheetFrame = true) {
    return solvedFoldsOn(sheet, normals, solved, sheetFrame);
  };
  auto trySolved = [&](const SolvedPleat& solved) {
    const Folds folds = solvedFolds(solved);
    return folds.empty() ? kNone : tryFolds(folds);
  };
  // Both ends' pleats as one step: each end's hinge found on the sheet as it was (the first
  // pleat moves only its own end, the part beyond its hinge joined to its seed).
  auto tryPair = [&](const SolvedPleat& a, const SolvedPleat& b) {
    Folds folds = solvedFolds(a);
    const Folds other = solvedFolds(b);
    if (folds.empty() || other.empty()) return kNone;
    folds.insert(folds.end(), other.begin(), other.end());
    return tryFolds(folds);
  };
  // Both ends of two lines across each other as one step, from a flat sheet (a saddle's rising
  // ends along one, its falling ends along the other): the first line's ends bent, one fold each
  // (on a flat sheet a reflection through a plane at half the turn about the hinge turns the
  // end; a pleat there would stack three layers that the second line's pleats cross, and the
  // paper passed through itself at every crossing: 160-200 triangle pairs on the example
  // saddle), then the second line's ends pleated (the bent sheet's ends keep their bend, which one
  // reflection would flip), their hinges found on the sheet the bends left (its ends now carry
  // the raised flaps, so the pleat is widened by their height, and the seeds are its vertices).
  auto tryCross = [&](const std::array<SolvedPleat, 4>& cross) {
    Folds first;
    for (int i = 0; i < 2; ++i) {
      const std::optional<Hinge> hinge =
          hingeAt(centre + cross[i].at * cross[i].direction, cross[i].direction, 1.0);
      if (!hinge) return kNone;
      // The end's direction once turned; the plane reflecting the along direction onto it.
      const glm::dvec3 turned =
          std::cos(cross[i].turn) * hinge->along + std::sin(cross[i].turn) * cross[i].up;
      first.emplace_back(ReflectionPlane{hinge->middle, glm::normalize(hinge->along - turned)},
                         hinge->seed);
    }
    deadline.countEvaluation();
    if (!makeFolds(first, sheet)) {
      undoAll();
      return kNone;
    }
    const Sheet bent = session.fixed();
    const std::vector<glm::dvec3> bentNormals = vertexNormals(bent);
    for (int i = 2; i < 4; ++i) {
      const Folds second = solvedFoldsOn(bent, bentNormals, cross[i], true);
      if (second.empty() || !makeFolds(second, bent)) {
        undoAll();
        return kNone;
      }
    }
    return scoreMade(kNone);
  };
  const std::vector<double> heights = heightsOver(points, distances, query, axisOf(solver, 0));
  const std::vector<SolvedPleat> solved = solvePleats(points, heights, centre, solver, width);
  // Pairs first: toward a saddle one step turns both ends of a curved sheet. Not on a flat one
  // (a square): there a pair wins the first step and leaves no step after it, where a single
  // fold first would (example saddle from the square: 3.01% Chamfer against 1.80%).
  const bool flat = solver.eigenvalues()(0) < 1e-4 * solver.eigenvalues()(2);
  // Families first, toward a saddle (no axis: a vase or a bowl gets rings) from a curved sheet:
  // each end's pleats made from the middle out, each pleat's planes (solved on the sheet as it
  // was) moved with its end by the pleats made before it there.
  double farthestBefore = kNone;  // measured once, for the first family made
  auto tryFamily = [&](const PleatFamily& family, double share) {
    Folds folds;
    Motion moved;
    glm::dvec3 end(0.0);
    for (SolvedPleat pleat : family.pleats) {
      if (pleat.direction != end) moved = Motion{};  // the other end: the middle has not moved
      end = pleat.direction;
      pleat.turn *= share;
      const Folds made = solvedFolds(pleat, false);
      if (made.size() != 2) continue;
      const ReflectionPlane first = moved(made[0].first), second = moved(made[1].first);
      folds.emplace_back(first, made[0].second);
      folds.emplace_back(second, made[1].second);
      moved = reflectedAfter(second, reflectedAfter(first, moved));
    }
    if (farthestBefore == kNone)
      farthestBefore =
          surfaceDistance(meshOf(sheet), fitter.measuredTarget(), kFarthestSamples).hausdorff;
    return folds.size() > 4 ? tryFolds(folds, farthestBefore) : kNone;
  };
  if (!flat && !fitter.revolutionTarget())
    for (const PleatFamily& family : solveFamilies(
             points, heightsAlong(points, query, axisOf(solver, 0)), centre, solver, width))
      for (const double share : kFamilyShares) {
        if (deadline.passed()) return out;
        tryFamily(family, share);
      }
  if (flat && !fitter.revolutionTarget())
    for (const std::array<SolvedPleat, 4>& cross :
         solveCrosses(points, heightsAlong(points, query, axisOf(solver, 0)), centre, solver))
      for (const double share : kSolvedShares) {
        if (deadline.passed()) return out;
        std::array<SolvedPleat, 4> tried = cross;
        for (SolvedPleat& pleat : tried) pleat.turn *= share;
        tryCross(tried);
      }
  for (const auto& [a, b] :
       flat ? decltype(solvedPairs(solved, 0.0)){} : solvedPairs(solved, 4.0 * width))
    for (const double share : kSolvedShares) {
      if (deadline.passed()) return out;
      SolvedPleat x = a, y = b;
      x.turn *= share;
      y.turn *= share;
      tryPair(x, y);
    }
  SolvedPleat bestSolved;
  double bestAfter = kNone;
  for (const SolvedPleat& one : topSolved(solved))
    for (const double share : kSolvedShares) {
      if (deadline.passed()) return out;
      SolvedPleat tried = one;
      tried.turn *= share;
      if (const double after = trySolved(tried); after < bestAfter) {
        bestAfter = after;
        bestSolved = tried;
      }
    }
  // The best refined (the model leaves out the width a pleat folds away): its hinge and turn
  // nudged, a step that helps kept, halved once.
  if (bestAfter < before)
    for (double shift = 0.04 * size, scale = 0.2; shift > 0.015 * size; shift *= 0.5, scale *= 0.5)
      for (const auto& [at, turn] : {std::pair{bestSolved.at - shift, bestSolved.turn},
                                     std::pair{bestSolved.at + shift, bestSolved.turn},
                                     std::pair{bestSolved.at, bestSolved.turn * (1 - scale)},
                                     std::pair{bestSolved.at, bestSolved.turn * (1 + scale)}}) {
        if (deadline.passed()) return out;
        SolvedPleat tried = bestSolved;
        tried.at = at;
        tried.turn = turn;
        if (const double after = trySolved(tried); after < bestAfter) {
          bestAfter = after;
          bestSolved = tried;
        }
      }
  if (!out.empty()) return out;

  struct Tried {
    glm::dvec3 far{0.0}, direction{0.0};
    double t = 0.0, degrees = 0.0, after = kNone;
  };
  std::vector<Tried> tried;
  std::vector<std::pair<VertexIndex, glm::dvec3>> seen;  // hinges tried: a vertex, a direction
  for (const glm::dvec3& p : far) {
    std::vector<glm::dvec3> directions{glm::normalize(p - centre)};
    glm::dvec3 axis = axes[0];
    for (const glm::dvec3& a : axes)
      if (std::abs(glm::dot(a, p - centre)) > std::abs(glm::dot(axis, p - centre))) axis = a;
    if (glm::dot(axis, p - centre) < 0.0) axis = -axis;
    if (glm::dot(axis, directions[0]) < 0.995) directions.push_back(axis);
    for (const glm::dvec3& direction : directions)
      for (const double t : kHingeAt) {
        const std::optional<Hinge> hinge = hingeAt(p, direction, t);
        if (!hinge) continue;
        const auto key = std::make_pair(hinge->seed, glm::round(hinge->middle / (0.01 * size)));
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
        seen.push_back(key);
        for (const double degrees : kBends) {
          if (deadline.passed()) return out;
          tried.push_back({p, direction, t, degrees, tryPleat(*hinge, degrees)});
        }
      }
  }
  // The best few refined: the bend and the hinge nudged, a step that helps kept, halved twice.
  std::stable_sort(tried.begin(), tried.end(),
                   [](const Tried& a, const Tried& b) { return a.after < b.after; });
  if (tried.size() > kRefined) tried.resize(kRefined);
  for (Tried& best : tried) {
    if (!(best.after < before)) break;
    double dt = 0.06, scale = 0.25;
    for (int round = 0; round < 2; ++round, dt *= 0.5, scale *= 0.5)
      for (const auto& [t, degrees] :
           {std::pair{best.t - dt, best.degrees}, std::pair{best.t + dt, best.degrees},
            std::pair{best.t, best.degrees * (1 - scale)},
            std::pair{best.t, best.degrees * (1 + scale)}}) {
        if (deadline.passed()) return out;
        const std::optional<Hinge> hinge = hingeAt(best.far, best.direction, t);
        if (!hinge) continue;
        const double after = tryPleat(*hinge, degrees);
        if (after < best.after) best = {best.far, best.direction, t, degrees, after};
      }
  }
  return out;
}

}  // namespace curvefold
