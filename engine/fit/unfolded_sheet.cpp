#include "engine/fit/unfolded_sheet.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "engine/fit/crease_planes.hpp"
#include "engine/fit/eigen_glm.hpp"
#include "engine/fit/subplex.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/fit/target_unfolding.hpp"
#include "engine/geometry/boundary_edges.hpp"
#include "engine/geometry/principal_moments.hpp"

namespace curvefold {
namespace {

// Folds keep the area: within this share, the defaults may be the sheet.
constexpr double kSameArea = 1e-5;
// Crease the unfolding may leave (of the diagonal), as it counts an unfolding smooth.
constexpr double kSmoothLeft = 0.003;
// How near (of the diagonal, on average both ways) the fitted sheet must lie on the unfolded one.
constexpr double kLiesOn = 1e-3;
// How near (of the diagonal, on average both ways) a choice of sides must lie on a sheet at its
// guessed parameters to be polished before the frames read from the shape are tried.
constexpr double kNearStart = 0.02;
// Folds an unfolding may read (the fit's own cap).
constexpr std::size_t kMaxFolds = 12;
// Points measured each way per evaluation, and evaluations per fit.
constexpr std::size_t kPoints = 600;
constexpr int kEvaluations = 600;
// The coarse measure: every this many-th of those points each way (the sheet's rim too). A
// polish runs on it first, and the fine one follows only where it came near the unfolded
// sheet: far (over kCoarseNear times kLiesOn), the fine one never lay on it either.
constexpr std::size_t kCoarseStride = 4;
constexpr double kCoarseNear = 4.0;
// The fine polish from the coarse one's end: its evaluations, and its first steps (of the
// coarse polish's first steps).
constexpr int kFineEvaluations = 300;
constexpr double kFineStep = 0.1;
// A coarse polish within this (of the diagonal) lies on the unfolded sheet: no fine one follows.
constexpr double kExact = 1e-9;
// Sheets one reading (parametersFromUnfolding's, at one threshold) measures at most, all choices
// and polishes together: a clock-free bound where no deadline is given.
constexpr std::size_t kMostEvaluations = 3000;
// Steps whose sides are tried every way (2^n choices) to find the part that never moved.
constexpr std::size_t kExhaustiveChoices = 8;
// Wavelengths a swept curve's sine is read at: so many, from and to these shares of its width.
constexpr int kWavelengths = 240;
constexpr double kShortestWave = 0.05, kLongestWave = 4.0;
// Leans (radians, either way) of a swept curve's axis off its principal axis tried, and how many.
constexpr double kMostLean = 0.6;
constexpr int kLeans = 121;
// Steps of each finer scan about the best lean and wavelength, each way, and such scans.
constexpr int kFiner = 10;
constexpr int kFinerRounds = 4;
// Angles (radians) about a helix's axis closer than this are one strip's.
constexpr double kStripGap = 1e-3;
// A star's points: vertices within this share of the farthest one's radius, apart by more than
// this angle (radians; a 12-point star's are 0.52 apart).
constexpr double kTipShare = 1e-3;
constexpr double kTipGap = 0.05;
// How far (degrees) from the defaults' threshold the target's own must be to be tried too.
constexpr double kThresholdStep = 0.5;

bool fitted(const SurfaceParameter& p) {
  return !p.integer && p.name != "resolution" && p.name != "hole_radius";
}

std::vector<glm::dvec3> spread(const std::vector<glm::dvec3>& points) {
  std::vector<glm::dvec3> out;
  const std::size_t step = 1 + points.size() / kPoints;
  for (std::size_t i = 0; i < points.size(); i += step) out.push_back(points[i]);
  return out;
}

// A spread of the unfolded target's vertices and its whole rim (boundaryVerticesAlong, found once
// per reading: every way the target lies keeps its triangles). A sheet too short leaves the
// target's rim off it, which a spread in index order may never meet: a helix's far row of 34
// per ruling, every 4th vertex taken, read its width 1% short (seed-19 tangent-params 3-4).
std::vector<glm::dvec3> spreadAndRim(const std::vector<glm::dvec3>& positions,
                                     const std::vector<std::uint32_t>& rim) {
  std::vector<glm::dvec3> out = spread(positions);
  for (const std::uint32_t v : rim) out.push_back(positions[v]);
  return out;
}

// One reading's sheets measured (its bound, and UnfoldingWork's count), and the points measured
// on a sheet of the grid measured last: a spread of its vertices, then its whole boundary (a
// spread may miss a row of its grid, and a sheet a row longer than the unfolded one would then
// lie as near). The same for every sheet of one grid (the parameters a polish moves keep it):
// found once per grid, not per sheet.
struct Budget {
  UnfoldingWork* work = nullptr;
  std::size_t used = 0;
  std::vector<std::array<std::uint32_t, 3>> grid;
  std::size_t gridVertices = 0;
  std::vector<std::uint32_t> picked;

