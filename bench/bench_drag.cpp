// Drag update (fixed sheet + target -> temporal sheet) against a plain copy of the mesh arrays,
// on cylinders of about 10k, 100k and 1M triangles with 5 prior folds (docs/design.md 8); and the
// planar simplification that the display session makes after an undo, redo or open, on the
// folded cylinders and on a flat square of about 100k triangles (an unstructured mesh).
//
//   build/bench/bench_drag --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <map>

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/planar_simplification.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {
namespace {

// Cylinder resolutions for ~10k / ~100k / ~1M triangles (see surfaces.hpp).
int resolutionFor(long triangles) {
  switch (triangles) {
    case 10'000:
      return 82;
    case 100'000:
      return 259;
    default:
      return 820;
  }
}

// A cylinder (axis y, radius 0.045, height 0.21) with five committed folds: corners and edges
// pushed in and bent over, the kind of start a designer has after a minute.
struct FoldedCylinder {
  explicit FoldedCylinder(long triangles)
      : session(makeSurface("cylinder", {{"resolution", resolutionFor(triangles)}})) {
    const double top = 0.105, r = 0.045;
    const std::vector<std::pair<glm::dvec3, glm::dvec3>> folds = {
        {{0.0, top, r}, {0.0, top - 0.04, 0.0}},        // front top pushed in
        {{r, -top, 0.0}, {0.01, -top + 0.03, 0.0}},     // side bottom pushed in
        {{-r, top, 0.0}, {-0.01, top - 0.05, 0.0}},     // other side top
        {{0.0, -top, -r}, {0.0, -top + 0.03, -0.005}},  // back bottom
        {{0.0, 0.0, r}, {0.0, 0.01, 0.03}},             // dent in the middle
    };
    for (const auto& [grab, target] : folds) {
      session.beginDragNear(grab);
      session.updateDrag(target);
      session.commit();
    }
  }
  FoldSession session;
};

FoldedCylinder& cylinder(long triangles) {
  static std::map<long, std::unique_ptr<FoldedCylinder>> cache;
  auto& slot = cache[triangles];
  if (!slot) slot = std::make_unique<FoldedCylinder>(triangles);
  return *slot;
}

void BM_DragUpdate(benchmark::State& state) {
  FoldSession& session = cylinder(state.range(0)).session;
  // Grab the middle of the top rim and swing it down: about a third of the sheet is reflected.
  const glm::dvec3 grabbed = session.beginDragNear({0.03, 0.105, 0.03});
  const glm::dvec3 targets[2] = {grabbed + glm::dvec3{0.0, -0.07, 0.01},
                                 grabbed + glm::dvec3{0.001, -0.071, 0.012}};
  std::size_t moved = 0, iteration = 0;
  for (auto _ : state) {
    const ReflectionChanges& changes = session.updateDrag(targets[iteration++ & 1]);
    moved = changes.movedVertices.size();
    benchmark::DoNotOptimize(session.current().positions.data());
  }
  // Memory while dragging, in sheets (the arrays of one temporal sheet).
  const SessionMemory memory = session.memoryUse();
  const double sheet = static_cast<double>(sheetBytes(session.current()));
  state.counters["pair_in_sheets"] = (memory.fixed + memory.temporal) / sheet;
  state.counters["all_in_sheets"] =
      (memory.fixed + memory.temporal + memory.adjacency + memory.workspace) / sheet;
  session.cancel();
  state.counters["triangles"] = static_cast<double>(session.fixed().triangleCount());
  state.counters["moved_vertices"] = static_cast<double>(moved);
}

// Issue 17: the same drag with the live self-intersection test after each update (the
// reflected part against a tree of the sheet built at the grab), and the tree's build at the grab.
// Drags the point nearest `grabNear` back and forth between two targets `offset` (and a
// millimetre more) from it, with the live test after each update (arg 1 = 1) or without it but
// with the reflected triangles listed, which a renderer asks for anyway (arg 1 = 0): the
// difference is the watch's cost.
void watchedDrag(benchmark::State& state, FoldSession& session, const glm::dvec3& grabNear,
                 const glm::dvec3& offset) {
  const glm::dvec3 grabbed = session.beginDragNear(grabNear);
  DragIntersectionWatch watch;
  watch.begin(session.fixed());
  const glm::dvec3 targets[2] = {grabbed + offset, grabbed + offset + glm::dvec3(0.001)};
  std::size_t iteration = 0;
  const bool watching = state.range(1) == 1;
  for (auto _ : state) {
    session.updateDrag(targets[iteration++ & 1]);
    const std::vector<TriangleIndex>& reflected = session.reflectedTriangles();
    if (watching)
      watch.update(session.current(), session.lastChanges(), session.plane(), reflected);
    benchmark::DoNotOptimize(watch.pairCount());
  }
  state.counters["pairs"] = static_cast<double>(watch.pairCount());
  state.counters["node_pairs"] = static_cast<double>(watch.nodePairsVisited());
  state.counters["tested"] = static_cast<double>(watch.trianglePairsTested());
  state.counters["reflected"] = static_cast<double>(session.reflectedTriangles().size());
  session.cancel();
}

// The drag benchmark's drag: the top rim swung down, through the sheet.
void BM_DragUpdateWithIntersectionWatch(benchmark::State& state) {
  watchedDrag(state, cylinder(state.range(0)).session, {0.03, 0.105, 0.03}, {0.0, -0.07, 0.01});
}

// The same where nothing passes through (a tube's mirrored part generally crosses the tube again,
// along the second plane that bisects the two axes): a flat square of about 100k triangles, half
// of it lifted about a straight crease.
void BM_DragUpdateWithIntersectionWatchCleanSheet(benchmark::State& state) {
  FoldSession session(makeSurface("square", {{"resolution", 224}}));
  watchedDrag(state, session, {0.1, 0.0, 0.0}, {-0.04, 0.0, 0.04});
}

void BM_IntersectionWatchBegin(benchmark::State& state) {
  FoldSession& session = cylinder(state.range(0)).session;
  session.beginDragNear({0.03, 0.105, 0.03});
  for (auto _ : state) {
    DragIntersectionWatch watch;
    watch.begin(session.fixed());
    benchmark::DoNotOptimize(&watch);
  }
  session.cancel();
}

// The whole sheet checked (`curvefold check`), and CGAL's does_self_intersect on the same mesh
// (exact predicates, no contact tolerance) for the ratio.
void BM_SelfIntersectionCheck(benchmark::State& state) {
  const Sheet& sheet = cylinder(state.range(0)).session.fixed();
  std::size_t pairs = 0, contacts = 0;
  for (auto _ : state) {
    const SelfIntersectionReport report = findSelfIntersections(sheet);
    pairs = report.intersections.size();
    contacts = report.contacts.size();
  }
  state.counters["triangles"] = static_cast<double>(sheet.triangleCount());
  state.counters["pairs"] = static_cast<double>(pairs);
  state.counters["contacts"] = static_cast<double>(contacts);
}

void BM_CgalDoesSelfIntersect(benchmark::State& state) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  const Sheet& sheet = cylinder(state.range(0)).session.fixed();
  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertices;
  for (const glm::dvec3& p : sheet.positions) vertices.push_back(mesh.add_vertex({p.x, p.y, p.z}));
  for (const Triangle& t : sheet.triangles)
    mesh.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]]);
  // Arg 1 = 0: does_self_intersect (stops at the first pair); 1: self_intersections (every pair,
  // the work `check` does).
  bool intersects = false;
  std::size_t pairs = 0;
  for (auto _ : state) {
    if (state.range(1) == 0) {
      intersects = CGAL::Polygon_mesh_processing::does_self_intersect(mesh);
    } else {
      std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> found;
      CGAL::Polygon_mesh_processing::self_intersections(mesh, std::back_inserter(found));
      pairs = found.size();
      intersects = pairs > 0;
    }
  }
  state.counters["intersects"] = intersects ? 1.0 : 0.0;
  state.counters["pairs"] = static_cast<double>(pairs);
}

