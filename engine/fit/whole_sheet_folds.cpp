#include "engine/fit/whole_sheet_folds.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <glm/geometric.hpp>

#include "engine/fit/eigen_glm.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/fit/surface_samples.hpp"
#include "engine/geometry/boundary_edges.hpp"
#include "engine/geometry/principal_moments.hpp"

namespace curvefold {
namespace {

double diagonalOf(const std::vector<glm::dvec3>& points) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return points.empty() ? 0.0 : glm::distance(lo, hi);
}

struct Frame {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // principal axes, columns
};

Frame principalFrame(const TriangleMesh& mesh) {
  const std::vector<SurfaceSample> samples = sampleSurface(mesh, 4000, 11);
  std::vector<glm::dvec3> positions;
  positions.reserve(samples.size());
  for (const SurfaceSample& s : samples) positions.push_back(s.position);
  const PointMoments moments = pointMoments(positions);
  Frame frame;
  frame.centre = eigenOf(moments.centre);
  frame.axes =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(eigenOf(moments.scatter)).eigenvectors();
  return frame;
}

// A proper motion after a fixed mirror (or none): what ICP refines.
struct Pose {
  bool mirrored = false;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  double residual = 1e300;
};

const Eigen::Matrix3d kMirror = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();

Eigen::Vector3d apply(const Pose& pose, const Eigen::Vector3d& x) {
  return pose.rotation * (pose.mirrored ? Eigen::Vector3d(kMirror * x) : x) + pose.offset;
}

double meanDistance(const Pose& pose, const std::vector<Eigen::Vector3d>& points,
                    const SurfaceDistanceQuery& moved) {
  double sum = 0.0;
  for (const Eigen::Vector3d& p : points) sum += moved.distance(glmOf(apply(pose, p)));
  return sum / double(std::max<std::size_t>(1, points.size()));
}

// Points of the sheet with its unit normals there: what a refinement lays on the copy.
struct Anchors {
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<char> onBoundary;  // a vertex of the sheet's boundary (its rim, a slit's side)
  void add(const Eigen::Vector3d& point, const Eigen::Vector3d& normal, bool boundary = false) {
    points.push_back(point);
    normals.push_back(normal);
    onBoundary.push_back(boundary ? 1 : 0);
  }
};

// A mesh's boundary as segments (its edges with one face): a slit's two sides, a sheet's rim.
// Closest points by brute force: a sheet's boundary holds a few hundred edges.
struct BoundaryCurve {
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments;

  BoundaryCurve(const TriangleMesh& mesh,
                const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges) {
    for (const auto& [a, b] : edges)
      segments.emplace_back(eigenOf(mesh.positions[a]), eigenOf(mesh.positions[b]));
  }
  bool empty() const { return segments.empty(); }
  Eigen::Vector3d closestPoint(const Eigen::Vector3d& p) const {
    Eigen::Vector3d best = p;
    double bestSquared = 1e300;
    for (const auto& [a, b] : segments) {
      const Eigen::Vector3d ab = b - a;
      const double length = ab.squaredNorm();
      const double t = length > 0.0 ? std::clamp((p - a).dot(ab) / length, 0.0, 1.0) : 0.0;
      const Eigen::Vector3d q = a + t * ab;
      const double squared = (p - q).squaredNorm();
      if (squared < bestSquared) {
        bestSquared = squared;
        best = q;
      }
    }
    return best;
  }
  double distance(const Eigen::Vector3d& p) const { return (p - closestPoint(p)).norm(); }
};

// The vertices' area-weighted normals.
std::vector<Eigen::Vector3d> vertexNormals(const TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> normals(mesh.positions.size(), Eigen::Vector3d::Zero());
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                    mesh.positions[t[2]] - mesh.positions[t[0]]);
    for (const std::uint32_t v : t) normals[v] += eigenOf(n);
  }
  for (Eigen::Vector3d& n : normals)
    n = n.norm() > 0.0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::UnitZ();
  return normals;
}

