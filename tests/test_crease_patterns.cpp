// The crease-pattern readers (engine/io/fold_crease_pattern.hpp, svg_crease_pattern.hpp) on the
// project's own patterns (tests/data/crease_patterns: by hand, and by make_patterns.py), and every
// kind of bad input with its one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <tuple>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "engine/io/atomic_file.hpp"
#include "engine/io/crease_pattern_graph.hpp"
#include "engine/io/crease_pattern_reader.hpp"
#include "engine/io/fold_crease_pattern.hpp"
#include "engine/io/fold_format.hpp"
#include "engine/io/input_limits.hpp"
#include "engine/io/svg_crease_pattern.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "test_paths.hpp"

using namespace curvefold;

namespace {

const std::filesystem::path kPatterns =
    std::filesystem::path(CURVEFOLD_TEST_DATA) / "crease_patterns";

double area(const CreasePattern& p) {
  double sum = 0.0;
  for (const auto& t : p.triangles) {
    const glm::dvec2 a = p.vertices[t[0]], b = p.vertices[t[1]], c = p.vertices[t[2]];
    sum += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  return sum;
}

std::map<CreaseAssignment, int> counts(const CreasePattern& p) {
  std::map<CreaseAssignment, int> out;
  for (const auto& e : p.edges) ++out[e.assignment];
  return out;
}

// Pieces of paper: triangles joined across shared edges.
int pieces(const CreasePattern& p) {
  std::vector<int> parent(p.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& t : p.triangles)
    for (int k = 0; k < 3; ++k) parent[find(t[k])] = find(t[(k + 1) % 3]);
  std::set<int> roots;
  for (const auto& t : p.triangles) roots.insert(find(t[0]));
  return static_cast<int>(roots.size());
}

// The edge between the vertices nearest to p and q; fails the test when there is none.
const CreasePatternEdge* edgeBetween(const CreasePattern& pattern, glm::dvec2 p, glm::dvec2 q) {
  for (const auto& e : pattern.edges) {
    const glm::dvec2 a = pattern.vertices[e.a], b = pattern.vertices[e.b];
    const auto near = [](glm::dvec2 x, glm::dvec2 y) {
      return std::hypot(x.x - y.x, x.y - y.y) < 1e-6;
    };
    if ((near(a, p) && near(b, q)) || (near(a, q) && near(b, p))) return &e;
  }
  return nullptr;
}

void expectValid(const CreasePattern& pattern) {
  const auto problem = validateCreasePattern(pattern);
  EXPECT_FALSE(problem) << *problem;
}

std::string foldError(const std::string& text) {
  try {
    readFoldCreasePatternText(text, "bad.fold");
  } catch (const CreasePatternError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind("bad.fold: ", 0), 0u) << message;
    return message;
  }
  ADD_FAILURE() << "no error for " << text.substr(0, 200);
  return {};
}

std::string svgError(const std::string& text) {
  try {
    readSvgCreasePatternText(text, "bad.svg");
  } catch (const CreasePatternError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind("bad.svg: ", 0), 0u) << message;
    return message;
  }
  ADD_FAILURE() << "no error for " << text.substr(0, 200);
  return {};
}

// A unit square with the given extra vertices and edges (after its 4 border edges).
std::string squareFold(const std::string& extraVertices, const std::string& extraEdges,
                       const std::string& extraAssignments, const std::string& more = "") {
  return R"({"vertices_coords": [[0,0],[1,0],[1,1],[0,1])" + extraVertices +
         R"(], "edges_vertices": [[0,1],[1,2],[2,3],[3,0])" + extraEdges +
         R"(], "edges_assignment": ["B","B","B","B")" + extraAssignments + "]" + more + "}";
}

const std::string kSvgSquare =
    R"(<svg xmlns="http://www.w3.org/2000/svg"><rect x="0" y="0" width="10" height="10" stroke="#000"/>)";

}  // namespace

// --- FOLD ---

TEST(CreasePatternFold, SingleCreaseKeepsItsAngleAndSplitsTheSquareIntoTriangles) {
  const CreasePattern p = readFoldCreasePattern(kPatterns / "single_crease.fold");
  expectValid(p);
  EXPECT_EQ(p.vertices.size(), 6u);
  EXPECT_EQ(p.triangles.size(), 4u);
  EXPECT_NEAR(area(p), 1.0, 1e-12);
  const CreasePatternEdge* crease = edgeBetween(p, {0.5, 0}, {0.5, 1});
  ASSERT_TRUE(crease);
  EXPECT_EQ(crease->assignment, CreaseAssignment::Valley);
  EXPECT_EQ(crease->foldAngleDegrees, 90.0);
  auto c = counts(p);
  EXPECT_EQ(c[CreaseAssignment::Boundary], 6);
  EXPECT_EQ(c[CreaseAssignment::Flat], 2);  // one diagonal in each half
}

TEST(CreasePatternFold, WaterbombBaseWithFacesLowerCaseAndDefaultAngles) {
  const CreasePattern p = readFoldCreasePattern(kPatterns / "waterbomb_base.fold");
  expectValid(p);
  EXPECT_EQ(p.triangles.size(), 8u);
  EXPECT_NEAR(area(p), 4.0, 1e-12);
  auto c = counts(p);
  EXPECT_EQ(c[CreaseAssignment::Mountain], 4);
  EXPECT_EQ(c[CreaseAssignment::Valley], 4);
  EXPECT_EQ(c[CreaseAssignment::Flat], 0);  // the faces are triangles already
  for (const auto& e : p.edges) {
    if (e.assignment == CreaseAssignment::Mountain) {
      EXPECT_EQ(e.foldAngleDegrees, -180.0);
    }
    if (e.assignment == CreaseAssignment::Valley) {
      EXPECT_EQ(e.foldAngleDegrees, 180.0);
    }
  }
  // The frames (two, with the same keys: not a key given twice) are not read, and a note says so.
  EXPECT_TRUE(std::any_of(p.notes.begin(), p.notes.end(), [](const std::string& n) {
    return n.find("file_frames (2 frames)") != std::string::npos;
  }));
}

