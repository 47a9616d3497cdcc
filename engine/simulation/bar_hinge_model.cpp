#include "engine/simulation/bar_hinge_model.hpp"

#include "engine/simulation/dynamic_solver.hpp"
#include "engine/simulation/hinge_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtx/rotate_vector.hpp>

namespace curvefold {
namespace {

using hinge_kernel::angleWithGradient;

constexpr double kDegrees = 180.0 / std::numbers::pi;

std::string edgeName(std::uint32_t a, std::uint32_t b) {
  return "edge " + std::to_string(a) + "-" + std::to_string(b);
}

struct EdgeSides {
  std::uint32_t left = kNoTriangle, right = kNoTriangle;
  static constexpr std::uint32_t kNoTriangle = 0xffffffffu;
};

}  // namespace

double hingeAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                  const glm::dvec3& d, double previous) {
  return hinge_kernel::angle(a, b, c, d, previous);
}

std::array<glm::dvec3, 4> hingeAngleGradient(const glm::dvec3& a, const glm::dvec3& b,
                                             const glm::dvec3& c, const glm::dvec3& d) {
  std::array<glm::dvec3, 4> gradient;
  angleWithGradient(a, b, c, d, 0.0, gradient);
  return gradient;
}

double hingeAngleWithGradient(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                              const glm::dvec3& d, double previous,
                              std::array<glm::dvec3, 4>& gradient) {
  return angleWithGradient(a, b, c, d, previous, gradient);
}

namespace {

using EdgeKey = std::pair<std::uint32_t, std::uint32_t>;

// The pattern's vertices at z = 0, each checked finite.
std::vector<glm::dvec3> flatPositionsOf(const CreasePattern& pattern) {
  std::vector<glm::dvec3> positions;
  positions.reserve(pattern.vertices.size());
  for (const glm::dvec2& p : pattern.vertices) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw SimulationInputError("a vertex position is not a finite number");
    positions.emplace_back(p.x, p.y, 0.0);
  }
  return positions;
}

// Which triangle runs each edge a->b (left) and b->a (right), and each triangle's area; a
// triangle that names no vertex, is degenerate or clockwise, or an edge with more than two
// triangles is refused, and so is a pattern whose edge list leaves out an edge of its triangles.
std::map<EdgeKey, EdgeSides> triangleSides(const CreasePattern& pattern,
                                           std::vector<double>& area) {
  const std::size_t n = pattern.vertices.size();
  std::map<EdgeKey, EdgeSides> sides;
  area.assign(pattern.triangles.size(), 0.0);
  for (std::size_t t = 0; t < pattern.triangles.size(); ++t) {
    const auto& tri = pattern.triangles[t];
    for (std::uint32_t v : tri)
      if (v >= n)
        throw SimulationInputError("triangle " + std::to_string(t) + " names vertex " +
                                   std::to_string(v) + ", past the last");
    const glm::dvec2 e1 = pattern.vertices[tri[1]] - pattern.vertices[tri[0]];
    const glm::dvec2 e2 = pattern.vertices[tri[2]] - pattern.vertices[tri[0]];
    area[t] = 0.5 * (e1.x * e2.y - e1.y * e2.x);
    if (!(area[t] > 0.0))
      throw SimulationInputError("triangle " + std::to_string(t) + " is degenerate or clockwise");
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = tri[k], v = tri[(k + 1) % 3];
      EdgeSides& s = sides[{std::min(u, v), std::max(u, v)}];
      std::uint32_t& slot = u < v ? s.left : s.right;
      if (slot != EdgeSides::kNoTriangle)
        throw SimulationInputError(edgeName(std::min(u, v), std::max(u, v)) +
                                   " has more than two triangles or two of one orientation");
      slot = static_cast<std::uint32_t>(t);
    }
  }
  if (sides.size() != pattern.edges.size())
    throw SimulationInputError("the pattern lists " + std::to_string(pattern.edges.size()) +
                               " edges but its triangles have " + std::to_string(sides.size()));
  return sides;
}

// Lumped masses, mean 1, so the explicit step depends on stiffness and shape, not on units.
std::vector<double> lumpedMasses(const CreasePattern& pattern, const std::vector<double>& area) {
  const std::size_t n = pattern.vertices.size();
  std::vector<double> mass(n, 0.0);
  double totalArea = 0.0;
  for (std::size_t t = 0; t < pattern.triangles.size(); ++t) {
    for (std::uint32_t v : pattern.triangles[t]) mass[v] += area[t] / 3.0;
    totalArea += area[t];
  }
  for (double& m : mass) {
    m *= static_cast<double>(n) / totalArea;
    if (m == 0.0) m = 1.0;  // a vertex no triangle uses: it only drifts with glue
  }
  return mass;
}