// Gauss-Newton on the distance to the copy [Chen & Medioni 1992, point to plane], damped as
// Levenberg-Marquardt [Marquardt 1963], each step against the exact closest points. A point
// off the copy across its surface is held along the sheet's normal there; one off it along the
// surface (past the copy's boundary: a corner of a 96-gon turned, a slit's edge) along the way
// back too. Point-to-point steps [Besl & McKay 1992] hold every point to its closest point, so
// on a sheet with a near-continuous symmetry (a disk turned about its normal, a cylinder about
// its axis) the interior pinned the turn and only the few corners or the slit moved it: hundreds
// of steps, seconds to a minute. Here the interior holds no turn it does not see, and a handful
// of steps lands the corners. Stops at `deadline` too, checked every step: one step on every
// vertex of a large sheet takes milliseconds to tens of them.
// With `boundary` (the copy's), each boundary anchor is also held to the copy's boundary, point
// to point: what fixes the turn of a sheet that lies on its copy in a continuous family of ways.
Pose refine(Pose pose, const Anchors& anchors, const SurfaceDistanceQuery& moved, double scale,
            const Deadline& deadline, int iterations = 100, int* steps = nullptr,
            const BoundaryCurve* boundary = nullptr) {
  const std::size_t count = anchors.points.size();
  std::vector<Eigen::Vector3d> source(count), normal(count);
  for (std::size_t i = 0; i < count; ++i) {
    source[i] = pose.mirrored ? Eigen::Vector3d(kMirror * anchors.points[i]) : anchors.points[i];
    normal[i] = pose.mirrored ? Eigen::Vector3d(kMirror * anchors.normals[i]) : anchors.normals[i];
  }
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  using Matrix6d = Eigen::Matrix<double, 6, 6>;
  struct Linearized {
    Matrix6d normal = Matrix6d::Zero();
    Vector6d gradient = Vector6d::Zero();
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  };
  // The mean distance at `at`, and the normal equations of its rows about their centroid.
  auto linearize = [&](const Pose& at, Linearized& system) {
    std::vector<Eigen::Vector3d> placed(count);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < count; ++i) {
      placed[i] = at.rotation * source[i] + at.offset;
      centre += placed[i];
    }
    centre /= double(std::max<std::size_t>(1, count));
    system = {};
    system.centre = centre;
    double sum = 0.0;
    auto row = [&](const Eigen::Vector3d& arm, const Eigen::Vector3d& direction, double value) {
      Vector6d j;
      j << arm.cross(direction), direction;
      system.normal += j * j.transpose();
      system.gradient += j * value;
    };
    for (std::size_t i = 0; i < count; ++i) {
      // A pass on every vertex of a large sheet takes tens of milliseconds under load.
      if (i % 512 == 511 && deadline.passed()) return 1e300;
      const Eigen::Vector3d q = eigenOf(moved.closestPoint(glmOf(placed[i])));
      const Eigen::Vector3d off = placed[i] - q, n = at.rotation * normal[i];
      const double distance = off.norm();
      sum += distance;
      const Eigen::Vector3d arm = placed[i] - centre;
      row(arm, n, n.dot(off));
      // Off along the surface: its way back too (across it, the normal's row says it all).
      const Eigen::Vector3d along = off - n * n.dot(off);
      if (along.norm() > 0.3 * distance && along.norm() > 1e-12 * scale)
        row(arm, along.normalized(), along.norm());
      if (boundary && anchors.onBoundary[i]) {
        const Eigen::Vector3d offEdge = placed[i] - boundary->closestPoint(placed[i]);
        sum += offEdge.norm();
        if (offEdge.norm() > 1e-12 * scale) row(arm, offEdge.normalized(), offEdge.norm());
      }
    }
    return sum / double(std::max<std::size_t>(1, count));
  };
  Linearized best;
  if (deadline.passed()) return pose;
  pose.residual = linearize(pose, best);
  double damping = 1e-6;
  int taken = 0;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    // Far below any tolerance a caller checks (1e-4 of the diagonal): more is time only.
    if (deadline.passed() || pose.residual < 1e-8 * scale || damping > 1e6) break;
    ++taken;
    // Marquardt's damping, and a floor for a turn no row sees (a disk on few points: any turn
    // about its normal lies as well), which then stays as it is.
    Matrix6d a = best.normal;
    const double floor = 1e-12 * std::max(1e-300, a.diagonal().maxCoeff());
    for (int k = 0; k < 6; ++k) a(k, k) += damping * a(k, k) + floor;
    const Vector6d step = a.ldlt().solve(-best.gradient);
    if (!step.allFinite()) break;
    const Eigen::Vector3d w = step.head<3>();
    const Eigen::Matrix3d turnBy =
        w.norm() > 0.0 ? Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix()
                       : Eigen::Matrix3d::Identity();
    Pose next = pose;
    next.rotation = turnBy * pose.rotation;
    next.offset = turnBy * (pose.offset - best.centre) + best.centre + step.tail<3>();
    Linearized system;
    next.residual = linearize(next, system);
    if (next.residual < pose.residual) {
      const bool stalled = next.residual > pose.residual - 1e-14 * scale;
      pose = next;
      best = system;
      damping = std::max(1e-9, damping / 4.0);
      if (stalled) break;
    } else {
      damping *= 8.0;
    }
  }
  if (steps) *steps += taken;
  return pose;
}

RigidMotion motionOf(const Pose& pose) {
  const Eigen::Matrix3d linear =
      pose.mirrored ? Eigen::Matrix3d(pose.rotation * kMirror) : pose.rotation;
  return {glmOf(linear), glmOf(pose.offset)};
}

Pose poseOf(const RigidMotion& motion) {
  Pose pose;
  const Eigen::Matrix3d linear = eigenOf(motion.linear);
  pose.mirrored = linear.determinant() < 0.0;
  pose.rotation = pose.mirrored ? Eigen::Matrix3d(linear * kMirror) : linear;
  pose.offset = eigenOf(motion.offset);
  return pose;
}

Eigen::Matrix3d turn(int axis, double radians) {
  return Eigen::AngleAxisd(radians, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
}

// As close as registration finds a motion (1e-4 of the diagonal): a motion registered on an
// unfolded target carries the small errors of the crease planes read (1.6e-5 seen), which a
// tighter bound took for another motion.
bool sameMotion(const RigidMotion& a, const RigidMotion& b, double scale) {
  double linear = 0.0;
  for (int c = 0; c < 3; ++c) linear = std::max(linear, glm::length(a.linear[c] - b.linear[c]));
  return linear < 1e-4 && glm::distance(a.offset, b.offset) < 1e-4 * std::max(scale, 1e-9);
}

// Whether the plane leaves every point on one side, `margin` clear.
bool misses(const ReflectionPlane& plane, const std::vector<glm::dvec3>& points, double margin) {
  bool above = false, below = false;
  for (const glm::dvec3& p : points) {
    const double d = plane.signedDistance(p);
    if (std::abs(d) < margin) return false;
    (d > 0.0 ? above : below) = true;
    if (above && below) return false;
  }
  return true;
}

// Every plane misses the sheet where the planes before it left it, and together they make
// `motion`.
bool folds(const std::vector<ReflectionPlane>& planes, const RigidMotion& motion,
           std::vector<glm::dvec3> points, double margin, double scale) {
  RigidMotion made;
  for (const ReflectionPlane& plane : planes) {
    if (!misses(plane, points, margin)) return false;
    for (glm::dvec3& p : points) p = plane.reflect(p);
    made = then(made, reflectionOf(plane));
  }
  return sameMotion(made, motion, scale);
}

double highest(const glm::dvec3& n, const std::vector<glm::dvec3>& points) {
  double h = -1e300;
  for (const glm::dvec3& p : points) h = std::max(h, glm::dot(n, p));
  return h;
}

}  // namespace