TEST(CreasePatternFold, ConcaveFaceFoundWithoutFacesIsTriangulatedInsideOnly) {
  const CreasePattern p = readFoldCreasePattern(kPatterns / "concave_face.fold");
  expectValid(p);
  // The L's area: a triangle across the notch would add 0.5 or more.
  EXPECT_NEAR(area(p), 3.0, 1e-12);
  const CreasePatternEdge* crease = edgeBetween(p, {0, 1.5}, {1, 1.5});
  ASSERT_TRUE(crease);
  EXPECT_EQ(crease->assignment, CreaseAssignment::Mountain);
  EXPECT_EQ(crease->foldAngleDegrees, -60.0);
  EXPECT_FALSE(edgeBetween(p, {2, 1}, {1, 1.5}));  // across the notch, outside the paper
}

TEST(CreasePatternFold, MiuraOriFromFoldAndSvgGiveTheSamePattern) {
  const CreasePattern fold = readFoldCreasePattern(kPatterns / "miura_ori.fold");
  const CreasePattern svg = readSvgCreasePattern(kPatterns / "miura_ori.svg");
  expectValid(fold);
  expectValid(svg);
  EXPECT_EQ(fold.vertices.size(), 20u);
  EXPECT_EQ(fold.triangles.size(), 24u);  // 12 parallelograms
  EXPECT_EQ(counts(fold), counts(svg));
  EXPECT_NEAR(area(fold), area(svg), 1e-9);
  // Every crease of one is a crease of the other, with the same assignment.
  for (const auto& e : fold.edges) {
    if (e.assignment == CreaseAssignment::Flat) continue;
    const CreasePatternEdge* other = edgeBetween(svg, fold.vertices[e.a], fold.vertices[e.b]);
    ASSERT_TRUE(other);
    EXPECT_EQ(other->assignment, e.assignment);
    EXPECT_EQ(other->foldAngleDegrees, e.foldAngleDegrees);
  }
}

TEST(CreasePatternFold, CurvedPleatSegmentsAreKept) {
  const CreasePattern p = readFoldCreasePattern(kPatterns / "curved_pleat.fold");
  expectValid(p);
  auto c = counts(p);
  EXPECT_EQ(c[CreaseAssignment::Mountain], 32);  // two creases of 16 segments
  EXPECT_EQ(c[CreaseAssignment::Valley], 16);
  EXPECT_NEAR(area(p), 16.0, 1e-9);
}

TEST(CreasePatternFold, ThreeDimensionalFileFlatInYReadsInXZ) {
  const CreasePattern p = readFoldCreasePatternText(
      R"({"vertices_coords": [[0,0,0],[2,0,0],[2,0,1],[0,0,1]], "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[0,2]],
          "edges_assignment": ["B","B","B","B","V"], "edges_foldAngle": [0,0,0,0,45],
          "frame_classes": ["creasePattern"]})",
      "flat3d.fold");
  expectValid(p);
  EXPECT_NEAR(area(p), 2.0, 1e-12);
  ASSERT_TRUE(edgeBetween(p, {0, 0}, {2, 1}));
  EXPECT_EQ(edgeBetween(p, {0, 0}, {2, 1})->foldAngleDegrees, 45.0);
}

// A flat sheet in a plane tilted to every axis (a pattern exported in a scene's frame) is as flat
// as one in z = 0: read in its plane, with a note, not refused as a folded state.
TEST(CreasePatternFold, ThreeDimensionalFileFlatInATiltedPlaneReadsInThatPlane) {
  // The 2 x 1 rectangle with a diagonal valley, at x u + y v + (1, 2, 3), u and v orthonormal.
  const glm::dvec3 u(2.0 / 3, 2.0 / 3, 1.0 / 3), v(-2.0 / 3, 1.0 / 3, 2.0 / 3), at(1, 2, 3);
  std::string coords;
  for (const glm::dvec2 q :
       {glm::dvec2(0, 0), glm::dvec2(2, 0), glm::dvec2(2, 1), glm::dvec2(0, 1)}) {
    const glm::dvec3 p = at + q.x * u + q.y * v;
    char text[96];
    std::snprintf(text, sizeof text, "%s[%.17g,%.17g,%.17g]", coords.empty() ? "" : ",", p.x, p.y,
                  p.z);
    coords += text;
  }
  const CreasePattern p =
      readFoldCreasePatternText(R"({"vertices_coords": [)" + coords +
                                    R"(], "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[0,2]],
          "edges_assignment": ["B","B","B","B","V"], "edges_foldAngle": [0,0,0,0,45]})",
                                "tilted.fold");
  expectValid(p);
  EXPECT_NEAR(area(p), 2.0, 1e-12);
  std::size_t creases = 0;
  for (const CreasePatternEdge& e : p.edges)
    if (e.assignment == CreaseAssignment::Valley) {
      ++creases;
      EXPECT_NEAR(glm::distance(p.vertices[e.a], p.vertices[e.b]), std::sqrt(5.0), 1e-12);
      EXPECT_EQ(e.foldAngleDegrees, 45.0);
    }
  EXPECT_EQ(creases, 1u);
  EXPECT_TRUE(std::any_of(p.notes.begin(), p.notes.end(), [](const std::string& note) {
    return note.find("a plane tilted to the axes") != std::string::npos;
  }));
}

TEST(CreasePatternFold, CutIsOpenedAndCanSplitThePaper) {
  // A slit from the bottom edge's midpoint up to the centre: the border vertex is doubled.
  const CreasePattern slit = readFoldCreasePatternText(
      R"({"vertices_coords": [[0,0],[0.5,0],[1,0],[1,1],[0,1],[0.5,0.5]],
          "edges_vertices": [[0,1],[1,2],[2,3],[3,4],[4,0],[1,5]],
          "edges_assignment": ["B","B","B","B","B","C"]})",
      "slit.fold");
  expectValid(slit);
  EXPECT_EQ(slit.vertices.size(), 7u);
  EXPECT_EQ(counts(slit)[CreaseAssignment::Cut], 2);  // one each side
  EXPECT_EQ(pieces(slit), 1);
  // A cut right across makes two pieces.
  const CreasePattern across = readFoldCreasePatternText(
      R"({"vertices_coords": [[0,0],[1,0],[1,1],[0,1],[0,0.5],[1,0.5]],
          "edges_vertices": [[0,1],[1,5],[5,2],[2,3],[3,4],[4,0],[4,5]],
          "edges_assignment": ["B","B","B","B","B","B","C"]})",
      "across.fold");
  expectValid(across);
  EXPECT_EQ(pieces(across), 2);
  EXPECT_EQ(across.vertices.size(), 8u);
}