// The paper's bending stiffness (plate theory), after checking its properties in paper mode.
double bendingStiffnessOf(const ModelOptions& options) {
  const PaperProperties& paper = options.paper;
  if (options.mode == SimulationMode::Paper &&
      !(paper.thickness > 0.0 && paper.youngsModulus > 0.0 && paper.poissonRatio > -1.0 &&
        paper.poissonRatio < 0.5 && paper.creaseLength > 0.0))
    throw SimulationInputError("paper thickness, modulus and crease length must be positive");
  return paper.youngsModulus * std::pow(paper.thickness, 3) /
         (12.0 * (1.0 - paper.poissonRatio * paper.poissonRatio));
}

// What the bars and hinges are built from, read once.
struct ElementInputs {
  const CreasePattern& pattern;
  const ModelOptions& options;
  const std::map<EdgeKey, EdgeSides>& sides;
  const std::vector<double>& area;
  double bendingStiffness = 0.0;
  bool paperMode() const { return options.mode == SimulationMode::Paper; }
};

// Edge e's bar (every edge has one); returns its stiffness.
double addBar(BarHingeModel& model, const ElementInputs& in, const EdgeKey& key,
              const EdgeSides& s) {
  const PaperProperties& paper = in.options.paper;
  const double length =
      glm::distance(model.flatPositions[key.first], model.flatPositions[key.second]);
  const double adjacentArea = (s.left != EdgeSides::kNoTriangle ? in.area[s.left] : 0.0) +
                              (s.right != EdgeSides::kNoTriangle ? in.area[s.right] : 0.0);
  model.bars.push_back({key.first, key.second});
  model.barLength.push_back(length);
  const double barK = in.paperMode() ? paper.youngsModulus * paper.thickness *
                                           (adjacentArea / 3.0) / (length * length)
                                     : in.options.axialStiffness / length;
  model.barStiffness.push_back(barK);
  return barK;
}

// Edge e's hinge, for an edge between two triangles.
void addHinge(BarHingeModel& model, const ElementInputs& in, std::size_t e, const EdgeKey& key,
              const EdgeSides& s) {
  const CreasePatternEdge& edge = in.pattern.edges[e];
  const PaperProperties& paper = in.options.paper;
  const bool paperMode = in.paperMode();
  const double length = model.barLength[e];
  const auto& left = in.pattern.triangles[s.left];
  const auto& right = in.pattern.triangles[s.right];
  auto opposite = [](const std::array<std::uint32_t, 3>& tri, std::uint32_t u, std::uint32_t v) {
    for (std::uint32_t w : tri)
      if (w != u && w != v) return w;
    return tri[0];
  };
  Hinge hinge{key.first, key.second, opposite(left, key.first, key.second),
              opposite(right, key.first, key.second)};
  const bool crease =
      edge.assignment == CreaseAssignment::Mountain || edge.assignment == CreaseAssignment::Valley;
  double targetDegrees = edge.foldAngleDegrees;
  double shapeDegrees = 0.0;
  if (crease && targetDegrees == 0.0)  // an M or V with no angle: folded flat, as FOLD says
    targetDegrees = edge.assignment == CreaseAssignment::Valley ? 180.0 : -180.0;
  // A sliver (a triangle lower than half its hinge edge) turns a lot for a small move of its
  // wing; its hinge is weakened in proportion, or its forces would swamp every other.
  const double sliver =
      std::min(1.0, 4.0 * std::min(in.area[s.left], in.area[s.right]) / (length * length));
  double stiffness = 0.0;
  // The stiffness a facet hinge of this edge would have: the one-sided term's unit.
  const double facetLike =
      (paperMode ? 6.0 * in.bendingStiffness : in.options.facetStiffness * length) * sliver;
  double wrongSide = 0.0;
  if (crease && targetDegrees != 0.0)
    wrongSide = (targetDegrees > 0.0 ? 1.0 : -1.0) * in.options.wrongSideScale * facetLike;
  if (crease) {
    stiffness = (paperMode ? in.bendingStiffness * length / paper.creaseLength
                           : in.options.creaseStiffness * length) *
                sliver;
  } else {
    if (paperMode) {
      shapeDegrees = targetDegrees;  // the design's bending, where glue must close a slit
      targetDegrees = 0.0;           // paper's rest state is flat
    }
    stiffness = facetLike;
  }
  model.hinges.push_back(hinge);
  model.hingeEdge.push_back(static_cast<std::uint32_t>(e));
  model.hingeTriangles.push_back({s.left, s.right});
  model.hingeTarget.push_back(targetDegrees / kDegrees);
  model.hingeShape.push_back(shapeDegrees / kDegrees);
  model.hingeCrease.push_back(crease ? 1 : 0);
  model.hingeDriven.push_back(crease || !paperMode ? 1 : 0);
  model.hingeStiffness.push_back(stiffness);
  model.hingeWrongSide.push_back(wrongSide);
  model.hingeBridge.push_back(0);
}

