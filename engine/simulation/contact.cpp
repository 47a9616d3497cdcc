#include "engine/simulation/contact.hpp"
#include "engine/simulation/contact_advance.hpp"
#include "engine/simulation/contact_lanes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "engine/geometry/self_intersection.hpp"
#include "engine/simulation/bar_hinge_model.hpp"

namespace curvefold {

// Ericson, "Real-Time Collision Detection", 5.1.5: the Voronoi regions of the corners, the edges,
// then the face.
glm::dvec3 nearestTriangleWeights(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                  const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return {1.0 - v, v, 0.0};
  }
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - w, w};
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) return {1.0, 0.0, 0.0};  // a degenerate triangle: its first corner
  const double v = vb / sum, w = vc / sum;
  return {1.0 - v - w, v, w};
}

namespace {

// Edge pairs nearer than this x ContactParameters::exclusion on the flat sheet are never pairs. Two
// edges that end on a crease a flat distance D apart meet nearer the crease than any vertex lies,
// where the model's sharp fold leaves its layers a gap of about the distance to the crease times
// the fold's opening: kept a thickness t apart, the crease stays open by about t / D. On the
// recorded cone glued (sliver rows 0.33 to 0.62 mm wide along its curved creases, 0.1 mm paper) 20
// such pairs started up to 47 um inside the thickness and the settle ended at 5.5% strain (0.9%
// without edge pairs); at 3 (0.9 mm there, t / D under 6.4 degrees) it ends at 0.9% (contact21,
// docs/performance.md).
constexpr double kEdgeExclusionScale = 3.0;

double distanceToTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                          const glm::dvec3& c) {
  const glm::dvec3 w = nearestTriangleWeights(p, a, b, c);
  return glm::distance(p, w.x * a + w.y * b + w.z * c);
}

// The nearest points of segments p0 p1 and q0 q1 as their parameters (s, t) in [0, 1] (Ericson,
// "Real-Time Collision Detection", 5.1.9; parallel segments: s from the first's start).
std::pair<double, double> nearestSegmentParameters(const glm::dvec3& p0, const glm::dvec3& p1,
                                                   const glm::dvec3& q0, const glm::dvec3& q1) {
  const glm::dvec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  if (!(a > 0.0) && !(e > 0.0)) return {0.0, 0.0};
  if (!(a > 0.0)) return {0.0, std::clamp(f / e, 0.0, 1.0)};
  const double c = glm::dot(d1, r);
  if (!(e > 0.0)) return {std::clamp(-c / a, 0.0, 1.0), 0.0};
  const double b = glm::dot(d1, d2), denominator = a * e - b * b;
  double sp = denominator > 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  double tp = (b * sp + f) / e;
  if (tp < 0.0) {
    tp = 0.0;
    sp = std::clamp(-c / a, 0.0, 1.0);
  } else if (tp > 1.0) {
    tp = 1.0;
    sp = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return {sp, tp};
}

double segmentDistance(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& q0,
                       const glm::dvec3& q1) {
  const auto [sp, tp] = nearestSegmentParameters(p0, p1, q0, q1);
  return glm::distance(p0 + sp * (p1 - p0), q0 + tp * (q1 - q0));
}

struct Box {
  glm::dvec3 low{INFINITY}, high{-INFINITY};
  void add(const glm::dvec3& p) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  void inflate(double by) {
    low -= glm::dvec3(by);
    high += glm::dvec3(by);
  }
  bool meets(const Box& other) const {
    return low.x <= other.high.x && other.low.x <= high.x && low.y <= other.high.y &&
           other.low.y <= high.y && low.z <= other.high.z && other.low.z <= high.z;
  }
};

// A bounding-volume hierarchy over boxes, by median splits along the longest axis (nth_element
// on the centres, ties by index: the same tree for the same boxes).
class BoxTree {
 public:
  BoxTree() = default;
  explicit BoxTree(std::vector<Box> boxes) : boxes_(std::move(boxes)) {
    order_.resize(boxes_.size());
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    if (!boxes_.empty()) build(0, static_cast<std::uint32_t>(order_.size()));
    builtLooseness_ = looseness();
  }
  std::size_t size() const { return boxes_.size(); }
  std::vector<Box> releaseBoxes() { return std::move(boxes_); }
  // New boxes for the same items: every node's box fitted to them again, the splits kept (a
  // node's children come after it, so one pass from the back). A query finds what it finds in a
  // tree built on these boxes; only its speed depends on the splits.
  void refit(std::vector<Box> boxes) {
    boxes_ = std::move(boxes);
    for (std::size_t i = nodes_.size(); i-- > 0;) {
      Node& node = nodes_[i];
      Box box;
      if (node.count > 0) {
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
          box.add(boxes_[order_[k]].low);
          box.add(boxes_[order_[k]].high);
        }
      } else {
        for (const std::uint32_t child : {node.left, node.right}) {
          box.add(nodes_[child].box.low);
          box.add(nodes_[child].box.high);
        }
      }
      node.box = box;
    }
  }
  // How far its splits have gone stale: the nodes' half-perimeters summed over the items',
  // against that sum when the tree was built (1: as built).
  double staleness() const { return looseness() / builtLooseness_; }
  // Calls visit(item) for every box that meets `query`.
  template <typename Visit>
  void query(const Box& query, Visit&& visit) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (!node.box.meets(query)) continue;
      if (node.count > 0) {
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k)
          if (boxes_[order_[k]].meets(query)) visit(order_[k]);
      } else {
        stack[top++] = node.left;
        stack[top++] = node.right;
      }
    }
  }

 private:
  struct Node {
    Box box;
    std::uint32_t first = 0, count = 0;  // leaf: range of order_; inner: count 0
    std::uint32_t left = 0, right = 0;   // inner: children
  };
  static constexpr std::uint32_t kLeaf = 4;

  std::uint32_t build(std::uint32_t first, std::uint32_t count) {
    const std::uint32_t index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    Box box;
    for (std::uint32_t k = first; k < first + count; ++k) {
      box.add(boxes_[order_[k]].low);
      box.add(boxes_[order_[k]].high);
    }
    nodes_[index].box = box;
    if (count <= kLeaf) {
      nodes_[index].first = first;
      nodes_[index].count = count;
      return index;
    }
    const glm::dvec3 size = box.high - box.low;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    const std::uint32_t half = count / 2;
    auto centre = [&](std::uint32_t i) { return boxes_[i].low[axis] + boxes_[i].high[axis]; };
    std::nth_element(order_.begin() + first, order_.begin() + first + half,
                     order_.begin() + first + count, [&](std::uint32_t a, std::uint32_t b) {
                       const double ca = centre(a), cb = centre(b);
                       return ca < cb || (ca == cb && a < b);
                     });
    const std::uint32_t left = build(first, half);
    const std::uint32_t right = build(first + half, count - half);
    nodes_[index].left = left;
    nodes_[index].right = right;
    return index;
  }

  static double halfPerimeter(const Box& box) {
    const glm::dvec3 size = box.high - box.low;
    return size.x + size.y + size.z;
  }
  double looseness() const {
    double nodes = 0.0, items = 0.0;
    for (const Node& node : nodes_) nodes += halfPerimeter(node.box);
    for (const Box& box : boxes_) items += halfPerimeter(box);
    return items > 0.0 ? nodes / items : 1.0;
  }

  std::vector<Box> boxes_;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
  double builtLooseness_ = 1.0;
};