TEST(CreasePatternFold, ASlitWithBothEndsInsideThePaperStaysJoinedAsAFreeHinge) {
  // One cut edge from (0.3, 0.5) to (0.7, 0.5): neither end can double, so it cannot open.
  const CreasePattern p = readFoldCreasePatternText(
      R"({"vertices_coords": [[0,0],[1,0],[1,1],[0,1],[0.3,0.5],[0.7,0.5]],
          "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[4,5]],
          "edges_assignment": ["B","B","B","B","C"]})",
      "inner_slit.fold");
  expectValid(p);
  EXPECT_EQ(p.vertices.size(), 6u);
  EXPECT_EQ(counts(p)[CreaseAssignment::Cut], 0);
  ASSERT_TRUE(edgeBetween(p, {0.3, 0.5}, {0.7, 0.5}));
  EXPECT_EQ(edgeBetween(p, {0.3, 0.5}, {0.7, 0.5})->assignment, CreaseAssignment::Unassigned);
  EXPECT_TRUE(std::any_of(p.notes.begin(), p.notes.end(), [](const std::string& note) {
    return note.find("cannot open") != std::string::npos;
  }));
  // Two edges: the middle vertex doubles and the slit opens.
  const CreasePattern opens = readFoldCreasePatternText(
      R"({"vertices_coords": [[0,0],[1,0],[1,1],[0,1],[0.3,0.5],[0.5,0.5],[0.7,0.5]],
          "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[4,5],[5,6]],
          "edges_assignment": ["B","B","B","B","C","C"]})",
      "inner_slit2.fold");
  expectValid(opens);
  EXPECT_EQ(opens.vertices.size(), 8u);
  EXPECT_EQ(counts(opens)[CreaseAssignment::Cut], 4);
}

TEST(CreasePatternFold, BadInputGetsOneLineNamingTheProblem) {
  EXPECT_NE(foldError("{\"vertices_coords\": [[0,0],").find("not valid JSON"), std::string::npos);
  EXPECT_NE(
      foldError(R"({"vertices_coords": [[0,0]], "vertices_coords": [[1,1]], "edges_vertices": []})")
          .find("duplicate key \"vertices_coords\" in the top-level object"),
      std::string::npos);
  EXPECT_NE(foldError(squareFold("", "", "",
                                 R"(, "file_frames": [{"frame_title": "a", "frame_title": "b"}])"))
                .find("duplicate key \"frame_title\" in file_frames[0]"),
            std::string::npos);
  EXPECT_NE(foldError(R"({"vertices_coords": "square", "edges_vertices": []})")
                .find("vertices_coords: must be an array"),
            std::string::npos);
  EXPECT_NE(foldError(squareFold("", ",[0,7]", ",\"M\""))
                .find("edges_vertices[4]: vertex 7 out of range"),
            std::string::npos);
  EXPECT_NE(foldError(squareFold("", ",[0,2]", ",\"Q\"")).find("unknown assignment \"Q\""),
            std::string::npos);
  EXPECT_NE(foldError(squareFold("", ",[0,2]", "")).find("edges_assignment: has 4 entries"),
            std::string::npos);
  EXPECT_NE(foldError(squareFold("", ",[0,2]", ",\"M\"", R"(, "edges_foldAngle": [0,0,0,0,200])"))
                .find("outside [-180, 180]"),
            std::string::npos);
  // Two diagonals crossing at the centre without a vertex there.
  EXPECT_NE(foldError(squareFold("", ",[0,2],[1,3]", ",\"M\",\"V\""))
                .find("cross at (0.5, 0.5) without a vertex"),
            std::string::npos);
  // A crease ending on another crease's inside.
  EXPECT_NE(foldError(squareFold(",[0.5,0.5]", ",[0,2],[1,4]", ",\"M\",\"V\""))
                .find("passes through vertex 4"),
            std::string::npos);
  // A crease outside the paper.
  EXPECT_NE(foldError(squareFold(",[2,0],[3,1]", ",[4,5]", ",\"M\"")).find("has no face"),
            std::string::npos);
  EXPECT_NE(foldError(squareFold(",[1,1]", ",[2,4]", ",\"M\"")).find("length zero"),
            std::string::npos);
  EXPECT_NE(foldError(R"({"vertices_coords": [[0,0,0],[1,0,0],[1,1,0.5],[0,1,0]],
                          "edges_vertices": [[0,1],[1,2],[2,3],[3,0]], "edges_assignment": ["B","B","B","B"]})")
                .find("vertices_coords: not a flat crease pattern"),
            std::string::npos);
  EXPECT_NE(foldError(squareFold("", ",[0,2]", ",\"M\"", R"(, "faces_vertices": [[0,1]])"))
                .find("faces_vertices[0]: has fewer than 3 vertices"),
            std::string::npos);
  EXPECT_NE(
      foldError(
          R"({"vertices_coords": [[0,0],[1,0]], "edges_vertices": [[0,1]], "edges_assignment": ["B"]})")
          .find("no paper"),
      std::string::npos);
}

TEST(CreasePatternFold, CountsAndSizesPastTheLimitsAreRefused) {
  std::string text = R"({"vertices_coords": [)";
  text.reserve(8 * kMaxCreasePatternVertices);
  for (std::uint64_t i = 0; i <= kMaxCreasePatternVertices; ++i) text += i ? ",[0,0]" : "[0,0]";
  text += R"(], "edges_vertices": []})";
  EXPECT_NE(foldError(text).find("more than a crease pattern may hold (1000000)"),
            std::string::npos);
  // A file over the byte limit is refused before it is read (a sparse file costs nothing).
  const auto path = std::filesystem::temp_directory_path() / "curvefold_huge_pattern.fold";
  { std::ofstream out(path); }
  std::filesystem::resize_file(path, kMaxCreasePatternBytes + 1);
  EXPECT_THROW(readFoldCreasePattern(path), FileError);
  EXPECT_THROW(readSvgCreasePattern(path), FileError);
  std::filesystem::remove(path);
}