  bool spent() const { return used >= kMostEvaluations; }
  int left() const { return static_cast<int>(kMostEvaluations - std::min(used, kMostEvaluations)); }
  const std::vector<std::uint32_t>& sheetPoints(const TriangleMesh& sheet) {
    if (sheet.triangles == grid && sheet.positions.size() == gridVertices) return picked;
    grid = sheet.triangles;
    gridVertices = sheet.positions.size();
    picked.clear();
    const std::size_t step = 1 + sheet.positions.size() / kPoints;
    for (std::size_t i = 0; i < sheet.positions.size(); i += step)
      picked.push_back(static_cast<std::uint32_t>(i));
    // Along the rim, not in index order: every k-th (the coarse measure's) then samples each side
    // of the grid, where in index order it kept to one (a helix's far rim, one row longer than the
    // unfolded target's, measured 0 and its width was read 1.2% wide).
    const std::vector<std::uint32_t> rim = boundaryVerticesAlong(sheet);
    if (work) ++work->boundaries;
    picked.insert(picked.end(), rim.begin(), rim.end());
    return picked;
  }
};

// The unfolded target as it may lie on the sheet: how far a sheet made with some parameters lies
// from it, on average both ways, finely (kPoints each way, and each one's rim) or coarsely (every
// kCoarseStride-th).
class Unfolded {
 public:
  Unfolded(TriangleMesh mesh, const std::vector<std::uint32_t>& rim, Budget& budget)
      : mesh_(std::move(mesh)),
        query_(mesh_, "unfolded target"),
        points_(spreadAndRim(mesh_.positions, rim)),
        budget_(budget) {}
  double apart(const std::string& kind, const SurfaceParameters& parameters,
               bool coarse = false) const {
    ++budget_.used;
    if (budget_.work) ++budget_.work->evaluations;
    const std::size_t stride = coarse ? kCoarseStride : 1;
    try {
      const TriangleMesh sheet = meshOf(makeSurface(kind, parameters));
      const SurfaceDistanceQuery onSheet(sheet, "sheet");
      double there = 0.0;
      std::size_t thereCount = 0;
      for (std::size_t i = 0; i < points_.size(); i += stride, ++thereCount)
        there += onSheet.distance(points_[i]);
      const std::vector<std::uint32_t>& picked = budget_.sheetPoints(sheet);
      double back = 0.0;
      std::size_t backCount = 0;
      for (std::size_t i = 0; i < picked.size(); i += stride, ++backCount)
        back += query_.distance(sheet.positions[picked[i]]);
      return there / static_cast<double>(thereCount) + back / static_cast<double>(backCount);
    } catch (const std::exception&) {  // parameters the kind refuses
      return 1e30;
    }
  }