// A bar per edge, in the pattern's edge order, and a hinge per interior edge; returns the
// stiffest bar's stiffness.
double addBarsAndHinges(BarHingeModel& model, const ElementInputs& in) {
  model.bars.reserve(in.pattern.edges.size());
  double maxBar = 0.0;
  for (std::size_t e = 0; e < in.pattern.edges.size(); ++e) {
    const CreasePatternEdge& edge = in.pattern.edges[e];
    const EdgeKey key = std::make_pair(std::min(edge.a, edge.b), std::max(edge.a, edge.b));
    const auto found = in.sides.find(key);
    if (found == in.sides.end())
      throw SimulationInputError(edgeName(edge.a, edge.b) + " is on no triangle");
    if (!std::isfinite(edge.foldAngleDegrees))
      throw SimulationInputError(edgeName(edge.a, edge.b) + " has a fold angle that is not finite");
    const EdgeSides& s = found->second;
    maxBar = std::max(maxBar, addBar(model, in, key, s));
    if (s.left == EdgeSides::kNoTriangle || s.right == EdgeSides::kNoTriangle) continue;
    addHinge(model, in, e, key, s);
  }
  return maxBar;
}

// A wing lower than this share of its hinge's edge makes a sliver (reflection cuts leave them: a
// 1e-6 edge beside 1e-2 ones).
constexpr double kSliverHeight = 0.05;

// The triangle's vertex that is on neither end of the edge.
std::uint32_t oppositeVertex(const std::array<std::uint32_t, 3>& tri, std::uint32_t u,
                             std::uint32_t v) {
  for (std::uint32_t w : tri)
    if (w != u && w != v) return w;
  return tri[0];
}