const glm::dvec3& corner(const BarHingeModel& model, const std::vector<glm::dvec3>& x,
                         std::uint32_t t, int k) {
  return x[model.triangles[t][k]];
}

bool ownTriangle(const BarHingeModel& model, std::uint32_t v, std::uint32_t t) {
  const auto& tri = model.triangles[t];
  return tri[0] == v || tri[1] == v || tri[2] == v;
}

// Whether the pair is the sheet's own neighbourhood (near on the flat sheet).
bool excluded(const BarHingeModel& model, std::uint32_t v, std::uint32_t t, double exclusion) {
  const auto& flat = model.flatPositions;
  const auto near = [&](std::uint32_t u) {
    return distanceToTriangle(flat[u], corner(model, flat, t, 0), corner(model, flat, t, 1),
                              corner(model, flat, t, 2)) < exclusion;
  };
  if (near(v)) return true;
  // Across a glued seam the sheet is one: a vertex glued to one near the triangle is near it.
  for (const auto& pair : model.glue)
    if ((pair[0] == v && near(pair[1])) || (pair[1] == v && near(pair[0]))) return true;
  return false;
}

// Whether two bars are the sheet's own neighbourhood: nearer than kEdgeExclusionScale x the
// exclusion on the flat sheet, or an end of one glued to a vertex near the other.
bool edgesExcluded(const BarHingeModel& model, std::uint32_t i, std::uint32_t j, double exclusion) {
  const auto& flat = model.flatPositions;
  const auto& e = model.bars[i];
  const auto& f = model.bars[j];
  if (segmentDistance(flat[e[0]], flat[e[1]], flat[f[0]], flat[f[1]]) <
      kEdgeExclusionScale * exclusion)
    return true;
  const auto nearBar = [&](std::uint32_t u, const std::array<std::uint32_t, 2>& bar) {
    return segmentDistance(flat[u], flat[u], flat[bar[0]], flat[bar[1]]) < exclusion;
  };
  for (const auto& pair : model.glue)
    for (int k = 0; k < 2; ++k) {
      const std::uint32_t end = pair[k], other = pair[1 - k];
      if ((end == e[0] || end == e[1]) && nearBar(other, f)) return true;
      if ((end == f[0] || end == f[1]) && nearBar(other, e)) return true;
    }
  return false;
}

bool barsShareAnEnd(const BarHingeModel& model, std::uint32_t i, std::uint32_t j) {
  const auto& e = model.bars[i];
  const auto& f = model.bars[j];
  return e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1];
}

BoxTree barTree(const BarHingeModel& model, const std::vector<glm::dvec3>& x, double inflation,
                const std::vector<glm::dvec3>* step = nullptr);

// The pairs of bars (i < j, no end in common, not excluded) whose segments are nearer than
// `within`, sorted.
// `tree`: the bars' boxes at x inflated by `within` (built here when null).
std::vector<ContactPair> edgePairsWithin(const BarHingeModel& model,
                                         const std::vector<glm::dvec3>& x, double within,
                                         double exclusion, const BoxTree* given = nullptr) {
  const std::size_t m = model.bars.size();
  if (m == 0) return {};
  BoxTree built;
  if (!given) built = barTree(model, x, within);
  const BoxTree& tree = given ? *given : built;
  std::vector<std::vector<std::uint32_t>> found(m);
  forEachIndex(m, [&](std::size_t bar) {
    const std::uint32_t i = static_cast<std::uint32_t>(bar);
    const auto& e = model.bars[i];
    Box box;
    box.add(x[e[0]]);
    box.add(x[e[1]]);
    tree.query(box, [&](std::uint32_t j) {
      if (j <= i || barsShareAnEnd(model, i, j)) return;
      const auto& f = model.bars[j];
      if (segmentDistance(x[e[0]], x[e[1]], x[f[0]], x[f[1]]) < within &&
          !edgesExcluded(model, i, j, exclusion))
        found[bar].push_back(j);
    });
    std::sort(found[bar].begin(), found[bar].end());
  });
  std::vector<ContactPair> pairs;
  for (std::uint32_t i = 0; i < m; ++i)
    for (std::uint32_t j : found[i]) pairs.push_back({1, i, j});
  return pairs;
}