void BM_CopyMeshArrays(benchmark::State& state) {
  const Sheet& fixed = cylinder(state.range(0)).session.fixed();
  Sheet copy;
  for (auto _ : state) {
    copy.positions = fixed.positions;
    copy.development = fixed.development;
    copy.triangles = fixed.triangles;
    benchmark::DoNotOptimize(copy.positions.data());
    benchmark::ClobberMemory();
  }
  state.counters["triangles"] = static_cast<double>(fixed.triangleCount());
}

void BM_SimplifyPlanar(benchmark::State& state) {
  const Sheet& fixed = cylinder(state.range(0)).session.fixed();
  std::size_t drawn = 0;
  for (auto _ : state) drawn = simplifyPlanar(fixed).sheet.triangleCount();
  state.counters["triangles"] = double(fixed.triangleCount());
  state.counters["simplified"] = double(drawn);
}

void BM_SimplifyPlanarFlatSquare(benchmark::State& state) {
  const Sheet square = makeSurface("square", {{"resolution", 150}});
  std::size_t drawn = 0;
  for (auto _ : state) drawn = simplifyPlanar(square).sheet.triangleCount();
  state.counters["triangles"] = double(square.triangleCount());
  state.counters["simplified"] = double(drawn);
}

BENCHMARK(BM_SimplifyPlanar)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SimplifyPlanarFlatSquare)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DragUpdate)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DragUpdateWithIntersectionWatch)
    ->ArgsProduct({{10'000, 100'000}, {0, 1}})
    ->ArgNames({"triangles", "watch"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DragUpdateWithIntersectionWatchCleanSheet)
    ->ArgsProduct({{100'000}, {0, 1}})  // the first argument names the size only
    ->ArgNames({"triangles", "watch"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IntersectionWatchBegin)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SelfIntersectionCheck)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK(BM_CgalDoesSelfIntersect)
    ->ArgsProduct({{100'000, 1'000'000}, {0, 1}})
    ->ArgNames({"triangles", "all_pairs"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK(BM_CopyMeshArrays)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace curvefold

BENCHMARK_MAIN();
