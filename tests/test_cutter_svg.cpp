// The cutter SVG (issue 18, 2): its layers by name and colour, hairlines in millimetres, the cut
// layer around the whole sheet, creases joined into polylines, and perforations of the asked
// lengths.
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/geometry/creases.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/io/cutter_svg.hpp"
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
// gap between dashes (along a crease, dashes continue across its vertices); the cut is not.
TEST(CutterSvg, PerforationsHaveTheirLengths) {
  const Perforation perforation{3.0, 1.5};
  const std::vector<CutterLayer> layers = cutterLayers(foldedRectangle(), perforation);
  ASSERT_EQ(layers[0].polylines.size(), 1u);
  for (int k = 1; k <= 2; ++k) {
    const auto& dashes = layers[k].polylines;
    // 100 mm: 22 whole periods of 4.5 mm, then a last dash of 1 mm.
    ASSERT_EQ(dashes.size(), 23u) << layers[k].name;
    for (std::size_t i = 0; i < dashes.size(); ++i) {
      ASSERT_EQ(dashes[i].size(), 2u);
      EXPECT_NEAR(length(dashes[i]), i + 1 < dashes.size() ? 3.0 : 1.0, 1e-9) << i;
      if (i > 0) {
        EXPECT_NEAR(glm::distance(dashes[i - 1][1], dashes[i][0]), 1.5, 1e-9) << i;
      }
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
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string svg = text.str();
  // Each layer's paths ("M x y L x y ...", millimetres), summed by the layer's label.
  std::map<std::string, double> layerMm;
  const std::regex layer(R"re(<g [^>]*inkscape:label="([^"]*)"[^>]*>([\s\S]*?)</g>)re");
  const std::regex pathData(R"re(<path d="M ([^"]*)"/>)re");
  for (std::sregex_iterator g(svg.begin(), svg.end(), layer), end; g != end; ++g) {
    const std::string name = (*g)[1], body = (*g)[2];
    double& total = layerMm[name];
    for (std::sregex_iterator p(body.begin(), body.end(), pathData); p != end; ++p) {
      std::string d = (*p)[1];
      for (char& c : d)
        if (c == 'L') c = ' ';
      std::istringstream numbers(d);
      std::vector<glm::dvec2> line;
      for (glm::dvec2 q; numbers >> q.x >> q.y;) line.push_back(q);
      total += length(line);
    }
  }
  ASSERT_EQ(layerMm.size(), 3u);
  // The file rounds coordinates to 0.1 micrometres.
  EXPECT_NEAR(layerMm["mountain score"], mountainMm, 0.01);
  EXPECT_NEAR(layerMm["valley score"], valleyMm, 0.01);
  EXPECT_NEAR(layerMm["cut"], 600.0, 0.01);
}

}  // namespace
}  // namespace curvefold