// Per vertex in order, the triangles `accept(v, t)` takes among those whose (already inflated)
// box meets the vertex's box; concatenated in vertex order, each vertex's sorted.
template <typename VertexBox, typename Accept>
std::vector<ContactPair> collectPairs(const BarHingeModel& model, const BoxTree& tree,
                                      const VertexBox& vertexBox, const Accept& accept) {
  const std::size_t n = model.vertexCount();
  std::vector<std::vector<std::uint32_t>> found(n);
  forEachIndex(n, [&](std::size_t v) {
    const std::uint32_t vertex = static_cast<std::uint32_t>(v);
    tree.query(vertexBox(vertex), [&](std::uint32_t t) {
      if (!ownTriangle(model, vertex, t) && accept(vertex, t)) found[v].push_back(t);
    });
    std::sort(found[v].begin(), found[v].end());
  });
  std::vector<ContactPair> pairs;
  for (std::uint32_t v = 0; v < n; ++v)
    for (std::uint32_t t : found[v]) pairs.push_back({0, v, t});
  return pairs;
}

// Each element's box (its corners, and with `step` the corners moved by it), inflated.
template <typename Elements>
std::vector<Box> elementBoxes(const Elements& elements, const std::vector<glm::dvec3>& x,
                              double inflation, const std::vector<glm::dvec3>* step) {
  std::vector<Box> boxes(elements.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::uint32_t v : elements[i]) {
      boxes[i].add(x[v]);
      if (step) boxes[i].add(x[v] + (*step)[v]);
    }
    boxes[i].inflate(inflation);
  }
  return boxes;
}

BoxTree triangleTree(const BarHingeModel& model, const std::vector<glm::dvec3>& x, double inflation,
                     const std::vector<glm::dvec3>* step = nullptr) {
  return BoxTree(elementBoxes(model.triangles, x, inflation, step));
}

BoxTree barTree(const BarHingeModel& model, const std::vector<glm::dvec3>& x, double inflation,
                const std::vector<glm::dvec3>* step) {
  return BoxTree(elementBoxes(model.bars, x, inflation, step));
}

// The barrier b(s) and its first two derivatives (ContactParameters; header).
void barrier(const ContactParameters& c, double s, double& b, double& slope, double& curvature,
             bool dynamic = false) {
  const double taylorBelow = dynamic ? std::max(c.minimumGap, c.dynamicMinimumGap) : c.minimumGap;
  const double sHat = c.activation, kappa = c.stiffness;
  const auto exact = [&](double at, double& e, double& d1, double& d2) {
    const double gap = at - sHat, log = std::log(at / sHat);
    e = -kappa * gap * gap * log;
    d1 = -kappa * (2.0 * gap * log + gap * gap / at);
    d2 = -kappa * (2.0 * log + 4.0 * gap / at - gap * gap / (at * at));
  };
  if (s >= taylorBelow) {
    exact(s, b, slope, curvature);
    return;
  }
  double e0 = 0.0, d1 = 0.0, d2 = 0.0;
  exact(taylorBelow, e0, d1, d2);
  const double ds = s - taylorBelow;
  b = e0 + d1 * ds + 0.5 * d2 * ds * ds;
  slope = d1 + d2 * ds;
  curvature = d2;
}

}  // namespace

void setDynamicContactStep(ContactParameters& contact, double largestStiffness) {
  contact.dynamicMinimumGap = contact.minimumGap;
  if (!contact.enabled || !(largestStiffness > 0.0)) return;
  // b'' falls as the gap grows: bisect for the gap where it equals the largest stiffness.
  double low = contact.minimumGap, high = contact.activation, b = 0.0, d1 = 0.0, d2 = 0.0;
  barrier(contact, low, b, d1, d2);
  if (d2 <= largestStiffness) return;
  for (int k = 0; k < 60; ++k) {
    const double middle = 0.5 * (low + high);
    barrier(contact, middle, b, d1, d2);
    (d2 > largestStiffness ? low : high) = middle;
  }
  contact.dynamicMinimumGap = high;
}

ContactParameters contactParameters(const BarHingeModel& model, const ContactOptions& options,
                                    double paperThickness) {
  ContactParameters c;
  if (model.mode != SimulationMode::Paper || !options.enabled) return c;
  c.thickness = options.thickness > 0.0 ? options.thickness : paperThickness;
  if (!(c.thickness > 0.0) || !(options.stiffnessScale > 0.0)) return c;
  c.enabled = true;
  c.activation = c.thickness;
  c.minimumGap = 1e-3 * c.activation;
  c.exclusion = 1.5 * (c.thickness + c.activation);
  c.edgePairs = options.edgePairs && (model.glue.empty() || options.edgePairsWhereGlued);
  double scale = 0.0;  // the static solver's forceScale
  for (std::size_t j = 0; j < model.hinges.size(); ++j)
    scale = std::max(scale, model.hingeStiffness[j] / model.barLength[model.hingeEdge[j]]);
  if (scale == 0.0)
    for (std::size_t i = 0; i < model.bars.size(); ++i)
      scale = std::max(scale, model.barStiffness[i] * model.barLength[i]);
  c.stiffness = options.stiffnessScale * (scale > 0.0 ? scale : 1.0) / c.activation;
  return c;
}