// --- SVG ---

TEST(CreasePatternSvg, SquareTwistWithGroupTransformStylesAndColourSpellings) {
  const CreasePattern p = readSvgCreasePattern(kPatterns / "square_twist.svg");
  expectValid(p);
  EXPECT_EQ(p.vertices.size(), 16u);
  EXPECT_EQ(p.triangles.size(), 18u);
  EXPECT_NEAR(area(p), 100.0 * 100.0, 1e-6);  // scale(25) on a 4 x 4 sheet
  auto c = counts(p);
  EXPECT_EQ(c[CreaseAssignment::Mountain], 8);
  EXPECT_EQ(c[CreaseAssignment::Valley], 4);
  EXPECT_EQ(c[CreaseAssignment::Boundary], 12);
  for (const auto& e : p.edges) {
    if (e.assignment == CreaseAssignment::Valley) {
      EXPECT_NEAR(e.foldAngleDegrees, 90.0, 1e-12);
    }
    if (e.assignment == CreaseAssignment::Mountain) {
      EXPECT_EQ(e.foldAngleDegrees, -180.0);
    }
  }
  // SVG's y points down: the twisted square's corner (1.5, 1) is at (37.5, -25).
  ASSERT_TRUE(edgeBetween(p, {37.5, -25}, {75, -37.5}));
  EXPECT_EQ(edgeBetween(p, {37.5, -25}, {75, -37.5})->assignment, CreaseAssignment::Mountain);
}

TEST(CreasePatternSvg, CutSlitIsOpenedAndTheHairlineGapsInTheBorderSnapShut) {
  const CreasePattern p = readSvgCreasePattern(kPatterns / "cut_slit.svg");
  expectValid(p);
  EXPECT_NEAR(area(p), 100.0 * 100.0, 1e-2);
  EXPECT_EQ(counts(p)[CreaseAssignment::Cut], 2);
  // The slit's end on the border, (50, -100), is two vertices now.
  EXPECT_EQ(std::count_if(p.vertices.begin(), p.vertices.end(),
                          [](glm::dvec2 v) { return std::hypot(v.x - 50, v.y + 100) < 1e-6; }),
            2);
  const CreasePatternEdge* valley = edgeBetween(p, {0, -20}, {100, -20});
  ASSERT_TRUE(valley);
  EXPECT_NEAR(valley->foldAngleDegrees, 45.0, 1e-12);  // opacity 0.25
}

TEST(CreasePatternSvg, FaceBoundedOnlyByBorderLinesIsAHole) {
  // A 10 x 10 sheet with a 2 x 2 window, and a valley through the sheet beside it.
  const CreasePattern p = readSvgCreasePatternText(
      kSvgSquare + R"(<rect x="2" y="2" width="2" height="2" stroke="black"/>
                      <line x1="6" y1="0" x2="6" y2="10" stroke="blue"/></svg>)",
      "window.svg");
  expectValid(p);
  EXPECT_NEAR(area(p), 96.0, 1e-9);
  EXPECT_EQ(counts(p)[CreaseAssignment::Boundary],
            4 + 2 + 4);  // outline (split by the valley) and window
}

TEST(CreasePatternSvg, CurvedPleatCubicsAreFlattenedOntoTheCurve) {
  const CreasePattern p = readSvgCreasePattern(kPatterns / "curved_pleat.svg");
  expectValid(p);
  const auto c = counts(p);
  EXPECT_GE(c.at(CreaseAssignment::Mountain), 8);  // at least 4 pieces a curve
  EXPECT_LE(c.at(CreaseAssignment::Mountain), 128);
  // Every crease vertex lies on its cubic (t found from x by bisection; y negated by the reader).
  for (const auto& e : p.edges) {
    if (e.assignment != CreaseAssignment::Mountain && e.assignment != CreaseAssignment::Valley)
      continue;
    EXPECT_NEAR(e.foldAngleDegrees, e.assignment == CreaseAssignment::Valley ? 90.0 : -90.0, 1e-12);
    for (std::uint32_t v : {e.a, e.b}) {
      const glm::dvec2 at = p.vertices[v];
      const auto bx = [](double t) {
        const double s = 1 - t;
        return 3 * s * s * t * 1.2 + 3 * s * t * t * 2.8 + t * t * t * 4;
      };
      double low = 0, high = 1;
      for (int k = 0; k < 60; ++k)
        (bx(0.5 * (low + high)) < at.x ? low : high) = 0.5 * (low + high);
      const double t = 0.5 * (low + high), s = 1 - t;
      const double k = std::round(at.y);
      const double y =
          s * s * s * k + 3 * s * s * t * (k + 0.4) + 3 * s * t * t * (k + 0.4) + t * t * t * k;
      EXPECT_NEAR(at.y, y, 1e-9);
    }
  }
}

TEST(CreasePatternSvg, CrossingLinesAreSplitWhereTheyCross) {
  const CreasePattern p = readSvgCreasePatternText(
      kSvgSquare +
          R"(<line x1="0" y1="0" x2="10" y2="10" stroke="red"/><line x1="10" y1="0" x2="0" y2="10" stroke="blue"/></svg>)",
      "x.svg");
  expectValid(p);
  EXPECT_EQ(p.vertices.size(), 5u);
  ASSERT_TRUE(edgeBetween(p, {5, -5}, {0, 0}));
  EXPECT_EQ(edgeBetween(p, {5, -5}, {0, 0})->assignment, CreaseAssignment::Mountain);
  EXPECT_EQ(edgeBetween(p, {5, -5}, {10, 0})->assignment, CreaseAssignment::Valley);
  // A crease ending a hair short of the border (a T) is joined to it.
  const CreasePattern t = readSvgCreasePatternText(
      kSvgSquare + R"(<line x1="5" y1="0.001" x2="5" y2="10" stroke="blue"/></svg>)", "t.svg");
  expectValid(t);
  EXPECT_EQ(t.triangles.size(), 4u);
}

