// The printable crease pattern (issue 18, 1): page counts and sizes of tiled PDFs for known sheets
// on A4, letter and A3, the scale bar's length in points, mountain and valley told apart by their
// line styles in black and white, the tiles' marks, guides and labels, fit to one page, the file
// Cairo writes, pages counted before any is drawn, and (issue 28) tiles that overlap by their band
// with no gap and print a known length at real size.
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/fabrication/crease_pattern_pdf.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "io_test_support.hpp"

namespace curvefold {
namespace {

namespace fs = std::filesystem;

// A 500 x 300 mm sheet folded twice, so it has a mountain and a valley.
Sheet foldedSheet() {
  FoldSession session(makeSurface("rectangle", {{"width", 0.5}, {"height", 0.3}}));
  session.beginDragNear({0.2, 0.1, 0.0});
  session.updateDrag({0.1, 0.05, 0.08});
  EXPECT_TRUE(session.commit());
  session.beginDragNear({-0.25, -0.15, 0.0});
  session.updateDrag({-0.15, -0.1, -0.06});
  EXPECT_TRUE(session.commit());
  return session.fixed();
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The page objects of a PDF (its dictionaries are plain text; only streams are compressed).
std::size_t pdfPages(const std::string& pdf) {
  const std::regex page(R"(/Type\s*/Page[^s])");
  return std::size_t(
      std::distance(std::sregex_iterator(pdf.begin(), pdf.end(), page), std::sregex_iterator()));
}

TEST(PrintPdf, A4AndLetterTileAKnownSheet) {
  const Sheet sheet = foldedSheet();
  // 500 x 300 mm: on A4 landscape (277 x 176 mm to print on a page, tiles overlapping by 10 mm)
  // two columns and two rows; portrait would need six.
  PdfOptions options;
  options.paper = Paper::A4;
  const PdfPlan a4 = planCreasePatternPdf(sheet, options);
  EXPECT_NEAR(a4.patternMm.x, 500.0, 1e-6);
  EXPECT_NEAR(a4.patternMm.y, 300.0, 1e-6);
  EXPECT_TRUE(a4.landscape);
  EXPECT_EQ(a4.rows, 2);
  EXPECT_EQ(a4.columns, 2);
  EXPECT_EQ(a4.scale, 1.0);
  ASSERT_EQ(a4.pages.size(), 5u);  // the cover and four tiles
  for (const PdfPage& page : a4.pages) {
    EXPECT_NEAR(page.sizePt.x, 841.89, 0.01);
    EXPECT_NEAR(page.sizePt.y, 595.28, 0.01);
  }
  options.paper = Paper::Letter;
  const PdfPlan letter = planCreasePatternPdf(sheet, options);
  EXPECT_EQ(letter.rows * letter.columns, 4);
  ASSERT_EQ(letter.pages.size(), 5u);
  EXPECT_NEAR(letter.pages[1].sizePt.x, 792.0, 1e-9);
  EXPECT_NEAR(letter.pages[1].sizePt.y, 612.0, 1e-9);
  // A small sheet fits one A4 page at real size: a cover and one tile, portrait.
  const PdfPlan small = planCreasePatternPdf(makeSurface("square", {{"size", 0.15}}), PdfOptions{});
  EXPECT_EQ(small.pages.size(), 2u);
  EXPECT_FALSE(small.landscape);
  // A3 holds more: the 500 x 300 mm sheet on two pages.
  options.paper = Paper::A3;
  EXPECT_EQ(
      planCreasePatternPdf(sheet, options).rows * planCreasePatternPdf(sheet, options).columns, 2);
}

TEST(PrintPdf, EveryPageHasA50MillimetreScaleBar) {
  PdfOptions options;
  for (const Paper paper : {Paper::A4, Paper::Letter, Paper::Fit}) {
    options.paper = paper;
    for (const PdfPage& page : planCreasePatternPdf(foldedSheet(), options).pages) {
      EXPECT_NEAR(page.scaleBarLengthPt, 141.732, 0.001);  // 50 mm at 72 points per inch
      EXPECT_GT(page.scaleBarStart.x, 0.0);
      EXPECT_LT(page.scaleBarStart.x + page.scaleBarLengthPt, page.sizePt.x);
      EXPECT_LT(page.scaleBarStart.y, page.sizePt.y);
    }
  }
}

// In black and white a mountain and a valley differ by their dashes: dash-dot (four lengths, one
// a dot) against dashed (two); cuts and the boundary are solid. In colour, red against blue.
TEST(PrintPdf, MountainAndValleyDifferInBlackAndWhite) {
  const PdfLineStyle mountain = pdfLineStyle(Assignment::Mountain);
  const PdfLineStyle valley = pdfLineStyle(Assignment::Valley);
  ASSERT_EQ(mountain.dashMm.size(), 4u);
  ASSERT_EQ(valley.dashMm.size(), 2u);
  EXPECT_LT(mountain.dashMm[2], 0.5);  // the dot
  EXPECT_GT(mountain.dashMm[0], 1.0);
  EXPECT_GT(valley.dashMm[0], 1.0);
  EXPECT_TRUE(pdfLineStyle(Assignment::Boundary).dashMm.empty());
  EXPECT_TRUE(pdfLineStyle(Assignment::Cut).dashMm.empty());
  EXPECT_EQ(mountain.red, 1.0);
  EXPECT_EQ(valley.blue, 1.0);
  EXPECT_EQ(mountain.blue, 0.0);
  EXPECT_EQ(valley.red, 0.0);
}

// Every tile has lines, its eight cut marks and its row and column; each tile but the first column
// and row has a guide where its neighbour's edge goes; mountains, valleys and (with --angles) the
// crease curves' angles are printed; the cover has the picture's place and the pattern at a
// glance. Where the tiles' windows lie and what their lines are:
// TilesOverlapByTheirBandAndLeaveNoGap.
TEST(PrintPdf, TilesCoverThePatternWithCutMarksAndLabels) {
  const Sheet sheet = foldedSheet();
  PdfOptions options;
  options.angles = true;
  const PdfPlan plan = planCreasePatternPdf(sheet, options);
  std::size_t mountains = 0, valleys = 0, labels = 0;
  for (std::size_t i = 1; i < plan.pages.size(); ++i) {
    const PdfPage& page = plan.pages[i];
    SCOPED_TRACE(i);
    EXPECT_FALSE(page.lines.empty());
    EXPECT_EQ(page.marks.size(), 8u);  // two marks at each of four corners
    const int row = int(i - 1) / plan.columns, column = int(i - 1) % plan.columns;
    EXPECT_EQ(page.guides.size(), std::size_t((row > 0) + (column > 0)));
    bool labelled = false;
    for (const PdfText& text : page.texts) {
      labelled = labelled || text.text.find("row " + std::to_string(row + 1) + ", column " +
                                            std::to_string(column + 1)) == 0;
      labels += text.text.rfind("M ", 0) == 0 || text.text.rfind("V ", 0) == 0;
    }
    EXPECT_TRUE(labelled);
    for (const PdfSegment& s : page.lines) {
      mountains += s.assignment == Assignment::Mountain;
      valleys += s.assignment == Assignment::Valley;
    }
  }
  EXPECT_GT(mountains, 0u);
  EXPECT_GT(valleys, 0u);
  EXPECT_GE(labels, 2u);  // --angles: each crease curve says its angle
  // The cover: the picture's place, the pattern at a glance, the facts.
  const PdfPage& cover = plan.pages.front();
  EXPECT_TRUE(cover.cover);
  EXPECT_TRUE(cover.pictureBox.has_value());
  EXPECT_FALSE(cover.lines.empty());
}

TEST(PrintPdf, FitScalesToOnePageAndSaysTheScale) {
  PdfOptions options;
  options.paper = Paper::Fit;
  const PdfPlan plan = planCreasePatternPdf(foldedSheet(), options);
  ASSERT_EQ(plan.pages.size(), 2u);
  EXPECT_TRUE(plan.landscape);
  // 500 mm into 277 mm of A4 landscape, 300 into 176: the width decides (portrait: 190 mm).
  EXPECT_NEAR(plan.scale, 277.0 / 500.0, 1e-9);
  bool said = false;
  for (const PdfText& text : plan.pages[1].texts)
    said = said || text.text.find("scale 55.4%") != std::string::npos;
  EXPECT_TRUE(said);
  EXPECT_TRUE(plan.pages[1].marks.empty());
}

using PrintPdfFile = testing::ScratchDirectory;

TEST_F(PrintPdfFile, WritesThePagesItPlanned) {
  const Sheet sheet = foldedSheet();
  PdfOptions options;
  options.title = "two folds";
  options.facts = {"surface: rectangle", "folds: 2"};
  options.picture = PdfPicture{2, 2, std::vector<std::uint8_t>(16, 200)};
  const fs::path path = dir() / "pattern.pdf";
  writeCreasePatternPdf(sheet, path, options);
  const std::string pdf = slurp(path);
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  EXPECT_EQ(pdfPages(pdf), planCreasePatternPdf(sheet, options).pages.size());
  EXPECT_NE(pdf.find("/MediaBox [ 0 0 841.889764 595.275591 ]"), std::string::npos);
  EXPECT_EQ(entries(), std::vector<std::string>{"pattern.pdf"});  // no temporary left
  // An unwritable place: one line naming it, nothing written.
  EXPECT_THROW(writeCreasePatternPdf(sheet, dir() / "missing" / "p.pdf", options), FileError);
}

// Issue 29, 1: the page count comes from the extent alone, agrees with the plan, and a plan past
// kMaxPdfPages is refused before any page is made.
TEST(PrintPdf, PagesAreCountedFirstAndTooManyAreRefused) {
  const Sheet sheet = foldedSheet();  // 500 x 300 mm: 2 x 2 tiles on A4
  EXPECT_EQ(pdfPageCount(sheet, Paper::A4), 4.0);
  EXPECT_EQ(pdfPageCount(sheet, Paper::Fit), 1.0);
  Sheet huge = sheet;
  for (glm::dvec2& q : huge.development) q *= 200.0;  // 100 x 60 m
  for (glm::dvec3& p : huge.positions) p *= 200.0;
  const double pages = pdfPageCount(huge, Paper::A4);
  EXPECT_GT(pages, kMaxPdfPages);
  PdfOptions options;
  EXPECT_THROW(planCreasePatternPdf(huge, options), PdfTooLarge);
  options.paper = Paper::Fit;
  EXPECT_EQ(planCreasePatternPdf(huge, options).pages.size(), 2u);  // the cover and one page
}

TEST(PrintPdf, PaperNames) {
  EXPECT_EQ(parsePaper("a4"), Paper::A4);
  EXPECT_EQ(parsePaper("letter"), Paper::Letter);
  EXPECT_EQ(parsePaper("a3"), Paper::A3);
  EXPECT_EQ(parsePaper("fit"), Paper::Fit);
  EXPECT_FALSE(parsePaper("A5"));
}

// The development's vertices in pattern millimetres (from its top left, y down), as printed.
std::vector<glm::dvec2> patternVerticesMm(const Sheet& sheet) {
  const DevelopmentBounds bounds = developmentBounds(sheet);
  std::vector<glm::dvec2> vertices;
  for (const glm::dvec2& p : sheet.development)
    vertices.push_back({(p.x - bounds.low.x) * 1000.0, (bounds.high.y - p.y) * 1000.0});
  return vertices;
}

bool nearAny(const glm::dvec2& q, const std::vector<glm::dvec2>& points, double tolerance) {
  for (const glm::dvec2& p : points)
    if (glm::distance(p, q) <= tolerance) return true;
  return false;
}

// Issue 28: tiles that left 10 mm gaps between them, and tiles printed at half size, passed every
// print test. Each tile shows a window of the pattern as large as its printable area (real size);
// a tile's window starts kOverlapMm before its left and upper neighbours' end (no gap, the
// documented overlap); the windows together hold every vertex; and every line drawn on a tile,
// read back through its window at real size, runs between vertices of the development.
TEST(PrintPdf, TilesOverlapByTheirBandAndLeaveNoGap) {
  Sheet large = foldedSheet();  // 500 x 300 mm; doubled, 1000 x 600 mm
  for (glm::dvec2& q : large.development) q *= 2.0;
  for (glm::dvec3& p : large.positions) p *= 2.0;
  for (const Sheet& sheet : {foldedSheet(), large})
    for (const Paper paper : {Paper::A4, Paper::Letter}) {
      PdfOptions options;
      options.paper = paper;
      const PdfPlan plan = planCreasePatternPdf(sheet, options);
      SCOPED_TRACE(std::to_string(plan.patternMm.x) + " mm, paper " + std::to_string(int(paper)));
      ASSERT_GT(plan.rows * plan.columns, 1);
      ASSERT_EQ(plan.pages.size(), std::size_t(plan.rows * plan.columns + 1));
      const std::vector<glm::dvec2> vertices = patternVerticesMm(sheet);
      auto tile = [&](int row, int column) -> const PdfPage& {
        return plan.pages[1 + std::size_t(row * plan.columns + column)];
      };
      for (int row = 0; row < plan.rows; ++row)
        for (int column = 0; column < plan.columns; ++column) {
          SCOPED_TRACE("row " + std::to_string(row) + ", column " + std::to_string(column));
          const PdfPage& page = tile(row, column);
          const PdfRect& window = page.patternWindowMm;
          const glm::dvec2 clipMm = (page.clip.high - page.clip.low) / kPointsPerMm;
          EXPECT_NEAR(window.high.x - window.low.x, clipMm.x, 1e-9);  // real size
          EXPECT_NEAR(window.high.y - window.low.y, clipMm.y, 1e-9);
          if (column == 0) {
            EXPECT_NEAR(window.low.x, 0.0, 1e-9);
          }
          if (row == 0) {
            EXPECT_NEAR(window.low.y, 0.0, 1e-9);
          }
          if (column > 0) {
            const PdfRect& left = tile(row, column - 1).patternWindowMm;
            EXPECT_NEAR(window.low.x, left.high.x - kOverlapMm, 1e-9);
            EXPECT_NEAR(window.low.y, left.low.y, 1e-9);
          }
          if (row > 0) {
            const PdfRect& up = tile(row - 1, column).patternWindowMm;
            EXPECT_NEAR(window.low.y, up.high.y - kOverlapMm, 1e-9);
            EXPECT_NEAR(window.low.x, up.low.x, 1e-9);
          }
          if (column + 1 == plan.columns) {
            EXPECT_GE(window.high.x, plan.patternMm.x);
          }
          if (row + 1 == plan.rows) {
            EXPECT_GE(window.high.y, plan.patternMm.y);
          }
          for (const PdfSegment& s : page.lines)
            for (const glm::dvec2& end : {s.a, s.b})
              ASSERT_TRUE(
                  nearAny(window.low + (end - page.clip.low) / kPointsPerMm, vertices, 1e-6))
                  << "a line end off the pattern at real size";
        }
      for (const glm::dvec2& v : vertices) {
        bool shown = false;
        for (std::size_t i = 1; i < plan.pages.size(); ++i) {
          const PdfRect& w = plan.pages[i].patternWindowMm;
          shown = shown || (v.x >= w.low.x && v.x <= w.high.x && v.y >= w.low.y && v.y <= w.high.y);
        }
        ASSERT_TRUE(shown) << "vertex at " << v.x << ", " << v.y << " mm is on no tile";
      }
    }
}

// Issue 28: a 150 mm square prints 150 mm wide and high (in page points over 72/25.4), within
// 0.1%, on its one tile; fit to a page, a 500 mm sheet prints at the scale the plan says.
TEST(PrintPdf, AKnownLengthPrintsAtRealSize) {
  const PdfPlan plan = planCreasePatternPdf(makeSurface("square", {{"size", 0.15}}), PdfOptions{});
  ASSERT_EQ(plan.pages.size(), 2u);
  auto extentMm = [](const PdfPage& page) {
    glm::dvec2 low(1e300), high(-1e300);
    for (const PdfSegment& s : page.lines)
      for (const glm::dvec2& end : {s.a, s.b}) {
        low = glm::min(low, end);
        high = glm::max(high, end);
      }
    return (high - low) / kPointsPerMm;
  };
  const glm::dvec2 printed = extentMm(plan.pages[1]);
  EXPECT_NEAR(printed.x, 150.0, 0.15);
  EXPECT_NEAR(printed.y, 150.0, 0.15);
  PdfOptions fit;
  fit.paper = Paper::Fit;
  const PdfPlan fitted = planCreasePatternPdf(foldedSheet(), fit);
  const glm::dvec2 fittedMm = extentMm(fitted.pages[1]);
  EXPECT_NEAR(fittedMm.x, 500.0 * fitted.scale, 0.001 * 500.0 * fitted.scale);
  EXPECT_NEAR(fittedMm.y, 300.0 * fitted.scale, 0.001 * 300.0 * fitted.scale);
}

}  // namespace
}  // namespace curvefold