std::vector<RigidMotion> registerSheetOntoAll(const TriangleMesh& sheet, const TriangleMesh& moved,
                                              double tolerance, std::size_t most,
                                              const Deadline& deadline, int* steps) {
  if (sheet.triangles.empty() || moved.triangles.empty() || most == 0) return {};
  const SurfaceDistanceQuery movedSurface(moved, "target");
  const double scale = boundingDiagonal(sheet);
  const Frame from = principalFrame(sheet), to = principalFrame(moved);
  // Few area samples to tell the starts apart; then every boundary vertex (the corners and the
  // slit, which hold a near-symmetric sheet's turn) and some 600 others; then every vertex.
  Anchors coarse, fine, all;
  std::vector<Eigen::Vector3d> coarsePoints;
  for (const SurfaceSample& s : sampleSurface(sheet, 64, 5)) {
    coarse.add(eigenOf(s.position), eigenOf(s.normal));
    coarsePoints.push_back(eigenOf(s.position));
  }
  const std::vector<Eigen::Vector3d> normals = vertexNormals(sheet);
  std::vector<char> onBoundary(sheet.positions.size(), 0);
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> sheetRim = boundaryEdges(sheet);
  for (const auto& [a, b] : sheetRim) onBoundary[a] = onBoundary[b] = 1;
  std::vector<Eigen::Vector3d> sheetBoundary;
  for (std::size_t i = 0; i < sheet.positions.size(); ++i) {
    all.add(eigenOf(sheet.positions[i]), normals[i], onBoundary[i]);
    if (onBoundary[i] || i % (1 + sheet.positions.size() / 600) == 0)
      fine.add(eigenOf(sheet.positions[i]), normals[i], onBoundary[i]);
    if (onBoundary[i]) sheetBoundary.push_back(eigenOf(sheet.positions[i]));
  }
  // The boundaries, each onto the other: a slit cone's or cylinder's sides meet in space, so as
  // a set of points it is whole and lies on its copy turned any way about its axis (a disk, a
  // 96-gon, nearly so); only the slit (the corners) says which turn the development's folds
  // were made on. A copy with no boundary of its own (a slit welded shut) says nothing.
  // The copy's, made when a way first lays the surfaces (a copy laid no way needs none).
  const BoundaryCurve sheetEdges(sheet, sheetRim);
  std::optional<BoundaryCurve> copyEdgesMade;
  std::vector<Eigen::Vector3d> copyBoundary;
  auto copyEdgesOf = [&]() -> const BoundaryCurve& {
    if (!copyEdgesMade) {
      copyEdgesMade.emplace(moved, boundaryEdges(moved));
      for (const auto& [a, b] : copyEdgesMade->segments) {
        copyBoundary.push_back(a);
        copyBoundary.push_back(b);
      }
    }
    return *copyEdgesMade;
  };
  auto edgesFit = [&](const RigidMotion& motion) {
    const BoundaryCurve& copyEdges = copyEdgesOf();
    if (sheetEdges.empty() || copyEdges.empty()) return true;
    const Eigen::Matrix3d linear = eigenOf(motion.linear);
    const Eigen::Vector3d offset = eigenOf(motion.offset);
    for (const Eigen::Vector3d& p : sheetBoundary)
      if (!(copyEdges.distance(linear * p + offset) <= tolerance)) return false;
    const Eigen::Matrix3d back = linear.transpose();
    for (const Eigen::Vector3d& q : copyBoundary)
      if (!(sheetEdges.distance(back * (q - offset)) <= tolerance)) return false;
    return true;
  };
  // Every so many boundary vertices, to choose a turn by.
  std::vector<Eigen::Vector3d> someBoundary;
  for (std::size_t i = 0; i < sheetBoundary.size(); i += 1 + sheetBoundary.size() / 96)
    someBoundary.push_back(sheetBoundary[i]);

  // Starts: the principal axes matched with every sign, and turned about each of the sheet's
  // axes (a square's or a disk's axes are any in its plane).
  std::vector<Pose> starts;
  for (int signs = 0; signs < 8; ++signs) {
    const Eigen::Vector3d s(signs & 1 ? -1.0 : 1.0, signs & 2 ? -1.0 : 1.0, signs & 4 ? -1.0 : 1.0);
    for (int axis = 0; axis < 3; ++axis)
      for (int step = 0; step < 24; ++step) {
        if (step == 0 && axis > 0) continue;
        if (deadline.passed()) return {};  // each start's measure is 64 closest points
        const Eigen::Matrix3d linear = to.axes * s.asDiagonal() *
                                       turn(axis, step * std::numbers::pi / 12.0) *
                                       from.axes.transpose();
        Pose pose;
        pose.mirrored = linear.determinant() < 0.0;
        pose.rotation = pose.mirrored ? Eigen::Matrix3d(linear * kMirror) : linear;
        pose.offset = to.centre - linear * from.centre;
        pose.residual = meanDistance(pose, coarsePoints, movedSurface);
        starts.push_back(pose);
      }
  }
  std::stable_sort(starts.begin(), starts.end(),
                   [](const Pose& a, const Pose& b) { return a.residual < b.residual; });
  // Both ways within the tolerance: the sheet on the copy and the copy on the sheet.
  auto lays = [&](const RigidMotion& motion) {
    TriangleMesh placed = sheet;
    for (glm::dvec3& p : placed.positions) p = motion(p);
    const SurfaceDistanceQuery placedSurface(placed, "sheet");
    for (std::size_t i = 0; i < placed.positions.size(); ++i)
      if ((i % 512 == 511 && deadline.passed()) ||
          !(movedSurface.distance(placed.positions[i]) <= tolerance))
        return false;
    for (std::size_t i = 0; i < moved.positions.size(); ++i)
      if ((i % 512 == 511 && deadline.passed()) ||
          !(placedSurface.distance(moved.positions[i]) <= tolerance))
        return false;
    return true;
  };
  auto near = [](const Eigen::Matrix3d& a, const Eigen::Matrix3d& b, double radians) {
    // The angle of a^T b's turn (a and b of one handedness).
    return std::acos(std::clamp(0.5 * ((a.transpose() * b).trace() - 1.0), -1.0, 1.0)) < radians;
  };
  // The best few starts refined first (the best registration); then, where the sheet lies on the
  // copy several ways (its symmetries), every other start that lies about as well, skipping one
  // that begins near a motion found.
  // `motion` turned about one of the sheet's principal axes (through its centroid) until the
  // boundaries lie on each other (every degree, the sheet's boundary on the copy's and the
  // sheet on the copy), then refined holding the boundaries together: nothing where no turn
  // lays them.
  auto turnedOntoEdges = [&](const RigidMotion& motion) -> std::optional<RigidMotion> {
    const BoundaryCurve& copyEdges = copyEdgesOf();
    const Eigen::Matrix3d linear = eigenOf(motion.linear);
    const Eigen::Vector3d offset = eigenOf(motion.offset);
    struct Turned {
      double cost = 1e300;
      RigidMotion motion;
    };
    std::vector<Turned> best(3);
    for (int axis = 0; axis < 3; ++axis)
      for (int step = 0; step < 360; ++step) {
        if (deadline.passed()) return std::nullopt;
        const Eigen::Matrix3d r =
            Eigen::AngleAxisd(step * std::numbers::pi / 180.0, Eigen::Vector3d(from.axes.col(axis)))
                .toRotationMatrix();
        // x -> motion(c + R (x - c))
        const RigidMotion turned{
            glmOf(Eigen::Matrix3d(linear * r)),
            glmOf(Eigen::Vector3d(linear * (from.centre - r * from.centre) + offset))};
        double cost = 0.0;
        for (const Eigen::Vector3d& p : someBoundary)
          cost += copyEdges.distance(eigenOf(turned(glmOf(p))));
        cost /= double(std::max<std::size_t>(1, someBoundary.size()));
        for (const Eigen::Vector3d& p : coarsePoints)
          cost += movedSurface.distance(turned(glmOf(p))) / double(coarsePoints.size());
        if (cost < best[axis].cost) best[axis] = {cost, turned};
      }
    std::sort(best.begin(), best.end(),
              [](const Turned& a, const Turned& b) { return a.cost < b.cost; });
    for (const Turned& turned : best) {
      if (deadline.passed()) return std::nullopt;
      const Pose pose = refine(poseOf(turned.motion), fine, movedSurface, scale, deadline, 100,
                               steps, &copyEdges);
      const RigidMotion refined = motionOf(pose);
      if (deadline.passed()) return std::nullopt;
      if (edgesFit(refined) && lays(refined)) return refined;
    }
    return std::nullopt;
  };
  std::vector<RigidMotion> found;
  std::vector<char> foundFits;  // whether each way found lays the boundaries on each other
  constexpr int kTurnsTried = 2;
  int turnsTried = 0;  // turns that laid no boundaries
  std::vector<Pose> foundPoses;
  const std::size_t kFirst = 4, kMostRefined = 64;
  const double coarseEnough = 3.0 * starts.front().residual + 2e-3 * scale;
  for (std::size_t k = 0, refined = 0; k < starts.size() && refined < kMostRefined; ++k) {
    if (found.size() >= most || deadline.passed()) break;
    if (k >= kFirst && starts[k].residual > coarseEnough) break;
    const bool begunNear = std::any_of(foundPoses.begin(), foundPoses.end(), [&](const Pose& f) {
      return f.mirrored == starts[k].mirrored && near(f.rotation, starts[k].rotation, 0.15);
    });
    if (begunNear) continue;
    ++refined;
    // Refined on few points first (cheap), on more only where that lies on the copy; each
    // checked exactly (`lays`) before it counts.
    Pose pose = refine(starts[k], coarse, movedSurface, scale, deadline, 30, steps);
    if (!(pose.residual < std::max(tolerance, 3e-3 * scale))) continue;  // not near a way yet
    // One that comes near a way found leads to it again: not refined further.
    const bool nearFound = std::any_of(foundPoses.begin(), foundPoses.end(), [&](const Pose& f) {
      return f.mirrored == pose.mirrored && near(f.rotation, pose.rotation, 0.05) &&
             (f.offset - pose.offset).norm() < 0.02 * scale;
    });
    if (nearFound) continue;
    pose = refine(pose, fine, movedSurface, scale, deadline, 100, steps);
    RigidMotion motion = motionOf(pose);
    const bool again = std::any_of(found.begin(), found.end(), [&](const RigidMotion& f) {
      double linear = 0.0;
      for (int c = 0; c < 3; ++c)
        linear = std::max(linear, glm::length(f.linear[c] - motion.linear[c]));
      return linear < 1e-3 && glm::distance(f.offset, motion.offset) < 1e-3 * scale;
    });
    // A refinement the deadline cut short is no way found (and `lays` costs a tree and a pass
    // over every vertex).
    if (deadline.passed()) break;
    foundPoses.push_back(pose);
    if (again) continue;
    if (!lays(motion)) {
      pose = refine(pose, all, movedSurface, scale, deadline, 100, steps);
      if (deadline.passed()) break;
      motion = motionOf(pose);
      if (!lays(motion)) continue;
    }
    bool fits = edgesFit(motion);
    if (!fits && turnsTried < kTurnsTried) {
      const std::optional<RigidMotion> onEdges = turnedOntoEdges(motion);
      if (deadline.passed()) break;
      // Where no turn lays the boundaries (a copy whose slit was welded shut), none will for
      // the next way either: a few tries, not one per way.
      if (!onEdges) ++turnsTried;
      if (onEdges) {
        const bool seen = std::any_of(found.begin(), found.end(), [&](const RigidMotion& f) {
          double linear = 0.0;
          for (int c = 0; c < 3; ++c)
            linear = std::max(linear, glm::length(f.linear[c] - onEdges->linear[c]));
          return linear < 1e-3 && glm::distance(f.offset, onEdges->offset) < 1e-3 * scale;
        });
        if (seen) continue;
        motion = *onEdges;
        fits = true;
      }
    }
    found.push_back(motion);
    foundFits.push_back(fits ? 1 : 0);
  }
  // The ways that lay the boundaries together first: the others are the sheet turned along a
  // near-symmetry off the development's own way.
  std::vector<RigidMotion> ordered;
  for (const char wanted : {1, 0})
    for (std::size_t k = 0; k < found.size(); ++k)
      if (foundFits[k] == wanted) ordered.push_back(found[k]);
  return ordered;
}

