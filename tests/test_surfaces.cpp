#include "engine/surfaces/surfaces.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/geometry/topology.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/surfaces/surface_builders.hpp"

namespace curvefold {
namespace {

using std::numbers::pi;

double area3(const Sheet& s) {
  double total = 0.0;
  for (const Triangle& t : s.triangles)
    total += 0.5 * glm::length(glm::cross(s.positions[t[1]] - s.positions[t[0]],
                                          s.positions[t[2]] - s.positions[t[0]]));
  return total;
}

double area2(const Sheet& s) {
  double total = 0.0;
  for (const Triangle& t : s.triangles) {
    const glm::dvec2 u = s.development[t[1]] - s.development[t[0]];
    const glm::dvec2 v = s.development[t[2]] - s.development[t[0]];
    total += 0.5 * (u.x * v.y - u.y * v.x);
  }
  return total;
}

glm::dvec3 frontNormal(const Sheet& s, const Triangle& t) {
  return glm::normalize(
      glm::cross(s.positions[t[1]] - s.positions[t[0]], s.positions[t[2]] - s.positions[t[0]]));
}

// The triangle whose centroid is highest in z: the middle of a curved sheet.
Triangle topTriangle(const Sheet& s) {
  Triangle best = s.triangles.front();
  double bestZ = -std::numeric_limits<double>::infinity();
  for (const Triangle& t : s.triangles) {
    const double z = s.positions[t[0]].z + s.positions[t[1]].z + s.positions[t[2]].z;
    if (z > bestZ) {
      bestZ = z;
      best = t;
    }
  }
  return best;
}

struct Expectation {
  long euler;
  std::size_t loops;
};

// Every invariant a generated sheet must meet: valid, exact development, expected topology.
void expectGoodSheet(const Sheet& sheet, Expectation expected, const std::string& label) {
  SCOPED_TRACE(label);
  ASSERT_NO_THROW(validate(sheet)) << label;
  const SheetReport report = measure(sheet);
  EXPECT_EQ(report.firstProblem, "");
  EXPECT_EQ(report.eulerCharacteristic, expected.euler);
  EXPECT_EQ(report.boundaryLoopCount, expected.loops);
  EXPECT_EQ(report.componentCount, 1u);
  EXPECT_LT(report.maxEdgeLengthError, 1e-12 * report.size);
  EXPECT_NEAR(area2(sheet), area3(sheet), 1e-12 * area3(sheet));
  EXPECT_GT(report.size, 0.05);  // paper-sized
  EXPECT_LT(report.size, 1.0);
  // Slit edges lie on the boundary in pairs over the same 3D points.
  const EdgeTopology edges = buildEdgeTopology(sheet);
  std::multiset<std::pair<std::array<double, 3>, std::array<double, 3>>> seams;
  for (const TaggedEdge& tag : sheet.tags) {
    if (tag.kind != EdgeKind::Slit) continue;
    EXPECT_TRUE(edges.edges[edges.find(tag.edge)].isBoundary());
    glm::dvec3 a = sheet.positions[tag.edge.a], b = sheet.positions[tag.edge.b];
    std::array<double, 3> pa{a.x, a.y, a.z}, pb{b.x, b.y, b.z};
    if (pb < pa) std::swap(pa, pb);
    seams.insert({pa, pb});
  }
  for (const auto& seam : seams) EXPECT_EQ(seams.count(seam) % 2, 0u);
}

Expectation expectationFor(const std::string& name, const SurfaceParameters& params) {
  auto hole = params.find("hole_radius");
  if (hole != params.end() && hole->second > 0.0) return {0, 2};
  (void)name;
  return {1, 1};  // every surface is a disk; tubes and cones are cut open by their slit
}

TEST(SurfaceCatalog, NamesParametersAndDefaultsAreConsistent) {
  const auto& catalog = surfaceCatalog();
  std::set<std::string> names;
  for (const SurfaceInfo& info : catalog) {
    EXPECT_TRUE(names.insert(info.name).second) << info.name;
    EXPECT_FALSE(info.description.empty()) << info.name;
    bool hasResolution = false;
    for (const SurfaceParameter& p : info.parameters) {
      EXPECT_LE(p.min, p.defaultValue) << info.name << "." << p.name;
      EXPECT_LE(p.defaultValue, p.max) << info.name << "." << p.name;
      EXPECT_FALSE(p.description.empty()) << info.name << "." << p.name;
      hasResolution |= p.name == "resolution" && p.integer;
    }
    EXPECT_TRUE(hasResolution) << info.name;
  }
  for (const char* name : {"square", "rectangle", "disk", "star", "cylinder", "half_cylinder",
                           "cone", "swept_curve", "helix_tangent"})
    EXPECT_TRUE(names.count(name)) << name;
}

TEST(Surfaces, EveryCatalogSurfaceIsValidAtSeveralResolutions) {
  for (const SurfaceInfo& info : surfaceCatalog()) {
    const Sheet byDefault = makeSurface(info.name);
    expectGoodSheet(byDefault, expectationFor(info.name, {}), info.name + " default");
    EXPECT_GE(byDefault.triangleCount(), 1000u) << info.name;
    EXPECT_LE(byDefault.triangleCount(), 10000u) << info.name;
    for (double resolution : {16.0, 90.0}) {
      const Sheet sheet = makeSurface(info.name, {{"resolution", resolution}});
      expectGoodSheet(sheet, expectationFor(info.name, {}),
                      info.name + " resolution " + std::to_string(resolution));
    }
  }
}

TEST(Surfaces, FlatSurfacesWithHolesHaveTwoBoundaryLoops) {
  for (const char* name : {"square", "rectangle", "disk", "star"}) {
    const SurfaceParameters params{{"hole_radius", 0.02}};
    const Sheet sheet = makeSurface(name, params);
    expectGoodSheet(sheet, expectationFor(name, params), name);
    for (const glm::dvec3& p : sheet.positions) {
      EXPECT_EQ(p.z, 0.0);
      EXPECT_GT(glm::length(glm::dvec2(p)), 0.02 * std::cos(pi / 8) - 1e-12);
    }
    for (std::size_t v = 0; v < sheet.vertexCount(); ++v)
      EXPECT_EQ(glm::dvec2(sheet.positions[v]), sheet.development[v]);
  }
}

TEST(Surfaces, FlatMeshRespectsResolutionAndFacesUp) {
  const Sheet sheet = makeSurface("square", {{"size", 0.2}, {"resolution", 20}});
  const EdgeTopology edges = buildEdgeTopology(sheet);
  for (const auto& sides : edges.edges)
    EXPECT_LE(glm::distance(sheet.development[sides.edge.a], sheet.development[sides.edge.b]),
              0.01 * (1.0 + 1e-9));
  EXPECT_NEAR(area2(sheet), 0.04, 1e-15);
  for (const Triangle& t : sheet.triangles) EXPECT_GT(frontNormal(sheet, t).z, 0.999);
}

TEST(Surfaces, CylinderDevelopsToItsDiscreteCircumference) {
  const double radius = 0.05, height = 0.1;
  const Sheet sheet = makeSurface(
      "cylinder", {{"radius", radius}, {"height", height}, {"angle", 360}, {"resolution", 40}});
  // arc 2 pi r = 0.314 > height: 40 segments around, round(40 * 0.1 / 0.314) = 13 along.
  EXPECT_EQ(sheet.triangleCount(), 2u * 40u * 13u);
  double lo = 1e9, hi = -1e9;
  for (const glm::dvec2& p : sheet.development) {
    lo = std::min(lo, p.x);
    hi = std::max(hi, p.x);
  }
  EXPECT_NEAR(hi - lo, 40 * 2 * radius * std::sin(pi / 40), 1e-15);
  EXPECT_LT(hi - lo, 2 * pi * radius);
  // Every vertex lies on the cylinder around the y axis.
  for (const glm::dvec3& p : sheet.positions) {
    EXPECT_NEAR(std::hypot(p.x, p.z), radius, 1e-15);
    EXPECT_LE(std::abs(p.y), 0.5 * height + 1e-15);
  }
  // The slit: 13 edges on either side, over identical 3D points.
  std::size_t slits = 0;
  for (const TaggedEdge& tag : sheet.tags) slits += tag.kind == EdgeKind::Slit;
  EXPECT_EQ(slits, 2u * 13u);
  // The middle faces +z with its front side: the outside of the tube.
  EXPECT_GT(frontNormal(sheet, topTriangle(sheet)).z, 0.99);
}

TEST(Surfaces, CylinderTriangleCountFollowsTheDocumentedFormula) {
  const std::pair<int, std::size_t> cases[] = {{82, 10004}, {259, 99456}};
  for (const auto& [resolution, triangles] : cases)
    EXPECT_EQ(makeSurface("cylinder", {{"resolution", resolution}}).triangleCount(), triangles);
}

TEST(Surfaces, PartialCylindersHaveNoSlit) {
  for (const auto& [name, params] : std::vector<std::pair<std::string, SurfaceParameters>>{
           {"half_cylinder", {}}, {"cylinder", {{"angle", 90}}}, {"cylinder", {{"angle", 359}}}}) {
    const Sheet sheet = makeSurface(name, params);
    expectGoodSheet(sheet, {1, 1}, name);
    EXPECT_TRUE(sheet.tags.empty());
    EXPECT_GT(frontNormal(sheet, topTriangle(sheet)).z, 0.99);
  }
}

TEST(Surfaces, ConeHasAnApexAndASlitAndDevelopsToAFan) {
  const double baseRadius = 0.08, height = 0.12;
  const Sheet sheet = makeSurface("cone", {{"resolution", 32}});
  expectGoodSheet(sheet, {1, 1}, "cone");
  // One apex vertex on the axis at the top, shared by the innermost ring of triangles.
  std::size_t apexCount = 0;
  for (const glm::dvec3& p : sheet.positions) {
    const double rho = std::hypot(p.x, p.z);
    // Every vertex is on the cone: radius falls linearly from base to apex.
    EXPECT_NEAR(rho, baseRadius * (0.5 - p.y / height), 1e-15);
    apexCount += rho == 0.0;
  }
  EXPECT_EQ(apexCount, 1u);
  EXPECT_FALSE(sheet.tags.empty());
  for (const TaggedEdge& tag : sheet.tags) EXPECT_EQ(tag.kind, EdgeKind::Slit);
  EXPECT_GT(frontNormal(sheet, topTriangle(sheet)).z, 0.0);
  // Development: every base vertex at the full slant from the apex.
  const double slant = std::hypot(baseRadius, height);
  glm::dvec2 apex2(0.0);
  for (std::size_t v = 0; v < sheet.vertexCount(); ++v)
    if (std::hypot(sheet.positions[v].x, sheet.positions[v].z) == 0.0) apex2 = sheet.development[v];
  for (std::size_t v = 0; v < sheet.vertexCount(); ++v)
    if (std::abs(sheet.positions[v].y + 0.5 * height) < 1e-12) {
      EXPECT_NEAR(glm::distance(sheet.development[v], apex2), slant, 1e-15);
    }
}

TEST(Surfaces, TruncatedAndPartialConesAreValid) {
  expectGoodSheet(makeSurface("cone", {{"top_radius", 0.03}}), {1, 1}, "truncated cone");
  expectGoodSheet(makeSurface("cone", {{"top_radius", 0.03}, {"angle", 120}}), {1, 1},
                  "truncated partial cone");
  expectGoodSheet(makeSurface("cone", {{"angle", 200}, {"resolution", 8}}), {1, 1}, "partial cone");
  expectGoodSheet(makeSurface("cone", {{"resolution", 1}}), {1, 1}, "coarsest cone");
  EXPECT_TRUE(makeSurface("cone", {{"angle", 120}}).tags.empty());
  // Nearly a cylinder: the least taper still develops exactly; less is refused by name (fuzz_fold
  // found a cone with radii 3e-15 apart whose development was 1.3 mm off).
  const double base = 0.08;
  expectGoodSheet(makeSurface("cone", {{"top_radius", base * (1.0 - 2.0 * detail::kMinConeTaper)},
                                       {"resolution", 4}}),
                  {1, 1}, "least tapered cone");
  try {
    makeSurface("cone", {{"base_radius", 1.0}, {"top_radius", 1.0 - 3.3e-15}, {"resolution", 1}});
    ADD_FAILURE() << "a cone with radii 3e-15 apart was built";
  } catch (const SurfaceError& error) {
    EXPECT_NE(std::string(error.what()).find("top_radius"), std::string::npos) << error.what();
  }
}

TEST(Surfaces, SweptCurveFollowsTheSineAndFacesUp) {
  const double amplitude = 0.02, wavelength = 0.1;
  const Sheet sheet =
      makeSurface("swept_curve", {{"amplitude", amplitude}, {"wavelength", wavelength}});
  for (const glm::dvec3& p : sheet.positions)
    EXPECT_NEAR(p.z, amplitude * std::sin(2 * pi * p.x / wavelength), 1e-15);
  for (const Triangle& t : sheet.triangles) EXPECT_GT(frontNormal(sheet, t).z, 0.0);
  // The development is longer than the curve's width by the waves' arc.
  double lo = 1e9, hi = -1e9;
  for (const glm::dvec2& p : sheet.development) {
    lo = std::min(lo, p.x);
    hi = std::max(hi, p.x);
  }
  EXPECT_GT(hi - lo, 0.2 * 1.1);
}

TEST(Surfaces, HelixTangentRulingsTouchTheHelix) {
  const Sheet sheet = makeSurface("helix_tangent");
  expectGoodSheet(sheet, {1, 1}, "helix_tangent");
  // Extending each ruling back by ruling_start lands on the helix of radius 0.04.
  // Vertex (i, 0) and (i, 1) of the grid are consecutive along ruling i.
  const double start = 0.02;
  const glm::dvec3 a = sheet.positions[0], b = sheet.positions[1];
  const glm::dvec3 onHelix = a - start * glm::normalize(b - a);
  EXPECT_NEAR(std::hypot(onHelix.x, onHelix.z), 0.04, 1e-12);
}

TEST(Surfaces, BadParametersAreRefusedByName) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    std::string surface;
    SurfaceParameters params;
    std::vector<std::string> expected;
  };
  const std::vector<Case> cases{
      {"sphere", {}, {"sphere", "unknown surface"}},
      {"square", {{"radius", 1}}, {"square", "radius"}},
      {"square", {{"size", 0}}, {"square", "size", "= 0"}},
      {"disk", {{"radius", -1}}, {"disk", "radius", "-1"}},
      {"cylinder", {{"radius", nan}}, {"cylinder", "radius", "nan"}},
      {"cone", {{"height", inf}}, {"cone", "height", "inf"}},
      {"rectangle", {{"width", 1e30}}, {"rectangle", "width", "1e+30"}},
      // Found by fuzz_fold: a hole or top ring far below a real length made degenerate triangles.
      {"square", {{"hole_radius", 5.4e-20}}, {"square", "hole_radius", "must be 0 (none)"}},
      {"cone", {{"top_radius", 1e-9}}, {"cone", "top_radius", "must be 0 (none)"}},
      {"disk", {{"resolution", 10.5}}, {"disk", "resolution", "10.5"}},
      {"square", {{"resolution", 0}}, {"square", "resolution"}},
      {"star", {{"points", 2}}, {"star", "points", "2"}},
      {"star", {{"inner_radius", 0.1}, {"outer_radius", 0.1}}, {"star", "inner_radius", "0.1"}},
      {"disk", {{"hole_radius", 0.1}}, {"disk", "hole_radius", "0.1"}},
      {"square", {{"hole_radius", -0.01}}, {"square", "hole_radius"}},
      {"star", {{"hole_radius", 0.04}}, {"star", "hole_radius", "0.04"}},
      {"cone", {{"top_radius", 0.08}}, {"cone", "top_radius", "0.08"}},
      {"cylinder", {{"angle", 0}}, {"cylinder", "angle", "0"}},
      {"cylinder", {{"angle", 400}}, {"cylinder", "angle", "400"}},
      {"helix_tangent", {{"turns", 3}}, {"helix_tangent", "turns", "3"}},
      {"helix_tangent", {{"ruling_start", 0.001}}, {"helix_tangent", "ruling_start", "0.001"}},
      {"cylinder", {{"resolution", 2000}}, {"cylinder", "resolution", "2000"}},
      {"square", {{"resolution", 2000}}, {"square", "resolution", "2000"}},
  };
  for (const Case& c : cases) {
    try {
      makeSurface(c.surface, c.params);
      ADD_FAILURE() << c.surface << " accepted bad parameters";
    } catch (const SurfaceError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      for (const std::string& part : c.expected)
        EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
    }
  }
  static_assert(std::is_base_of_v<std::invalid_argument, SurfaceError>);
}