TEST(CreasePatternSvg, PathCommandsRelativeAbsoluteAndArcs) {
  // The border as one path: absolute M and V, relative h, closing z; a valley drawn
  // with relative l from a relative first m; a mountain quarter arc around the corner.
  const CreasePattern p = readSvgCreasePatternText(
      R"(<svg xmlns="http://www.w3.org/2000/svg"><path d="M10,10h-10V0h10z" stroke="#000"/>
         <path d="m5,0 l0,5 5,0" stroke="#0000ff"/>
         <path d="M0,6 A4,4 0 0,1 4,10" stroke="#f00"/></svg>)",
      "paths.svg");
  expectValid(p);
  EXPECT_NEAR(area(p), 100.0, 1e-9);
  ASSERT_TRUE(edgeBetween(p, {5, 0}, {5, -5}));
  ASSERT_TRUE(edgeBetween(p, {5, -5}, {10, -5}));
  int onArc = 0;
  for (const glm::dvec2 v : p.vertices)
    if (v.x > 1e-9 && v.y < -4.0 - 1e-9 && v.x < 4.0 - 1e-9) {
      EXPECT_NEAR(std::hypot(v.x - 0, v.y + 10), 4.0, 1e-9);  // centre (0, 10) in SVG's y
      ++onArc;
    }
  EXPECT_GE(onArc, 4);
}

TEST(CreasePatternSvg, StyleSheetClassesAndUnknownColoursAreNoted) {
  const CreasePattern p = readSvgCreasePatternText(
      R"(<svg xmlns="http://www.w3.org/2000/svg"><style>/* c */ .b{stroke:#000000} line.m { stroke: rgb(100%, 0%, 0%); opacity: 0.5 }</style>
         <rect class="b" width="10" height="10"/><line class="m" x1="0" y1="5" x2="10" y2="5"/>
         <line x1="0" y1="2" x2="10" y2="2" stroke="#231F20"/><defs><line x1="0" y1="0" x2="1" y2="9" stroke="red"/></defs></svg>)",
      "classes.svg");
  expectValid(p);
  ASSERT_TRUE(edgeBetween(p, {0, -5}, {10, -5}));
  EXPECT_NEAR(edgeBetween(p, {0, -5}, {10, -5})->foldAngleDegrees, -90.0, 1e-12);
  EXPECT_FALSE(edgeBetween(p, {0, -2}, {10, -2}));
  EXPECT_TRUE(std::any_of(p.notes.begin(), p.notes.end(), [](const std::string& n) {
    return n.find("\"#231f20\" (1)") != std::string::npos;
  }));
}

// An SVG's size is its root's width and height against its viewBox, SVG's px being 1/96 inch:
// read by readCreasePattern (what simulate and the Python module call) in metres. Before, the
// user units were taken as metres, and a pattern 20 mm wide drawn in mm became a 20 m sheet.
TEST(CreasePatternSvg, WidthHeightAndViewBoxGiveTheSheetsSizeInMetres) {
  const auto directory = std::filesystem::temp_directory_path() / "curvefold_svg_units";
  std::filesystem::create_directories(directory);
  const auto sizeOf = [&](const std::string& root, const std::string& drawing) {
    const auto path = directory / "p.svg";
    std::ofstream(path) << "<svg xmlns=\"http://www.w3.org/2000/svg\" " << root << ">" << drawing
                        << "</svg>";
    const CreasePattern p = readCreasePattern(path);
    glm::dvec2 low(INFINITY), high(-INFINITY);
    for (const glm::dvec2& v : p.vertices) {
      low = glm::min(low, v);
      high = glm::max(high, v);
    }
    EXPECT_EQ(p.metresPerUnit, 1.0);
    return high - low;
  };
  // A 20 x 10 drawing with one valley across it.
  const std::string wide = R"(<rect width="20" height="10" stroke="black" fill="none"/>
      <line x1="10" y1="0" x2="10" y2="10" stroke="blue"/>)";
  const auto expectSize = [&](const std::string& root, double x, double y) {
    const glm::dvec2 size = sizeOf(root, wide);
    EXPECT_NEAR(size.x, x, 1e-12 * x) << root;
    EXPECT_NEAR(size.y, y, 1e-12 * y) << root;
  };
  expectSize(R"(width="200mm" height="100mm" viewBox="0 0 20 10")", 0.2, 0.1);
  expectSize(R"(width="20cm" height="10cm" viewBox="0 0 20 10")", 0.2, 0.1);
  expectSize(R"(width="2in" height="1in" viewBox="0 0 20 10")", 0.0508, 0.0254);
  expectSize(R"(width="144pt" height="72pt" viewBox="0 0 20 10")", 0.0508, 0.0254);
  expectSize(R"(width="192px" height="96px" viewBox="0 0 20 10")", 0.0508, 0.0254);
  expectSize(R"(width="192" height="96" viewBox="0 0 20 10")", 0.0508, 0.0254);  // unitless: px
  // Only one of them: it scales both; a viewBox of another aspect: the smaller scale (meet).
  expectSize(R"(width="200mm" viewBox="0 0 20 10")", 0.2, 0.1);
  expectSize(R"(width="200mm" height="200mm" viewBox="0 0 20 10")", 0.2, 0.1);
  expectSize(R"(width="400mm" height="100mm" viewBox="0 0 20 10")", 0.2, 0.1);
  // No size of its own, or no viewBox: a user unit is a px.
  expectSize(R"(viewBox="0 0 20 10")", 20 * 0.0254 / 96, 10 * 0.0254 / 96);
  expectSize("", 20 * 0.0254 / 96, 10 * 0.0254 / 96);
  expectSize(R"(width="100%" height="100%" viewBox="0 0 20 10")", 20 * 0.0254 / 96,
             10 * 0.0254 / 96);

  // The reader itself keeps the file's user units and says how it sized them.
  const CreasePattern asRead = readSvgCreasePatternText(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="100mm" viewBox="0 0 20 10">)" +
          wide + "</svg>",
      "mm.svg");
  EXPECT_NEAR(asRead.metresPerUnit, 0.01, 1e-15);
  EXPECT_NE(asRead.unitSource.find("mm"), std::string::npos) << asRead.unitSource;
  EXPECT_NEAR(area(asRead), 200.0, 1e-9);

  // scaleToSize: the larger side as asked, the shape kept.
  CreasePattern sized = asRead;
  scaleToSize(sized, 0.5);
  EXPECT_NEAR(area(sized), 0.5 * 0.25, 1e-12);
  std::filesystem::remove_all(directory);
}