std::optional<RigidMotion> registerSheetOnto(const TriangleMesh& sheet, const TriangleMesh& moved,
                                             double tolerance) {
  const std::vector<RigidMotion> motions = registerSheetOntoAll(sheet, moved, tolerance, 1);
  if (motions.empty()) return std::nullopt;
  return motions.front();
}

namespace {

// The turn of a proper linear part: its axis (unit) and angle.
void axisAngle(const Eigen::Matrix3d& rotation, glm::dvec3& axis, double& angle) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(0.5 *
                                                              (rotation + rotation.transpose()));
  axis = glm::normalize(glmOf(Eigen::Vector3d(solver.eigenvectors().col(2))));
  angle = std::acos(std::clamp(0.5 * (rotation.trace() - 1.0), -1.0, 1.0));
}

Eigen::Matrix3d orthogonalPart(const glm::dmat3& m) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(eigenOf(m),
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

// A turn about a line (no shift along it) as two planes through that line: the line's point
// (least squares across the axis of (I - A) q = t) and two unit directions across the axis;
// normalAt(phi) is the plane normal at angle phi about the axis.
struct TurnFrame {
  glm::dvec3 through, u, w;
  TurnFrame(const Eigen::Matrix3d& A, const glm::dvec3& t, const glm::dvec3& axis)
      : through(glmOf(Eigen::Vector3d((Eigen::Matrix3d::Identity() - A)
                                          .completeOrthogonalDecomposition()
                                          .solve(eigenOf(t))))),
        u(glm::normalize(
            glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)))),
        w(glm::cross(axis, u)) {}
  glm::dvec3 normalAt(double phi) const { return std::cos(phi) * u + std::sin(phi) * w; }
};