// Bridges across slivers. A sliver's plane is ill-defined: a move of its low wing by its height
// (1e-6 of the sheet) turns it half a turn, so its hinges are weakened (addHinge) and the two
// good triangles on either side of it are left nearly free to turn about the line between them,
// and in 3D the sliver collapses and its hinges' angles jump, which stalls the solvers. Each
// chain of slivers between two good triangles T1 and Tk (entered across a long edge, left across
// its other long edge) gets one hinge from T1 straight to Tk, about the first crossed edge, with
// Tk's far vertex as its wing: its target is the angle T1 and Tk make when every crossed hinge is
// at its own target (the triangles turned about their flat edges in turn, so it is exact for
// targets the sheet can take), and its stiffness is that of an unweakened hinge of the edge.
// The crossed hinges, whose angles jump, are then left with no stiffness.
void addSliverBridges(BarHingeModel& model, const ElementInputs& in) {
  const std::size_t hingeCount = model.hinges.size();
  std::map<EdgeKey, std::uint32_t> hingeOf;
  for (std::size_t j = 0; j < hingeCount; ++j) {
    const Hinge& h = model.hinges[j];
    hingeOf[{std::min(h.a, h.b), std::max(h.a, h.b)}] = static_cast<std::uint32_t>(j);
  }
  const auto& flat = model.flatPositions;
  auto edgeLength = [&](std::size_t j) { return model.barLength[model.hingeEdge[j]]; };
  // The height of triangle t's wing over hinge j's edge, as a share of the edge.
  auto wingHeight = [&](std::size_t j, std::uint32_t t) {
    return 2.0 * in.area[t] / (edgeLength(j) * edgeLength(j));
  };
  std::set<std::pair<std::uint32_t, std::uint32_t>> bridged;
  std::vector<std::uint8_t> crossed(hingeCount, 0);
  std::vector<std::uint32_t> slivers;  // the triangles of every bridged chain
  for (std::size_t j = 0; j < hingeCount; ++j)
    for (int side = 0; side < 2; ++side) {
      const std::uint32_t first = model.hingeTriangles[j][side];
      std::uint32_t current = model.hingeTriangles[j][1 - side];
      if (wingHeight(j, first) < kSliverHeight || wingHeight(j, current) >= kSliverHeight) continue;
      std::vector<std::uint32_t> path{static_cast<std::uint32_t>(j)};
      std::vector<std::uint32_t> chain;
      std::uint32_t u = model.hinges[j].a, v = model.hinges[j].b, last = 0;
      bool reached = false;
      for (int step = 0; step < 8 && !reached; ++step) {
        chain.push_back(current);
        const std::uint32_t w = oppositeVertex(model.triangles[current], u, v);
        // Out across the longer of the sliver's other two edges.
        if (glm::distance(flat[u], flat[w]) > glm::distance(flat[v], flat[w]))
          v = w;
        else
          u = w;
        const auto found = hingeOf.find({std::min(u, v), std::max(u, v)});
        if (found == hingeOf.end()) break;  // a boundary: nothing to bridge to
        const std::uint32_t k = found->second;
        path.push_back(k);
        const auto& pair = model.hingeTriangles[k];
        const std::uint32_t next = pair[0] == current ? pair[1] : pair[0];
        if (wingHeight(k, next) >= kSliverHeight) {
          last = next;
          reached = true;
        }
        current = next;
      }
      if (!reached || !bridged.insert({std::min(first, last), std::max(first, last)}).second)
        continue;
      // The far wing, turned about each crossed edge (last first, all still flat) so the crossed
      // hinges sit at their targets; the sense of each turn is the one that gives its target.
      const Hinge& lastHinge = model.hinges[path.back()];
      const std::uint32_t farWing = oppositeVertex(model.triangles[last], lastHinge.a, lastHinge.b);
      glm::dvec3 wing = flat[farWing];
      double sum = 0.0;
      bool crease = false, driven = false;
      // The side of the creases crossed (+1 valley, -1 mountain; 0 for none, or both kinds).
      double creaseSide = 0.0;
      bool mixedSides = false;
      for (std::size_t i = path.size(); i-- > 0;) {
        const Hinge& h = model.hinges[path[i]];
        const double target = model.hingeTarget[path[i]];
        sum += target;
        if (model.hingeWrongSide[path[i]] != 0.0) {
          const double sideHere = model.hingeWrongSide[path[i]] > 0.0 ? 1.0 : -1.0;
          mixedSides = mixedSides || (creaseSide != 0.0 && creaseSide != sideHere);
          creaseSide = sideHere;
        }
        crease = crease || model.hingeCrease[path[i]];
        driven = driven || model.hingeDriven[path[i]];
        const glm::dvec3 axis = glm::normalize(flat[h.b] - flat[h.a]);
        const std::uint32_t nearTriangle =
            i == 0 ? first
                   : [&] {  // the triangle this hinge shares with the previous one on the path
                       const auto& mine = model.hingeTriangles[path[i]];
                       const auto& before = model.hingeTriangles[path[i - 1]];
                       return mine[0] == before[0] || mine[0] == before[1] ? mine[0] : mine[1];
                     }();
        const bool nearIsLeft = model.hingeTriangles[path[i]][0] == nearTriangle;
        const glm::dvec3 farVertex = flat[nearIsLeft ? h.d : h.c];
        double bestError = INFINITY, sense = 1.0;
        for (double candidate : {1.0, -1.0}) {
          const glm::dvec3 turned =
              flat[h.a] + glm::rotate(farVertex - flat[h.a], candidate * target, axis);
          const double angle = nearIsLeft
                                   ? hingeAngle(flat[h.a], flat[h.b], flat[h.c], turned, target)
                                   : hingeAngle(flat[h.a], flat[h.b], turned, flat[h.d], target);
          if (std::abs(angle - target) < bestError) {
            bestError = std::abs(angle - target);
            sense = candidate;
          }
        }
        wing = flat[h.a] + glm::rotate(wing - flat[h.a], sense * target, axis);
      }
      const Hinge& h = model.hinges[j];
      const bool firstIsLeft = side == 0;
      const Hinge bridge =
          firstIsLeft ? Hinge{h.a, h.b, h.c, farWing} : Hinge{h.a, h.b, farWing, h.d};
      const double target = firstIsLeft ? hingeAngle(flat[h.a], flat[h.b], flat[h.c], wing, sum)
                                        : hingeAngle(flat[h.a], flat[h.b], wing, flat[h.d], sum);
      const double length = edgeLength(j);
      const double base =
          crease
              ? (in.paperMode() ? in.bendingStiffness * length / in.options.paper.creaseLength
                                : in.options.creaseStiffness * length)
              : (in.paperMode() ? 6.0 * in.bendingStiffness : in.options.facetStiffness * length);
      const double weakest = std::min(wingHeight(j, first), wingHeight(path.back(), last));
      model.hinges.push_back(bridge);
      model.hingeEdge.push_back(model.hingeEdge[j]);
      model.hingeTriangles.push_back(firstIsLeft ? std::array<std::uint32_t, 2>{first, last}
                                                 : std::array<std::uint32_t, 2>{last, first});
      model.hingeTarget.push_back(target);
      model.hingeShape.push_back(0.0);
      model.hingeCrease.push_back(0);  // the crossed creases report their own angle errors
      model.hingeDriven.push_back(driven ? 1 : 0);
      model.hingeStiffness.push_back(base * std::min(1.0, 2.0 * weakest));
      // The crossed creases' one-sided term moves onto the bridge, which now holds their angle
      // (a square twist's valley crossed so was free to fold as a mountain). Not where the
      // bridge's own target passes flat-folded (two valleys of 180 degrees crossed: 360): the
      // term's bound at flat-folded would hold it half a turn short of its target at every
      // amount past half (langKnlDragon's two such bridges: NOT settled at 100%, energy 195 at
      // the last stage's start).
      const double facetLike =
          (in.paperMode() ? 6.0 * in.bendingStiffness : in.options.facetStiffness * length) *
          std::min(1.0, 2.0 * weakest);
      const bool pastFlatFolded = std::abs(target) > std::numbers::pi;
      model.hingeWrongSide.push_back(
          mixedSides || pastFlatFolded ? 0.0 : creaseSide * in.options.wrongSideScale * facetLike);
      model.hingeBridge.push_back(crease ? 2 : 1);
      for (std::uint32_t k : path) crossed[k] = 1;
      slivers.insert(slivers.end(), chain.begin(), chain.end());
    }
  // A crease on a sliver's short edge, off the path, turns it too: the sliver does not weaken its
  // hinge (it is high over so short an edge), yet its plane is as ill-defined, and driven (a
  // 0.26 mm crease of langCardinal.svg beside an 8 mm sliver) it collapsed the sliver in 3D to a
  // height of 1e-10 m, where its force and the crossed hinge's, 3e6 each through the 1 / height
  // lever, cancelled to a residual of 5 that no step could lower (NOT settled at 100%). Such a
  // crease is left to the bridge too, keeping its one-sided term as the crossed ones do. (Facets
  // there keep theirs: freed too, the designs' reflection slivers took up to twice the
  // iterations at 25-75%.)
  std::sort(slivers.begin(), slivers.end());
  // Short: the sliver stands at least 8 times its length over it (langCardinal's 30; a curved
  // pleat's ruling triangles, at 2 to 4, keep their creases driven: freed, one stayed 17.5
  // degrees off its angle with Origami Simulator's soft facets).
  constexpr double kShortEdge = 4.0;  // area over length squared: half the height over length
  for (std::size_t j = 0; j < hingeCount; ++j) {
    bool shortEdge = false;  // of a bridged sliver, which does not weaken its hinge (addHinge)
    for (std::uint32_t t : model.hingeTriangles[j])
      shortEdge = shortEdge || (std::binary_search(slivers.begin(), slivers.end(), t) &&
                                in.area[t] >= kShortEdge * edgeLength(j) * edgeLength(j));
    if (crossed[j] || (shortEdge && model.hingeCrease[j])) model.hingeStiffness[j] = 0.0;
  }
}