// FOLD's frame_unit scales to metres (mm, cm, m, um, nm, in, pt); "unit", FOLD's default, and
// none leave the coordinates as metres. Before, every unit was read as metres.
TEST(CreasePatternFold, FrameUnitGivesTheSizeInMetres) {
  const auto directory = std::filesystem::temp_directory_path() / "curvefold_fold_units";
  std::filesystem::create_directories(directory);
  const auto side = [&](const std::string& more) {
    const auto path = directory / "p.fold";
    std::ofstream(path) << squareFold("", "", "", more);
    const CreasePattern p = readCreasePattern(path);
    double largest = 0.0;
    for (const glm::dvec2& v : p.vertices) largest = std::max({largest, v.x, v.y});
    return largest;
  };
  EXPECT_NEAR(side(R"(, "frame_unit": "mm")"), 1e-3, 1e-18);
  EXPECT_NEAR(side(R"(, "frame_unit": "in")"), 0.0254, 1e-17);
  EXPECT_NEAR(side(R"(, "frame_unit": "pt")"), 0.0254 / 72, 1e-18);
  EXPECT_EQ(side(R"(, "frame_unit": "unit")"), 1.0);
  EXPECT_EQ(side(""), 1.0);
  const CreasePattern asRead =
      readFoldCreasePatternText(squareFold("", "", "", R"(, "frame_unit": "cm")"), "cm.fold");
  EXPECT_EQ(asRead.metresPerUnit, 1e-2);
  EXPECT_NE(asRead.unitSource.find("cm"), std::string::npos) << asRead.unitSource;
  std::filesystem::remove_all(directory);
}

// Keys the reader does not use are each said in a note, by kind: the key frame's metadata, and
// anything else; the file's own keys and the unit it reads are not. (With frame_unit read, an
// unbraced if took the file_ and unknown keys' branches into the frame_ branch, and no unknown
// key was noted.)
TEST(CreasePatternFold, KeysNotReadAreNotedAndTheUnitIsNot) {
  const CreasePattern p = readFoldCreasePatternText(
      squareFold("", "", "",
                 R"(, "frame_title": "t", "frame_unit": "mm", "file_creator": "x", "my_key": 1)"),
      "keys.fold");
  auto noted = [&](const std::string& text) {
    return std::any_of(p.notes.begin(), p.notes.end(),
                       [&](const std::string& n) { return n.find(text) != std::string::npos; });
  };
  EXPECT_TRUE(noted("ignored: \"my_key\""));
  EXPECT_TRUE(noted("frame_title"));
  EXPECT_FALSE(noted("frame_unit"));
  EXPECT_FALSE(noted("file_creator"));
}

// A malformed root width or height (not a number, not positive, a unit SVG does not know) is
// ignored, as a browser and Origami Simulator ignore it, and said in a note naming the attribute
// and its value; the size then comes from the other one or the stated default (96 px per inch).
// Before, such a file was read at that other size without a word.
TEST(CreasePatternSvg, AMalformedWidthOrHeightIsNotedByNameAndValue) {
  const std::string drawing = R"(<rect width="20" height="10" stroke="black" fill="none"/>
      <line x1="10" y1="0" x2="10" y2="10" stroke="blue"/></svg>)";
  const auto read = [&](const std::string& root) {
    return readSvgCreasePatternText(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" " + root + " viewBox=\"0 0 20 10\">" + drawing,
        "p.svg");
  };
  const auto noteWith = [](const CreasePattern& p, const std::string& text) {
    return std::count_if(p.notes.begin(), p.notes.end(),
                         [&](const std::string& n) { return n.find(text) != std::string::npos; });
  };
  constexpr double kPx = 0.0254 / 96;
  for (const auto& [root, noted, metresPerUnit] :
       std::vector<std::tuple<std::string, std::string, double>>{
           {R"(width="12qq" height="100mm")", R"(<svg width="12qq">: unknown unit "qq")", 0.01},
           {R"(width="-5mm" height="100mm")", R"(<svg width="-5mm">: not a positive)", 0.01},
           {R"(width="200mm" height="NaN")", R"(<svg height="NaN">: not a length)", 0.01},
           {R"(width="0" height="100mm")", R"(<svg width="0">: not a positive)", 0.01},
           {R"(width="200 mm wide")", R"(<svg width="200 mm wide">: unknown unit)", kPx},
           {R"(width="1e999mm")", R"(<svg width="1e999mm">: not a length)", kPx}}) {
    const CreasePattern p = read(root);
    EXPECT_EQ(noteWith(p, noted), 1) << root << ": " << ::testing::PrintToString(p.notes);
    EXPECT_NEAR(p.metresPerUnit, metresPerUnit, 1e-12) << root;
  }
  // Well-formed sizes, and relative ones (no size of their own, as documented), are not noted.
  for (const std::string root : {R"(width="200mm" height="100mm")", R"(width="192" height="96")",
                                 R"(width="100%" height="100%")", ""}) {
    const CreasePattern p = read(root);
    EXPECT_EQ(noteWith(p, "<svg "), 0) << root << ": " << ::testing::PrintToString(p.notes);
  }
}