// Two planes, both missing the sheet where each acts, making a proper motion: parallel planes
// for a shift, else planes through the motion's fixed line (a turn with a shift along its axis
// has none: nothing).
std::optional<std::vector<ReflectionPlane>> twoPlanes(const RigidMotion& motion,
                                                      const std::vector<glm::dvec3>& points,
                                                      double margin, double scale) {
  const Eigen::Matrix3d A = orthogonalPart(motion.linear);
  if (A.determinant() < 0.0) return std::nullopt;
  const glm::dvec3 t = motion.offset;
  glm::dvec3 axis;
  double angle = 0.0;
  axisAngle(A, axis, angle);
  if (angle < 1e-9) {
    const double length = glm::length(t);
    if (length < 1e-12 * scale) return std::nullopt;
    const glm::dvec3 n = t / length;
    const double d1 = highest(n, points) + 0.5 * length + 10.0 * margin;
    const std::vector<ReflectionPlane> pair{{d1 * n, n}, {(d1 + 0.5 * length) * n, n}};
    if (folds(pair, motion, points, margin, scale)) return pair;
    return std::nullopt;
  }
  if (std::abs(glm::dot(t, axis)) > 1e-9 * scale) return std::nullopt;
  const TurnFrame frame(A, t, axis);
  for (int step = 0; step < 720; ++step) {
    const double phi = step * std::numbers::pi / 360.0;
    if (!misses({frame.through, frame.normalAt(phi)}, points, margin)) continue;
    for (const double sign : {1.0, -1.0}) {
      const std::vector<ReflectionPlane> pair{
          {frame.through, frame.normalAt(phi)},
          {frame.through, frame.normalAt(phi + sign * 0.5 * angle)}};
      if (folds(pair, motion, points, margin, scale)) return pair;
    }
  }
  return std::nullopt;
}