// The options' pins and glue, each vertex checked.
void addPinsAndGlue(BarHingeModel& model, const ModelOptions& options) {
  const std::size_t n = model.vertexCount();
  model.pinned.assign(n, 0);
  for (std::uint32_t v : options.pins) {
    if (v >= n)
      throw SimulationInputError("pin names vertex " + std::to_string(v) + ", past the last");
    model.pinned[v] = 1;
  }
  for (const auto& [i, j] : options.glue) {
    if (i >= n || j >= n || i == j)
      throw SimulationInputError("glue names vertices " + std::to_string(i) + " and " +
                                 std::to_string(j));
    model.glue.push_back({i, j});
  }
}

// The gather lists: each vertex's slots in slot order (counting sort).
void buildGatherLists(BarHingeModel& model) {
  const std::size_t n = model.vertexCount();
  model.hingeSlot0 = 2 * model.bars.size();
  model.glueSlot0 = model.hingeSlot0 + 4 * model.hinges.size();
  model.slotCount = model.glueSlot0 + 2 * model.glue.size();
  std::vector<std::uint32_t> slotVertex(model.slotCount);
  for (std::size_t i = 0; i < model.bars.size(); ++i) {
    slotVertex[2 * i] = model.bars[i][0];
    slotVertex[2 * i + 1] = model.bars[i][1];
  }
  for (std::size_t j = 0; j < model.hinges.size(); ++j) {
    const Hinge& h = model.hinges[j];
    const std::size_t s = model.hingeSlot0 + 4 * j;
    slotVertex[s] = h.a;
    slotVertex[s + 1] = h.b;
    slotVertex[s + 2] = h.c;
    slotVertex[s + 3] = h.d;
  }
  for (std::size_t g = 0; g < model.glue.size(); ++g) {
    slotVertex[model.glueSlot0 + 2 * g] = model.glue[g][0];
    slotVertex[model.glueSlot0 + 2 * g + 1] = model.glue[g][1];
  }
  model.gatherOffsets.assign(n + 1, 0);
  for (std::uint32_t v : slotVertex) ++model.gatherOffsets[v + 1];
  for (std::size_t v = 0; v < n; ++v) model.gatherOffsets[v + 1] += model.gatherOffsets[v];
  model.gatherSlots.resize(model.slotCount);
  std::vector<std::uint32_t> fill(model.gatherOffsets.begin(), model.gatherOffsets.end() - 1);
  for (std::size_t s = 0; s < model.slotCount; ++s)
    model.gatherSlots[fill[slotVertex[s]]++] = static_cast<std::uint32_t>(s);
  if (model.slotCount > 0xffffffffu)
    throw SimulationInputError("the pattern has more elements than the simulation can index");
  model.scatterSlots.resize(model.slotCount);
  for (std::size_t k = 0; k < model.slotCount; ++k)
    model.scatterSlots[model.gatherSlots[k]] = static_cast<std::uint32_t>(k);
  model.gatherBarEnd.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    std::uint32_t k = model.gatherOffsets[v];
    while (k < model.gatherOffsets[v + 1] && model.gatherSlots[k] < model.hingeSlot0) ++k;
    model.gatherBarEnd[v] = k;
  }
}

}  // namespace