namespace {

// The pairs (vertex, triangle not its own) nearer than `within`, those nearer than `exclusion` on
// the flat sheet left out.
// `tree`: the triangles' boxes at the positions inflated by `within` (built here when null).
std::vector<ContactPair> pairsWithin(const BarHingeModel& model,
                                     const std::vector<glm::dvec3>& positions, double within,
                                     double exclusion, const BoxTree* given = nullptr) {
  if (model.triangles.empty()) return {};
  BoxTree built;
  if (!given) built = triangleTree(model, positions, within);
  const BoxTree& tree = given ? *given : built;
  return collectPairs(
      model, tree,
      [&](std::uint32_t v) {
        Box box;
        box.add(positions[v]);
        return box;
      },
      [&](std::uint32_t v, std::uint32_t t) {
        return distanceToTriangle(positions[v], corner(model, positions, t, 0),
                                  corner(model, positions, t, 1),
                                  corner(model, positions, t, 2)) < within &&
               !excluded(model, v, t, exclusion);
      });
}

}  // namespace

std::vector<ContactPair> findContactPairs(const BarHingeModel& model,
                                          const std::vector<glm::dvec3>& positions, double reach) {
  if (!model.contact.enabled) return {};
  std::vector<ContactPair> pairs =
      pairsWithin(model, positions, model.contact.thickness + reach, model.contact.exclusion);
  if (!model.contact.edgePairs) return pairs;
  const std::vector<ContactPair> edges =
      edgePairsWithin(model, positions, model.contact.thickness + reach, model.contact.exclusion);
  pairs.insert(pairs.end(), edges.begin(), edges.end());
  return pairs;
}

std::array<std::uint32_t, 4> contactPairVertices(const BarHingeModel& model,
                                                 const ContactPair& pair) {
  if (pair.edges) {
    const auto& e = model.bars[pair.vertex];
    const auto& f = model.bars[pair.triangle];
    return {e[0], e[1], f[0], f[1]};
  }
  const auto& t = model.triangles[pair.triangle];
  return {pair.vertex, t[0], t[1], t[2]};
}

namespace {

// The distance's gradient direction: away / d, or where the distance is 0 the unit `fallback`
// (the triangle's or the two edges' normal; 0 where that is 0 too).
glm::dvec3 pairNormal(const glm::dvec3& away, double d, const glm::dvec3& fallback) {
  if (d > 0.0) return away / d;
  const double length = glm::length(fallback);
  return length > 0.0 ? fallback / length : glm::dvec3(0.0);
}

// A vertex-triangle pair's term from its nearest point's weights w, p minus that point (away)
// and its length d: contactTerm's and triangleDistanceLanes' one copy.
bool triangleTerm(const ContactParameters& c, const ContactPair& pair,
                  const std::array<std::uint32_t, 3>& tri, const glm::dvec3& w,
                  const glm::dvec3& away, double d, const glm::dvec3& a, const glm::dvec3& b,
                  const glm::dvec3& cc, ContactTerm& term, bool dynamic) {
  const double s = d - c.thickness;
  if (s >= c.activation) return false;
  const glm::dvec3 normal = d > 0.0 ? away / d : pairNormal(away, d, glm::cross(b - a, cc - a));
  term.vertices = {pair.vertex, tri[0], tri[1], tri[2]};
  term.gradient = {normal, -w.x * normal, -w.y * normal, -w.z * normal};
  barrier(c, s, term.energy, term.slope, term.curvature, dynamic);
  return true;
}

}  // namespace

bool contactTerm(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                 const ContactPair& pair, ContactTerm& term, bool dynamic) {
  const ContactParameters& c = model.contact;
  if (pair.edges) {
    const std::array<std::uint32_t, 4> v = contactPairVertices(model, pair);
    const glm::dvec3 &p0 = positions[v[0]], &p1 = positions[v[1]];
    const glm::dvec3 &q0 = positions[v[2]], &q1 = positions[v[3]];
    const auto [sp, tp] = nearestSegmentParameters(p0, p1, q0, q1);
    const glm::dvec3 away = (p0 + sp * (p1 - p0)) - (q0 + tp * (q1 - q0));
    const double d = glm::length(away);
    const double s = d - c.thickness;
    if (s >= c.activation) return false;
    const glm::dvec3 normal = pairNormal(away, d, glm::cross(p1 - p0, q1 - q0));
    term.vertices = v;
    term.gradient = {(1.0 - sp) * normal, sp * normal, -(1.0 - tp) * normal, -tp * normal};
    barrier(c, s, term.energy, term.slope, term.curvature, dynamic);
    return true;
  }
  const auto& tri = model.triangles[pair.triangle];
  const glm::dvec3& p = positions[pair.vertex];
  const glm::dvec3 &a = positions[tri[0]], &b = positions[tri[1]], &cc = positions[tri[2]];
  const glm::dvec3 w = nearestTriangleWeights(p, a, b, cc);
  const glm::dvec3 away = p - (w.x * a + w.y * b + w.z * cc);
  return triangleTerm(c, pair, tri, w, away, glm::length(away), a, b, cc, term, dynamic);
}

double contactEnergy(const BarHingeModel& model, const std::vector<glm::dvec3>& positions) {
  if (!model.contact.enabled) return 0.0;
  double energy = 0.0;
  ContactTerm term;
  for (const ContactPair& pair : findContactPairs(model, positions, model.contact.activation))
    if (contactTerm(model, positions, pair, term)) energy += term.energy;
  return energy;
}