 private:
  TriangleMesh mesh_;
  SurfaceDistanceQuery query_;
  std::vector<glm::dvec3> points_;
  Budget& budget_;
};

// The kind's parameters read off `positions` as they lie in the catalogue's frame (tubes and
// cones turn about the y axis, flat sheets lie in z = 0), `base` for the rest: the distance has
// local minima far from the right sheet (a cone's angle), so the search starts here.
SurfaceParameters guessFor(const std::string& kind, const std::vector<glm::dvec3>& positions,
                           double area, SurfaceParameters guess) {
  glm::dvec3 lo(1e300), hi(-1e300);
  double sumRho = 0.0, sumY = 0.0, sumYY = 0.0, sumRhoY = 0.0;
  for (const glm::dvec3& p : positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
    const double rho = std::hypot(p.x, p.z);
    sumRho += rho;
    sumY += p.y;
    sumYY += p.y * p.y;
    sumRhoY += rho * p.y;
  }
  const double count = static_cast<double>(positions.size());
  const double meanRho = sumRho / count, meanY = sumY / count;
  const double height = hi.y - lo.y;
  const double varY = sumYY / count - meanY * meanY;
  const double slope = varY > 0.0 ? (sumRhoY / count - meanRho * meanY) / varY : 0.0;
  constexpr double kDegrees = 180.0 / std::numbers::pi;
  if (kind == "square") {
    guess["size"] = std::sqrt(area);
  } else if (kind == "rectangle") {
    guess["width"] = hi.x - lo.x;
    guess["height"] = hi.y - lo.y;
  } else if (kind == "disk") {
    guess["radius"] = std::max({hi.x, -lo.x, hi.y, -lo.y});
  } else if (kind == "cylinder" || kind == "half_cylinder") {
    guess["radius"] = meanRho;
    guess["height"] = height;
    if (kind == "cylinder") guess["angle"] = std::min(360.0, area / (meanRho * height) * kDegrees);
  } else if (kind == "cone") {
    const double bottom = meanRho + slope * (lo.y - meanY), top = meanRho + slope * (hi.y - meanY);
    const double wide = std::max(bottom, top), narrow = std::max(0.0, std::min(bottom, top));
    const double topRadius = narrow < 0.05 * wide ? 0.0 : narrow;
    guess["base_radius"] = wide;
    guess["top_radius"] = topRadius;
    guess["height"] = height;
    const double slant = std::hypot(height, wide - topRadius);
    guess["angle"] =
        std::min(360.0, area / (std::numbers::pi * (wide + topRadius) * slant) * 360.0);
  } else if (kind == "star") {
    // The points lie farthest, all at the outer radius: their count is the number of angles the
    // farthest vertices gather at, and the inner radius follows from the area (n R r sin(pi / n)).
    // Without it a frame turned right but measured at the defaults' count and radii lies farther
    // than one turned wrong, and the polish cannot turn it (issue 38, a 7-point star).
    double outer = 0.0;
    for (const glm::dvec3& p : positions) outer = std::max(outer, std::hypot(p.x, p.y));
    std::vector<double> tips;
    for (const glm::dvec3& p : positions)
      if (std::hypot(p.x, p.y) >= (1.0 - kTipShare) * outer) tips.push_back(std::atan2(p.y, p.x));
    std::sort(tips.begin(), tips.end());
    int count = 0;
    for (std::size_t i = 0; i < tips.size(); ++i) {
      const double next = i + 1 < tips.size() ? tips[i + 1] : tips.front() + 2.0 * std::numbers::pi;
      if (next - tips[i] > kTipGap) ++count;
    }
    if (count >= 3 && count <= 12 && outer > 0.0) {
      const double inner = area / (count * outer * std::sin(std::numbers::pi / count));
      if (inner < outer) {
        guess["points"] = count;
        guess["outer_radius"] = outer;
        guess["inner_radius"] = inner;
      }
    }
  } else if (kind == "swept_curve") {
    guess["amplitude"] = 0.5 * (hi.z - lo.z);
    guess["curve_width"] = hi.x - lo.x;
    guess["length"] = hi.y - lo.y;
    // The wave's length: the one whose sine (least squares, z = a sin(2 pi x / wavelength)) the
    // points lie nearest; the distance from a sheet of another wavelength has minima at its
    // multiples and fractions, so the polish alone stays where it starts.
    const double width = hi.x - lo.x;
    double bestResidual = 1e300;
    for (int i = 0; i < kWavelengths && width > 0.0; ++i) {
      const double wavelength =
          width * kShortestWave * std::pow(kLongestWave / kShortestWave, i / (kWavelengths - 1.0));
      const double k = 2.0 * std::numbers::pi / wavelength;
      double zs = 0.0, ss = 0.0, zz = 0.0;
      for (const glm::dvec3& p : positions) {
        const double sine = std::sin(k * p.x);
        zs += p.z * sine;
        ss += sine * sine;
        zz += p.z * p.z;
      }
      if (!(ss > 0.0)) continue;
      const double residual = zz - zs * zs / ss;
      if (residual < bestResidual) {
        bestResidual = residual;
        guess["wavelength"] = wavelength;
        guess["amplitude"] = std::abs(zs / ss);
      }
    }
  }
  return guess;
}

// Area-weighted moments of the triangles' centroids (or of their unit normals): the mean and the
// covariance's eigenvectors, the least first.
struct Moments {
  glm::dvec3 mean{0.0};
  glm::dvec3 axes[3];
};

Moments momentsOf(const std::vector<glm::dvec3>& positions, const TriangleMesh& mesh,
                  bool normals) {
  std::vector<glm::dvec3> points;
  std::vector<double> areas;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 a = positions[t[0]], b = positions[t[1]], c = positions[t[2]];
    const glm::dvec3 cross = glm::cross(b - a, c - a);
    const double area = 0.5 * glm::length(cross);
    if (!(area > 0.0)) continue;
    points.push_back(normals ? cross / (2.0 * area) : (a + b + c) / 3.0);
    areas.push_back(area);
  }
  const PointMoments moments = pointMoments(points, areas);
  Moments m;
  m.mean = moments.centre;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(eigenOf(moments.scatter));
  for (int i = 0; i < 3; ++i)
    m.axes[i] = glm::normalize(glmOf(Eigen::Vector3d(solver.eigenvectors().col(i))));
  return m;
}

// `positions` in the frame (x, y, z) = (e[0], e[1], e[2]) about `origin`.
std::vector<glm::dvec3> inFrame(const std::vector<glm::dvec3>& positions, const glm::dvec3& origin,
                                const glm::dvec3 (&e)[3]) {
  std::vector<glm::dvec3> out;
  out.reserve(positions.size());
  for (const glm::dvec3& p : positions) {
    const glm::dvec3 d = p - origin;
    out.emplace_back(glm::dot(d, e[0]), glm::dot(d, e[1]), glm::dot(d, e[2]));
  }
  return out;
}

// A tangent developable of a helix moved whole, put where the catalogue makes it: the helix about
// y, its first ruling's foot on +z at height -rise pi turns. Its normals are the helix's binormals,
// which all make one angle with the axis (the axis: their covariance's least eigenvector, as a
// tube's), and a face's foot on the helix lies the radius from the axis along the principal
// normal, axis x normal: those lines fix the axis's place and the radius (least squares), the
// cone of normals the rise. Each face's angle about the axis, unwrapped by its foot's height,
// gives the helix's start and turns; the screw along it the height. Both senses of the axis are
// tried, the frame mirrored where a reflection turned the helix's hand; a sense along which the
// rulings run back (their foot ahead of them) is dropped.
struct HelixFrame {
  std::vector<glm::dvec3> positions;
  SurfaceParameters guess;
};

std::vector<HelixFrame> helixFrames(const std::vector<glm::dvec3>& positions,
                                    const TriangleMesh& mesh) {
  std::vector<HelixFrame> out;
  const glm::dvec3 axis = momentsOf(positions, mesh, true).axes[0];
  const glm::dvec3 e0 = glm::normalize(
      glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
  const glm::dvec3 e1 = glm::cross(axis, e0);
  struct Face {
    glm::dvec3 centre, normal;
    double area;
  };
  std::vector<Face> faces;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 a = positions[t[0]], b = positions[t[1]], c = positions[t[2]];
    const glm::dvec3 cross = glm::cross(b - a, c - a);
    const double area = 0.5 * glm::length(cross);
    if (!(area > 0.0)) continue;
    faces.push_back({(a + b + c) / 3.0, cross / (2.0 * area), area});
  }
  // The axis's place (u, v across it) and the radius: n . O - r = n . q for each face's principal
  // normal n (unit, across the axis) and centre q.
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  double cosine = 0.0, total = 0.0;
  std::vector<glm::dvec2> across(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const Face& f = faces[i];
    const glm::dvec3 principal = glm::cross(axis, f.normal);
    const double length = glm::length(principal);
    cosine += f.area * glm::dot(f.normal, axis);
    total += f.area;
    if (!(length > 1e-9)) continue;
    across[i] = glm::dvec2(glm::dot(principal, e0), glm::dot(principal, e1)) / length;
    const Eigen::Vector3d row(across[i].x, across[i].y, -1.0);
    m += f.area * row * row.transpose();
    rhs += f.area * row *
           (across[i].x * glm::dot(f.centre, e0) + across[i].y * glm::dot(f.centre, e1));
  }
  if (!(total > 0.0)) return out;
  const Eigen::Vector3d solved = m.ldlt().solve(rhs);
  double radius = solved.z();
  const glm::dvec3 centre = solved.x() * e0 + solved.y() * e1;
  // The principal normals point from the foot to the axis: where the normals' sense made the
  // radius negative, they point away.
  const double flip = radius < 0.0 ? -1.0 : 1.0;
  radius = std::abs(radius);
  const double along = std::min(1.0, std::abs(cosine) / total);  // r / L
  if (!(radius > 0.0) || !(along > 1e-3) || !(along < 1.0 - 1e-9)) return out;
  const double slant = radius / along, rise = std::sqrt(slant * slant - radius * radius);
  for (const double sense : {1.0, -1.0}) {
    for (const double hand : {1.0, -1.0}) {
      const glm::dvec3 y = sense * axis, z = e0, x = hand * glm::cross(y, z);
      // Each face's angle from z toward x, its foot's height and its distance along the ruling.
      std::vector<double> angle, height, ruling;
      std::vector<std::size_t> used;
      double forward = 0.0;
      for (std::size_t i = 0; i < faces.size(); ++i) {
        if (!(glm::length(across[i]) > 0.5)) continue;
        const glm::dvec3 toAxis = flip * (across[i].x * e0 + across[i].y * e1);
        const glm::dvec3 q = faces[i].centre - centre;
        const glm::dvec3 qAcross = q - glm::dot(q, axis) * axis;
        const glm::dvec3 foot = -radius * toAxis;  // across the axis
        const double a = std::atan2(glm::dot(-toAxis, x), glm::dot(-toAxis, z));
        const glm::dvec3 tangent = std::cos(a) * x - std::sin(a) * z;
        const double ahead = glm::dot(qAcross - foot, tangent);
        forward += faces[i].area * ahead;
        const double u = std::abs(ahead) * slant / radius;
        angle.push_back(a);
        ruling.push_back(u);
        height.push_back(glm::dot(q, y) - u * rise / slant);
        used.push_back(i);
      }
      if (used.empty() || !(forward > 0.0)) continue;
      // Unwrapped by height from the lowest foot.
      const std::size_t low =
          static_cast<std::size_t>(std::min_element(height.begin(), height.end()) - height.begin());
      constexpr double kTurn = 2.0 * std::numbers::pi;
      double first = 1e300, last = -1e300, offset = 0.0, weights = 0.0;
      double nearest = 1e300, farthest = -1e300;
      std::vector<double> unwrapped;
      for (std::size_t k = 0; k < used.size(); ++k) {
        const double expected = angle[low] + (rise > 0.0 ? (height[k] - height[low]) / rise : 0.0);
        const double t = angle[k] + kTurn * std::round((expected - angle[k]) / kTurn);
        unwrapped.push_back(t);
        first = std::min(first, t);
        last = std::max(last, t);
        offset += faces[used[k]].area * (height[k] - rise * t);
        weights += faces[used[k]].area;
        nearest = std::min(nearest, ruling[k]);
        farthest = std::max(farthest, ruling[k]);
      }
      offset /= weights;
      // A strip between rulings i and i + 1 lies in the plane of the helix's samples i to i + 2,
      // so its faces read sample i + 1: the first ruling's foot is a step (the usual one between
      // the strips read) before the first read, and ruling i's points lie a chord (the step's
      // length along the helix) nearer the foot read than on their own ruling.
      std::sort(unwrapped.begin(), unwrapped.end());
      std::vector<double> steps;
      for (std::size_t k = 1; k < unwrapped.size(); ++k)
        if (unwrapped[k] - unwrapped[k - 1] > kStripGap)
          steps.push_back(unwrapped[k] - unwrapped[k - 1]);
      double step = 0.0;
      if (!steps.empty()) {
        std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
        step = steps[steps.size() / 2];
        first -= step;
      }
      const double turns = (last - first) / kTurn;
      if (!(turns > 0.0)) continue;
      // The catalogue's helix: angle 0 at the start, height rise (t - pi turns).
      const double turn = first;
      const double shift = offset + rise * turn + rise * std::numbers::pi * turns;
      const double c = std::cos(turn), s = std::sin(turn);
      HelixFrame frame;
      frame.positions.reserve(positions.size());
      for (const glm::dvec3& p : positions) {
        const glm::dvec3 d = p - centre;
        const double px = glm::dot(d, x), pz = glm::dot(d, z);
        // Turned back by the start's angle about y (z toward x is the positive sense).
        frame.positions.emplace_back(c * px - s * pz, glm::dot(d, y) - shift, s * px + c * pz);
      }
      frame.guess["radius"] = radius;
      frame.guess["pitch"] = kTurn * rise;
      frame.guess["turns"] = turns;
      frame.guess["ruling_start"] = nearest + step * slant;
      frame.guess["ruling_width"] = farthest - nearest - step * slant;
      out.push_back(std::move(frame));
    }
  }
  return out;
}

// A smooth unfolded sheet that folds whose planes missed it moved whole (a rigid copy of the
// kind at some parameters, anywhere) put where the catalogue makes the kind, read from its shape
// alone: a tube's axis (the normals' plane) on y, its middle height at 0 and its arc's middle on +z
// (a slit tube's slit on -z); a flat sheet's plane on z = 0 about its centroid, turned so its
// principal axis lies on x, or its farthest point where the catalogue puts a corner, a disk's
// first vertex or a star's first point. Several ways where the shape leaves the turn open; none for
// other kinds.
std::vector<std::vector<glm::dvec3>> catalogueFrames(const std::string& kind,
                                                     const std::vector<glm::dvec3>& positions,
                                                     const TriangleMesh& mesh) {
  std::vector<std::vector<glm::dvec3>> out;
  if (kind == "cylinder" || kind == "half_cylinder" || kind == "cone") {
    glm::dvec3 axis = momentsOf(positions, mesh, true).axes[0];
    const glm::dvec3 e0 = glm::normalize(
        glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 e1 = glm::cross(axis, e0);
    double lo = 1e300, hi = -1e300;
    for (const glm::dvec3& p : positions) {
      lo = std::min(lo, glm::dot(p, axis));
      hi = std::max(hi, glm::dot(p, axis));
    }
    glm::dvec3 centre(0.0);
    if (kind == "cone") {
      // Every face's plane holds the apex (least squares), which lies above the base (+y).
      Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
      Eigen::Vector3d b = Eigen::Vector3d::Zero();
      glm::dvec3 mean(0.0);
      double weights = 0.0;
      for (const auto& t : mesh.triangles) {
        const glm::dvec3 p0 = positions[t[0]], p1 = positions[t[1]], p2 = positions[t[2]];
        const glm::dvec3 cross = glm::cross(p1 - p0, p2 - p0);
        if (!(glm::length(cross) > 0.0)) continue;
        const Eigen::Vector3d n = eigenOf(glm::normalize(cross));
        // Weighed by area: a sliver's normal is noise.
        const double w = 0.5 * glm::length(cross);
        a += w * n * n.transpose();
        b += w * n * n.dot(eigenOf(p0));
        mean += w * (p0 + p1 + p2) / 3.0;
        weights += w;
      }
      if (!(weights > 0.0)) return out;
      // The area's centroid (a sum of weighed centroids is not one: the apex would be placed by
      // where the folds moved the sheet, not by the sheet).
      mean /= weights;
      const glm::dvec3 apex = glmOf(Eigen::Vector3d(a.ldlt().solve(b)));
      if (glm::dot(apex - mean, axis) < 0.0) {
        axis = -axis;
        std::swap(lo, hi);
        lo = -lo;
        hi = -hi;
      }
      centre = apex - glm::dot(apex, axis) * axis + 0.5 * (lo + hi) * axis;
    } else {
      // The axis through the circle the points lie on across it (least squares, Kasa).
      Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
      Eigen::Vector3d b = Eigen::Vector3d::Zero();
      for (const glm::dvec3& p : positions) {
        const double u = glm::dot(p, e0), v = glm::dot(p, e1);
        const Eigen::Vector3d row(u, v, 1.0);
        a += row * row.transpose();
        b -= row * (u * u + v * v);
      }
      const Eigen::Vector3d circle = a.ldlt().solve(b);
      centre = -0.5 * circle.x() * e0 - 0.5 * circle.y() * e1 + 0.5 * (lo + hi) * axis;
    }
    auto across = [&](const glm::dvec3& p) {
      const glm::dvec3 d = p - centre;
      return d - glm::dot(d, axis) * axis;
    };
    // The arc's middle, by area; where the arc is nearly whole, the slit's (its boundary off
    // the rims) is the middle's opposite.
    glm::dvec3 middle(0.0);
    double total = 0.0;
    for (const auto& t : mesh.triangles) {
      const glm::dvec3 p0 = positions[t[0]], p1 = positions[t[1]], p2 = positions[t[2]];
      const double area = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
      const glm::dvec3 r = across((p0 + p1 + p2) / 3.0);
      if (glm::length(r) > 0.0) middle += area * glm::normalize(r);
      total += area;
    }
    if (!(total > 0.0)) return out;
    if (glm::length(middle) < 0.2 * total) {
      glm::dvec3 slit(0.0);
      const double band = 0.1 * (hi - lo);
      for (const auto& [edge, around] : edgeFaces(mesh)) {
        if (around.size() != 1) continue;
        for (const std::uint32_t v : {edge.first, edge.second}) {
          const double t = glm::dot(positions[v], axis);
          const glm::dvec3 r = across(positions[v]);
          if (t > lo + band && t < hi - band && glm::length(r) > 0.0) slit += glm::normalize(r);
        }
      }
      if (!(glm::length(slit) > 0.0)) return out;
      middle = -slit;
    }
    const glm::dvec3 z = glm::normalize(middle);
    const glm::dvec3 frame[3] = {glm::cross(axis, z), axis, z};
    out.push_back(inFrame(positions, centre, frame));
  } else if (kind == "swept_curve") {
    // Swept along y: the normals lie across it (their least eigenvector), the curve spreads
    // most along x about the centroid (a sine over a span centred on a node: its mean is 0),
    // and its sheet is the same turned half about y; a reflection's mirror image is z's sign.
    const glm::dvec3 y = momentsOf(positions, mesh, true).axes[0];
    const Moments m = momentsOf(positions, mesh, false);
    glm::dvec3 x(0.0);
    for (int i = 2; i >= 0 && !(glm::length(x) > 0.5); --i)
      x = m.axes[i] - glm::dot(m.axes[i], y) * y;
    if (!(glm::length(x) > 0.5)) return out;
    x = glm::normalize(x);
    // A sine spans a node's both sides unevenly (x and z correlate), so the principal axis leans
    // off the curve's x: the lean and the wavelength whose sine (least squares) the points lie
    // nearest, on a spread of them.
    const glm::dvec3 z = glm::cross(x, y);
    const std::vector<glm::dvec3> points = spread(positions);
    double width = 0.0, bestResidual = 1e300, bestLean = 0.0, bestWave = 0.0;
    for (const glm::dvec3& p : points)
      width = std::max(width, 2.0 * std::abs(glm::dot(p - m.mean, x)));
    if (!(width > 0.0)) return out;
    auto tryLean = [&](double lean, double wavelength) {
      const glm::dvec3 u = std::cos(lean) * x + std::sin(lean) * z;
      const glm::dvec3 w = glm::cross(u, y);
      const double k = 2.0 * std::numbers::pi / wavelength;
      double zs = 0.0, ss = 0.0, zz = 0.0;
      for (const glm::dvec3& p : points) {
        const double sine = std::sin(k * glm::dot(p - m.mean, u)), h = glm::dot(p - m.mean, w);
        zs += h * sine;
        ss += sine * sine;
        zz += h * h;
      }
      if (ss > 0.0 && zz - zs * zs / ss < bestResidual) {
        bestResidual = zz - zs * zs / ss;
        bestLean = lean;
        bestWave = wavelength;
      }
    };
    const double ratio = std::pow(kLongestWave / kShortestWave, 1.0 / (kWavelengths - 1.0));
    for (int j = 0; j < kLeans; ++j)
      for (int i = 0; i < kWavelengths; i += 2)
        tryLean(kMostLean * (2.0 * j / (kLeans - 1.0) - 1.0),
                width * kShortestWave * std::pow(ratio, i));
    // Then finer about the best, a coarse step each way, and again a fifth of that each time.
    double leanSpan = 2.0 * kMostLean / (kLeans - 1.0), waveSpan = ratio * ratio;
    for (int round = 0; round < kFinerRounds; ++round) {
      const double aboutLean = bestLean, aboutWave = bestWave;
      for (int j = -kFiner; j <= kFiner; ++j)
        for (int i = -kFiner; i <= kFiner; ++i)
          tryLean(aboutLean + leanSpan * j / kFiner,
                  aboutWave * std::pow(waveSpan, static_cast<double>(i) / kFiner));
      leanSpan /= 5.0;
      waveSpan = std::pow(waveSpan, 0.2);
    }
    const glm::dvec3 along = std::cos(bestLean) * x + std::sin(bestLean) * z;
    for (const double side : {1.0, -1.0}) {
      const glm::dvec3 frame[3] = {along, y, side * glm::cross(along, y)};
      out.push_back(inFrame(positions, m.mean, frame));
    }
  } else if (kind == "square" || kind == "rectangle" || kind == "disk" || kind == "star") {
    const Moments m = momentsOf(positions, mesh, false);
    const glm::dvec3 normal = m.axes[0];
    const glm::dvec3 principal[3] = {m.axes[2], glm::cross(normal, m.axes[2]), normal};
    out.push_back(inFrame(positions, m.mean, principal));
    // The farthest point turned onto the sheet's own farthest direction.
    const std::vector<glm::dvec3>& flat = out.back();
    glm::dvec3 far(0.0);
    for (const glm::dvec3& p : flat)
      if (glm::length(glm::dvec3(p.x, p.y, 0.0)) > glm::length(far)) far = {p.x, p.y, 0.0};
    // Where the catalogue puts a corner, a polygon's first vertex, a star's first point.
    const double toward = kind == "star"     ? 0.5 * std::numbers::pi
                          : kind == "square" ? 0.25 * std::numbers::pi
                                             : 0.0;
    const double turn = toward - std::atan2(far.y, far.x);
    const double c = std::cos(turn), s = std::sin(turn);
    std::vector<glm::dvec3> turned;
    turned.reserve(flat.size());
    for (const glm::dvec3& p : flat) turned.emplace_back(c * p.x - s * p.y, s * p.x + c * p.y, p.z);
    out.push_back(std::move(turned));
  }
  return out;
}

// Whether two unfoldings give a reading the same sheets to measure: what fromUnfolding uses of
// them (the planes and where the target lies unfolded).
bool sameUnfolding(const TargetUnfolding& a, const TargetUnfolding& b) {
  if (a.folds.size() != b.folds.size() || a.unfolded != b.unfolded) return false;
  for (std::size_t u = 0; u < a.folds.size(); ++u)
    if (a.folds[u].plane.point != b.folds[u].plane.point ||
        a.folds[u].plane.normal != b.folds[u].plane.normal)
      return false;
  return true;
}

// The parameters, with creases read above `threshold` degrees (see parametersFromUnfolding).
// `failed`: the unfoldings earlier readings found no sheet on; one the same again is not read
// again (a smooth target reads no crease at either threshold: the same thousands of sheets to
// the same end), and this one is added where it is read.
std::optional<SurfaceParameters> fromUnfolding(const TriangleMesh& target,
                                               const SurfaceInfo& kindInfo,
                                               const TriangleMesh& defaults, double threshold,
                                               double facetBend, const Deadline& deadline,
                                               Budget& budget,
                                               std::vector<TargetUnfolding>& failed) {
  const std::string& kind = kindInfo.name;
  const SurfaceInfo* info = &kindInfo;
  const double area = surfaceArea(target), defaultArea = surfaceArea(defaults);
  const double diagonal = boundingDiagonal(target);
  const TargetUnfolding unfolding =
      unfoldTarget(target, defaults, threshold, kMaxFolds, deadline, {}, facetBend);
  if (unfolding.cutShort || deadline.passed() || unfolding.sharpLengthLeft > kSmoothLeft * diagonal)
    return std::nullopt;
  for (const TargetUnfolding& earlier : failed)
    if (sameUnfolding(earlier, unfolding)) return std::nullopt;
  failed.push_back(unfolding);  // a reading that finds its sheet ends the search
  // The parameters fitted, from the defaults' lengths scaled to the target's area.
  std::vector<const SurfaceParameter*> free;
  SurfaceParameters base;
  const double scale = std::sqrt(area / defaultArea);
  for (const SurfaceParameter& p : info->parameters) {
    if (!fitted(p)) continue;
    free.push_back(&p);
    // Lengths scale with the area's root; angles and counts do not.
    const bool length = p.description.find("metres") != std::string::npos;
    base[p.name] = length ? p.defaultValue * scale : p.defaultValue;
  }
  // Each step of the unfolding moved its piece, so the largest part stayed; the part that never
  // moved may be a piece (a drag moves the side of its grab, often the larger): every choice of
  // sides, each a reflection of the whole through the step's plane, and the one whose guess lies
  // nearest its sheet kept.
  const std::size_t steps = std::min(unfolding.folds.size(), kExhaustiveChoices);
  std::vector<glm::dvec3> chosen;
  const std::vector<std::uint32_t> targetRim = boundaryVerticesAlong(target);
  SurfaceParameters start = base;
  double nearest = 1e300;
  // Each way the unfolded target may lie, at the start's and at its shape's parameters.
  auto consider = [&](const std::vector<glm::dvec3>& positions,
                      const SurfaceParameters& read = {}) {
    const Unfolded candidate(TriangleMesh{positions, target.triangles}, targetRim, budget);
    SurfaceParameters fromShape = guessFor(kind, positions, area, base);
    for (const auto& [name, value] : read) fromShape[name] = value;
    for (const SurfaceParameters& tried : {base, fromShape}) {
      const double d = candidate.apart(kind, tried);
      if (d < nearest) {
        nearest = d;
        start = tried;
        chosen = positions;
      }
    }
  };
  for (std::uint32_t bits = 0; bits < (1u << steps) && !deadline.passed() && !budget.spent();
       ++bits) {
    std::vector<glm::dvec3> positions = unfolding.unfolded;
    // A step's reflection of the rest moves every earlier step's result: the last step read
    // (the design's first fold) applies first.
    for (std::size_t u = 0; u < steps; ++u)
      if (bits >> u & 1u)
        for (glm::dvec3& p : positions) p = unfolding.folds[u].plane.reflect(p);
    consider(positions);
  }
  // The parameters that lay the sheet nearest the unfolded target as chosen, polished (nothing
  // where none lies on it).
  auto polish = [&]() {
    if (chosen.empty()) return std::optional<SurfaceParameters>();
    const Unfolded unfolded(TriangleMesh{chosen, target.triangles}, targetRim, budget);
    SurfaceParameters from = start;
    auto parametersOf = [&](const std::vector<double>& x) {
      SurfaceParameters out = from;
      for (std::size_t i = 0; i < free.size(); ++i) out[free[i]->name] = x[i];
      return out;
    };
    // A star's points are a count: each tried at the start, the nearest kept.
    const auto points = std::find_if(info->parameters.begin(), info->parameters.end(),
                                     [](const SurfaceParameter& p) { return p.name == "points"; });
    if (points != info->parameters.end()) {
      double best = 1e300;
      SurfaceParameters tried = from;
      for (int count = 3; count <= 12 && !deadline.passed() && !budget.spent(); ++count) {
        tried["points"] = count;
        const double d = unfolded.apart(kind, tried);
        if (d < best) {
          best = d;
          from["points"] = count;
        }
      }
    }
    std::vector<double> x, stepSizes;
    SubplexBounds bounds;
    for (const SurfaceParameter* p : free) {
      x.push_back(from[p->name]);
      bounds.lower.push_back(p->min);
      bounds.upper.push_back(p->max);
      stepSizes.push_back(p->name == "angle" ? 5.0
                                             : std::max(0.05 * from[p->name], 0.005 * diagonal));
    }
    // Subplex from x, on the coarse or the fine measure; x left at the best point it measured
    // (NLopt's own x after a forced stop is its last), and that point's value.
    auto minimize = [&](std::vector<double>& at, const std::vector<double>& steps, int evaluations,
                        bool coarse) {
      double best = 1e300;
      std::vector<double> bestAt = at;
      if (evaluations > 0)
        minimizeSubplex(
            at, steps, evaluations,
            [&](const std::vector<double>& y) {
              const double d = unfolded.apart(kind, parametersOf(y), coarse);
              if (d < best) {
                best = d;
                bestAt = y;
              }
              return d;
            },
            &deadline, &bounds);
      at = bestAt;
      return best;
    };
    if (!x.empty()) {
      // Coarse first: where it ends far from the unfolded sheet, no fine polish lies on it.
      const double coarse = minimize(x, stepSizes, std::min(kEvaluations, budget.left()), true);
      if (!(coarse <= kCoarseNear * kLiesOn * diagonal)) return std::optional<SurfaceParameters>();
      // Lying on it (a sheet the target was folded from), the fine measure finds no nearer.
      for (double& step : stepSizes) step *= kFineStep;
      if (!(coarse <= kExact * diagonal))
        minimize(x, stepSizes, std::min(kFineEvaluations, budget.left()), false);
    }
    const SurfaceParameters found = parametersOf(x);
    if (!(unfolded.apart(kind, found) <= kLiesOn * diagonal))
      return std::optional<SurfaceParameters>();
    return std::optional<SurfaceParameters>(found);
  };
  // The choices of sides first: where one lies on a sheet it is the sheet exactly, which a frame
  // read from the shape may only approach. One far from every sheet is not polished alone (600
  // sheets measured for nothing) but beside the frames.
  const bool near = nearest <= kNearStart * diagonal;
  std::optional<SurfaceParameters> found = near ? polish() : std::nullopt;
  if (!found && !deadline.passed()) {
    if (near) {
      nearest = 1e300;
      chosen.clear();
    }
    // Folds whose planes missed the sheet moved it whole: no choice of sides puts it back, but its
    // shape says where the catalogue made it.
    for (const std::vector<glm::dvec3>& positions :
         catalogueFrames(kind, unfolding.unfolded, target)) {
      if (deadline.passed() || budget.spent()) break;
      consider(positions);
    }
    if (kind == "helix_tangent")
      for (const HelixFrame& helix : helixFrames(unfolding.unfolded, target)) {
        if (deadline.passed() || budget.spent()) break;
        consider(helix.positions, helix.guess);
      }
    found = polish();
  }
  if (!found) return std::nullopt;
  SurfaceParameters changed;
  for (const auto& entry : *found) {
    // Not a structured binding: clang 14 (the sanitized build) cannot capture one.
    const std::string& name = entry.first;
    const auto p = std::find_if(info->parameters.begin(), info->parameters.end(),
                                [&](const SurfaceParameter& q) { return q.name == name; });
    if (p != info->parameters.end() && entry.second != p->defaultValue)
      changed[name] = entry.second;
  }
  return changed;
}

}  // namespace

std::optional<SurfaceParameters> parametersFromUnfolding(const TriangleMesh& target,
                                                         const std::string& kind,
                                                         const Deadline& deadline,
                                                         UnfoldingWork* work) {
  const auto& catalog = surfaceCatalog();
  const auto info = std::find_if(catalog.begin(), catalog.end(),
                                 [&](const SurfaceInfo& s) { return s.name == kind; });
  if (info == catalog.end()) return std::nullopt;
  const TriangleMesh defaults = meshOf(makeSurface(kind));
  const double area = surfaceArea(target);
  if (std::abs(area - surfaceArea(defaults)) <= kSameArea * area) return std::nullopt;
  // The defaults' facets bend as the target's sheet need not: a tube of another radius or arc
  // bends more or less, so the defaults' threshold reads its facets as creases, or misses a
  // shallow crease. Where the defaults' bends read nothing, the target's own.
  const double threshold = sharpEdgeThreshold(defaults);
  Budget first, second, third;
  first.work = second.work = third.work = work;
  std::vector<TargetUnfolding> failed;
  if (std::optional<SurfaceParameters> found =
          fromUnfolding(target, *info, defaults, threshold, -1.0, deadline, first, failed))
    return found;
  const double bend = facetBendDegrees(target), own = sharpEdgeThresholdFor(bend);
  if (std::abs(own - threshold) > kThresholdStep && !deadline.passed())
    if (std::optional<SurfaceParameters> found =
            fromUnfolding(target, *info, defaults, own, bend, deadline, second, failed))
      return found;
  // Facets that bend unevenly (a swept curve's by its curvature) bend more than nine tenths of
  // the edges: read as creases at `own`, and left as crease after it. The bends below the gap
  // that parts them from the creases are facets (the threshold kept under the gap's top).
  double creases = 0.0;
  const std::optional<double> uneven = facetBendBelowGap(target, &creases);
  if (uneven && !deadline.passed()) {
    const double gapped = std::min(sharpEdgeThresholdFor(*uneven), std::sqrt(*uneven * creases));
    if (std::abs(gapped - own) > kThresholdStep || std::abs(*uneven - bend) > kThresholdStep)
      if (std::optional<SurfaceParameters> found =
              fromUnfolding(target, *info, defaults, gapped, *uneven, deadline, third, failed))
        return found;
  }
  // A sheet whose facets bend more than the defaults' but still under their threshold (a steeper
  // sine at the same resolution): the first reading saw every crease, but its facets' bends
  // counted as crease left. Where a crease's bend falls near the facets' along it (a curved
  // fold's angle varies), no gap parts them: every bend under the threshold is the facets'.
  const double under = largestBendBelow(target, threshold);
  if (under <= largestDihedralDegrees(defaults) + kThresholdStep || deadline.passed())
    return std::nullopt;
  Budget fourth;
  fourth.work = work;
  return fromUnfolding(target, *info, defaults, threshold, under, deadline, fourth, failed);
}

}  // namespace curvefold