TEST(TriangulateOutline, LShapeWithASquareHole) {
  const std::vector<glm::dvec2> outline{{0, 0},     {0.2, 0},   {0.2, 0.1},
                                        {0.1, 0.1}, {0.1, 0.2}, {0, 0.2}};
  const std::vector<std::vector<glm::dvec2>> holes{
      {{0.02, 0.02}, {0.02, 0.06}, {0.06, 0.06}, {0.06, 0.02}}};
  const Sheet sheet = triangulateOutline(outline, holes, 0.01);
  expectGoodSheet(sheet, {0, 2}, "L with hole");
  EXPECT_NEAR(area2(sheet), 0.03 - 0.0016, 1e-15);
  const EdgeTopology edges = buildEdgeTopology(sheet);
  for (const auto& sides : edges.edges)
    EXPECT_LE(glm::distance(sheet.development[sides.edge.a], sheet.development[sides.edge.b]),
              0.01 * (1.0 + 1e-9));
}

TEST(TriangulateOutline, RefusesBadOutlines) {
  const std::vector<glm::dvec2> square{{0, 0}, {0.1, 0}, {0.1, 0.1}, {0, 0.1}};
  const std::vector<glm::dvec2> bowTie{{0, 0}, {0.1, 0.1}, {0.1, 0}, {0, 0.1}};
  const std::vector<glm::dvec2> outside{{0.2, 0.2}, {0.3, 0.2}, {0.3, 0.3}};
  const std::vector<glm::dvec2> crossing{{0.05, 0.05}, {0.2, 0.05}, {0.05, 0.08}};
  EXPECT_THROW(triangulateOutline(bowTie, {}, 0.01), SurfaceError);
  EXPECT_THROW(triangulateOutline(square, {outside}, 0.01), SurfaceError);
  EXPECT_THROW(triangulateOutline(square, {crossing}, 0.01), SurfaceError);
  EXPECT_THROW(triangulateOutline({{0, 0}, {1, 0}}, {}, 0.01), SurfaceError);
  EXPECT_THROW(triangulateOutline({{0, 0}, {1, 0}, {2, 0}}, {}, 0.01), SurfaceError);
  EXPECT_THROW(triangulateOutline(square, {}, 0.0), SurfaceError);
  EXPECT_THROW(triangulateOutline(square, {}, 1e-6), SurfaceError);  // far over 4M triangles
  EXPECT_THROW(triangulateOutline({{0, 0}, {std::nan(""), 0}, {0, 1}}, {}, 0.1), SurfaceError);
}

}  // namespace
}  // namespace curvefold