namespace {

// The pair's distance at `x` (vertex to triangle, or segment to segment) and its change to
// `moved`. A move far below the distance (under 1e-6 of it: a Newton step near equilibrium) is
// measured from the moves with the nearest points' weights held (the change they make is of the
// move's second order over the distance, 1e-20 m and less there), as d' - d = da (2 a + da) /
// (|a + da| + d), not as the difference of two distances rounded at 1e-17 m.
std::pair<double, double> pairDistanceChange(const BarHingeModel& model,
                                             const std::vector<glm::dvec3>& x,
                                             const std::vector<glm::dvec3>& moved,
                                             const ContactPair& pair) {
  const std::array<std::uint32_t, 4> v = contactPairVertices(model, pair);
  std::array<double, 4> w{};  // a = sum w_k x_k, the nearest points' difference
  const auto distanceAt = [&](const std::vector<glm::dvec3>& at) {
    return pair.edges ? segmentDistance(at[v[0]], at[v[1]], at[v[2]], at[v[3]])
                      : distanceToTriangle(at[v[0]], at[v[1]], at[v[2]], at[v[3]]);
  };
  if (pair.edges) {
    const auto [sp, tp] = nearestSegmentParameters(x[v[0]], x[v[1]], x[v[2]], x[v[3]]);
    w = {1.0 - sp, sp, -(1.0 - tp), -tp};
  } else {
    const glm::dvec3 b = nearestTriangleWeights(x[v[0]], x[v[1]], x[v[2]], x[v[3]]);
    w = {1.0, -b.x, -b.y, -b.z};
  }
  glm::dvec3 a(0.0), da(0.0);
  for (int k = 0; k < 4; ++k) {
    a += w[k] * x[v[k]];
    da += w[k] * (moved[v[k]] - x[v[k]]);
  }
  const double d = distanceAt(x);
  if (!(glm::length(da) < 1e-6 * d)) return {d, distanceAt(moved) - d};
  return {d, glm::dot(da, 2.0 * a + da) / (glm::length(a + da) + glm::length(a))};
}

// b(s + ds) - b(s) of the static barrier, from ds itself where both gaps lie in one piece of it
// (the log's piece or the Taylor polynomial's), so that a change far below b's own rounding
// (a Newton step near equilibrium) is not lost in the difference of two values.
double barrierChange(const ContactParameters& c, double s, double ds) {
  const double sHat = c.activation, kappa = c.stiffness, t = c.minimumGap, s2 = s + ds;
  const auto value = [&](double at) {
    if (at >= sHat) return 0.0;
    double b = 0.0, d1 = 0.0, d2 = 0.0;
    barrier(c, at, b, d1, d2);
    return b;
  };
  if (s >= sHat && s2 >= sHat) return 0.0;
  if (s >= t && s2 >= t && s < sHat && s2 < sHat) {
    // -kappa ((g + ds)^2 ln(s2 / sHat) - g^2 ln(s / sHat)), g = s - sHat
    const double g = s - sHat, log = std::log(s / sHat);
    return -kappa * ((2.0 * g + ds) * ds * log + (g + ds) * (g + ds) * std::log1p(ds / s));
  }
  if (s < t && s2 < t) {
    double b = 0.0, d1 = 0.0, d2 = 0.0;
    barrier(c, s, b, d1, d2);  // d1, d2 at s; the polynomial's change is exact in ds
    return ds * (d1 + 0.5 * d2 * ds);
  }
  return value(s2) - value(s);
}

}  // namespace

double contactEnergyChange(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                           const std::vector<glm::dvec3>& moved) {
  if (!model.contact.enabled) return 0.0;
  const double reach = model.contact.activation;
  std::vector<ContactPair> pairs = findContactPairs(model, positions, reach);
  const std::vector<ContactPair> after = findContactPairs(model, moved, reach);
  std::vector<ContactPair> both;
  std::set_union(pairs.begin(), pairs.end(), after.begin(), after.end(), std::back_inserter(both));
  double change = 0.0;
  for (const ContactPair& pair : both) {
    const auto [d, dd] = pairDistanceChange(model, positions, moved, pair);
    change += barrierChange(model.contact, d - model.contact.thickness, dd);
  }
  return change;
}

void addContactForces(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                      const std::vector<ContactPair>& pairs, std::vector<glm::dvec3>& vertexForces,
                      bool dynamic) {
  if (!model.contact.enabled || pairs.empty()) return;
  // Each pair's term on all cores, then summed in pair order: the same bits for any thread count.
  std::vector<ContactTerm> terms(pairs.size());
  std::vector<std::uint8_t> active(pairs.size(), 0);
  forEachIndex(pairs.size(), [&](std::size_t i) {
    active[i] = contactTerm(model, positions, pairs[i], terms[i], dynamic);
  });
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (!active[i]) continue;
    for (int k = 0; k < 4; ++k)
      if (!model.pinned[terms[i].vertices[k]])
        vertexForces[terms[i].vertices[k]] -= terms[i].slope * terms[i].gradient[k];
  }
}

void addContactForces(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                      std::vector<glm::dvec3>& vertexForces) {
  if (!model.contact.enabled) return;
  addContactForces(model, positions, findContactPairs(model, positions, model.contact.activation),
                   vertexForces);
}