// Three planes for an improper motion: one plane chosen so that the rest is a turn about a line
// (no shift along it), which two planes make; that plane acting first or last.
std::optional<std::vector<ReflectionPlane>> threePlanes(const RigidMotion& motion,
                                                        const std::vector<glm::dvec3>& points,
                                                        double margin, double scale) {
  const Eigen::Matrix3d A = orthogonalPart(motion.linear);
  if (A.determinant() > 0.0) return std::nullopt;
  const glm::dmat3 linear = glmOf(A);
  const glm::dvec3 t = motion.offset;
  constexpr int kDirections = 300;
  for (int k = 0; k < kDirections; ++k) {
    // Directions spread over the half sphere (a normal and its opposite are one plane).
    const double z = 1.0 - (k + 0.5) / kDirections;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = k * 2.39996322972865332;
    const glm::dvec3 n(r * std::cos(phi), r * std::sin(phi), z);
    const glm::dmat3 H = glm::dmat3(1.0) - 2.0 * glm::outerProduct(n, n);
    glm::dvec3 axis;
    double angle = 0.0;
    // The plane first: the rest is T after it, linear A H, shift A (2 d n) + t.
    axisAngle(eigenOf(linear * H), axis, angle);
    if (std::abs(glm::dot(linear * n, axis)) > 1e-3) {
      const double d = -glm::dot(t, axis) / (2.0 * glm::dot(linear * n, axis));
      const ReflectionPlane first{d * n, n};
      if (misses(first, points, margin)) {
        std::vector<glm::dvec3> after = points;
        for (glm::dvec3& p : after) p = first.reflect(p);
        const RigidMotion rest{linear * H, linear * (2.0 * d * n) + t};
        if (const auto pair = twoPlanes(rest, after, margin, scale)) {
          const std::vector<ReflectionPlane> planes{first, (*pair)[0], (*pair)[1]};
          if (folds(planes, motion, points, margin, scale)) return planes;
        }
      }
    }
    // The plane last: the rest is linear H A, shift H t + 2 d n.
    axisAngle(eigenOf(H * linear), axis, angle);
    if (std::abs(glm::dot(n, axis)) > 1e-3) {
      const double d = -glm::dot(H * t, axis) / (2.0 * glm::dot(n, axis));
      const RigidMotion rest{H * linear, H * t + 2.0 * d * n};
      if (const auto pair = twoPlanes(rest, points, margin, scale)) {
        const std::vector<ReflectionPlane> planes{(*pair)[0], (*pair)[1], {d * n, n}};
        if (folds(planes, motion, points, margin, scale)) return planes;
      }
    }
  }
  return std::nullopt;
}

}  // namespace

std::vector<ReflectionPlane> wholeSheetReflections(const RigidMotion& motion,
                                                   const std::vector<glm::dvec3>& points) {
  for (std::size_t count = 1; count <= 5; ++count) {
    std::vector<ReflectionPlane> planes = wholeSheetReflections(motion, points, count);
    if (!planes.empty()) return planes;
  }
  return {};
}

std::vector<ReflectionPlane> wholeSheetReflections(const RigidMotion& motion,
                                                   const std::vector<glm::dvec3>& points,
                                                   std::size_t count) {
  const double scale = std::max(diagonalOf(points), 1e-9);
  const double margin = 1e-3 * scale;  // how far a plane keeps clear of the sheet
  if (sameMotion(motion, RigidMotion{}, scale) || count == 0) return {};
  const Eigen::Matrix3d A = orthogonalPart(motion.linear);
  const glm::dvec3 t = motion.offset;

  // One plane: a mirror, shifted along its normal.
  if (A.determinant() < 0.0 && count == 1) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(0.5 * (A + A.transpose()));
    const glm::dvec3 n = glm::normalize(glmOf(Eigen::Vector3d(solver.eigenvectors().col(0))));
    const ReflectionPlane plane{0.5 * glm::dot(t, n) * n, n};
    if (folds({plane}, motion, points, margin, scale)) return {plane};
    return {};
  }
  if (A.determinant() < 0.0 && count == 3) {
    if (const auto planes = threePlanes(motion, points, margin, scale)) return *planes;
  } else if (A.determinant() > 0.0 && count == 2) {
    if (const auto pair = twoPlanes(motion, points, margin, scale)) return *pair;
    return {};
  }
  if (count < 3) return {};

  // Otherwise: the linear part as reflections through planes pushed off the sheet (a mirror
  // across the axis for an improper part, then a turn as two), and the shift left as two
  // parallel planes.
  std::vector<glm::dvec3> normals;  // in the order they act
  Eigen::Matrix3d B = A;
  if (A.determinant() < 0.0) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(0.5 * (A + A.transpose()));
    const Eigen::Vector3d a = solver.eigenvectors().col(0);
    normals.push_back(glmOf(a));
    B = A * (Eigen::Matrix3d::Identity() - 2.0 * a * a.transpose());  // A = B H_a
  }
  glm::dvec3 axis;
  double angle = 0.0;
  axisAngle(B, axis, angle);
  if (angle > 1e-12) {
    const glm::dvec3 u = glm::normalize(
        glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 w = glm::cross(axis, u);
    // H(n2) H(n1) turns by twice the angle from n1 to n2: the sign that makes B.
    for (const double sign : {1.0, -1.0}) {
      const glm::dvec3 n2 = std::cos(0.5 * angle) * u + sign * std::sin(0.5 * angle) * w;
      const glm::dmat3 made = (glm::dmat3(1.0) - 2.0 * glm::outerProduct(n2, n2)) *
                              (glm::dmat3(1.0) - 2.0 * glm::outerProduct(u, u));
      if ((eigenOf(made) - B).norm() < 1e-7) {
        normals.push_back(u);
        normals.push_back(n2);
        break;
      }
    }
  }
  std::vector<ReflectionPlane> planes;
  std::vector<glm::dvec3> at = points;
  RigidMotion made;
  for (const glm::dvec3& n : normals) {
    const ReflectionPlane plane{(highest(n, at) + 50.0 * margin) * n, n};
    for (glm::dvec3& p : at) p = plane.reflect(p);
    made = then(made, reflectionOf(plane));
    planes.push_back(plane);
  }
  const glm::dvec3 shift = motion.offset - made.offset;
  const double length = glm::length(shift);
  if (length > 1e-12 * scale) {
    const glm::dvec3 n = shift / length;
    const double d1 = highest(n, at) + 0.5 * length + 10.0 * margin;
    planes.push_back({d1 * n, n});
    planes.push_back({(d1 + 0.5 * length) * n, n});
  }
  if (planes.size() == count && folds(planes, motion, points, margin, scale)) return planes;
  return {};
}

}  // namespace curvefold