// FOLD's frame_unit that names no unit this reader knows (a misspelling, a number) is said in a
// note, and the coordinates read as metres, as documented; before, silently metres.
TEST(CreasePatternFold, AnUnknownFrameUnitIsNoted) {
  for (const std::string unit : {R"("furlong")", R"("MM")", "5", "null"}) {
    const CreasePattern p =
        readFoldCreasePatternText(squareFold("", "", "", ", \"frame_unit\": " + unit), "u.fold");
    EXPECT_EQ(p.metresPerUnit, 1.0) << unit;
    EXPECT_EQ(std::count_if(p.notes.begin(), p.notes.end(),
                            [&](const std::string& n) {
                              return n.rfind("frame_unit " + unit + ": not a unit", 0) == 0;
                            }),
              1)
        << unit << ": " << ::testing::PrintToString(p.notes);
    EXPECT_NE(p.unitSource.find("unknown"), std::string::npos) << p.unitSource;
  }
  const CreasePattern unit =
      readFoldCreasePatternText(squareFold("", "", "", R"(, "frame_unit": "unit")"), "u.fold");
  EXPECT_TRUE(std::none_of(unit.notes.begin(), unit.notes.end(), [](const std::string& n) {
    return n.find("frame_unit") != std::string::npos;
  }));
  EXPECT_NE(unit.unitSource.find("no physical size"), std::string::npos) << unit.unitSource;
}

// Files under the 64 MiB limit that pass libxml2's own (no XML_PARSE_HUGE): one path of 2.1
// million segments (a minified file, 10.5 MB in one d attribute), and 22 paths of 100,000 (11
// MB of long attributes). The message names the limit, where libxml2's said the start tag had no
// end or "Huge input lookup".
TEST(CreasePatternSvg, AnAttributePastTheXmlReadersLimitIsNamed) {
  for (const auto& [paths, segments] : {std::pair{1, 2'100'000}, std::pair{22, 100'000}}) {
    std::string text = kSvgSquare;
    for (int p = 0; p < paths; ++p) {
      text += R"(<path stroke="red" d="M0 0)";
      for (int k = 0; k < segments; ++k) text += " l0 0";
      text += R"("/>)";
    }
    text += "</svg>";
    const std::string message = svgError(text);
    EXPECT_NE(message.find("more than the XML reader takes (10000000 bytes"), std::string::npos)
        << message;
  }
}

TEST(CreasePatternSvg, BadInputGetsOneLineNamingTheProblem) {
  EXPECT_NE(svgError("<svg><line").find("not valid XML at line 1"), std::string::npos);
  EXPECT_NE(svgError("<html/>").find("not an SVG file"), std::string::npos);
  EXPECT_NE(svgError(kSvgSquare + R"(<path d="M0,0 L5" stroke="red"/></svg>)")
                .find("line 1: malformed path data"),
            std::string::npos);
  EXPECT_NE(svgError(kSvgSquare + R"(<path d="M0,0 X5,5" stroke="red"/></svg>)")
                .find("malformed path data"),
            std::string::npos);
  EXPECT_NE(
      svgError(kSvgSquare + R"(<line x1="a" stroke="red"/></svg>)").find("x1 is not a number"),
      std::string::npos);
  EXPECT_NE(
      svgError(kSvgSquare + R"svg(<g transform="rotate(1,2)"><line stroke="red"/></g></svg>)svg")
          .find("transform \"rotate\" with 2 numbers"),
      std::string::npos);
  EXPECT_NE(svgError(R"(<svg><line x1="0" y1="0" x2="1" y2="1" stroke="#123456"/></svg>)")
                .find("no lines of a crease colour"),
            std::string::npos);
  // A border that does not close leaves no paper.
  EXPECT_NE(svgError(R"(<svg><polyline points="0,0 10,0 10,10 0,10" stroke="black"/></svg>)")
                .find("no paper"),
            std::string::npos);
  // Entities are not expanded from outside, and a billion laughs stays small (libxml2's limits).
  svgError(R"(<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY a "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa">
    <!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;"><!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;">]>
    <svg><line stroke="&c;"/></svg>)");
}