namespace {

constexpr int kAdvanceRounds = 2000;  // per pair; a sliding layer takes gap / motion per round

// Conservative advancement of one pair along the step (stepBound's `advance`): the gap changes
// at most by `relative` per unit of the share, so from a share where the gap is g it may grow by
// (g - floor) / relative keeping the gap above floor (a tenth of the gap at the start, as the
// one-shot bound keeps); taken again from there until the share reaches `upTo` or an advance
// falls under 0.1% of the share reached (the gap closing on its floor). A layer sliding at a
// steady gap advances by the same share each round and passes. gapAt(share): the pair's gap there.
template <typename GapAt>
double advancedShare(GapAt&& gapAt, double gap, double relative, double upTo) {
  const double floor = 0.1 * gap;
  double share = 0.0, here = gap;
  for (int round = 0; round < kAdvanceRounds && share < upTo; ++round) {
    const double further = (here - floor) / relative;
    if (!(further > 1e-3 * (share + further))) break;  // converged onto the closing
    share = std::min(upTo, share + further);
    here = gapAt(share);
  }
  return std::max(share, 0.9 * gap / relative);
}

// contactStepBound and advancedContactStepBound (contact_advance.hpp): one search of the pairs.
double stepBound(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                 const std::vector<glm::dvec3>& step, bool advance) {
  if (!model.contact.enabled || model.triangles.empty()) return 1.0;
  const double thickness = model.contact.thickness;
  const BoxTree tree = triangleTree(model, positions, thickness, &step);
  const std::size_t n = model.vertexCount();
  std::vector<double> bound(n, 1.0);
  forEachIndex(n, [&](std::size_t v) {
    Box box;
    box.add(positions[v]);
    box.add(positions[v] + step[v]);
    tree.query(box, [&](std::uint32_t t) {
      if (ownTriangle(model, static_cast<std::uint32_t>(v), t)) return;
      const auto& tri = model.triangles[t];
      double relative = 0.0;  // the gap changes at most by this over the whole step
      for (std::uint32_t corner : tri)
        relative = std::max(relative, glm::length(step[v] - step[corner]));
      const double gap = distanceToTriangle(positions[v], positions[tri[0]], positions[tri[1]],
                                            positions[tri[2]]) -
                         thickness;
      if (!(gap > 0.0) || 0.9 * gap >= relative * bound[v]) return;
      if (excluded(model, static_cast<std::uint32_t>(v), t, model.contact.exclusion)) return;
      const auto gapAt = [&](double share) {
        return distanceToTriangle(positions[v] + share * step[v],
                                  positions[tri[0]] + share * step[tri[0]],
                                  positions[tri[1]] + share * step[tri[1]],
                                  positions[tri[2]] + share * step[tri[2]]) -
               thickness;
      };
      bound[v] = advance ? advancedShare(gapAt, gap, relative, bound[v]) : 0.9 * gap / relative;
    });
  });
  if (!model.contact.edgePairs) return *std::min_element(bound.begin(), bound.end());
  // Edges alike: the segments' distance changes at most by the largest relative motion of an end
  // of one against an end of the other.
  const BoxTree bars = barTree(model, positions, thickness, &step);
  const std::size_t m = model.bars.size();
  std::vector<double> barBound(m, 1.0);
  forEachIndex(m, [&](std::size_t bar) {
    const std::uint32_t i = static_cast<std::uint32_t>(bar);
    const auto& e = model.bars[i];
    Box box;
    for (std::uint32_t v : e) {
      box.add(positions[v]);
      box.add(positions[v] + step[v]);
    }
    bars.query(box, [&](std::uint32_t j) {
      if (j <= i || barsShareAnEnd(model, i, j)) return;
      const auto& f = model.bars[j];
      double relative = 0.0;
      for (std::uint32_t a : e)
        for (std::uint32_t b : f) relative = std::max(relative, glm::length(step[a] - step[b]));
      const double gap =
          segmentDistance(positions[e[0]], positions[e[1]], positions[f[0]], positions[f[1]]) -
          thickness;
      if (!(gap > 0.0) || 0.9 * gap >= relative * barBound[bar]) return;
      if (edgesExcluded(model, i, j, model.contact.exclusion)) return;
      const auto gapAt = [&](double share) {
        return segmentDistance(
                   positions[e[0]] + share * step[e[0]], positions[e[1]] + share * step[e[1]],
                   positions[f[0]] + share * step[f[0]], positions[f[1]] + share * step[f[1]]) -
               thickness;
      };
      barBound[bar] =
          advance ? advancedShare(gapAt, gap, relative, barBound[bar]) : 0.9 * gap / relative;
    });
  });
  double smallest = *std::min_element(bound.begin(), bound.end());
  if (m > 0) smallest = std::min(smallest, *std::min_element(barBound.begin(), barBound.end()));
  return smallest;
}

}  // namespace

double contactStepBound(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                        const std::vector<glm::dvec3>& step) {
  return stepBound(model, positions, step, false);
}

double advancedContactStepBound(const BarHingeModel& model,
                                const std::vector<glm::dvec3>& positions,
                                const std::vector<glm::dvec3>& step) {
  return stepBound(model, positions, step, true);
}

namespace {

// The dynamic list's skin over the activation gap: searched again every skin / 2 of motion, each
// step evaluating the pairs within the activation gap plus twice the motion since. At 2 (main
// had 1) the folding grids of bench_simulation (BM_DynamicStepPaper) are searched about half as
// often, and a sheet folded flat lists no more pairs (contact22, docs/performance.md).
constexpr double kSkinScale = 2.0;

// A search refits the list's trees (ContactTrees) while their nodes' half-perimeters, summed over
// their items', stay within this factor of the sum when built; beyond it builds them anew. A
// folding sheet's boxes move apart from their siblings, and a stale tree visits more nodes per
// query; a refit costs a pass over the nodes, a build sorts every level.
constexpr double kRefitStaleness = 1.5;

// Pairs a task of the list's passes takes.
constexpr std::size_t kPairGrain = 2048;

// The pair's distance (vertex to triangle, or segment to segment).
double pairDistance(const BarHingeModel& model, const std::vector<glm::dvec3>& x,
                    const ContactPair& pair) {
  const std::array<std::uint32_t, 4> v = contactPairVertices(model, pair);
  return pair.edges ? segmentDistance(x[v[0]], x[v[1]], x[v[2]], x[v[3]])
                    : distanceToTriangle(x[v[0]], x[v[1]], x[v[2]], x[v[3]]);
}

// The list's per-pair distances and the vertices it touches after a search; the contact forces
// zeroed (a vertex in no pair keeps 0 until the next search).
void indexContactList(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                      ContactList& list, std::vector<glm::dvec3>& contactForces) {
  const std::size_t n = positions.size(), count = list.pairs.size();
  list.builtDistance.resize(count);
  forEachRange(count, kPairGrain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      list.builtDistance[i] = pairDistance(model, positions, list.pairs[i]);
  });
  list.forces.resize(count);
  list.pushing.assign(count, 0);
  std::vector<std::uint8_t> inPair(n, 0);
  for (const ContactPair& pair : list.pairs)
    for (std::uint32_t v : contactPairVertices(model, pair)) inPair[v] = 1;
  list.touched.clear();
  for (std::size_t v = 0; v < n; ++v)
    if (inPair[v]) list.touched.push_back(static_cast<std::uint32_t>(v));
  contactForces.assign(n, glm::dvec3(0.0));
  list.indexed = list.rebuilds;
}

}  // namespace

