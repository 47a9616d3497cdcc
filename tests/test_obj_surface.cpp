#include "engine/surfaces/obj_surface.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/geometry/unfold.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "test_paths.hpp"

namespace curvefold {
namespace {

std::string dataPath(const std::string& name) {
  return std::string(CURVEFOLD_TEST_DATA) + "/obj/" + name;
}

const ValidationOptions kObjOptions{.relativeLengthTolerance = kObjRelativeTolerance};

glm::dvec2 developmentExtent(const Sheet& sheet) {
  glm::dvec2 lo(1e9), hi(-1e9);
  for (const glm::dvec2& p : sheet.development) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return hi - lo;
}

std::size_t slitCount(const Sheet& sheet) {
  std::size_t count = 0;
  for (const TaggedEdge& tag : sheet.tags) count += tag.kind == EdgeKind::Slit;
  return count;
}

// The ObjError message of a file that must be refused.
std::string refusal(const std::string& file) {
  try {
    readObjSurface(dataPath(file));
  } catch (const ObjError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find(file), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << file << " was accepted";
  return "";
}

Sheet parse(const std::string& text) {
  std::istringstream in(text);
  return parseObjSurface(in, "inline.obj");
}

// A wavy cone strip (rays from an apex through a wavy curve: developable, each quad planar) that
// sweeps `turns` times around its axis, as OBJ text without vt, optionally moved by `offset`.
std::string wavyCone(double turns, int steps, const glm::dvec3& offset = glm::dvec3(0.0)) {
  std::ostringstream out;
  out.precision(17);
  for (int i = 0; i <= steps; ++i) {
    const double a = 2.0 * std::numbers::pi * turns * i / steps;
    const glm::dvec3 ray =
        glm::normalize(glm::dvec3(std::cos(a) * (1.0 + 0.15 * std::sin(3.0 * a)), -0.6,
                                  std::sin(a) * (1.0 + 0.15 * std::sin(3.0 * a))));
    for (double t : {0.05, 0.12}) {
      const glm::dvec3 p = offset + t * ray;
      out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    }
  }
  for (int i = 0; i < steps; ++i) {
    const int a = 2 * i + 1, b = a + 1, c = a + 2, d = a + 3;
    out << "f " << a << ' ' << c << ' ' << d << "\nf " << a << ' ' << d << ' ' << b << '\n';
  }
  return out.str();
}

// Issue 13, D16: a cone sweeping about twice around unfolds piece by piece, but its development
// overlaps itself; it imported, folded and passed `check` while its crease pattern crossed itself.
TEST(ObjSurface, ADevelopmentThatOverlapsItselfIsRefused) {
  EXPECT_NO_THROW(parse(wavyCone(0.9, 180)));
  try {
    parse(wavyCone(2.0, 360));
    ADD_FAILURE() << "an overlapping development was accepted";
  } catch (const ObjError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("the development overlaps itself: the edge between vertices"),
              std::string::npos)
        << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
}

// Issue 40, 4: two flat pieces whose vt lie one inside the other (a small square in the middle of
// a large one), or on each other, share no crossing edge; both were accepted though pieces must
// not overlap. Side by side they are fine.
TEST(ObjSurface, PiecesWhoseTextureCoordinatesLieOnEachOtherAreRefused) {
  auto twoSquares = [](double small, const glm::dvec2& at) {
    std::ostringstream out;
    out.precision(17);
    out << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        << "v 0 0 1\nv " << small << " 0 1\nv " << small << ' ' << small << " 1\nv 0 " << small
        << " 1\n"
        << "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
        << "vt " << at.x << ' ' << at.y << "\nvt " << at.x + small << ' ' << at.y << "\nvt "
        << at.x + small << ' ' << at.y + small << "\nvt " << at.x << ' ' << at.y + small << '\n'
        << "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\nf 5/5 6/6 7/7\nf 5/5 7/7 8/8\n";
    return out.str();
  };
  EXPECT_NO_THROW(parse(twoSquares(0.25, {2.0, 0.0})));
  // Inside (below the large square's diagonal, from its first vertex to its third), and on it.
  for (const auto& [small, at] :
       {std::pair{0.25, glm::dvec2(0.6, 0.1)}, std::pair{1.0, glm::dvec2(0.0, 0.0)}}) {  // on it
    try {
      parse(twoSquares(small, at));
      ADD_FAILURE() << "pieces lying on each other were accepted (" << small << ")";
    } catch (const ObjError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("the development overlaps itself: this face's piece lies on the "
                             "piece of the face on line"),
                std::string::npos)
          << message;
      EXPECT_EQ(message.find('\n'), std::string::npos);
    }
  }
}

// Issue 13, D16: an OBJ 1e9 m from the origin imported, then every fold failed to round-off.
// It is recentred on import, and a fold on it keeps every invariant.
TEST(ObjSurface, AMeshFarFromTheOriginIsRecentred) {
  const Sheet sheet = parse(wavyCone(0.9, 180, glm::dvec3(1e9, -2e9, 5e8)));
  for (const glm::dvec3& p : sheet.positions) EXPECT_LT(glm::length(p), 1.0);
  FoldSession session(sheet);
  session.beginDragNear(sheet.positions[10]);
  session.updateDrag(sheet.positions[10] + glm::dvec3(0.0, 0.03, 0.02));
  ASSERT_TRUE(session.commit());
  EXPECT_NO_THROW(validate(session.fixed(), kObjOptions));
}

TEST(ObjSurface, FoldedStripWithoutVtUnfoldsFlat) {
  const Sheet sheet = readObjSurface(dataPath("strip_folded.obj"));
  ASSERT_NO_THROW(validate(sheet));  // unfolding exact data is exact
  EXPECT_EQ(sheet.vertexCount(), 6u);
  EXPECT_EQ(sheet.triangleCount(), 4u);
  const glm::dvec2 extent = developmentExtent(sheet);
  EXPECT_NEAR(std::max(extent.x, extent.y), 0.2, 1e-15);
  EXPECT_NEAR(std::min(extent.x, extent.y), 0.1, 1e-15);
  const SheetReport report = measure(sheet);
  EXPECT_EQ(report.eulerCharacteristic, 1);
  EXPECT_EQ(report.boundaryLoopCount, 1u);
  EXPECT_LT(report.maxEdgeLengthError, 1e-12 * report.size);
  EXPECT_TRUE(sheet.tags.empty());
}

TEST(ObjSurface, ScaledVtIsFittedToMetres) {
  const Sheet sheet = readObjSurface(dataPath("strip_scaled_vt.obj"));
  ASSERT_NO_THROW(validate(sheet));
  // vt (0.5, 0.5) of vertex 4 at (0.1, 0.1, 0) becomes (0.1, 0.1) m: one unit is 0.2 m.
  for (std::size_t v = 0; v < sheet.vertexCount(); ++v)
    if (sheet.positions[v] == glm::dvec3(0.1, 0.1, 0.0)) {
      EXPECT_NEAR(glm::distance(sheet.development[v], glm::dvec2(0.1, 0.1)), 0.0, 1e-15);
    }
  const glm::dvec2 extent = developmentExtent(sheet);
  EXPECT_NEAR(extent.x, 0.2, 1e-15);
  EXPECT_NEAR(extent.y, 0.1, 1e-15);
}

TEST(ObjSurface, MirroredVtIsFlipped) {
  const Sheet sheet = parse(
      "v 0 0 0\nv 0.1 0 0\nv 0.1 0.1 0\nv 0 0.1 0\n"
      "vt 0 0\nvt -1 0\nvt -1 1\nvt 0 1\n"
      "f 1/1 2/2 3/3 4/4\n");
  ASSERT_NO_THROW(validate(sheet));
  EXPECT_NEAR(developmentExtent(sheet).x, 0.1, 1e-15);
}

TEST(ObjSurface, VtSeamBecomesASlit) {
  const Sheet sheet = readObjSurface(dataPath("tube_seam_vt.obj"));
  ASSERT_NO_THROW(validate(sheet, kObjOptions));
  EXPECT_EQ(sheet.vertexCount(), 14u);
  EXPECT_EQ(sheet.triangleCount(), 12u);
  EXPECT_EQ(slitCount(sheet), 2u);
  const SheetReport report = measure(sheet, kObjOptions);
  EXPECT_EQ(report.eulerCharacteristic, 1);
  EXPECT_EQ(report.boundaryLoopCount, 1u);
  // Six sides of 0.1 m: the texture's unit is fitted to 0.6 m.
  EXPECT_NEAR(developmentExtent(sheet).x, 0.6, 1e-6);
  EXPECT_NEAR(developmentExtent(sheet).y, 0.1, 1e-6);
}

TEST(ObjSurface, DuplicatedSeamVerticesWithoutVtUnfoldWithASlit) {
  const Sheet sheet = readObjSurface(dataPath("tube_split.obj"));
  ASSERT_NO_THROW(validate(sheet, kObjOptions));
  EXPECT_EQ(slitCount(sheet), 2u);
  const EdgeTopology edges = buildEdgeTopology(sheet);
  for (const TaggedEdge& tag : sheet.tags)
    EXPECT_TRUE(edges.edges[edges.find(tag.edge)].isBoundary());
  EXPECT_NEAR(std::max(developmentExtent(sheet).x, developmentExtent(sheet).y), 0.6, 1e-6);
}

TEST(ObjSurface, ClosedTubeNeedsACut) {
  const std::string message = refusal("tube_closed.obj");
  EXPECT_NE(message.find("does not develop without a cut"), std::string::npos) << message;
}

TEST(ObjSurface, PyramidIsNotDevelopable) {
  const std::string message = refusal("pyramid.obj");
  EXPECT_NE(message.find("angle defect"), std::string::npos) << message;
  EXPECT_NE(message.find("pyramid.obj:6:"), std::string::npos) << message;  // the apex's line
}

TEST(ObjSurface, MalformedFilesAreRefusedWithTheirLine) {
  const std::pair<std::string, std::string> cases[] = {
      {"bad_number.obj:3:", "malformed number \"1.0.5\""},
      {"zero_index.obj:4:", "index 0"},
      {"out_of_range.obj:5:", "out of range"},
      {"nan_coordinate.obj:2:", "non-finite"},
      {"empty.obj", "no faces"},
      {"no_faces.obj", "no faces"},
      {"nonmanifold.obj:9:", "non-manifold"},
      {"bad_vt.obj:10:", "not a development"},
  };
  for (const auto& [where, what] : cases) {
    const std::string file = where.substr(0, where.find(".obj") + 4);
    const std::string message = refusal(file);
    EXPECT_NE(message.find(where), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  }
  EXPECT_THROW(readObjSurface(dataPath("missing.obj")), ObjError);
}

TEST(ObjSurface, IndexFormsPolygonsAndMixedFaces) {
  // A flat pentagon as one polygon with negative indices and v//vn corners.
  const Sheet pentagon = parse(
      "v 0 0 0\nv 0.1 0 0\nv 0.13 0.08 0\nv 0.05 0.13 0\nv -0.03 0.08 0\nvn 0 0 1\n"
      "f -5//1 -4//1 -3//1 -2//1 -1//1\n");
  EXPECT_EQ(pentagon.triangleCount(), 3u);
  EXPECT_NO_THROW(validate(pentagon));
  EXPECT_THROW(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                     "f 1/1 2/2 3/3\nf 2 4 3\n"),
               ObjError);
  EXPECT_THROW(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n"), ObjError);
  EXPECT_THROW(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n"), ObjError);
  EXPECT_THROW(parse("v 0 0\nf 1 1 1\n"), ObjError);
}

// Issue 38's judge exports a target with `export --obj` and deletes its vt lines: the faces keep
// their `v/vt` corners, whose vt indices point at nothing. The target is read by its positions
// (it was refused as "texture coordinate index out of range").
TEST(ObjSurface, FacesWhoseVtLinesWereDeletedAreReadByTheirPositions) {
  const Sheet withoutVt =
      parse("v 0 0 0\nv 0.1 0 0\nv 0.1 0.1 0.05\nv 0 0.1 0.05\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
  const Sheet plain = parse("v 0 0 0\nv 0.1 0 0\nv 0.1 0.1 0.05\nv 0 0.1 0.05\nf 1 2 3\nf 1 3 4\n");
  EXPECT_EQ(withoutVt.triangles, plain.triangles);
  EXPECT_EQ(withoutVt.positions, plain.positions);
  EXPECT_EQ(withoutVt.development, plain.development);
  // A vt index past the vt lines a file does hold is still refused.
  EXPECT_THROW(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/3\n"), ObjError);
}

TEST(Unfold, ConeUnfoldsCongruently) {
  const Sheet cone = makeSurface("cone", {{"resolution", 24}});
  Sheet unfolded = cone;
  unfolded.development = unfoldDevelopment(cone.positions, cone.triangles);
  const SheetReport report = measure(unfolded);
  EXPECT_EQ(report.firstProblem, "");
  EXPECT_LT(report.maxEdgeLengthError, 1e-12 * report.size);
}

TEST(Unfold, AngleDefectOfAPyramidApex) {
  // Apex over a unit square at height 1/2: four faces with apex angles acos(1/3).
  const std::vector<glm::dvec3> positions{
      {-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}, {0, 0, 0.5}};
  const std::vector<Triangle> triangles{{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  const AngleDefect defect = largestAngleDefect(positions, triangles);
  EXPECT_EQ(defect.vertex, 4u);
  EXPECT_NEAR(defect.radians, 2 * std::numbers::pi - 4 * std::acos(1.0 / 3.0), 1e-12);
  try {
    unfoldDevelopment(positions, triangles);
    ADD_FAILURE() << "pyramid unfolded";
  } catch (const NotDevelopable& error) {
    EXPECT_NE(std::string(error.what()).find("angle defect"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("vertex 4"), std::string::npos) << error.what();
  }
  // A flat mesh has no defect anywhere.
  const std::vector<glm::dvec3> flat{
      {-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}, {0, 0, 0}};
  EXPECT_NEAR(largestAngleDefect(flat, triangles).radians, 0.0, 1e-15);
}

TEST(Unfold, ClosedTubeDoesNotDevelopWithoutACut) {
  Sheet tube = makeSurface("cylinder", {{"resolution", 12}});
  // Glue the slit: the last column's vertices become the first column's.
  const std::size_t rows = tube.vertexCount() / 13;  // 12 + 1 columns of vertices
  for (Triangle& t : tube.triangles)
    for (VertexIndex& v : t)
      if (v >= 12 * rows) v -= 12 * rows;
  tube.positions.resize(12 * rows);
  try {
    unfoldDevelopment(tube.positions, tube.triangles);
    ADD_FAILURE() << "closed tube unfolded";
  } catch (const NotDevelopable& error) {
    EXPECT_NE(std::string(error.what()).find("does not develop without a cut"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace curvefold
