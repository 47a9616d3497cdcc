// The crease pattern as a PDF to print, cut and fold (issue 18, docs/design.md 4): at real size,
// tiled across pages that tape together (overlap bands, cut marks, row and column labels), each
// page with a 50 mm scale bar to check the printer's scaling; or scaled to fit one page, the scale
// printed. Mountains and valleys stay apart in black and white by the usual origami line styles
// (valley dashed, mountain dash-dot) as well as by colour (red and blue, as in the SVG). A first
// page shows the folded form (a picture the caller renders), the pattern at a glance and the
// design's facts.
//
// The plan (every page's lines, marks and texts in points) is made apart from the drawing
// (Cairo), so what will be printed can be read and tested.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "engine/fabrication/units.hpp"
#include "engine/geometry/creases.hpp"
#include "engine/geometry/sheet.hpp"

namespace curvefold {

inline constexpr double kScaleBarMm = 50.0;
// Blank paper around the printed area (most printers cannot print the outer 5 mm), the band at
// the foot of each page for its label and scale bar, and how far neighbouring tiles overlap.
inline constexpr double kPageMarginMm = 10.0;
inline constexpr double kFooterMm = 14.0;
inline constexpr double kOverlapMm = 10.0;

enum class Paper { A4, Letter, A3, Fit };

// "a4", "letter", "a3", "fit"; nothing for anything else.
std::optional<Paper> parsePaper(std::string_view name);

// Portrait size in millimetres (Fit prints on A4).
glm::dvec2 paperSizeMm(Paper paper);

// How a crease, the boundary or a cut is drawn: colour (colours.hpp), width and dash pattern
// (empty: solid).
struct PdfLineStyle {
  double red = 0.0, green = 0.0, blue = 0.0;
  double widthMm = 0.25;
  std::vector<double> dashMm;
};
PdfLineStyle pdfLineStyle(Assignment assignment);

// RGBA8 pixels, rows from the top (the renderer's picture of the folded form).
struct PdfPicture {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

struct PdfOptions {
  Paper paper = Paper::A4;
  bool angles = false;             // label each crease curve with its fold angle
  std::string title;               // the design's name
  std::vector<std::string> facts;  // lines for the first page: surface, folds, size, date
  std::optional<PdfPicture> picture;
};

// Page coordinates are points from the top left corner.
struct PdfSegment {
  glm::dvec2 a{0.0}, b{0.0};
  Assignment assignment = Assignment::Boundary;
};
struct PdfText {
  glm::dvec2 at{0.0};  // baseline start
  double sizePt = 9.0;
  std::string text;
};
struct PdfRect {
  glm::dvec2 low{0.0}, high{0.0};
};

struct PdfPage {
  glm::dvec2 sizePt{0.0};
  bool cover = false;
  PdfRect clip;                    // the pattern's lines are drawn inside it only
  std::vector<PdfSegment> lines;   // the pattern (crease, boundary, cut)
  std::vector<PdfSegment> marks;   // cut marks, in thin black
  std::vector<PdfSegment> guides;  // where the neighbouring tile's edge goes, in thin grey dashes
  std::vector<PdfText> texts;
  glm::dvec2 scaleBarStart{0.0};  // its left end; it runs kScaleBarMm to the right
  double scaleBarLengthPt = 0.0;
  std::optional<PdfRect> pictureBox;  // cover: where the folded form is drawn
  // The part of the pattern the clip shows, in millimetres of the pattern from its top left (y
  // down), for reading only: tiles' overlaps and the printed scale can be checked against it
  // (issue 28). On a tile at real size it is as large as the clip in millimetres.
  PdfRect patternWindowMm;
};

struct PdfPlan {
  std::vector<PdfPage> pages;  // the cover first
  int rows = 1, columns = 1;   // tiles
  bool landscape = false;
  double scale = 1.0;         // paper over pattern (1: real size)
  glm::dvec2 patternMm{0.0};  // the development's extent
};

// How the pattern lies on paper: tiles at real size (rows x columns) or one page scaled to fit.
struct PdfLayout {
  glm::dvec2 pageMm{0.0};
  double rows = 1.0, columns = 1.0;
  double scale = 1.0;  // paper over pattern (1: real size)
  bool landscape = false;
};
PdfLayout pdfLayout(const glm::dvec2& patternMm, Paper paper);

// The most tiles a crease pattern prints on (2,000 A4 tiles tape up to about 8 by 11 metres): a
// larger one is refused before anything is drawn.
inline constexpr double kMaxPdfPages = 2000.0;

// A pattern that would print on more than kMaxPdfPages tiles. One line naming the count.
class PdfTooLarge : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The tiles the sheet's crease pattern prints on (the cover not counted), from its extent alone.
double pdfPageCount(const Sheet& sheet, Paper paper);

// Lays out the sheet's development on pages. Throws std::invalid_argument for an empty sheet and
// PdfTooLarge for one that would need more than kMaxPdfPages tiles.
PdfPlan planCreasePatternPdf(const Sheet& sheet, const PdfOptions& options);

// Draws the plan with Cairo and writes it atomically. Throws FileError when the file cannot be
// written.
void writeCreasePatternPdf(const Sheet& sheet, const std::filesystem::path& path,
                           const PdfOptions& options);

}  // namespace curvefold