// The dynamic list's trees (ContactList::trees): the triangles' and the bars' boxes inflated by
// what the search reaches, as of the last search.
struct ContactTrees {
  BoxTree triangles, bars;
};

namespace {

// findContactPairs(model, positions, reach) with the list's trees: refitted to the positions
// (their splits kept) while their staleness stays within kRefitStaleness, built anew otherwise.
std::vector<ContactPair> searchContactList(const BarHingeModel& model,
                                           const std::vector<glm::dvec3>& positions, double reach,
                                           ContactList& list) {
  const double within = model.contact.thickness + reach;  // findContactPairs' sum
  if (!list.trees)
    list.trees = std::make_shared<ContactTrees>();
  else if (list.trees.use_count() > 1)  // a copied state's list: refit a copy of its own
    list.trees = std::make_shared<ContactTrees>(*list.trees);
  ContactTrees& trees = *list.trees;
  // Returns whether it refitted.
  const auto fit = [&](BoxTree& tree, std::vector<Box> boxes) {
    if (tree.size() == boxes.size() && !boxes.empty()) {
      tree.refit(std::move(boxes));
      if (tree.staleness() <= kRefitStaleness) return true;
      tree = BoxTree(tree.releaseBoxes());
      return false;
    }
    tree = BoxTree(std::move(boxes));
    return false;
  };
  bool refitted = fit(trees.triangles, elementBoxes(model.triangles, positions, within, nullptr));
  std::vector<ContactPair> pairs =
      pairsWithin(model, positions, within, model.contact.exclusion, &trees.triangles);
  if (model.contact.edgePairs) {
    refitted = fit(trees.bars, elementBoxes(model.bars, positions, within, nullptr)) && refitted;
    const std::vector<ContactPair> edges =
        edgePairsWithin(model, positions, within, model.contact.exclusion, &trees.bars);
    pairs.insert(pairs.end(), edges.begin(), edges.end());
  }
  list.refits += refitted;
  return pairs;
}

}  // namespace

bool refreshContactList(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                        ContactList& list) {
  if (!model.contact.enabled) {
    list.pairs.clear();
    return false;
  }
  const double skin = kSkinScale * model.contact.activation;
  list.skin = skin;
  bool stale = list.builtAt.size() != positions.size();
  if (!stale) {
    // The largest motion since the search, by chunks on all cores (a maximum: any order).
    constexpr std::size_t kGrain = 8192;
    const std::size_t n = positions.size(), chunks = (n + kGrain - 1) / kGrain;
    std::vector<double> largest(chunks, 0.0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t chunk = range.begin(); chunk != range.end(); ++chunk) {
                          double most = 0.0;
                          for (std::size_t v = chunk * kGrain;
                               v < std::min(n, (chunk + 1) * kGrain); ++v) {
                            const glm::dvec3 d = positions[v] - list.builtAt[v];
                            most = std::max(most, glm::dot(d, d));
                          }
                          largest[chunk] = most;
                        }
                      });
    list.moved = n > 0 ? std::sqrt(*std::max_element(largest.begin(), largest.end())) : 0.0;
    stale = list.moved > 0.5 * skin;
  }
  if (!stale) return false;
  list.pairs = searchContactList(model, positions, model.contact.activation + skin, list);
  list.builtAt = positions;
  list.moved = 0.0;
  ++list.rebuilds;
  return true;
}

