#include "engine/geometry/development_overlap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory_resource>
#include <set>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtx/exterior_product.hpp>

#include "engine/geometry/topology.hpp"

namespace curvefold {
namespace {

// Whether segments pq and rs cross at a point inside both, each endpoint clearly (beyond
// `tolerance`, an area) on its own side of the other segment.
bool crossProperly(const glm::dvec2& p, const glm::dvec2& q, const glm::dvec2& r,
                   const glm::dvec2& s, double tolerance) {
  const double r1 = glm::cross(q - p, r - p), r2 = glm::cross(q - p, s - p);
  const double p1 = glm::cross(s - r, p - r), p2 = glm::cross(s - r, q - r);
  return ((r1 > tolerance && r2 < -tolerance) || (r1 < -tolerance && r2 > tolerance)) &&
         ((p1 > tolerance && p2 < -tolerance) || (p1 < -tolerance && p2 > tolerance));
}

// The sweep's order of points: by x, then by y. It is a sweep line tilted an infinitesimal angle
// from the vertical, so vertical edges need no case of their own: they run upward along it.
bool sweepsBefore(const glm::dvec2& a, const glm::dvec2& b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// The sweep runs in a frame turned by an angle that no mesh favours (about 17 degrees), so the
// columns and rows of grids, whose vertices line up to within rounding, lie across it.
constexpr double kTurnCos = 0.9563047559630354, kTurnSin = 0.2923717047227367;
glm::dvec2 turned(const glm::dvec2& p) {
  return {kTurnCos * p.x - kTurnSin * p.y, kTurnSin * p.x + kTurnCos * p.y};
}

// An edge with its endpoints (in the turned frame) in sweep order: it enters at p, leaves at q.
struct Segment {
  glm::dvec2 p, q;
  Edge edge;
};

class Sweep {
 public:
  // The segments in the order they enter (sorted by p), so that the sweep reads them in order.
  // The tolerance is 1e-12 of the size squared, and no turned coordinate exceeds the size.
  Sweep(const Sheet& sheet, std::vector<Segment> segments, double tolerance,
        CrossingSearchStats& stats)
      : sheet_(sheet),
        segments_(std::move(segments)),
        tolerance_(tolerance),
        rounding_(16.0 * std::numeric_limits<double>::epsilon() * std::sqrt(tolerance * 1e12)),
        stats_(stats) {}

  std::optional<EdgeCrossing> run() {
    const auto n = static_cast<std::uint32_t>(segments_.size());
    std::vector<std::uint32_t> leaving(n);
    for (std::uint32_t i = 0; i < n; ++i) leaving[i] = i;
    std::sort(leaving.begin(), leaving.end(), [&](std::uint32_t a, std::uint32_t b) {
      return sweepsBefore(segments_[a].q, segments_[b].q);
    });
    // Nodes freed as edges leave are reused as others enter.
    std::pmr::unsynchronized_pool_resource pool;
    Status status(Below{this}, &pool);
    std::vector<Status::iterator> where(n);
    std::uint32_t in = 0, out = 0;
    while (out < n) {
      // At a shared point, edges leave before others enter: edges meeting at a vertex are never
      // side by side there, and the ones entering are ordered only against edges that go on.
      if (in < n && sweepsBefore(segments_[in].p, segments_[leaving[out]].q)) {
        const std::uint32_t s = in++;
        const auto at = status.insert(s).first;
        where[s] = at;
        if (at != status.begin())
          if (auto c = test(*std::prev(at), s)) return c;
        if (std::next(at) != status.end())
          if (auto c = test(s, *std::next(at))) return c;
      } else {
        const auto at = where[leaving[out++]];
        if (at != status.begin() && std::next(at) != status.end())
          if (auto c = test(*std::prev(at), *std::next(at))) return c;
        status.erase(at);
      }
    }
    return std::nullopt;
  }

 private:
  // Orders the edges that one sweep line crosses, bottom to top: the one that starts later (a
  // higher index: segments are sorted by start) is placed where it starts, so the order of a
  // pair never depends on which is compared first (a strict weak ordering: irreflexive,
  // asymmetric, and transitive where the edges do not cross). A std::set compares only the edge
  // entering with the ones the line crosses at its start point.
 public:
  struct Below {
    const Sweep* sweep;
    bool operator()(std::uint32_t a, std::uint32_t b) const {
      if (a == b) return false;
      return a > b ? sweep->startsBelow(a, b) : !sweep->startsBelow(b, a);
    }
  };

 private:
  using Status = std::pmr::set<std::uint32_t, Below>;

  // Whether edge `later` passes below edge t where the sweep line meets its start point.
  bool startsBelow(std::uint32_t later, std::uint32_t t) const {
    ++stats_.orderTests;
    const Segment& s = segments_[later];
    const Segment& e = segments_[t];
    const glm::dvec2 along = e.q - e.p, v = s.p - e.p;
    const double side = glm::cross(along, v);
    if (side > tolerance_) return false;
    if (side < -tolerance_) return true;
    // Near t's line, beyond an end of it: t is steep (the line meets it within its span of x),
    // and y decides.
    const double at = glm::dot(along, v);
    if (at < -tolerance_ || at > glm::dot(along, along) + tolerance_) {
      if (s.p.y < std::min(e.p.y, e.q.y)) return true;
      if (s.p.y > std::max(e.p.y, e.q.y)) return false;
    }
    // Starting on t, within the tolerance (a shared point, a T-junction, pieces laid edge to
    // edge): crossProperly counts that as touching t, so it is ordered by where it heads, as it
    // lies just past its start. Edges from one point part at any angle, so that angle is taken
    // exactly (up to the rounding of the differences), not to the tolerance.
    const glm::dvec2 heading = s.q - s.p;
    const double turn = glm::cross(along, heading);
    const double rounding = rounding_ * (std::abs(along.x) + std::abs(along.y) +
                                         std::abs(heading.x) + std::abs(heading.y));
    if (turn > rounding) return false;
    if (turn < -rounding) return true;
    // Parallel. Both head forward in the sweep's order, so if they point apart, one heads
    // straight up and the other straight down.
    if (glm::dot(along, heading) < 0.0) return heading.y < 0.0;
    return later < t;  // along t: any fixed order will do, as neither crosses the other
  }

  // Decided on the development itself, not the turned frame: exactly the contract.
  std::optional<EdgeCrossing> test(std::uint32_t a, std::uint32_t b) const {
    ++stats_.pairTests;
    const Edge e = segments_[a].edge, f = segments_[b].edge;
    if (e.a == f.a || e.a == f.b || e.b == f.a || e.b == f.b) return std::nullopt;
    const auto& at = sheet_.development;
    if (!crossProperly(at[e.a], at[e.b], at[f.a], at[f.b], tolerance_)) return std::nullopt;
    return e < f ? EdgeCrossing{e, f} : EdgeCrossing{f, e};
  }

  const Sheet& sheet_;
  std::vector<Segment> segments_;
  double tolerance_;
  double rounding_;
  CrossingSearchStats& stats_;
};

// The development's edges as the sweep takes them, in the order they enter, with the tolerance;
// no segments when the development has no extent.
struct SweepInput {
  std::vector<Segment> segments;
  double tolerance = 0.0;
};

SweepInput sweepInput(const Sheet& sheet) {
  const EdgeTopology topology = buildEdgeTopology(sheet);
  SweepInput input;
  const auto finite = [](const glm::dvec2& p) { return std::isfinite(p.x) && std::isfinite(p.y); };
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const auto& sides : topology.edges)
    for (const VertexIndex v : {sides.edge.a, sides.edge.b})
      if (finite(sheet.development[v])) {
        lo = glm::min(lo, sheet.development[v]);
        hi = glm::max(hi, sheet.development[v]);
      }
  const double size = glm::length(hi - lo);
  if (!(size > 0.0) || !std::isfinite(size)) return input;
  // Turned about the centre, so that turning rounds at the scale of the size: an edge it shrinks
  // to a point is far too short to cross anything beyond the tolerance.
  const glm::dvec2 centre = 0.5 * (lo + hi);
  input.segments.reserve(topology.edges.size());
  for (const auto& sides : topology.edges) {
    const glm::dvec2 a = sheet.development[sides.edge.a], b = sheet.development[sides.edge.b];
    // validate() refuses an end that is not finite; here such an edge is left out, as it has no
    // place in the sweep's order.
    if (!finite(a) || !finite(b)) continue;
    glm::dvec2 p = turned(a - centre), q = turned(b - centre);
    if (sweepsBefore(q, p)) std::swap(p, q);
    if (p != q) input.segments.push_back({p, q, sides.edge});
  }
  // Edges from one point in a fixed order (the topology's), so that any two runs agree.
  std::stable_sort(input.segments.begin(), input.segments.end(),
                   [](const Segment& a, const Segment& b) { return sweepsBefore(a.p, b.p); });
  input.tolerance = kRelativeCrossingArea * size * size;
  return input;
}

}  // namespace

std::optional<EdgeCrossing> findDevelopmentCrossing(const Sheet& sheet,
                                                    CrossingSearchStats* stats) {
  CrossingSearchStats local;
  CrossingSearchStats& work = stats ? *stats : local;
  work = {};
  SweepInput input = sweepInput(sheet);
  if (input.segments.size() < 2) return std::nullopt;
  return Sweep(sheet, std::move(input.segments), input.tolerance, work).run();
}

std::optional<PieceOverlap> findPieceOverlap(const Sheet& sheet) {
  const EdgeTopology topology = buildEdgeTopology(sheet);
  const std::vector<std::uint32_t> component = connectedComponents(sheet, topology);
  if (component.empty()) return std::nullopt;
  const std::uint32_t pieces = *std::max_element(component.begin(), component.end()) + 1;
  if (pieces < 2) return std::nullopt;
  const auto& at = sheet.development;
  auto twiceArea = [&](const Triangle& t) {
    return glm::cross(at[t[1]] - at[t[0]], at[t[2]] - at[t[0]]);
  };
  // Each piece's point: the centroid of its largest triangle, well inside the piece.
  std::vector<TriangleIndex> largest(pieces, TriangleIndex(kNoIndex));
  std::vector<double> largestArea(pieces, -1.0);
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (std::uint32_t t = 0; t < sheet.triangleCount(); ++t) {
    const double area = std::abs(twiceArea(sheet.triangles[t]));
    if (!std::isfinite(area)) return std::nullopt;  // validate() refuses such a sheet
    if (area > largestArea[component[t]]) {
      largestArea[component[t]] = area;
      largest[component[t]] = t;
    }
    for (const VertexIndex v : sheet.triangles[t]) {
      lo = glm::min(lo, at[v]);
      hi = glm::max(hi, at[v]);
    }
  }
  const double size = glm::length(hi - lo);
  const double tolerance = kRelativeCrossingArea * size * size;
  struct Probe {
    glm::dvec2 point;
    std::uint32_t piece;
  };
  std::vector<Probe> probes;
  probes.reserve(pieces);
  for (std::uint32_t c = 0; c < pieces; ++c) {
    const Triangle& t = sheet.triangles[largest[c]];
    probes.push_back({(at[t[0]] + at[t[1]] + at[t[2]]) / 3.0, c});
  }
  std::sort(probes.begin(), probes.end(),
            [](const Probe& a, const Probe& b) { return a.point.x < b.point.x; });
  for (std::uint32_t t = 0; t < sheet.triangleCount(); ++t) {
    const Triangle& tri = sheet.triangles[t];
    const glm::dvec2 a = at[tri[0]], b = at[tri[1]], c = at[tri[2]];
    const glm::dvec2 low = glm::min(a, glm::min(b, c)), high = glm::max(a, glm::max(b, c));
    // Either turning of the development: its sign says which side is inside.
    const double sign = twiceArea(tri) < 0.0 ? -1.0 : 1.0;
    auto first = std::lower_bound(probes.begin(), probes.end(), low.x,
                                  [](const Probe& p, double x) { return p.point.x < x; });
    for (auto probe = first; probe != probes.end() && probe->point.x <= high.x; ++probe) {
      if (probe->piece == component[t] || probe->point.y < low.y || probe->point.y > high.y)
        continue;
      const glm::dvec2 p = probe->point;
      if (sign * glm::cross(b - a, p - a) > tolerance &&
          sign * glm::cross(c - b, p - b) > tolerance &&
          sign * glm::cross(a - c, p - c) > tolerance)
        return PieceOverlap{largest[probe->piece], TriangleIndex(t)};
    }
  }
  return std::nullopt;
}

namespace detail {

bool sweepRunsBelow(const Sheet& sheet, Edge a, Edge b) {
  SweepInput input = sweepInput(sheet);
  std::uint32_t ia = kNoIndex, ib = kNoIndex;
  for (std::uint32_t i = 0; i < input.segments.size(); ++i) {
    if (input.segments[i].edge == a) ia = i;
    if (input.segments[i].edge == b) ib = i;
  }
  if (ia == kNoIndex || ib == kNoIndex) return false;
  CrossingSearchStats stats;
  const Sweep sweep(sheet, std::move(input.segments), input.tolerance, stats);
  return Sweep::Below{&sweep}(ia, ib);
}

}  // namespace detail

}  // namespace curvefold
