#include "engine/fit/target_unfolding.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "engine/fit/crease_planes.hpp"
#include "engine/fit/surface_distance.hpp"
#include "engine/fit/whole_sheet_folds.hpp"

namespace curvefold {
namespace {

// How much more than the sheet's own facets an edge may bend and still count as smooth.
constexpr double kBendMarginDegrees = 0.5;
// The least crease (of the diagonal) one unfolding step must take away: a fold of a thin tip
// leaves a crease a few millimetres long.
constexpr double kLeastCrease = 0.003;
// How far (of the diagonal, on average) an unfolding may end from the sheet and still lie on it.
constexpr double kOffSheet = 1e-3;
// The fewest whole-sheet folds an unfolding that ends off the sheet (on a rigid copy) leaves to
// make: counted to it when unfoldings are ranked by their folds, and no branch read deeper.
constexpr double kMotionPlanes = 1.0;
// A smooth unfolding off the sheet (a rigid copy): how near (of the diagonal) the sheet must lie
// on it, how many ways it is registered (the first: the sheet's own symmetries give the others;
// 24 took minutes on a cylinder), and how near a motion must be to a kind of fewer planes
// (radians, and of the diagonal) to count as it: as the fit makes its whole-sheet folds.
constexpr double kCopyTolerance = 1e-4;
constexpr std::size_t kCopyWays = 1;
constexpr double kKindSnap = 1e-4;
// A target with more area than the sheet by this share is no fold of it (every fold keeps the
// area; a catalogue sheet at another resolution differs by about 1%, as FoldFitter's reading
// allows): no order of its folds ends on the sheet.
constexpr double kMoreArea = 0.05;

struct MeshEdge {
  std::uint32_t a = 0, b = 0;
  std::uint32_t faces[2] = {0, 0};
};

// The mesh's connectivity, which unfolding never changes.
struct Connectivity {
  std::vector<MeshEdge> interior;                      // edges with exactly two faces
  std::vector<std::vector<std::uint32_t>> neighbours;  // per vertex
  std::vector<char> onBoundary;                        // per vertex: on an edge with one face
  // Per vertex: on the boundary where another boundary vertex lies (within `tolerance`): a slit's
  // two sides, where a point names either side of the development.
  std::vector<char> onSlit;
};

Connectivity connectivityOf(const TriangleMesh& mesh, double tolerance) {
  const EdgeFaces faces = edgeFaces(mesh);
  Connectivity c;
  c.neighbours.resize(mesh.positions.size());
  c.onBoundary.assign(mesh.positions.size(), 0);
  for (const auto& [edge, around] : faces) {
    if (around.size() == 1) c.onBoundary[edge.first] = c.onBoundary[edge.second] = 1;
    c.neighbours[edge.first].push_back(edge.second);
    c.neighbours[edge.second].push_back(edge.first);
    if (around.size() == 2) c.interior.push_back({edge.first, edge.second, {around[0], around[1]}});
  }
  // Boundary vertices swept along x: those within the tolerance of one another are a slit's.
  std::vector<std::uint32_t> rim;
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v)
    if (c.onBoundary[v]) rim.push_back(v);
  std::sort(rim.begin(), rim.end(), [&](std::uint32_t a, std::uint32_t b) {
    return mesh.positions[a].x < mesh.positions[b].x;
  });
  c.onSlit.assign(mesh.positions.size(), 0);
  for (std::size_t i = 0; i < rim.size(); ++i)
    for (std::size_t j = i + 1; j < rim.size(); ++j) {
      const glm::dvec3& a = mesh.positions[rim[i]];
      const glm::dvec3& b = mesh.positions[rim[j]];
      if (b.x - a.x > tolerance) break;
      if (glm::distance(a, b) <= tolerance) c.onSlit[rim[i]] = c.onSlit[rim[j]] = 1;
    }
  return c;
}

// Total length of the edges whose faces turn by more than the threshold.
double sharpLength(const TriangleMesh& mesh, const Connectivity& c,
                   const std::vector<glm::dvec3>& positions, double cosThreshold) {
  std::vector<glm::dvec3> normals(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    normals[t] = faceNormal(positions, mesh.triangles[t]);
  double total = 0.0;
  for (const MeshEdge& e : c.interior)
    if (glm::dot(normals[e.faces[0]], normals[e.faces[1]]) < cosThreshold)
      total += glm::distance(positions[e.a], positions[e.b]);
  return total;
}

struct Candidate {
  ReflectionPlane plane;
  std::vector<std::uint32_t> part;
  double sharpAfter = 0.0;
  // Its crease ends inside the sheet where another crease goes on: a crease a later fold moved in
  // part (the rest of it lies in another plane), which the fold made last cannot leave.
  bool interrupted = false;
};

// A form the unfolding met, read once (issue 38): the same form is met again by other orders of
// the steps before it, moved by another product of reflections (a pose), and its crease planes
// and pieces (the dear part of a step) are those read, moved by the pose; its pieces are vertex
// sets and its crease left after each pose-free.
struct Form {
  std::vector<glm::dvec3> positions;   // the pose it was read in
  std::uint32_t frame[3] = {0, 0, 0};  // three vertices far apart: they fix a pose
  std::vector<Candidate> candidates;   // in that pose
};

// The isometry x -> linear x + offset (a rotation or a reflection's) that takes `from` onto `to`,
// vertex by vertex within `tolerance`, found from the frame's three vertices; none where no
// isometry does (`used`: the vertices to check, those on a face).
std::optional<Isometry> poseBetween(const std::vector<glm::dvec3>& from,
                                    const std::vector<glm::dvec3>& to, const std::uint32_t frame[3],
                                    const std::vector<char>& used, double tolerance) {
  auto axes = [&](const std::vector<glm::dvec3>& p) {
    const glm::dvec3 e1 = glm::normalize(p[frame[1]] - p[frame[0]]);
    const glm::dvec3 along = p[frame[2]] - p[frame[0]];
    const glm::dvec3 e2 = glm::normalize(along - glm::dot(along, e1) * e1);
    return glm::dmat3(e1, e2, glm::cross(e1, e2));
  };
  const glm::dmat3 a = axes(from), b = axes(to);
  for (const double handed : {1.0, -1.0}) {
    glm::dmat3 mirrored = b;
    mirrored[2] *= handed;
    Isometry pose;
    pose.linear = mirrored * glm::transpose(a);
    pose.offset = to[frame[0]] - pose.linear * from[frame[0]];
    bool holds = true;
    for (std::size_t v = 0; holds && v < from.size(); ++v)
      holds = !used[v] || glm::distance(pose.apply(from[v]), to[v]) <= tolerance;
    if (holds) return pose;
  }
  return std::nullopt;
}

}  // namespace

std::vector<ReflectionPlane> planesBeforeWholeImage(const ReflectionPlane& moved,
                                                    const Isometry& g) {
  // a: n.x = d, b = g(a): m.x = e with m = L n, e = d + m.o. R_b(a) has the normal
  // n - 2 (n.m) m, and an offset linear in d: the normal is solved for, then d.
  auto normalAfter = [&](const glm::dvec3& n) {
    const glm::dvec3 m = g.linear * n;
    return n - 2.0 * glm::dot(n, m) * m;
  };
  const glm::dvec3 want = glm::normalize(moved.normal);
  auto residual = [&](const glm::dvec3& n) { return normalAfter(n) - want; };
  // Candidates: the normals of a Fibonacci grid nearest a solution, each refined.
  constexpr int kGrid = 2000;
  std::vector<std::pair<double, glm::dvec3>> grid;
  grid.reserve(kGrid);
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < kGrid; ++k) {
    const double z = 1.0 - 2.0 * (k + 0.5) / kGrid, r = std::sqrt(1.0 - z * z);
    const glm::dvec3 n(r * std::cos(golden * k), r * std::sin(golden * k), z);
    grid.emplace_back(glm::length(residual(n)), n);
  }
  std::partial_sort(grid.begin(), grid.begin() + 40, grid.end(),
                    [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<ReflectionPlane> planes;
  for (int c = 0; c < 40; ++c) {
    glm::dvec3 n = grid[std::size_t(c)].second;
    // Gauss-Newton on the sphere: two tangent directions, a numeric Jacobian.
    for (int it = 0; it < 30; ++it) {
      const glm::dvec3 t1 = glm::normalize(
          glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
      const glm::dvec3 t2 = glm::cross(n, t1);
      const glm::dvec3 r = residual(n);
      constexpr double h = 1e-7;
      const glm::dvec3 j1 = (residual(glm::normalize(n + h * t1)) - r) / h;
      const glm::dvec3 j2 = (residual(glm::normalize(n + h * t2)) - r) / h;
      const double a11 = glm::dot(j1, j1), a12 = glm::dot(j1, j2), a22 = glm::dot(j2, j2);
      const double b1 = -glm::dot(j1, r), b2 = -glm::dot(j2, r);
      const double det = a11 * a22 - a12 * a12;
      if (!(std::abs(det) > 1e-30)) break;
      const double u = (b1 * a22 - b2 * a12) / det, v = (a11 * b2 - a12 * b1) / det;
      n = glm::normalize(n + u * t1 + v * t2);
      if (std::abs(u) + std::abs(v) < 1e-14) break;
    }
    if (!(glm::length(residual(n)) < 1e-9)) continue;
    const glm::dvec3 m = g.linear * n, after = normalAfter(n);
    const double slope = glm::dot(after, n) - 2.0 * (glm::dot(m, n) - 1.0) * glm::dot(after, m);
    if (!(std::abs(slope) > 1e-6)) continue;  // every offset, or none: no one plane
    const double rise = 2.0 * glm::dot(m, g.offset) * glm::dot(after, m);
    const double d = (glm::dot(want, moved.point) - rise) / slope;
    const ReflectionPlane plane{d * n, n};
    const bool known = std::any_of(planes.begin(), planes.end(), [&](const ReflectionPlane& p) {
      return std::abs(std::abs(glm::dot(p.normal, n)) - 1.0) < 1e-9 &&
             std::abs(p.signedDistance(plane.point)) < 1e-9;
    });
    if (!known) planes.push_back(plane);
  }
  return planes;
}

namespace {

// The forms read, by their crease: the edges bent past the sheet's facets, which no pose changes
// (the folds keep the vertices); forms with the same crease told apart by a pose. Kept from one
// search over orders to the next.
struct FormTable {
  std::vector<Form> forms;
  std::map<std::vector<std::uint32_t>, std::vector<std::size_t>> byCrease;
};

struct Unfolder {
  const TriangleMesh& target;
  const Connectivity connectivity;
  const double diagonal, onPlane, cosThreshold, minDihedralDegrees;
  // What counts as crease left: any bend beyond the sheet's own facets'. A reflection through a
  // plane near a fold's (within the detection's tolerance) leaves its crease bent by a few
  // degrees, below the detection threshold: counted so, the right plane wins, and an unfolding
  // that ends with such creases says so.
  const double cosBent;
  const SurfaceDistanceQuery& sheetSurface;
  std::size_t maxFolds;
  const Deadline& deadline;
  const std::vector<Isometry>& images;  // a symmetric design's; empty: none
  std::size_t leaves = 0;               // unfoldings finished, to bound the branching
  // The fewest folds an unfolding that ended smooth has taken, kMotionPlanes more where it ended
  // off the sheet (a rigid copy: its motion takes whole-sheet folds): a branch deeper than
  // that cannot win, and is not read on (a plane read twice, a piece of one fold's part at a
  // time, reads more folds than the design made).
  double smoothCost = kInfinitySharp;
  // The deadline passed: each unfolding under way ends where it is (its steps so far, read off
  // as a finished one is), and the best of those and of the finished ones is kept.
  bool cutShort = false;

  // The forms read (issue 38); null: every node read.
  FormTable* table = nullptr;
  // The 600 unfoldings count only those that read a form none before had (3,000 in all), else
  // every one.
  bool newFormsOnly = false;
  std::size_t formsMet = 0;  // nodes whose planes were asked for: read, or found in the table
  std::size_t formsAtLastLeaf = 0;  // forms in the table when the last unfolding ended
  std::size_t newFormLeaves = 0;    // unfoldings ended that read a form none before had
  std::vector<char> onFace{};       // per vertex: on a face (a pose is checked on these)

  bool outOfTime() {
    cutShort = cutShort || deadline.passed();
    return cutShort;
  }

  // The interior edges bent past the sheet's facets: a form's crease, its key in the table.
  std::vector<std::uint32_t> creaseOf(const std::vector<glm::dvec3>& positions) const {
    std::vector<std::uint32_t> crease;
    for (std::size_t e = 0; e < connectivity.interior.size(); ++e) {
      const MeshEdge& edge = connectivity.interior[e];
      if (glm::dot(faceNormal(positions, target.triangles[edge.faces[0]]),
                   faceNormal(positions, target.triangles[edge.faces[1]])) < cosBent)
        crease.push_back(static_cast<std::uint32_t>(e));
    }
    return crease;
  }

  // Three vertices far apart on a face: the first, the farthest from it, the farthest from the
  // line through both.
  void frameOf(Form& form) const {
    const std::vector<glm::dvec3>& p = form.positions;
    std::uint32_t a = 0;
    while (a + 1 < p.size() && !onFace[a]) ++a;
    std::uint32_t b = a, c = a;
    double far = -1.0;
    for (std::uint32_t v = 0; v < p.size(); ++v)
      if (onFace[v] && glm::distance(p[v], p[a]) > far) far = glm::distance(p[v], p[a]), b = v;
    const glm::dvec3 line = glm::normalize(p[b] - p[a]);
    far = -1.0;
    for (std::uint32_t v = 0; v < p.size(); ++v) {
      const glm::dvec3 d = p[v] - p[a];
      const double off = glm::length(d - glm::dot(d, line) * line);
      if (onFace[v] && off > far) far = off, c = v;
    }
    form.frame[0] = a;
    form.frame[1] = b;
    form.frame[2] = c;
  }

  // The form's crease planes and pieces (candidatesAt): from the table where the form was read
  // before in another pose (its planes moved by the pose), else read and kept.
  std::vector<Candidate> candidatesFor(const std::vector<glm::dvec3>& positions) {
    ++formsMet;
    if (!table) return candidatesAt(positions);
    std::vector<Form>& forms = table->forms;
    std::vector<std::size_t>& same = table->byCrease[creaseOf(positions)];
    for (std::size_t f : same) {
      const Form& form = forms[f];
      const std::optional<Isometry> pose =
          poseBetween(form.positions, positions, form.frame, onFace, kSamePose * diagonal);
      if (!pose) continue;
      std::vector<Candidate> moved = form.candidates;
      for (Candidate& c : moved)
        c.plane = {pose->apply(c.plane.point), glm::normalize(pose->linear * c.plane.normal)};
      return moved;
    }
    Form form;
    form.positions = positions;
    form.candidates = candidatesAt(positions);
    // Maybe cut short: not kept; nor past the table's bound (its memory).
    if (deadline.passed() || forms.size() >= kMaxForms) return form.candidates;
    frameOf(form);
    same.push_back(forms.size());
    forms.push_back(std::move(form));
    return forms.back().candidates;
  }

  // Where the unfolded target lies off the sheet, on average: the right unfolding lies on it.
  double offSheet(const std::vector<glm::dvec3>& positions) const {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t v = 0; v < positions.size(); v += 1 + positions.size() / 500, ++count)
      sum += sheetSurface.distance(positions[v]);
    return count ? sum / static_cast<double>(count) : 0.0;
  }

  // Whether the crease in a plane (its sharp edges in it, `d` the vertices' distances to it) ends
  // at a vertex off the boundary from which another sharp edge goes on, off the plane: a crease
  // a later fold moved in part (the rest of it lies in another plane), which the fold made last
  // cannot leave. The last fold's crease runs from rim to rim (a later one crossing it goes on
  // through), or fades under the threshold (no sharp edge goes on).
  bool interrupted(const std::vector<glm::dvec3>& positions, const std::vector<double>& d) const {
    std::vector<std::uint8_t> inPlane(positions.size(), 0), offPlane(positions.size(), 0);
    for (const MeshEdge& e : connectivity.interior) {
      const glm::dvec3 n0 = faceNormal(positions, target.triangles[e.faces[0]]);
      const glm::dvec3 n1 = faceNormal(positions, target.triangles[e.faces[1]]);
      if (glm::dot(n0, n1) >= cosThreshold) continue;
      if (std::abs(d[e.a]) <= onPlane && std::abs(d[e.b]) <= onPlane) {
        inPlane[e.a] = static_cast<std::uint8_t>(std::min(inPlane[e.a] + 1, 2));
        inPlane[e.b] = static_cast<std::uint8_t>(std::min(inPlane[e.b] + 1, 2));
      } else {
        offPlane[e.a] = offPlane[e.b] = 1;
      }
    }
    for (std::size_t v = 0; v < positions.size(); ++v)
      if (inPlane[v] == 1 && !connectivity.onBoundary[v] && offPlane[v]) return true;
    return false;
  }

  std::vector<Candidate> candidatesAt(const std::vector<glm::dvec3>& positions) const {
    TriangleMesh current{positions, target.triangles};
    CreasePlaneOptions options;
    options.minDihedralDegrees = minDihedralDegrees;
    options.maxPlanes = 16;
    const std::vector<CreasePlane> planes = findCreasePlanes(current, options);
    std::vector<Candidate> candidates;
    std::vector<int> component(positions.size());
    for (const CreasePlane& crease : planes) {
      if (deadline.passed()) break;  // the caller sees it and ends the unfolding here
      const ReflectionPlane& plane = crease.plane;
      std::vector<double> d(positions.size());
      for (std::size_t v = 0; v < positions.size(); ++v) d[v] = plane.signedDistance(positions[v]);
      std::fill(component.begin(), component.end(), -1);
      const bool cut = interrupted(positions, d);
      // The pieces next to the crease: grown from each vertex of a face on a sharp edge in the
      // plane, through vertices on its side.
      for (const MeshEdge& e : connectivity.interior) {
        if (std::abs(d[e.a]) > onPlane || std::abs(d[e.b]) > onPlane) continue;
        const glm::dvec3 n0 = faceNormal(positions, target.triangles[e.faces[0]]);
        const glm::dvec3 n1 = faceNormal(positions, target.triangles[e.faces[1]]);
        if (glm::dot(n0, n1) >= cosThreshold) continue;
        for (std::uint32_t face : e.faces)
          for (std::uint32_t seed : target.triangles[face]) {
            if (std::abs(d[seed]) <= onPlane || component[seed] >= 0) continue;
            Candidate candidate;
            candidate.plane = plane;
            const bool positive = d[seed] > 0.0;
            const int piece = static_cast<int>(candidates.size());
            std::vector<std::uint32_t> stack{seed};
            component[seed] = piece;
            while (!stack.empty()) {
              const std::uint32_t v = stack.back();
              stack.pop_back();
              candidate.part.push_back(v);
              for (std::uint32_t w : connectivity.neighbours[v])
                if (component[w] < 0 && std::abs(d[w]) > onPlane && (d[w] > 0.0) == positive) {
                  component[w] = piece;
                  stack.push_back(w);
                }
            }
            // A vertex of the sheet that happens to lie within `onPlane` of the plane but off
            // the crease (a crease passing a grid vertex by a micrometre) stops the growth:
            // left behind, its slivers of triangles stay bent. It moves with the piece when every
            // neighbour off the plane is in it (a crease vertex has neighbours on both sides).
            const std::size_t grown = candidate.part.size();
            for (std::size_t k = 0; k < grown; ++k)
              for (std::uint32_t w : connectivity.neighbours[candidate.part[k]]) {
                if (component[w] >= 0 || std::abs(d[w]) > onPlane) continue;
                const auto& around = connectivity.neighbours[w];
                const bool inside = std::all_of(around.begin(), around.end(), [&](std::uint32_t u) {
                  return std::abs(d[u]) <= onPlane || component[u] == piece;
                });
                if (!inside) continue;
                component[w] = piece;
                candidate.part.push_back(w);
              }
            std::vector<glm::dvec3> moved = positions;
            for (std::uint32_t v : candidate.part) moved[v] = plane.reflect(moved[v]);
            candidate.sharpAfter = sharpLength(target, connectivity, moved, cosBent);
            candidate.interrupted = cut;
            candidates.push_back(std::move(candidate));
          }
      }
    }
    return candidates;
  }

  // One unfolding step as made: the piece beside the crease reflected, and where the deepest
  // vertex of the piece and of the rest lie after it.
  struct Step {
    ReflectionPlane plane;
    glm::dvec3 seedPiece{0.0}, seedRest{0.0};
    std::uint32_t seedPieceVertex = 0, seedRestVertex = 0;
    bool restReplayable = false;  // the rest lies on one side of the plane
  };

  // x -> linear x + offset.
  struct Motion {
    glm::dmat3 linear{1.0};
    glm::dvec3 offset{0.0};
    glm::dvec3 operator()(const glm::dvec3& x) const { return linear * x + offset; }
    Motion then(const ReflectionPlane& p) const {  // this after the reflection through p
      const glm::dmat3 mirror = glm::dmat3(1.0) - 2.0 * glm::outerProduct(p.normal, p.normal);
      return {linear * mirror, linear * (2.0 * glm::dot(p.point, p.normal) * p.normal) + offset};
    }
    Motion before(const ReflectionPlane& p) const {  // the reflection through p after this
      const glm::dmat3 mirror = glm::dmat3(1.0) - 2.0 * glm::outerProduct(p.normal, p.normal);
      return {mirror * linear, mirror * offset + 2.0 * glm::dot(p.point, p.normal) * p.normal};
    }
  };

  // The probes moved by `motion`, their distances to the sheet summed in order; the sum stops
  // (and is returned) once it passes `bar`, where the caller drops the choice.
  double probesOff(const std::vector<glm::dvec3>& probe, const Motion& motion, double bar) const {
    double off = 0.0;
    for (const glm::dvec3& p : probe) {
      off += sheetSurface.distance(motion(p));
      if (off > bar) break;
    }
    return off;
  }

  // One fold whose symmetric image moved the whole sheet: at unfolding step `step`, the fold's
  // plane before the image and the image's plane.
  struct WholeImage {
    std::size_t step = 0;
    ReflectionPlane plane, image;
  };

  // Reflecting the piece or the rest of the target unfolds a crease alike, the two results one
  // reflection of the whole apart, and only the right choices end on the sheet. Made with the
  // piece each time, the unfolding with the rest reflected at a set of steps is the same one
  // moved by those steps' reflections in order (each later step's plane moved by the earlier
  // ones), so every choice is read off at the end: the one that ends on the sheet wins.
  // `forced`: the sides chosen already (sidesForFewestPlanes), made as they are.
  TargetUnfolding bestSides(const std::vector<Step>& steps, const std::vector<glm::dvec3>& unfolded,
                            double sharp, const std::vector<char>* forced = nullptr) const {
    const std::size_t n = steps.size();
    std::vector<glm::dvec3> probe;
    for (std::size_t v = 0; v < unfolded.size(); v += 1 + unfolded.size() / 200)
      if (!connectivity.neighbours[v].empty()) probe.push_back(unfolded[v]);
    // A fold replays as a drag only where the part it moves is a whole side of its plane: a
    // rest that reaches across the plane elsewhere is not what a fold moved. Of the choices
    // that end on the sheet (a symmetric sheet has several), the fewest rests.
    // `rest[u]`: step u reflected the rest rather than the piece.
    // The probes' distances summed, stopped once past `bar`: distances are not negative, so the
    // sum only grows, and a choice past the bar cannot win (the same choice as the whole sum;
    // most choices lie far off and stop within a few probes).
    auto offOf = [&](const std::vector<char>& rest, double bar) {
      Motion motion;
      for (std::size_t u = 0; u < n; ++u)
        if (rest[u]) motion = motion.then(steps[u].plane);
      return probesOff(probe, motion, bar);
    };
    auto rests = [](const std::vector<char>& rest) {
      return std::count(rest.begin(), rest.end(), char(1));
    };
    const double tie = 1e-7 * diagonal * static_cast<double>(probe.size());
    std::vector<char> bestRest(n, 0), rest(n, 0);
    double bestOff = offOf(bestRest, kInfinitySharp);
    auto consider = [&](const std::vector<char>& choice) {
      const double off = offOf(choice, bestOff + tie);
      if (off < bestOff - tie || (off <= bestOff + tie && rests(choice) < rests(bestRest))) {
        bestOff = std::min(off, bestOff);
        bestRest = choice;
        return true;
      }
      return false;
    };
    // Past the deadline (an unfolding cut short ends here), the quick choice below, in two rounds.
    const bool late = deadline.passed();
    const double offSheetLimit = kOffSheet * diagonal * static_cast<double>(probe.size());
    // Whether some choice may end on the sheet: each choice's sum stopped once past the limit
    // (a choice off the sheet most often after a probe or two). Where none does, the closest
    // choice is not kept (the pieces are, below), so it is not looked for: an unfolding that
    // ends on a moved copy (most orders of a search) costs a few probes a choice.
    std::uint32_t allowed = 0;
    for (std::size_t u = 0; u < n; ++u)
      if (steps[u].restReplayable) allowed |= 1u << u;
    bool mayLand = bestOff <= offSheetLimit;
    if (!forced && n <= kExhaustiveSides && !late)
      for (std::uint32_t bits = 1; bits < (1u << n) && !mayLand; ++bits) {
        if (bits & ~allowed) continue;
        for (std::size_t u = 0; u < n; ++u) rest[u] = bits >> u & 1u;
        mayLand = offOf(rest, offSheetLimit) <= offSheetLimit;
      }
    if (forced) {
      bestRest = *forced;
    } else if (n <= kExhaustiveSides && !late && !mayLand) {
      bestOff = kInfinitySharp;  // no choice on the sheet: the pieces (below)
    } else if (n <= kExhaustiveSides && !late) {
      for (std::uint32_t bits = 1; bits < (1u << n) && !deadline.passed(); ++bits) {
        if (bits & ~allowed) continue;
        for (std::size_t u = 0; u < n; ++u) rest[u] = bits >> u & 1u;
        consider(rest);
      }
    } else {
      // Too many for every choice: one step flipped at a time while that brings the result
      // closer to the sheet (at most n rounds of n tries).
      const std::size_t rounds = late ? std::min<std::size_t>(n, 2) : n;
      for (std::size_t round = 0, better = 1;
           round < rounds && better && (late || !deadline.passed()); ++round) {
        better = 0;
        for (std::size_t u = 0; u < n && (late || !deadline.passed()); ++u) {
          if (!steps[u].restReplayable) continue;
          rest = bestRest;
          rest[u] = !rest[u];
          if (consider(rest)) better = 1;
        }
      }
    }
    // No choice ends on the sheet, but the design is symmetric: a fold's image may have moved
    // the whole sheet (and left no crease). Each step's fold then lay, before the image, in a
    // plane a whose image b = g(a) reflects it onto the crease's plane: b undone before the fold.
    WholeImage bestImage;  // used where imageFound
    bool imageFound = false;
    if (!forced && bestOff > offSheetLimit && !images.empty() && n <= kImageSteps) {
      double imageOff = kInfinitySharp;
      std::vector<char> imageRest;
      for (std::uint32_t bits = 0; bits < (1u << n) && !deadline.passed(); ++bits) {
        if (bits & ~allowed) continue;
        for (std::size_t u = 0; u < n; ++u) rest[u] = bits >> u & 1u;
        Motion upTo;  // the motion before step u
        for (std::size_t u = 0; u < n; ++u) {
          const ReflectionPlane crease{upTo(steps[u].plane.point),
                                       upTo.linear * steps[u].plane.normal};
          const Motion plain = rest[u] ? upTo.then(steps[u].plane) : upTo;
          for (const Isometry& g : images)
            for (const ReflectionPlane& plane : planesBeforeWholeImage(crease, g)) {
              const ReflectionPlane image{g.apply(plane.point), g.linear * plane.normal};
              Motion motion = plain.before(image);
              for (std::size_t w = u + 1; w < n; ++w)
                if (rest[w]) motion = motion.then(steps[w].plane);
              const double off = probesOff(probe, motion, imageOff + tie);
              if (off < imageOff - tie ||
                  (off <= imageOff + tie && rests(rest) < rests(imageRest))) {
                imageOff = std::min(off, imageOff);
                imageRest = rest;
                bestImage = WholeImage{u, plane, image};
                imageFound = true;
              }
            }
          upTo = plain;
        }
      }
      if (imageOff <= offSheetLimit && imageOff < bestOff) {
        bestOff = imageOff;
        bestRest = imageRest;
      } else {
        imageFound = false;
      }
    }
    // No choice ends on the sheet: folds that missed it moved it whole, and which choice lies
    // nearest it says nothing. The pieces then (each step's smaller side moved), so the largest
    // part stays and the folds read are the folds made (a symmetric design's read as the images
    // of one another); the whole motion is found apart (whole_sheet_folds.hpp).
    if (!forced && bestOff > offSheetLimit) bestRest.assign(n, 0);
    TargetUnfolding result;
    Motion motion;
    for (std::size_t u = 0; u < n; ++u) {
      const bool rest = bestRest[u] != 0;
      UnfoldedFold fold;
      fold.plane = {motion(steps[u].plane.point), motion.linear * steps[u].plane.normal};
      if (rest) motion = motion.then(steps[u].plane);
      if (imageFound && bestImage.step == u) {
        fold.plane = bestImage.plane;
        fold.wholeImage = bestImage.image;
        motion = motion.before(bestImage.image);
      }
      fold.seedBefore = motion(rest ? steps[u].seedRest : steps[u].seedPiece);
      fold.seedVertex = rest ? steps[u].seedRestVertex : steps[u].seedPieceVertex;
      result.folds.insert(result.folds.begin(), fold);  // unfolding runs backwards
    }
    for (const glm::dvec3& p : unfolded) result.unfolded.push_back(motion(p));
    result.sharpLengthLeft = sharp;
    return result;
  }

  // An unfolding, and what it was read off: its steps, where the target lies with every step's
  // piece reflected, and the crease left.
  struct Read {
    TargetUnfolding unfolding;
    std::vector<Step> steps;
    std::vector<glm::dvec3> positions;
    double sharp = 0.0;
    double off = -1.0;  // offSheet of the unfolding's end, once measured (every level asks)
  };

  // offSheet of `read`'s end, measured once: each level of the unfolding above asks again.
  double offSheetOf(Read& read) const {
    if (read.off < 0.0) read.off = offSheet(read.unfolding.unfolded);
    return read.off;
  }

  bool smooth(const TargetUnfolding& u) const {
    return u.sharpLengthLeft < kLeastCrease * diagonal;
  }
  bool onSheet(double off) const { return off <= kOffSheet * diagonal; }

  // An unfolding ended: where it ends smooth, the fewest folds so far are noted.
  Read leaf(const std::vector<Step>& steps, const std::vector<glm::dvec3>& positions,
            double sharp) {
    Read read{bestSides(steps, positions, sharp), steps, positions, sharp};
    if (smooth(read.unfolding))
      smoothCost = std::min(smoothCost, static_cast<double>(read.unfolding.folds.size()) +
                                            (onSheet(offSheetOf(read)) ? 0.0 : kMotionPlanes));
    return read;
  }

  // A smooth unfolding that ends off the sheet ends on a rigid copy of it, whose motion the fit
  // makes as whole-sheet folds; which side of each crease was reflected moves the copy by that
  // crease's plane (bestSides), one plane more or fewer. Where no choice ends on the sheet, the
  // sides whose copy's motion takes the fewest planes (of every way the sheet lies on it, times
  // its own symmetries), then the fewest rests: a design's folds with their own sides leave the
  // motion its whole-sheet folds made. Nothing where it ends on the sheet, or is not smooth.
  std::optional<std::vector<char>> sidesForFewestPlanes(const Read& read,
                                                        const TriangleMesh& sheet) const {
    const std::size_t n = read.steps.size();
    if (n == 0 || n > kExhaustiveSides || !smooth(read.unfolding) ||
        onSheet(read.off >= 0.0 ? read.off : offSheet(read.unfolding.unfolded)) ||
        deadline.passed())
      return std::nullopt;
    const double tolerance = kCopyTolerance * diagonal;
    const std::vector<RigidMotion> ways = registerSheetOntoAll(
        sheet, TriangleMesh{read.positions, target.triangles}, tolerance, kCopyWays, deadline);
    if (ways.empty()) return std::nullopt;
    std::vector<RigidMotion> symmetries = sheetSymmetries(sheet, tolerance);
    symmetries.emplace_back();       // the identity
    std::vector<RigidMotion> lying;  // every way times every symmetry: x -> way(s(x))
    for (const RigidMotion& way : ways)
      for (const RigidMotion& sym : symmetries)
        lying.push_back({way.linear * sym.linear, way.linear * sym.offset + way.offset});
    std::uint32_t allowed = 0;
    for (std::size_t u = 0; u < n; ++u)
      if (read.steps[u].restReplayable) allowed |= 1u << u;
    std::size_t fewest = 5, fewestRests = n + 1;
    std::uint32_t chosen = 0;
    for (std::uint32_t bits = 0; bits < (1u << n) && !deadline.passed(); ++bits) {
      if (bits & ~allowed) continue;
      const std::size_t rests = static_cast<std::size_t>(std::popcount(bits));
      RigidMotion flips;  // the copy moved by each rest's reflection, as bestSides makes it
      for (std::size_t u = 0; u < n; ++u) {
        if (!(bits >> u & 1u)) continue;
        flips = then(reflectionOf(read.steps[u].plane), flips);
      }
      for (const RigidMotion& way : lying) {
        const std::size_t planes =
            fewestReflections(then(way, flips), kKindSnap, kKindSnap * diagonal);
        if (planes < fewest || (planes == fewest && rests < fewestRests)) {
          fewest = planes;
          fewestRests = rests;
          chosen = bits;
        }
      }
    }
    if (chosen == 0) return std::nullopt;  // the pieces, as read
    std::vector<char> rest(n, 0);
    for (std::size_t u = 0; u < n; ++u) rest[u] = chosen >> u & 1u;
    return rest;
  }

  // Which of two unfoldings wins: the one that takes away more creases; of smooth ones, the one
  // that takes fewer folds (kMotionPlanes more where it ends off the sheet); then the one on the
  // sheet, then the one closer to it.
  bool better(const TargetUnfolding& a, double offA, const TargetUnfolding& b, double offB) const {
    if (a.sharpLengthLeft < b.sharpLengthLeft - kLeastCrease * diagonal) return true;
    if (a.sharpLengthLeft > b.sharpLengthLeft + kLeastCrease * diagonal) return false;
    if (!smooth(a) || !smooth(b)) return offA < offB;  // stopped short alike: the closer
    const double costA =
        static_cast<double>(a.folds.size()) + (onSheet(offA) ? 0.0 : kMotionPlanes);
    const double costB =
        static_cast<double>(b.folds.size()) + (onSheet(offB) ? 0.0 : kMotionPlanes);
    if (costA != costB) return costA < costB;
    if (onSheet(offA) != onSheet(offB)) return onSheet(offA);
    return offA < offB;
  }

  // Unfolds from `positions` (the steps so far in `steps`); returns the best unfolding.
  Read unfold(std::vector<glm::dvec3> positions, std::vector<Step> steps, double sharp) {
    std::vector<Candidate> candidates;
    if (outOfTime()) return leaf(steps, positions, sharp);
    // One step more would take more folds than an unfolding already found smooth.
    const bool deeper = static_cast<double>(steps.size()) + 1.0 <= smoothCost;
    if (steps.size() < maxFolds && deeper) candidates = candidatesFor(positions);
    if (outOfTime()) return leaf(steps, positions, sharp);
    double least = kInfinitySharp;
    for (const Candidate& c : candidates) least = std::min(least, c.sharpAfter);
    // Unfolding must take a crease away, not trade one for another.
    if (candidates.empty() || !(least < sharp - kLeastCrease * diagonal)) {
      ++leaves;
      const std::size_t read = table ? table->forms.size() : 0;
      if (read > formsAtLastLeaf) ++newFormLeaves;
      formsAtLastLeaf = read;
      return leaf(steps, positions, sharp);
    }
    // The pieces that take away a crease, best first (the most crease gone, then the smallest
    // piece), one per plane and at most kChoicesPerStep: the fold made last need not have the
    // longest crease (a corner folded last leaves a short one), and a crease a later fold moved
    // may be unfolded first and lead nowhere. Tried depth first while fewer than kMaxUnfoldings
    // unfoldings have ended, until one ends on the sheet.
    std::vector<const Candidate*> ranked;
    for (const Candidate& c : candidates)
      if (c.sharpAfter < sharp - kLeastCrease * diagonal) ranked.push_back(&c);
    std::stable_sort(ranked.begin(), ranked.end(), [&](const Candidate* a, const Candidate* b) {
      if (a->interrupted != b->interrupted) return b->interrupted;
      if (a->sharpAfter < b->sharpAfter - 1e-6 * diagonal) return true;
      if (b->sharpAfter < a->sharpAfter - 1e-6 * diagonal) return false;
      return a->part.size() < b->part.size();
    });
    std::vector<const Candidate*> choices;
    for (const Candidate* c : ranked) {
      if (choices.size() >= kChoicesPerStep) break;
      const bool samePlane = std::any_of(choices.begin(), choices.end(), [&](const Candidate* d) {
        return std::abs(std::abs(glm::dot(c->plane.normal, d->plane.normal)) - 1.0) < 1e-6 &&
               std::abs(d->plane.signedDistance(c->plane.point)) < onPlane;
      });
      if (!samePlane) choices.push_back(c);
    }
    Read best;
    double bestOff = kInfinitySharp;
    bool first = true;
    for (const Candidate* chosen : choices) {
      const std::size_t counted = newFormsOnly ? newFormLeaves : leaves;
      if (!first && (counted >= kMaxUnfoldings || leaves >= kMaxOrders || outOfTime())) break;
      std::vector<char> inPiece(positions.size(), 0);
      for (std::uint32_t v : chosen->part) inPiece[v] = 1;
      std::vector<glm::dvec3> next = positions;
      Step step{chosen->plane, {}, {}};
      // The seeds: the deepest vertices off the boundary and off the plane; where a side has
      // none (a strip between a crease and a rim, one row of faces wide: its inner vertices lie
      // on the crease, and a seed there grabs the crease and folds nothing), the deepest on a
      // rim, not a slit's (a point there names either side); any, where it has neither.
      double deepestPiece = -1.0, deepestRest = -1.0;
      for (std::size_t v = 0; v < positions.size(); ++v) {
        if (connectivity.neighbours[v].empty()) continue;
        if (inPiece[v]) next[v] = chosen->plane.reflect(next[v]);
        const double off = std::abs(chosen->plane.signedDistance(next[v]));
        const double rank = off <= onPlane                ? 0.0
                            : !connectivity.onBoundary[v] ? 4.0
                            : !connectivity.onSlit[v]     ? 2.0
                                                          : 0.0;
        const double depth = off + rank * diagonal;
        double& deepest = inPiece[v] ? deepestPiece : deepestRest;
        if (depth > deepest) {
          deepest = depth;
          (inPiece[v] ? step.seedPiece : step.seedRest) = next[v];
          (inPiece[v] ? step.seedPieceVertex : step.seedRestVertex) = static_cast<std::uint32_t>(v);
        }
      }
      double lowest = 0.0, highest = 0.0;
      for (std::size_t v = 0; v < positions.size(); ++v)
        if (!inPiece[v] && !connectivity.neighbours[v].empty()) {
          const double d = chosen->plane.signedDistance(next[v]);
          lowest = std::min(lowest, d);
          highest = std::max(highest, d);
        }
      step.restReplayable = lowest > -1e-4 * diagonal || highest < 1e-4 * diagonal;
      std::vector<Step> more = steps;
      more.push_back(step);
      Read result = unfold(std::move(next), std::move(more), chosen->sharpAfter);
      const double off = offSheetOf(result);
      if (first || better(result.unfolding, off, best.unfolding, bestOff)) {
        best = std::move(result);
        bestOff = off;
      }
      first = false;
      // On the sheet, with less crease left than one step must take away (so none could take
      // more, and what is left is the sheet's own bends, or a flap laid on it): the target's
      // folds, read whole. Nothing later wins but by lying closer still.
      if (best.unfolding.sharpLengthLeft < kLeastCrease * diagonal && bestOff <= 1e-5 * diagonal)
        break;
    }
    return best;
  }

  static constexpr double kInfinitySharp = 1e300;
  // Unfoldings that read a form none before had; those that read only forms in the table cost
  // the side choice alone, and are bounded apart.
  static constexpr std::size_t kMaxUnfoldings = 600;
  static constexpr std::size_t kMaxOrders = 3000;
  // How near (of the diagonal) a form moved by a pose must lie on one read to be it.
  static constexpr double kSamePose = 1e-6;
  // Forms kept at most (each holds its pose and pieces: a few hundred kilobytes on a fine mesh).
  static constexpr std::size_t kMaxForms = 2000;
  static constexpr std::size_t kChoicesPerStep = 4;
};

}  // namespace

TargetUnfolding unfoldTarget(const TriangleMesh& target, const TriangleMesh& sheet,
                             double minDihedralDegrees, std::size_t maxFolds,
                             const Deadline& deadline, const std::vector<Isometry>& symmetryImages,
                             double sheetBendDegrees) {
  const double diagonal = boundingDiagonal(target);
  const SurfaceDistanceQuery sheetSurface(sheet, "sheet");
  const Connectivity connectivity = connectivityOf(target, 1e-5 * diagonal);
  std::size_t formsMet = 0, unfoldings = 0;
  // The forms read, kept from the first search to the second; a symmetric design's search reads
  // every node (its ends look for images: dear, so it runs once, as before the table).
  FormTable table;
  FormTable* kept = symmetryImages.empty() ? &table : nullptr;
  std::size_t formsReadPlain = 0;  // nodes read without a table
  // One search over orders, with the table where kept. `newFormsOnly`: its 600 unfoldings count
  // only those that read a form none before had (3,000 in all), else all. `sides`: where it ends
  // on a copy, the sides whose copy's motion takes the fewest planes (only the answer needs them).
  // `onSheet`: whether it ended smooth on the sheet.
  auto search = [&](bool newFormsOnly, const Deadline& until, bool sides, bool& onSheet) {
    Unfolder unfolder{
        target,
        connectivity,
        diagonal,
        1e-5 * diagonal,  // a crease's vertices, to the digits a file keeps
        std::cos(minDihedralDegrees * std::numbers::pi / 180.0),
        minDihedralDegrees,
        std::cos(((sheetBendDegrees < 0.0 ? largestDihedralDegrees(sheet) : sheetBendDegrees) +
                  kBendMarginDegrees) *
                 std::numbers::pi / 180.0),
        sheetSurface,
        maxFolds,
        until,
        symmetryImages};
    unfolder.table = kept;
    unfolder.newFormsOnly = newFormsOnly;
    if (kept) unfolder.formsAtLastLeaf = kept->forms.size();
    for (const auto& around : unfolder.connectivity.neighbours)
      unfolder.onFace.push_back(around.empty() ? 0 : 1);
    const double sharp =
        sharpLength(target, unfolder.connectivity, target.positions, unfolder.cosBent);
    Unfolder::Read read = unfolder.unfold(target.positions, {}, sharp);
    onSheet = unfolder.smooth(read.unfolding) && unfolder.onSheet(unfolder.offSheetOf(read));
    TargetUnfolding unfolding = read.unfolding;
    // A symmetric design's images are read by bestSides (a fold whose image moved the sheet).
    if (sides && symmetryImages.empty())
      if (const std::optional<std::vector<char>> chosen =
              unfolder.sidesForFewestPlanes(read, sheet))
        unfolding = unfolder.bestSides(read.steps, read.positions, read.sharp, &*chosen);
    unfolding.cutShort = unfolder.outOfTime();
    if (!kept) formsReadPlain += unfolder.formsMet;
    formsMet += unfolder.formsMet;
    unfoldings += unfolder.leaves;
    unfolding.formsRead = kept ? kept->forms.size() : formsReadPlain;
    unfolding.formsMet = formsMet;
    unfolding.unfoldings = unfoldings;
    return unfolding;
  };
  // First the search as it was before the table (600 unfoldings in all, depth first), its forms
  // read once: where it lands, or is cut short, that is the answer.
  // The further search goes past the first only where the first stopped at its 600 (else it
  // tried every order it could, and the further one would try the same again), and only where
  // an order may land: a target folded from a larger sheet (the kind at other parameters)
  // unfolds onto a copy of that one, whatever the order.
  bool onSheet = false;
  TargetUnfolding first = search(false, deadline, true, onSheet);
  if (onSheet || first.cutShort || !kept || first.unfoldings < Unfolder::kMaxUnfoldings ||
      surfaceArea(target) > (1.0 + kMoreArea) * surfaceArea(sheet))
    return first;
  // Else the same search on, in at most half the time left, past those 600 to 600 that read a
  // form none before had (3,000 in all), with the forms read so far: the design's own order may
  // come later (the most-moved cone's and disk's did). Kept only where it lands: which unfolding
  // off the sheet wins is left as the first search found it (the one the fit was measured on).
  Deadline half = deadline;  // half of the clock's time left, and of a share of CPU
  const auto now = std::chrono::steady_clock::now();
  if (deadline.at != std::chrono::steady_clock::time_point::max() && deadline.at > now)
    half = deadline.notAfter(now + (deadline.at - now) / 2);
  if (deadline.shareAt != std::chrono::steady_clock::time_point::max()) {
    const double cpu = processCpuSeconds();
    if (deadline.cpuAt > cpu) half.cpuAt = cpu + 0.5 * (deadline.cpuAt - cpu);
  }
  TargetUnfolding further = search(true, half, false, onSheet);
  if (onSheet && !further.cutShort) return further;
  first.formsRead = further.formsRead;
  first.formsMet = further.formsMet;
  first.unfoldings = further.unfoldings;
  return first;
}

}  // namespace curvefold