const glm::dvec3* dynamicContactForces(const BarHingeModel& model, SimulationState& state) {
  if (!model.contact.enabled) return nullptr;
  ContactList& list = state.contactPairs;
  refreshContactList(model, state.positions, list);
  if (list.indexed != list.rebuilds)
    indexContactList(model, state.positions, list, state.contactForces);
  if (list.pairs.empty()) return nullptr;
  // A pair pushes only below thickness + activation; since the search its distance fell at most
  // by its vertices' motions (2 moved), so one found farther than that cannot (the margin far
  // above the distances' rounding).
  const ContactParameters& c = model.contact;
  const double reach = c.thickness + c.activation * (1.0 + 1e-6) + 2.0 * list.moved;
  const std::vector<glm::dvec3>& x = state.positions;
  // Calls keep(i, pushes, term) for the pairs [begin, end) in order, the vertex-triangle pairs
  // that can push computed in lane blocks (the last lane's pair repeated to fill a block).
  const auto evaluate = [&](std::size_t begin, std::size_t end, const auto& keep) {
    ContactTerm term;
    alignas(64) double out[7][kContactLanes];
    std::array<std::uint32_t, 4> vertices[kContactLanes];
    std::size_t lanePair[kContactLanes], filled = 0;
    const auto runLanes = [&] {
      triangleDistanceLanes(x.data(), vertices, filled, out);
      for (std::size_t k = 0; k < filled; ++k) {
        if (out[3][k] - c.thickness >= c.activation) {  // triangleTerm's test, before its loads
          keep(lanePair[k], false, term);
          continue;
        }
        const ContactPair& pair = list.pairs[lanePair[k]];
        const auto& tri = model.triangles[pair.triangle];
        const glm::dvec3 w(out[4][k], out[5][k], out[6][k]);
        const glm::dvec3 away(out[0][k], out[1][k], out[2][k]);
        keep(lanePair[k],
             triangleTerm(c, pair, tri, w, away, out[3][k], x[tri[0]], x[tri[1]], x[tri[2]], term,
                          true),
             term);
      }
      filled = 0;
    };
    for (std::size_t i = begin; i < end; ++i) {
      const ContactPair& pair = list.pairs[i];
      if (!(list.builtDistance[i] < reach)) {
        keep(i, false, term);  // adds nothing: the lanes' pairs may come after it
      } else if (pair.edges) {
        if (filled > 0) runLanes();  // the pair order
        keep(i, contactTerm(model, x, pair, term, true), term);
      } else {
        const auto& tri = model.triangles[pair.triangle];
        vertices[filled] = {pair.vertex, tri[0], tri[1], tri[2]};
        lanePair[filled++] = i;
        if (filled == kContactLanes) runLanes();
      }
    }
    if (filled > 0) runLanes();
  };
  const std::uint8_t* pinned = model.pinned.data();
  std::vector<glm::dvec3>& forces = state.contactForces;
  if (list.pairs.size() <= kPairGrain || tbb::this_task_arena::max_concurrency() == 1) {
    // One thread: each pair's force added as it is found, in pair order (no scratch to pass).
    for (std::uint32_t v : list.touched) forces[v] = glm::dvec3(0.0);
    evaluate(0, list.pairs.size(), [&](std::size_t, bool pushes, const ContactTerm& term) {
      if (!pushes) return;
      for (int k = 0; k < 4; ++k)
        if (!pinned[term.vertices[k]]) forces[term.vertices[k]] -= term.slope * term.gradient[k];
    });
    return forces.data();
  }
  // On all cores: each pair's forces; then the pushing pairs' slots (pair * 4 + corner) per
  // vertex, in pair order, by a counting sort over those pairs alone (at rest 4 to 30% of the
  // list push; each vertex read every listed slot of its own before); then each vertex sums its
  // run, on all cores.
  forEachRange(list.pairs.size(), kPairGrain, [&](std::size_t begin, std::size_t end) {
    evaluate(begin, end, [&](std::size_t i, bool pushes, const ContactTerm& term) {
      list.pushing[i] = pushes;
      if (pushes)
        for (int k = 0; k < 4; ++k) list.forces[i][k] = term.slope * term.gradient[k];
    });
  });
  const std::size_t n = x.size(), count = list.pairs.size();
  std::vector<std::uint32_t>& pushed = list.pushedPairs;
  pushed.clear();
  const std::uint8_t* pushing = list.pushing.data();
  std::size_t i = 0;
  for (; i + 8 <= count; i += 8) {  // eight flags at once: most are 0 at rest
    std::uint64_t eight;
    std::memcpy(&eight, pushing + i, sizeof eight);
    if (eight == 0) continue;
    for (std::size_t j = i; j < i + 8; ++j)
      if (pushing[j]) pushed.push_back(static_cast<std::uint32_t>(j));
  }
  for (; i < count; ++i)
    if (pushing[i]) pushed.push_back(static_cast<std::uint32_t>(i));
  std::vector<std::uint32_t>& offsets = list.pushOffsets;
  offsets.assign(n + 1, 0);
  for (std::uint32_t p : pushed)
    for (std::uint32_t v : contactPairVertices(model, list.pairs[p])) ++offsets[v + 1];
  for (std::size_t v = 0; v < n; ++v) offsets[v + 1] += offsets[v];
  list.pushSlots.resize(offsets[n]);
  list.pushNext.assign(offsets.begin(), offsets.end() - 1);
  for (std::uint32_t p : pushed) {
    const std::array<std::uint32_t, 4> v = contactPairVertices(model, list.pairs[p]);
    for (std::uint32_t k = 0; k < 4; ++k) list.pushSlots[list.pushNext[v[k]]++] = 4 * p + k;
  }
  forEachRange(list.touched.size(), kPairGrain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t j = begin; j < end; ++j) {
      const std::uint32_t v = list.touched[j];
      if (pinned[v]) continue;
      glm::dvec3 force(0.0);
      for (std::uint32_t k = offsets[v]; k < offsets[v + 1]; ++k) {
        const std::uint32_t slot = list.pushSlots[k];
        force -= list.forces[slot >> 2][slot & 3u];
      }
      forces[v] = force;
    }
  });
  return state.contactForces.data();
}

double smallestLayerDistance(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                             double thickness, double reach) {
  double smallest = reach;
  for (const ContactPair& pair : pairsWithin(model, positions, reach, 3.0 * thickness)) {
    const auto& tri = model.triangles[pair.triangle];
    smallest = std::min(smallest, distanceToTriangle(positions[pair.vertex], positions[tri[0]],
                                                     positions[tri[1]], positions[tri[2]]));
  }
  return smallest;
}

std::size_t crossingTrianglePairs(const BarHingeModel& model,
                                  const std::vector<glm::dvec3>& positions) {
  Sheet sheet;
  sheet.positions = positions;
  for (const glm::dvec3& p : model.flatPositions) sheet.development.emplace_back(p.x, p.y);
  for (const auto& t : model.triangles) sheet.triangles.push_back({t[0], t[1], t[2]});
  return findSelfIntersections(sheet).intersections.size();
}

}  // namespace curvefold