ModelOptions simulatorModelOptions() {
  ModelOptions options;
  options.axialStiffness = 20.0;
  options.creaseStiffness = 0.7;
  options.facetStiffness = 0.7;
  return options;
}

void setPaperMode(ModelOptions& options, double thicknessMm, double modulusGpa, bool contact) {
  if (!(thicknessMm > 0.0 && thicknessMm <= 10.0))
    throw std::invalid_argument("paper: the thickness must be above 0 and at most 10 mm");
  if (!(modulusGpa > 0.0 && modulusGpa <= 1000.0))
    throw std::invalid_argument("modulus: must be above 0 and at most 1000 GPa");
  options.mode = SimulationMode::Paper;
  options.paper.thickness = thicknessMm * 1e-3;
  options.paper.youngsModulus = modulusGpa * 1e9;
  options.contact.enabled = contact;
  // Edges against edges too: layers of a flat fold then stop passing through each other
  // (contact20: 47 of 126 paper runs crossed, 3 with them), glued sheets included since edges
  // near on the flat sheet are no pairs (contact21: the glued cone 5.5% -> 0.9% strain).
  options.contact.edgePairs = true;
  options.contact.edgePairsWhereGlued = true;
}

BarHingeModel buildModel(const CreasePattern& pattern, const ModelOptions& options) {
  BarHingeModel model;
  model.mode = options.mode;
  model.flatPositions = flatPositionsOf(pattern);
  model.triangles = pattern.triangles;
  std::vector<double> area;
  const std::map<EdgeKey, EdgeSides> sides = triangleSides(pattern, area);
  model.mass = lumpedMasses(pattern, area);
  const ElementInputs inputs{pattern, options, sides, area, bendingStiffnessOf(options)};
  const double maxBar = addBarsAndHinges(model, inputs);
  addSliverBridges(model, inputs);
  addPinsAndGlue(model, options);
  // Glue as stiff as the stiffest bar: seams close to within bar strain.
  model.glueStiffness = maxBar;
  buildGatherLists(model);
  model.barDamping.resize(model.bars.size());
  for (std::size_t i = 0; i < model.bars.size(); ++i)
    model.barDamping[i] =
        2.0 * std::sqrt(model.barStiffness[i] *
                        std::min(model.mass[model.bars[i][0]], model.mass[model.bars[i][1]]));
  model.contact = contactParameters(model, options.contact, options.paper.thickness);
  model.timeStep = stableTimeStep(model);
  double lightest = INFINITY;
  for (double m : model.mass) lightest = std::min(lightest, m);
  setDynamicContactStep(model.contact, 0.375 * lightest / (model.timeStep * model.timeStep));
  return model;
}

std::vector<double> hingeAngles(const BarHingeModel& model,
                                const std::vector<glm::dvec3>& positions,
                                const std::vector<double>& previous) {
  std::vector<double> angles(model.hinges.size());
  for (std::size_t j = 0; j < model.hinges.size(); ++j) {
    const Hinge& h = model.hinges[j];
    angles[j] = hingeAngle(positions[h.a], positions[h.b], positions[h.c], positions[h.d],
                           previous.empty() ? 0.0 : previous[j]);
  }
  return angles;
}

double BarHingeModel::motionTarget(std::size_t hinge, double foldAmount) const {
  const std::size_t rows = motionAmounts.size(), width = hinges.size();
  if (foldAmount <= motionAmounts.front()) return motionTargets[hinge];
  if (foldAmount >= motionAmounts.back()) return motionTargets[(rows - 1) * width + hinge];
  const std::size_t upper = static_cast<std::size_t>(
      std::upper_bound(motionAmounts.begin(), motionAmounts.end(), foldAmount) -
      motionAmounts.begin());
  const double from = motionAmounts[upper - 1], to = motionAmounts[upper];
  const double t = (foldAmount - from) / (to - from);
  const double a = motionTargets[(upper - 1) * width + hinge],
               b = motionTargets[upper * width + hinge];
  return a + (b - a) * t;
}

std::vector<double> hingeTargets(const BarHingeModel& model, double foldAmount) {
  std::vector<double> targets(model.hinges.size());
  for (std::size_t j = 0; j < targets.size(); ++j) targets[j] = model.target(j, foldAmount);
  return targets;
}

double modelEnergy(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                   const std::vector<double>& targets, const std::vector<double>& previous) {
  double energy = 0.0;
  for (std::size_t i = 0; i < model.bars.size(); ++i) {
    const double stretch = glm::distance(positions[model.bars[i][0]], positions[model.bars[i][1]]) -
                           model.barLength[i];
    energy += 0.5 * model.barStiffness[i] * stretch * stretch;
  }
  for (std::size_t j = 0; j < model.hinges.size(); ++j) {
    const Hinge& h = model.hinges[j];
    const double angle = hingeAngle(positions[h.a], positions[h.b], positions[h.c], positions[h.d],
                                    previous.empty() ? 0.0 : previous[j]);
    energy += hinge_kernel::hingeEnergy(angle, targets[j], model.hingeStiffness[j],
                                        model.hingeWrongSide[j]);
  }
  for (const auto& [i, k] : model.glue) {
    const glm::dvec3 gap = positions[i] - positions[k];
    energy += 0.5 * model.glueStiffness * glm::dot(gap, gap);
  }
  return energy + contactEnergy(model, positions);
}

