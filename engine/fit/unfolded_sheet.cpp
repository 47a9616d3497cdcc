#include "engine/fit/unfolded_sheet.hpp"

#include <algorithm>
#include <cmath>
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

namespace curvefold {
namespace {

// Folds keep the area: within this share, the defaults may be the sheet.
constexpr double kSameArea = 1e-5;
// Crease the unfolding may leave (of the diagonal), as it counts an unfolding smooth.
constexpr double kSmoothLeft = 0.003;
// How near (of the diagonal, on average both ways) the fitted sheet must lie on the unfolded one.
constexpr double kLiesOn = 1e-3;
// Folds an unfolding may read (the fit's own cap).
constexpr std::size_t kMaxFolds = 12;
// Points measured each way per evaluation, and evaluations per fit.
constexpr std::size_t kPoints = 600;
constexpr int kEvaluations = 600;
// Steps whose sides are tried every way (2^n choices) to find the part that never moved.
constexpr std::size_t kExhaustiveChoices = 8;
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

// The unfolded target as it may lie on the sheet: how far a sheet made with some parameters lies
// from it, on average both ways.
class Unfolded {
 public:
  explicit Unfolded(TriangleMesh mesh)
      : mesh_(std::move(mesh)),
        query_(mesh_, "unfolded target"),
        points_(spread(mesh_.positions)) {}
  double apart(const std::string& kind, const SurfaceParameters& parameters) const {
    try {
      const TriangleMesh sheet = meshOf(makeSurface(kind, parameters));
      const SurfaceDistanceQuery onSheet(sheet, "sheet");
      double there = 0.0;
      for (const glm::dvec3& p : points_) there += onSheet.distance(p);
      const std::vector<glm::dvec3> sheetPoints = spread(sheet.positions);
      double back = 0.0;
      for (const glm::dvec3& p : sheetPoints) back += query_.distance(p);
      return there / static_cast<double>(points_.size()) +
             back / static_cast<double>(sheetPoints.size());
    } catch (const std::exception&) {  // parameters the kind refuses
      return 1e30;
    }
  }