namespace curvefold {

namespace {

// `planes` placed each at the earliest stage (no earlier than the one before it) where it misses
// the sheet as it lies then: the stage moved by the planes made before it. Checked with the
// plane moved back rather than the stage moved (one plane, not every point).
std::optional<std::vector<PlacedPlane>> placedEarliest(
    const std::vector<ReflectionPlane>& planes, const std::vector<std::vector<glm::dvec3>>& stages,
    double margin) {
  std::vector<PlacedPlane> placed;
  RigidMotion made;
  std::size_t k = 0;
  for (const ReflectionPlane& plane : planes) {
    const RigidMotion back = inverse(made);
    const ReflectionPlane onStage{back(plane.point), glm::normalize(back.linear * plane.normal)};
    while (k < stages.size() && !misses(onStage, stages[k], margin)) ++k;
    if (k == stages.size()) return std::nullopt;
    placed.push_back({plane, k});
    made = then(made, reflectionOf(plane));
  }
  return placed;
}

}  // namespace

std::vector<PlacedPlane> placedWholeSheetReflections(
    const RigidMotion& motion, const std::vector<std::vector<glm::dvec3>>& stages,
    std::size_t count) {
  if (stages.empty() || stages.front().empty() || count == 0) return {};
  double scale = 1e-9;
  for (const std::vector<glm::dvec3>& stage : stages) scale = std::max(scale, diagonalOf(stage));
  const double margin = 1e-3 * scale;  // as wholeSheetReflections keeps clear of the sheet
  if (sameMotion(motion, RigidMotion{}, scale)) return {};
  const Eigen::Matrix3d A = orthogonalPart(motion.linear);
  const glm::dvec3 t = motion.offset;
  auto made = [&](const std::vector<ReflectionPlane>& planes) {
    RigidMotion m;
    for (const ReflectionPlane& plane : planes) m = then(m, reflectionOf(plane));
    return sameMotion(m, motion, scale);
  };
  auto tryPlanes = [&](const std::vector<ReflectionPlane>& planes) {
    if (!made(planes)) return std::optional<std::vector<PlacedPlane>>{};
    return placedEarliest(planes, stages, margin);
  };
  if (count == 1 && A.determinant() < 0.0) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(0.5 * (A + A.transpose()));
    const glm::dvec3 n = glm::normalize(glmOf(Eigen::Vector3d(solver.eigenvectors().col(0))));
    if (const auto placed = tryPlanes({{0.5 * glm::dot(t, n) * n, n}})) return *placed;
    return {};
  }
  if (count == 2 && A.determinant() > 0.0) {
    glm::dvec3 axis;
    double angle = 0.0;
    axisAngle(A, axis, angle);
    if (angle < 1e-9) {
      // A shift: two parallel planes half its length apart, anywhere along it.
      const double length = glm::length(t);
      if (length < 1e-12 * scale) return {};
      const glm::dvec3 n = t / length;
      double low = 1e300, high = -1e300;
      for (const std::vector<glm::dvec3>& stage : stages)
        for (const glm::dvec3& p : stage) {
          low = std::min(low, glm::dot(n, p));
          high = std::max(high, glm::dot(n, p));
        }
      constexpr int kSteps = 400;
      for (int step = 0; step <= kSteps; ++step) {
        const double d1 =
            low - length - margin +
            (high - low + 2.0 * length + 2.0 * margin) * static_cast<double>(step) / kSteps;
        if (const auto placed = tryPlanes({{d1 * n, n}, {(d1 + 0.5 * length) * n, n}}))
          return *placed;
      }
      return {};
    }
    if (std::abs(glm::dot(t, axis)) > 1e-9 * scale) return {};  // a screw: no two planes
    const TurnFrame frame(A, t, axis);
    for (int step = 0; step < 720; ++step) {
      const double phi = step * std::numbers::pi / 360.0;
      for (const double sign : {1.0, -1.0})
        if (const auto placed =
                tryPlanes({{frame.through, frame.normalAt(phi)},
                           {frame.through, frame.normalAt(phi + sign * 0.5 * angle)}}))
          return *placed;
    }
    return {};
  }
  if (count < 3) return {};
  // Three or more: all at one stage, the earliest that takes them.
  for (std::size_t k = 0; k < stages.size(); ++k) {
    const std::vector<ReflectionPlane> planes = wholeSheetReflections(motion, stages[k], count);
    if (planes.empty()) continue;
    std::vector<PlacedPlane> placed;
    for (const ReflectionPlane& plane : planes) placed.push_back({plane, k});
    return placed;
  }
  return {};
}