namespace {

// The change of a hinge's angle between two placements of its vertices (p and p + dp), from the
// moves: the kernel's angle is atan2(y, x) with y = |e| (n1 . w), x = n1 . n2 (hinge_kernel.hpp),
// and the change is atan2(y' x - x' y, x x' + y y'), whose y' x - x' y = dy x - dx y is formed
// from dx and dy expanded in the moves, never from y' and x' (which would lose it in rounding).
double hingeAngleChange(const std::array<glm::dvec3, 4>& p, const std::array<glm::dvec3, 4>& dp) {
  const glm::dvec3 e = p[1] - p[0], u = p[2] - p[0], w = p[3] - p[0];
  const glm::dvec3 de = dp[1] - dp[0], du = dp[2] - dp[0], dw = dp[3] - dp[0];
  const glm::dvec3 e2 = e + de, u2 = u + du, w2 = w + dw;
  const glm::dvec3 n1 = glm::cross(e, u), n2 = glm::cross(w, e);
  const glm::dvec3 dn1 = glm::cross(e, du) + glm::cross(de, u2);  // e' x u' - e x u
  const glm::dvec3 dn2 = glm::cross(w, de) + glm::cross(dw, e2);  // w' x e' - w x e
  const glm::dvec3 n1b = n1 + dn1, n2b = n2 + dn2;
  const double ee = glm::dot(e, e), ee2 = glm::dot(e2, e2);
  if (glm::dot(n1, n1) == 0.0 || glm::dot(n2, n2) == 0.0 || ee == 0.0 ||
      glm::dot(n1b, n1b) == 0.0 || glm::dot(n2b, n2b) == 0.0 || ee2 == 0.0)
    return 0.0;  // a degenerate triangle keeps its previous angle (hinge_kernel.hpp)
  const double length = std::sqrt(ee), length2 = std::sqrt(ee2);
  const double dLength = glm::dot(de, e + e2) / (length + length2);
  const double x = glm::dot(n1, n2), y = length * glm::dot(n1, w);
  const double dx = glm::dot(dn1, n2) + glm::dot(n1b, dn2);
  const double dy = dLength * glm::dot(n1b, w2) + length * (glm::dot(dn1, w2) + glm::dot(n1, dw));
  return std::atan2(dy * x - dx * y, x * (x + dx) + y * (y + dy));
}

}  // namespace

double modelEnergyChange(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                         const std::vector<glm::dvec3>& moved, const std::vector<double>& targets,
                         const std::vector<double>& angles) {
  double change = 0.0;
  for (std::size_t i = 0; i < model.bars.size(); ++i) {
    const auto [a, b] = model.bars[i];
    const glm::dvec3 d = positions[b] - positions[a];
    const glm::dvec3 dd = (moved[b] - positions[b]) - (moved[a] - positions[a]);
    const double length = glm::length(d), length2 = glm::length(d + dd);
    if (length + length2 == 0.0) continue;
    // (l' - L)^2 - (l - L)^2 = dl (2 (l - L) + dl), dl = l' - l from the move
    const double dl = glm::dot(dd, 2.0 * d + dd) / (length + length2);
    change += 0.5 * model.barStiffness[i] * dl * (2.0 * (length - model.barLength[i]) + dl);
  }
  for (std::size_t j = 0; j < model.hinges.size(); ++j) {
    const Hinge& h = model.hinges[j];
    const std::array<glm::dvec3, 4> p{positions[h.a], positions[h.b], positions[h.c],
                                      positions[h.d]};
    const std::array<glm::dvec3, 4> dp{moved[h.a] - p[0], moved[h.b] - p[1], moved[h.c] - p[2],
                                       moved[h.d] - p[3]};
    const double dTheta = hingeAngleChange(p, dp);
    change += 0.5 * model.hingeStiffness[j] * dTheta * (2.0 * (angles[j] - targets[j]) + dTheta);
    const double wrongSide = model.hingeWrongSide[j];
    if (wrongSide != 0.0) {
      // The one-sided term's change: the expanded form within one piece (past flat, or past
      // flat-folded), else the difference of its values.
      const double before = hinge_kernel::wrongSideExcess(angles[j], wrongSide);
      const double after = hinge_kernel::wrongSideExcess(angles[j] + dTheta, wrongSide);
      const double side = wrongSide > 0.0 ? 1.0 : -1.0;
      const double dq = side * dTheta;
      const bool samePiece = (before < 0.0 && after < 0.0) || (before > 0.0 && after > 0.0);
      change += 0.5 * std::abs(wrongSide) *
                (samePiece ? dq * (2.0 * before + dq) : after * after - before * before);
    }
  }
  for (const auto& pair : model.glue) {
    const glm::dvec3 gap = positions[pair[0]] - positions[pair[1]];
    const glm::dvec3 dGap =
        (moved[pair[0]] - positions[pair[0]]) - (moved[pair[1]] - positions[pair[1]]);
    change += 0.5 * model.glueStiffness * glm::dot(dGap, 2.0 * gap + dGap);
  }
  if (model.contact.enabled) change += contactEnergyChange(model, positions, moved);
  return change;
}