TEST(CreasePatternReader, ChoosesTheFormatByNameOrFirstCharacter) {
  EXPECT_EQ(readCreasePattern(kPatterns / "miura_ori.svg").triangles.size(), 24u);
  EXPECT_EQ(readCreasePattern(kPatterns / "miura_ori.fold").triangles.size(), 24u);
  const auto directory = std::filesystem::temp_directory_path() / "curvefold_pattern_reader";
  std::filesystem::create_directories(directory);
  std::filesystem::copy_file(kPatterns / "cut_slit.svg", directory / "slit.txt",
                             std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(kPatterns / "single_crease.fold", directory / "crease.json",
                             std::filesystem::copy_options::overwrite_existing);
  EXPECT_EQ(counts(readCreasePattern(directory / "slit.txt"))[CreaseAssignment::Cut], 2);
  EXPECT_EQ(readCreasePattern(directory / "crease.json").triangles.size(), 4u);
  { std::ofstream(directory / "note.txt") << "a crease pattern"; }
  try {
    readCreasePattern(directory / "note.txt");
    ADD_FAILURE() << "read a text file as a crease pattern";
  } catch (const CreasePatternError& error) {
    EXPECT_NE(std::string(error.what()).find("neither FOLD nor SVG"), std::string::npos);
  }
  EXPECT_THROW(readCreasePattern(directory / "missing.fold"), FileError);
  std::filesystem::remove_all(directory);
}

// The simulation promises the same state for the same input bit for bit, so the reader must give
// the same pattern every time, even where the Delaunay triangulation is not unique (a grid's
// squares have four points on one circle).
TEST(CreasePatternGraph, ReadingIsDeterministic) {
  std::string grid =
      R"(<svg xmlns="http://www.w3.org/2000/svg"><rect width="8" height="8" stroke="#000"/>)";
  for (int i = 1; i < 8; ++i)
    grid += "<line x1=\"0\" y1=\"" + std::to_string(i) + "\" x2=\"8\" y2=\"" + std::to_string(i) +
            "\" stroke=\"red\"/><line x1=\"" + std::to_string(i) + "\" y1=\"0\" x2=\"" +
            std::to_string(i) + "\" y2=\"8\" stroke=\"blue\"/>";
  grid += "</svg>";
  const CreasePattern first = readSvgCreasePatternText(grid, "grid.svg");
  expectValid(first);
  EXPECT_EQ(first.vertices.size(), 81u);
  for (int run = 0; run < 3; ++run) {
    const CreasePattern again = readSvgCreasePatternText(grid, "grid.svg");
    ASSERT_EQ(again.vertices, first.vertices);
    ASSERT_EQ(again.triangles, first.triangles);
    ASSERT_EQ(again.edges.size(), first.edges.size());
    for (std::size_t e = 0; e < first.edges.size(); ++e) {
      EXPECT_EQ(again.edges[e].a, first.edges[e].a);
      EXPECT_EQ(again.edges[e].b, first.edges[e].b);
      EXPECT_EQ(again.edges[e].assignment, first.edges[e].assignment);
    }
  }
}

// An SVG circle is 64 segments; the constrained Delaunay triangulation of its inside from its own
// points alone is a fan of lenses (three points of the circle, as low as its sagitta over two or
// three segments), which collapse when the circle folds (the static solver's residual at 1e5,
// NOT settled). Inside a region so bounded points are added: no triangle keeps all three corners
// on the circle, every triangle inside it is well shaped, and the circle keeps its 64 creases.
TEST(CreasePatternGraph, ACircleCreaseIsNotTriangulatedFromItsOwnPointsAlone) {
  const CreasePattern p = readSvgCreasePatternText(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="60mm" height="60mm" viewBox="0 0 60 60">
      <rect width="60" height="60" stroke="black" fill="none"/>
      <circle cx="30" cy="30" r="16" stroke="blue" stroke-opacity="0.5" fill="none"/></svg>)",
      "circle.svg");
  expectValid(p);
  const glm::dvec2 centre(30.0, -30.0);
  const auto onCircle = [&](std::uint32_t v) {
    return std::abs(glm::distance(p.vertices[v], centre) - 16.0) < 1e-9;
  };
  std::size_t creases = 0;
  for (const CreasePatternEdge& e : p.edges)
    if (e.assignment == CreaseAssignment::Valley) {
      ++creases;
      EXPECT_TRUE(onCircle(e.a) && onCircle(e.b));
    }
  EXPECT_EQ(creases, 64u);
  std::size_t inside = 0;
  for (const auto& t : p.triangles) {
    EXPECT_FALSE(onCircle(t[0]) && onCircle(t[1]) && onCircle(t[2]));
    const glm::dvec2 a = p.vertices[t[0]], b = p.vertices[t[1]], c = p.vertices[t[2]];
    if (glm::distance((a + b + c) / 3.0, centre) >= 16.0) continue;
    ++inside;
    // Twice the area over the longest side squared: 0.87 equilateral; a lens here is 0.07.
    const double longest =
        std::max({glm::distance(a, b), glm::distance(b, c), glm::distance(c, a)});
    const glm::dvec2 u = b - a, w = c - a;
    EXPECT_GT(std::abs(u.x * w.y - u.y * w.x) / (longest * longest), 0.2);
  }
  EXPECT_GT(inside, 64u);
}

TEST(CreasePatternGraph, ValidateCatchesBrokenPatterns) {
  CreasePattern p = readFoldCreasePattern(kPatterns / "single_crease.fold");
  expectValid(p);
  CreasePattern flipped = p;
  std::swap(flipped.triangles[0][0], flipped.triangles[0][1]);
  EXPECT_TRUE(validateCreasePattern(flipped));
  CreasePattern missing = p;
  missing.edges.pop_back();
  EXPECT_TRUE(validateCreasePattern(missing));
  CreasePattern inner = p;
  for (auto& e : inner.edges)
    if (e.assignment == CreaseAssignment::Valley) e.assignment = CreaseAssignment::Cut;
  EXPECT_TRUE(validateCreasePattern(inner));
}

// Origami Simulator's own examples (github.com/amandaghassaei/OrigamiSimulator, assets/), not in
// this repository (their licence): set CURVEFOLD_ORIGAMI_SIMULATOR_ASSETS to a checkout's assets
// folder and every .fold and .svg below it must load into a valid pattern. Skipped without it.
TEST(CreasePatternExternal, OrigamiSimulatorExamplesLoad) {
  const char* root = std::getenv("CURVEFOLD_ORIGAMI_SIMULATOR_ASSETS");
  if (!root) GTEST_SKIP() << "CURVEFOLD_ORIGAMI_SIMULATOR_ASSETS is not set";
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root))
    if (entry.path().extension() == ".fold" || entry.path().extension() == ".svg")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());
  for (const auto& file : files) {
    try {
      const CreasePattern p =
          file.extension() == ".fold" ? readFoldCreasePattern(file) : readSvgCreasePattern(file);
      expectValid(p);
      std::printf("%s: %zu vertices, %zu triangles, %zu edges\n", file.string().c_str(),
                  p.vertices.size(), p.triangles.size(), p.edges.size());
    } catch (const std::exception& error) {
      ADD_FAILURE() << error.what();
    }
  }
}

// curvefold's own FOLD export (engine/io/fold_format.hpp) of every catalogue surface, read back as
// a crease pattern: the same triangles (faces given), the same paper, slits reopened (their two
// sides are written at the same flat points and merged on reading), every promise kept.
TEST(CreasePatternFold, CurvefoldsOwnFoldExportReadsBack) {
  for (const SurfaceInfo& info : surfaceCatalog()) {
    SCOPED_TRACE(info.name);
    const Sheet sheet = makeSurface(info.name);
    const CreasePattern p = readFoldCreasePatternText(foldText(sheet), info.name + ".fold");
    expectValid(p);
    EXPECT_EQ(p.triangles.size(), sheet.triangleCount());
    EXPECT_EQ(p.vertices.size(), sheet.vertexCount());
    double developmentArea = 0.0;
    for (const Triangle& t : sheet.triangles) {
      const glm::dvec2 a = sheet.development[t[0]], b = sheet.development[t[1]],
                       c = sheet.development[t[2]];
      developmentArea += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    }
    EXPECT_NEAR(area(p), developmentArea, 1e-9 * developmentArea);
  }
}