 private:
  TriangleMesh mesh_;
  SurfaceDistanceQuery query_;
  std::vector<glm::dvec3> points_;
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
  } else if (kind == "swept_curve") {
    guess["amplitude"] = 0.5 * (hi.z - lo.z);
    guess["curve_width"] = hi.x - lo.x;
    guess["length"] = hi.y - lo.y;
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
  std::vector<std::pair<glm::dvec3, double>> points;
  double total = 0.0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 a = positions[t[0]], b = positions[t[1]], c = positions[t[2]];
    const glm::dvec3 cross = glm::cross(b - a, c - a);
    const double area = 0.5 * glm::length(cross);
    if (!(area > 0.0)) continue;
    points.emplace_back(normals ? cross / (2.0 * area) : (a + b + c) / 3.0, area);
    total += area;
  }
  Moments m;
  for (const auto& [p, w] : points) m.mean += w * p;
  if (total > 0.0) m.mean /= total;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& [p, w] : points) {
    const Eigen::Vector3d d = eigenOf(p - m.mean);
    covariance += w * d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
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
  if (kind == "cylinder" || kind == "half_cylinder") {
    const glm::dvec3 axis = momentsOf(positions, mesh, true).axes[0];
    const glm::dvec3 e0 = glm::normalize(
        glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 e1 = glm::cross(axis, e0);
    // The axis through the circle the points lie on across it (least squares, Kasa).
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    double lo = 1e300, hi = -1e300;
    for (const glm::dvec3& p : positions) {
      const double u = glm::dot(p, e0), v = glm::dot(p, e1), t = glm::dot(p, axis);
      lo = std::min(lo, t);
      hi = std::max(hi, t);
      const Eigen::Vector3d row(u, v, 1.0);
      a += row * row.transpose();
      b -= row * (u * u + v * v);
    }
    const Eigen::Vector3d circle = a.ldlt().solve(b);
    const glm::dvec3 centre =
        -0.5 * circle.x() * e0 - 0.5 * circle.y() * e1 + 0.5 * (lo + hi) * axis;
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

// The parameters, with creases read above `threshold` degrees (see parametersFromUnfolding).
std::optional<SurfaceParameters> fromUnfolding(const TriangleMesh& target,
                                               const SurfaceInfo& kindInfo,
                                               const TriangleMesh& defaults, double threshold,
                                               double facetBend, const Deadline& deadline) {
  const std::string& kind = kindInfo.name;
  const SurfaceInfo* info = &kindInfo;
  const double area = surfaceArea(target), defaultArea = surfaceArea(defaults);
  const double diagonal = boundingDiagonal(target);
  const TargetUnfolding unfolding =
      unfoldTarget(target, defaults, threshold, kMaxFolds, deadline, {}, facetBend);
  if (unfolding.cutShort || deadline.passed() || unfolding.sharpLengthLeft > kSmoothLeft * diagonal)
    return std::nullopt;
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
  SurfaceParameters start = base;
  double nearest = 1e300;
  // Each way the unfolded target may lie, at the start's and at its shape's parameters.
  auto consider = [&](const std::vector<glm::dvec3>& positions) {
    const Unfolded candidate(TriangleMesh{positions, target.triangles});
    for (const SurfaceParameters& tried : {base, guessFor(kind, positions, area, base)}) {
      const double d = candidate.apart(kind, tried);
      if (d < nearest) {
        nearest = d;
        start = tried;
        chosen = positions;
      }
    }
  };
  for (std::uint32_t bits = 0; bits < (1u << steps) && !deadline.passed(); ++bits) {
    std::vector<glm::dvec3> positions = unfolding.unfolded;
    // A step's reflection of the rest moves every earlier step's result: the last step read
    // (the design's first fold) applies first.
    for (std::size_t u = 0; u < steps; ++u)
      if (bits >> u & 1u)
        for (glm::dvec3& p : positions) p = unfolding.folds[u].plane.reflect(p);
    consider(positions);
  }
  // Folds whose planes missed the sheet moved it whole: no choice of sides puts it back, but its
  // shape says where the catalogue made it.
  for (const std::vector<glm::dvec3>& positions :
       catalogueFrames(kind, unfolding.unfolded, target)) {
    if (deadline.passed()) break;
    consider(positions);
  }
  if (chosen.empty()) return std::nullopt;
  const Unfolded unfolded(TriangleMesh{chosen, target.triangles});
  base = start;
  auto parametersOf = [&](const std::vector<double>& x) {
    SurfaceParameters out = base;
    for (std::size_t i = 0; i < free.size(); ++i) out[free[i]->name] = x[i];
    return out;
  };
  // A star's points are a count: each tried at the start, the nearest kept.
  const auto points = std::find_if(info->parameters.begin(), info->parameters.end(),
                                   [](const SurfaceParameter& p) { return p.name == "points"; });
  if (points != info->parameters.end()) {
    double best = 1e300;
    SurfaceParameters tried = base;
    for (int count = 3; count <= 12 && !deadline.passed(); ++count) {
      tried["points"] = count;
      const double d = unfolded.apart(kind, tried);
      if (d < best) {
        best = d;
        base["points"] = count;
      }
    }
  }
  std::vector<double> x, stepSizes;
  SubplexBounds bounds;
  for (const SurfaceParameter* p : free) {
    x.push_back(base[p->name]);
    bounds.lower.push_back(p->min);
    bounds.upper.push_back(p->max);
    stepSizes.push_back(p->name == "angle" ? 5.0
                                           : std::max(0.05 * base[p->name], 0.005 * diagonal));
  }
  if (!x.empty())
    minimizeSubplex(
        x, stepSizes, kEvaluations,
        [&](const std::vector<double>& y) { return unfolded.apart(kind, parametersOf(y)); },
        &deadline, &bounds);
  const SurfaceParameters found = parametersOf(x);
  if (!(unfolded.apart(kind, found) <= kLiesOn * diagonal)) return std::nullopt;
  SurfaceParameters changed;
  for (const auto& entry : found) {
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
                                                         const Deadline& deadline) {
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
  if (std::optional<SurfaceParameters> found =
          fromUnfolding(target, *info, defaults, threshold, -1.0, deadline))
    return found;
  const double bend = facetBendDegrees(target), own = sharpEdgeThresholdFor(bend);
  if (std::abs(own - threshold) > kThresholdStep && !deadline.passed())
    return fromUnfolding(target, *info, defaults, own, bend, deadline);
  return std::nullopt;
}

}  // namespace curvefold