void elementForces(const BarHingeModel& model, const std::vector<glm::dvec3>& positions,
                   const std::vector<double>& targets, const std::vector<double>& previous,
                   std::vector<double>& angles, std::vector<glm::dvec3>& slotForces,
                   const glm::dvec3* velocities, double dampingRatio) {
  slotForces.resize(model.slotCount);
  angles.resize(model.hinges.size());
  const glm::dvec3* x = positions.data();
  glm::dvec3* forces = slotForces.data();
  const std::size_t barCount = model.bars.size(), hingeCount = model.hinges.size();
  const double* previousAngles = previous.empty() ? nullptr : previous.data();
  double* angleOut = angles.data();
  // One pass over bars, then hinges, then glue: one barrier per call instead of three.
  auto element = [&](std::size_t e) {
    if (e < barCount) {
      const std::size_t i = e;
      const std::uint32_t a = model.bars[i][0], b = model.bars[i][1];
      const glm::dvec3 force = hinge_kernel::barForce(  // on a; b gets the opposite
          x[b] - x[a], velocities ? velocities[b] - velocities[a] : glm::dvec3(0.0),
          model.barStiffness[i], model.barLength[i],
          velocities ? dampingRatio * model.barDamping[i] : 0.0);
      forces[2 * i] = force;
      forces[2 * i + 1] = -force;
    } else if (e < barCount + hingeCount) {
      const std::size_t j = e - barCount;
      const Hinge& h = model.hinges[j];
      std::array<glm::dvec3, 4> gradient;
      const double angle = angleWithGradient(x[h.a], x[h.b], x[h.c], x[h.d],
                                             previousAngles ? previousAngles[j] : 0.0, gradient);
      angleOut[j] = angle;
      const double torque = -hinge_kernel::hingeMoment(angle, targets[j], model.hingeStiffness[j],
                                                       model.hingeWrongSide[j]);
      glm::dvec3* slot = forces + model.hingeSlot0 + 4 * j;
      for (int k = 0; k < 4; ++k) slot[k] = torque * gradient[k];
    } else {
      const std::size_t g = e - barCount - hingeCount;
      const std::uint32_t a = model.glue[g][0], b = model.glue[g][1];
      const glm::dvec3 force = model.glueStiffness * (x[b] - x[a]);
      forces[model.glueSlot0 + 2 * g] = force;
      forces[model.glueSlot0 + 2 * g + 1] = -force;
    }
  };
  forEachIndex(barCount + hingeCount + model.glue.size(), element);
}

void gatherForces(const BarHingeModel& model, const std::vector<glm::dvec3>& slotForces,
                  std::vector<glm::dvec3>& vertexForces) {
  vertexForces.resize(model.vertexCount());
  forEachIndex(model.vertexCount(), [&](std::size_t v) {
    glm::dvec3 total(0.0);
    if (!model.pinned[v])
      for (std::uint32_t s = model.gatherOffsets[v]; s < model.gatherOffsets[v + 1]; ++s)
        total += slotForces[model.gatherSlots[s]];
    vertexForces[v] = total;
  });
}

SimulationState flatState(const BarHingeModel& model) {
  SimulationState state;
  state.positions = model.flatPositions;
  state.velocities.assign(model.vertexCount(), glm::dvec3(0.0));
  state.hingeAngles = hingeAngles(model, state.positions);
  return state;
}

std::vector<double> edgeStrain(const BarHingeModel& model,
                               const std::vector<glm::dvec3>& positions) {
  std::vector<double> strain(model.bars.size());
  for (std::size_t i = 0; i < model.bars.size(); ++i)
    strain[i] = glm::distance(positions[model.bars[i][0]], positions[model.bars[i][1]]) /
                    model.barLength[i] -
                1.0;
  return strain;
}

std::vector<double> creaseAngleError(const BarHingeModel& model,
                                     const std::vector<glm::dvec3>& positions, double foldAmount,
                                     const std::vector<double>& previous) {
  std::vector<double> error(model.bars.size(), 0.0);
  const std::vector<double> angles = hingeAngles(model, positions, previous);
  for (std::size_t j = 0; j < model.hinges.size(); ++j)
    if (model.hingeCrease[j])
      error[model.hingeEdge[j]] = (angles[j] - model.target(j, foldAmount)) * kDegrees;
  return error;
}

}  // namespace curvefold
