// The cutter SVG (issue 18, 2): its layers by name and colour, hairlines in millimetres, the cut
// layer around the whole sheet, creases joined into polylines, and perforations of the asked
// lengths.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/fabrication/cutter_svg.hpp"
#include "engine/geometry/creases.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "io_test_support.hpp"

namespace curvefold {
namespace {

namespace fs = std::filesystem;

// A 200 x 100 mm sheet with a mountain and a valley, each one straight fold.
Sheet foldedRectangle() {
  FoldSession session(makeSurface("rectangle", {{"width", 0.2}, {"height", 0.1}}));
  session.beginDragNear({0.1, 0.0, 0.0});
  session.updateDrag({0.04, 0.0, 0.05});
  EXPECT_TRUE(session.commit());
  session.beginDragNear({-0.1, 0.0, 0.0});
  session.updateDrag({-0.04, 0.0, -0.05});
  EXPECT_TRUE(session.commit());
  return session.fixed();
}

double length(const std::vector<glm::dvec2>& line) {
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) total += glm::distance(line[i], line[i + 1]);
  return total;
}

TEST(CutterSvg, ThreeLayersInTheirColours) {
  const std::vector<CutterLayer> layers = cutterLayers(foldedRectangle());
  ASSERT_EQ(layers.size(), 3u);
  EXPECT_EQ(layers[0].name, "cut");
  EXPECT_EQ(layers[0].colour, "#ff0000");
  EXPECT_EQ(layers[1].name, "mountain score");
  EXPECT_EQ(layers[1].colour, "#0000ff");
  EXPECT_EQ(layers[2].name, "valley score");
  EXPECT_EQ(layers[2].colour, "#00ff00");
  // The boundary is one closed polyline round the 200 x 100 mm sheet; each fold one straight
  // crease across its 100 mm height, joined into one polyline.
  ASSERT_EQ(layers[0].polylines.size(), 1u);
  EXPECT_NEAR(length(layers[0].polylines[0]), 600.0, 1e-6);
  EXPECT_EQ(layers[0].polylines[0].front(), layers[0].polylines[0].back());
  for (int k = 1; k <= 2; ++k) {
    ASSERT_EQ(layers[k].polylines.size(), 1u) << layers[k].name;
    EXPECT_NEAR(length(layers[k].polylines[0]), 100.0, 1e-6) << layers[k].name;
  }
}

// Perforated scores: every dash as long as asked but a line's last, which may be shorter, with the
// gap between dashes (along a crease, dashes continue across its vertices); the cut is not. The
// dashes are cuts, in a layer of their own (issue 28, 3): the score layers are left empty.
TEST(CutterSvg, PerforationsHaveTheirLengths) {
  const Perforation perforation{3.0, 1.5};
  const std::vector<CutterLayer> layers = cutterLayers(foldedRectangle(), perforation);
  ASSERT_EQ(layers.size(), 4u);
  ASSERT_EQ(layers[0].polylines.size(), 1u);
  EXPECT_TRUE(layers[1].polylines.empty());
  EXPECT_TRUE(layers[2].polylines.empty());
  EXPECT_EQ(layers[3].name, "perforation");
  EXPECT_EQ(layers[3].colour, "#ff00ff");
  // Two creases of 100 mm (the mountain's, then the valley's): each 22 whole periods of 4.5 mm,
  // then a last dash of 1 mm.
  const auto& dashes = layers[3].polylines;
  ASSERT_EQ(dashes.size(), 46u);
  for (std::size_t i = 0; i < dashes.size(); ++i) {
    const bool last = i % 23 == 22;
    ASSERT_GE(dashes[i].size(), 2u);
    EXPECT_NEAR(length(dashes[i]), last ? 1.0 : 3.0, 1e-9) << i;
    if (i % 23 > 0) {
      EXPECT_NEAR(glm::distance(dashes[i - 1].back(), dashes[i].front()), 1.5, 1e-9) << i;
    }
  }
  EXPECT_THROW(cutterLayers(foldedRectangle(), Perforation{0.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(cutterLayers(foldedRectangle(), Perforation{1.0, -1.0}), std::invalid_argument);
  // Issue 29, 1: finer than a cutter cuts, or more dashes than a file holds (the rectangle's
  // creases are under a metre: a million dashes need a metre per micrometre).
  EXPECT_THROW(cutterLayers(foldedRectangle(), Perforation{0.05, 1.0}), std::invalid_argument);
  EXPECT_NO_THROW(cutterLayers(foldedRectangle(), Perforation{0.1, 0.1}));
  Sheet huge = foldedRectangle();
  for (glm::dvec2& q : huge.development) q *= 2000.0;
  for (glm::dvec3& p : huge.positions) p *= 2000.0;
  EXPECT_THROW(cutterLayers(huge, Perforation{0.1, 0.1}), std::invalid_argument);
  EXPECT_NO_THROW(cutterLayers(huge));
}

// The file: Inkscape layers with their labels, hairline strokes, real millimetres.
using CutterSvgFile = testing::ScratchDirectory;

TEST_F(CutterSvgFile, InkscapeLayersInMillimetres) {
  const fs::path path = dir() / "cut.svg";
  writeCutterSvg(foldedRectangle(), path);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string svg = text.str();
  EXPECT_NE(svg.find("width=\"210.0000mm\" height=\"110.0000mm\""), std::string::npos);
  for (const char* layer : {"cut", "mountain score", "valley score"})
    EXPECT_NE(svg.find(std::string("inkscape:groupmode=\"layer\" id=\"") +
                       std::regex_replace(layer, std::regex(" "), "-") + "\" inkscape:label=\"" +
                       layer + "\""),
              std::string::npos)
        << layer;
  EXPECT_NE(svg.find("stroke-width=\"0.0100\""), std::string::npos);
  EXPECT_EQ(entries(), std::vector<std::string>{"cut.svg"});
}

// Each layer's paths ("M x y L x y ...", millimetres) by the layer's label, read back from a file.
std::map<std::string, std::vector<std::vector<glm::dvec2>>> readLayers(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string svg = text.str();
  std::map<std::string, std::vector<std::vector<glm::dvec2>>> layers;
  const std::regex layer(R"re(<g [^>]*inkscape:label="([^"]*)"[^>]*>([\s\S]*?)</g>)re");
  const std::regex pathData(R"re(<path d="M ([^"]*)"/>)re");
  for (std::sregex_iterator g(svg.begin(), svg.end(), layer), end; g != end; ++g) {
    const std::string name = (*g)[1], body = (*g)[2];
    auto& lines = layers[name];
    for (std::sregex_iterator p(body.begin(), body.end(), pathData); p != end; ++p) {
      std::string d = (*p)[1];
      for (char& c : d)
        if (c == 'L') c = ' ';
      std::istringstream numbers(d);
      std::vector<glm::dvec2> line;
      for (glm::dvec2 q; numbers >> q.x >> q.y;) line.push_back(q);
      lines.push_back(std::move(line));
    }
  }
  return layers;
}

// Issue 28: the fixture above has one mountain and one valley of the same length, so the two score
// layers swapped passed every test. Here a 200 x 100 mm sheet gets a straight fold across it and a
// corner fold the other way, so mountains and valleys differ in length; each layer of the written
// file must hold as many millimetres as the engine's creases of its kind.
TEST_F(CutterSvgFile, MountainAndValleyScoresHoldTheirOwnCreases) {
  FoldSession session(makeSurface("rectangle", {{"width", 0.2}, {"height", 0.1}}));
  session.beginDragNear({0.1, 0.0, 0.0});
  session.updateDrag({0.04, 0.0, 0.05});
  ASSERT_TRUE(session.commit());
  session.beginDragNear({-0.1, -0.05, 0.0});
  session.updateDrag({-0.07, -0.03, -0.03});
  ASSERT_TRUE(session.commit());
  const Sheet& sheet = session.fixed();

  // The engine's assignment, in millimetres of the development.
  std::map<Assignment, double> creaseMm;
  for (const CreaseEdge& c : creaseEdges(sheet, buildEdgeTopology(sheet)))
    creaseMm[c.assignment] +=
        1000.0 * glm::distance(sheet.development[c.edge.a], sheet.development[c.edge.b]);
  const double mountainMm = creaseMm[Assignment::Mountain], valleyMm = creaseMm[Assignment::Valley];
  RecordProperty("mountain_mm", std::to_string(mountainMm));
  RecordProperty("valley_mm", std::to_string(valleyMm));
  ASSERT_GT(mountainMm, 10.0);
  ASSERT_GT(valleyMm, 10.0);
  ASSERT_GT(std::abs(mountainMm - valleyMm), 10.0) << "the design must tell the layers apart";

  const fs::path path = dir() / "cut.svg";
  writeCutterSvg(sheet, path);
  // Each layer's paths, summed by the layer's label.
  std::map<std::string, double> layerMm;
  for (const auto& [name, lines] : readLayers(path)) {
    double& total = layerMm[name];
    for (const std::vector<glm::dvec2>& line : lines) total += length(line);
  }
  ASSERT_EQ(layerMm.size(), 3u);
  // The file rounds coordinates to 0.1 micrometres.
  EXPECT_NEAR(layerMm["mountain score"], mountainMm, 0.01);
  EXPECT_NEAR(layerMm["valley score"], valleyMm, 0.01);
  EXPECT_NEAR(layerMm["cut"], 600.0, 0.01);
}

// A cone folded twice: long curved creases, each a polyline of many short edges.
Sheet foldedCone() {
  FoldSession session(makeSurface("cone", {}));
  const glm::dvec3 first = session.beginDragNear({0.03, 0.105, 0.03});
  session.updateDrag(first + glm::dvec3(-0.03, -0.075, 0.02));
  EXPECT_TRUE(session.commit());
  const glm::dvec3 second = session.beginDragNear({-0.045, -0.1, 0.0});
  session.updateDrag(second + glm::dvec3(0.02, 0.05, 0.01));
  EXPECT_TRUE(session.commit());
  return session.fixed();
}

// The engine's crease edges in the file's millimetres (y down, 5 mm margin).
std::vector<std::pair<glm::dvec2, glm::dvec2>> creaseSegmentsMm(const Sheet& sheet) {
  const DevelopmentBounds bounds = developmentBounds(sheet);
  auto mm = [&](VertexIndex v) {
    const glm::dvec2& p = sheet.development[v];
    return glm::dvec2((p.x - bounds.low.x) * 1000.0 + 5.0, (bounds.high.y - p.y) * 1000.0 + 5.0);
  };
  std::vector<std::pair<glm::dvec2, glm::dvec2>> segments;
  for (const CreaseEdge& c : creaseEdges(sheet, buildEdgeTopology(sheet)))
    if (c.assignment == Assignment::Mountain || c.assignment == Assignment::Valley)
      segments.emplace_back(mm(c.edge.a), mm(c.edge.b));
  return segments;
}

double distanceToSegment(glm::dvec2 q, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a;
  const double t = std::clamp(glm::dot(q - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::distance(q, a + t * ab);
}

// Issue 28, 1 and 3: on a curved crease every dash follows the crease (a chord across its bends
// was up to 0.64 mm off it), the dashes cut CUT/(CUT+GAP) of it, and they are all in the
// perforation layer, none in the score layers.
TEST_F(CutterSvgFile, PerforationsFollowCurvedCreasesInTheirOwnLayer) {
  const Sheet sheet = foldedCone();
  const auto segments = creaseSegmentsMm(sheet);
  double creaseMm = 0.0;
  for (const auto& [a, b] : segments) creaseMm += glm::distance(a, b);
  ASSERT_GT(segments.size(), 100u);
  ASSERT_GT(creaseMm, 300.0);

  const fs::path path = dir() / "cut.svg";
  const Perforation perforation{3.0, 1.5};
  writeCutterSvg(sheet, path, perforation);
  auto layers = readLayers(path);
  ASSERT_EQ(layers.size(), 4u);
  EXPECT_TRUE(layers["mountain score"].empty());
  EXPECT_TRUE(layers["valley score"].empty());
  const auto& dashes = layers["perforation"];
  ASSERT_FALSE(dashes.empty());
  double worst = 0.0, dashMm = 0.0;
  for (const auto& dash : dashes) {
    dashMm += length(dash);
    for (glm::dvec2 q : dash) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& [a, b] : segments) nearest = std::min(nearest, distanceToSegment(q, a, b));
      worst = std::max(worst, nearest);
    }
  }
  RecordProperty("worst_mm", std::to_string(worst));
  EXPECT_LT(worst, 0.01);
  // Sampled between the points too: a dash's chord across a bend leaves the crease mid-way.
  double worstBetween = 0.0;
  for (const auto& dash : dashes)
    for (std::size_t i = 0; i + 1 < dash.size(); ++i) {
      const glm::dvec2 mid = 0.5 * (dash[i] + dash[i + 1]);
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& [a, b] : segments) nearest = std::min(nearest, distanceToSegment(mid, a, b));
      worstBetween = std::max(worstBetween, nearest);
    }
  EXPECT_LT(worstBetween, 0.01);
  const double period = perforation.cutMm + perforation.gapMm;
  EXPECT_NEAR(dashMm, creaseMm * perforation.cutMm / period, period);

  // Without perforation the scores are as before and there is no perforation layer.
  writeCutterSvg(sheet, path);
  layers = readLayers(path);
  EXPECT_EQ(layers.size(), 3u);
  EXPECT_EQ(layers.count("perforation"), 0u);
  EXPECT_FALSE(layers["mountain score"].empty());
  EXPECT_FALSE(layers["valley score"].empty());
}

// Issue 28, 2: the dash pattern runs on along a whole crease of many edges, not restarted at each
// edge: ceil(length / period) dashes a crease (one more where its end falls in a gap's 1e-9).
TEST(CutterSvg, PerforationRunsOnAcrossEdges) {
  const Sheet sheet = foldedCone();
  const Perforation perforation{3.0, 1.5};
  const double period = perforation.cutMm + perforation.gapMm;
  const std::vector<CutterLayer> plain = cutterLayers(sheet);
  std::size_t expected = 0;
  for (int k = 1; k <= 2; ++k)
    for (const auto& line : plain[k].polylines) {
      ASSERT_GT(line.size(), 20u) << "each crease must be many edges";
      expected += static_cast<std::size_t>(std::ceil(length(line) / period));
    }
  const std::vector<CutterLayer> layers = cutterLayers(sheet, perforation);
  ASSERT_EQ(layers.size(), 4u);
  const auto& dashes = layers[3].polylines;
  EXPECT_NEAR(static_cast<double>(dashes.size()), static_cast<double>(expected), 1.0);
  // Every dash but each crease's last is whole: at most one short dash a crease.
  std::size_t shortDashes = 0;
  for (const auto& dash : dashes) shortDashes += length(dash) < perforation.cutMm - 1e-6;
  EXPECT_LE(shortDashes, plain[1].polylines.size() + plain[2].polylines.size());
}

}  // namespace
}  // namespace curvefold