std::vector<RigidMotion> sheetSymmetries(const TriangleMesh& sheet, double tolerance) {
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> rim = boundaryEdges(sheet);
  if (rim.empty()) return {};
  const BoundaryCurve curve(sheet, rim);
  std::vector<char> seen(sheet.positions.size(), 0);
  std::vector<glm::dvec3> corners;
  for (const auto& [a, b] : rim)
    for (const std::uint32_t v : {a, b})
      if (!seen[v]) {
        seen[v] = 1;
        corners.push_back(sheet.positions[v]);
      }
  std::vector<Eigen::Vector3d> boundary;
  for (const glm::dvec3& p : corners) boundary.push_back(eigenOf(p));
  // The boundary's centroid and axes: exact for a regular polygon's corners (area samples are
  // not), so a turn between corners is exact too.
  const PointMoments moments = pointMoments(corners);
  const Eigen::Vector3d centre = eigenOf(moments.centre);
  const Eigen::Matrix3d axes =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(eigenOf(moments.scatter)).eigenvectors();
  const SurfaceDistanceQuery surface(sheet, "sheet");
  const std::size_t stride = 1 + sheet.positions.size() / 200;
  const double scale = boundingDiagonal(sheet);
  std::vector<RigidMotion> found;
  auto consider = [&](const Eigen::Matrix3d& linear) {
    const RigidMotion s{glmOf(linear), glmOf(Eigen::Vector3d(centre - linear * centre))};
    if (sameMotion(s, RigidMotion{}, scale)) return;
    for (const RigidMotion& f : found)
      if (sameMotion(f, s, scale)) return;
    for (const Eigen::Vector3d& p : boundary)
      if (!(curve.distance(linear * (p - centre) + centre) <= tolerance)) return;
    for (std::size_t v = 0; v < sheet.positions.size(); v += stride)
      if (!(surface.distance(s(sheet.positions[v])) <= tolerance)) return;
    found.push_back(s);
  };
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d a = axes.col(k);
    auto across = [&](const Eigen::Vector3d& p) {
      const Eigen::Vector3d d = p - centre;
      return Eigen::Vector3d(d - a * a.dot(d));
    };
    // The boundary vertex farthest from the axis: the turn that moves it is the best defined.
    std::size_t far = 0;
    for (std::size_t i = 1; i < boundary.size(); ++i)
      if (across(boundary[i]).norm() > across(boundary[far]).norm()) far = i;
    const Eigen::Vector3d u = across(boundary[far]);
    const double height = a.dot(boundary[far] - centre);
    if (u.norm() <= tolerance) continue;
    const Eigen::Matrix3d acrossAxis = identity - 2.0 * a * a.transpose();  // height to -height
    for (const Eigen::Vector3d& q : boundary) {
      const Eigen::Vector3d w = across(q);
      if (std::abs(w.norm() - u.norm()) > tolerance) continue;
      const bool level = std::abs(a.dot(q - centre) - height) <= tolerance;
      const bool mirrored = std::abs(a.dot(q - centre) + height) <= tolerance;
      if (!level && !mirrored) continue;
      // The turn about the axis, and the mirror through the plane that holds the axis and
      // bisects u and w (holds u, where w is u), each taking u to w.
      const double angle = std::atan2(a.dot(u.cross(w)), u.dot(w));
      const Eigen::Matrix3d turned = Eigen::AngleAxisd(angle, a).toRotationMatrix();
      Eigen::Vector3d n = u - w;
      if (n.norm() <= 1e-9 * u.norm()) n = a.cross(u);
      n.normalize();
      const Eigen::Matrix3d flipped = identity - 2.0 * n * n.transpose();
      for (const Eigen::Matrix3d& linear : {turned, flipped}) {
        if (level) consider(linear);
        if (mirrored) consider(Eigen::Matrix3d(linear * acrossAxis));
      }
    }
  }
  return found;
}

std::size_t fewestReflections(const RigidMotion& motion, double angle, double shift) {
  const Eigen::Matrix3d A = orthogonalPart(motion.linear);
  const Eigen::Vector3d t = eigenOf(motion.offset);
  if (A.determinant() < 0.0) {
    // A mirror is -1 along its normal and shifts only along it.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(0.5 * (A + A.transpose()));
    const Eigen::Vector3d n = solver.eigenvectors().col(0);
    const Eigen::Matrix3d mirror = Eigen::Matrix3d::Identity() - 2.0 * n * n.transpose();
    return (mirror - A).norm() <= angle && (t - n * n.dot(t)).norm() <= shift ? 1 : 3;
  }
  const Eigen::AngleAxisd turned(A);
  if (std::abs(turned.angle()) <= angle) return t.norm() <= shift ? 0 : 2;
  return std::abs(turned.axis().dot(t)) <= shift ? 2 : 4;
}

}  // namespace curvefold
