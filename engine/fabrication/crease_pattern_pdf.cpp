#include "engine/fabrication/crease_pattern_pdf.hpp"

#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <ostream>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "engine/fabrication/colours.hpp"
#include "engine/fabrication/pattern_edges.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/io/atomic_file.hpp"

namespace curvefold {
namespace {

constexpr double kMarkLengthMm = 5.0;  // a cut mark runs this far out from a tile's corner
constexpr double kMarkGapMm = 1.0;     // and starts this far from it, so a cut leaves no line

std::string formatted(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// The drawn edges of the development: creases, boundary and cuts, in metres.
struct PatternEdge {
  glm::dvec2 a, b;
  Assignment assignment;
};

struct Pattern {
  std::vector<PatternEdge> edges;
  std::vector<std::pair<glm::dvec2, std::string>> labels;  // angle labels, at development points
  glm::dvec2 low{0.0}, high{0.0};                          // metres
};

Pattern patternOf(const Sheet& sheet, bool angles) {
  Pattern pattern;
  if (sheet.development.empty())
    throw std::invalid_argument("the sheet is empty: nothing to print");
  const DevelopmentBounds bounds = developmentBounds(sheet);
  pattern.low = bounds.low;
  pattern.high = bounds.high;
  const EdgeTopology topology = buildEdgeTopology(sheet);
  for (const DrawnEdge& e : drawnEdges(sheet, topology))
    pattern.edges.push_back(
        {sheet.development[e.edge.a], sheet.development[e.edge.b], e.assignment});
  if (angles) {
    // One label per crease curve, at its middle edge, with that edge's angle: along a curved
    // crease the angle varies, and one number per edge would bury the pattern.
    const std::vector<CreaseEdge> creases = creaseEdges(sheet, topology);
    for (const CreaseCurve& curve : creaseCurves(sheet, topology)) {
      if (curve.vertices.size() < 2) continue;
      const std::size_t middle = (curve.vertices.size() - 1) / 2;
      const Edge edge = Edge::of(curve.vertices[middle], curve.vertices[middle + 1]);
      const auto found = std::find_if(creases.begin(), creases.end(),
                                      [&](const CreaseEdge& c) { return c.edge == edge; });
      if (found == creases.end() ||
          (found->assignment != Assignment::Mountain && found->assignment != Assignment::Valley))
        continue;
      const char* kind = found->assignment == Assignment::Mountain ? "M " : "V ";
      pattern.labels.push_back({0.5 * (sheet.development[edge.a] + sheet.development[edge.b]),
                                kind + formatted("%.0f\u00b0", std::abs(found->foldAngle))});
    }
  }
  return pattern;
}

// The rectangle of a page that holds the pattern (points): inside the margins, above the footer.
PdfRect printableArea(const glm::dvec2& pagePt) {
  const double margin = kPageMarginMm * kPointsPerMm;
  return {{margin, margin}, {pagePt.x - margin, pagePt.y - margin - kFooterMm * kPointsPerMm}};
}

void addFooter(PdfPage& page, const std::string& label, const std::string& scaleNote) {
  const double margin = kPageMarginMm * kPointsPerMm;
  const double baseline = page.sizePt.y - margin - 2.0 * kPointsPerMm;
  page.scaleBarStart = {margin, baseline - 5.0 * kPointsPerMm};
  page.scaleBarLengthPt = kScaleBarMm * kPointsPerMm;
  page.texts.push_back({{margin, baseline}, 7.0, scaleNote});
  page.texts.push_back(
      {{page.sizePt.x * 0.5, page.scaleBarStart.y + 1.0 * kPointsPerMm}, 9.0, label});
}

// Corner marks outside a tile's rectangle, along both of its edges at each corner.
void addCutMarks(PdfPage& page, const PdfRect& tile) {
  const double gap = kMarkGapMm * kPointsPerMm, length = kMarkLengthMm * kPointsPerMm;
  for (const double x : {tile.low.x, tile.high.x})
    for (const double y : {tile.low.y, tile.high.y}) {
      const double sx = x == tile.low.x ? -1.0 : 1.0, sy = y == tile.low.y ? -1.0 : 1.0;
      page.marks.push_back({{x + sx * gap, y}, {x + sx * (gap + length), y}});
      page.marks.push_back({{x, y + sy * gap}, {x, y + sy * (gap + length)}});
    }
}

}  // namespace

std::optional<Paper> parsePaper(std::string_view name) {
  if (name == "a4") return Paper::A4;
  if (name == "letter") return Paper::Letter;
  if (name == "a3") return Paper::A3;
  if (name == "fit") return Paper::Fit;
  return std::nullopt;
}

glm::dvec2 paperSizeMm(Paper paper) {
  switch (paper) {
    case Paper::Letter:
      return {215.9, 279.4};
    case Paper::A3:
      return {297.0, 420.0};
    default:
      return {210.0, 297.0};
  }
}

PdfLineStyle pdfLineStyle(Assignment assignment) {
  const PaperRgb c = paperPdfColour(assignment);
  switch (assignment) {
    case Assignment::Mountain:  // dash-dot
      return {c.red, c.green, c.blue, 0.3, {3.0, 1.0, 0.3, 1.0}};
    case Assignment::Valley:  // dashed
      return {c.red, c.green, c.blue, 0.3, {2.0, 1.2}};
    default:  // the boundary and cuts (slits): solid
      return {c.red, c.green, c.blue, 0.3, {}};
  }
}

PdfLayout pdfLayout(const glm::dvec2& patternMm, Paper paper) {
  const glm::dvec2 portraitMm = paperSizeMm(paper);
  // Tiles at 1:1, or one page scaled down; portrait or landscape, whichever needs fewer pages
  // (or, to fit, allows the larger scale). Counts are doubles: a sheet kilometres wide would
  // overflow an int before it is refused.
  auto layoutFor = [&](const glm::dvec2& pageMm, bool landscape) {
    const glm::dvec2 area =
        pageMm - glm::dvec2(2.0 * kPageMarginMm, 2.0 * kPageMarginMm + kFooterMm);
    if (paper == Paper::Fit) {
      const double scale = std::min({area.x / std::max(patternMm.x, kSamePointMm),
                                     area.y / std::max(patternMm.y, kSamePointMm), 1.0});
      return PdfLayout{pageMm, 1.0, 1.0, scale, landscape};
    }
    auto count = [&](double extent, double room) {
      return extent <= room ? 1.0 : 1.0 + std::ceil((extent - room) / (room - kOverlapMm));
    };
    return PdfLayout{pageMm, count(patternMm.y, area.y), count(patternMm.x, area.x), 1.0,
                     landscape};
  };
  const PdfLayout portrait = layoutFor(portraitMm, false);
  const PdfLayout landscape = layoutFor({portraitMm.y, portraitMm.x}, true);
  const bool useLandscape =
      paper == Paper::Fit ? landscape.scale > portrait.scale
                          : landscape.rows * landscape.columns < portrait.rows * portrait.columns;
  return useLandscape ? landscape : portrait;
}

double pdfPageCount(const Sheet& sheet, Paper paper) {
  if (sheet.development.empty()) return 0.0;
  const DevelopmentBounds bounds = developmentBounds(sheet);
  const PdfLayout layout = pdfLayout((bounds.high - bounds.low) * kMmPerMetre, paper);
  return layout.rows * layout.columns;
}

namespace {

// A pattern that would print on more than kMaxPdfPages tiles is refused before anything is drawn.
void refuseTooManyPages(const glm::dvec2& patternMm, const PdfLayout& layout) {
  if (layout.rows * layout.columns > kMaxPdfPages)
    throw PdfTooLarge("a " + formatted("%.0f", patternMm.x) + " x " +
                      formatted("%.0f", patternMm.y) + " mm crease pattern would print on " +
                      formatted("%.0f", layout.rows * layout.columns) +
                      " pages at real size, more than " + formatted("%.0f", kMaxPdfPages));
}

std::string paperName(Paper paper) {
  return paper == Paper::Letter ? "letter" : paper == Paper::A3 ? "A3" : "A4";
}

// What every page of a plan is drawn from: the pattern, the options, the page size and the
// printable area on it (points).
struct PageSetup {
  const Pattern& pattern;
  const PdfOptions& options;
  glm::dvec2 pagePt;
  PdfRect area;
};

// Where the pattern lies on a page: the window whose top left pattern corner is `origin` (mm from
// the pattern's top left) drawn at `at` (points), at `scale`.
struct Placement {
  glm::dvec2 origin, at;
  double scale;
};

// Pattern (metres, y up) to page points (y down).
glm::dvec2 place(const Pattern& pattern, const Placement& placement, const glm::dvec2& p) {
  const glm::dvec2 mm((p.x - pattern.low.x) * kMmPerMetre, (pattern.high.y - p.y) * kMmPerMetre);
  return placement.at + (mm - placement.origin) * placement.scale * kPointsPerMm;
}

// The pattern's edges (and labels, if asked) that reach into the page's clip.
void addPattern(PdfPage& page, const Pattern& pattern, const Placement& placement, bool labels) {
  const PdfRect& clip = page.clip;
  const double pointsPerPatternMm = placement.scale * kPointsPerMm;
  page.patternWindowMm = {placement.origin + (clip.low - placement.at) / pointsPerPatternMm,
                          placement.origin + (clip.high - placement.at) / pointsPerPatternMm};
  for (const PatternEdge& e : pattern.edges) {
    const glm::dvec2 a = place(pattern, placement, e.a), b = place(pattern, placement, e.b);
    if (std::max(a.x, b.x) < clip.low.x || std::min(a.x, b.x) > clip.high.x ||
        std::max(a.y, b.y) < clip.low.y || std::min(a.y, b.y) > clip.high.y)
      continue;
    page.lines.push_back({a, b, e.assignment});
  }
  if (!labels) return;
  for (const auto& [p, text] : pattern.labels) {
    const glm::dvec2 q = place(pattern, placement, p);
    if (q.x >= clip.low.x && q.x <= clip.high.x && q.y >= clip.low.y && q.y <= clip.high.y)
      page.texts.push_back({q + glm::dvec2(1.0, -1.0), 6.0, text});
  }
}

// The cover's lines beside the pattern: the caller's facts, then the size, the paper and how to
// print, read and tape the pages.
std::vector<std::string> coverFacts(const PdfPlan& plan, const PdfOptions& options) {
  const int tiles = plan.rows * plan.columns;
  const std::string paper = paperName(options.paper);
  std::vector<std::string> facts = options.facts;
  facts.push_back("pattern " + formatted("%.1f", plan.patternMm.x) + " x " +
                  formatted("%.1f", plan.patternMm.y) + " mm");
  if (options.paper == Paper::Fit)
    facts.push_back("printed on one " + paper + " page at " +
                    formatted("%.1f", 100.0 * plan.scale) + "% of real size");
  else
    facts.push_back("printed at real size on " + std::to_string(tiles) + " " + paper +
                    (tiles == 1 ? " page" : " pages") + " (" + std::to_string(plan.rows) + " x " +
                    std::to_string(plan.columns) + ")");
  facts.push_back("print at 100% (actual size); check the 50 mm bar");
  facts.push_back("mountain: red dash-dot; valley: blue dashed");
  facts.push_back("cut: green; boundary: black");
  if (tiles > 1) {
    facts.push_back("cut each page at its corner marks, lay it");
    facts.push_back("over its left and upper neighbours so their");
    facts.push_back("edges meet the grey lines, and tape");
  }
  return facts;
}

// The cover: the folded form above, the pattern at a glance and the facts below.
PdfPage coverPage(const PageSetup& setup, const PdfPlan& plan) {
  const PdfRect& area = setup.area;
  PdfPage cover;
  cover.sizePt = setup.pagePt;
  cover.cover = true;
  const double line = 12.0;
  double y = area.low.y + 16.0;
  cover.texts.push_back(
      {{area.low.x, y}, 16.0, setup.options.title.empty() ? "curvefold" : setup.options.title});
  y += 8.0;
  const glm::dvec2 areaSize = area.high - area.low;
  cover.pictureBox = PdfRect{{area.low.x, y}, {area.high.x, y + 0.45 * areaSize.y}};
  y = cover.pictureBox->high.y + 10.0;
  const PdfRect glance{{area.low.x, y}, {area.low.x + 0.5 * areaSize.x, area.high.y}};
  cover.clip = glance;
  const glm::dvec2 glanceSize = glance.high - glance.low;
  const double glanceScale = std::min(glanceSize.x / (plan.patternMm.x * kPointsPerMm),
                                      glanceSize.y / (plan.patternMm.y * kPointsPerMm));
  addPattern(cover, setup.pattern, {{0.0, 0.0}, glance.low, glanceScale}, false);
  double factsY = y + line;
  const double factsX = glance.high.x + 12.0;
  for (const std::string& fact : coverFacts(plan, setup.options)) {
    cover.texts.push_back({{factsX, factsY}, 9.0, fact});
    factsY += line;
  }
  addFooter(cover, "cover, page 1 of " + std::to_string(plan.rows * plan.columns + 1), "50 mm");
  return cover;
}

// Where the left and upper neighbours' tile edges go on a tile: their overlap band ends there.
void addNeighbourGuides(PdfPage& page, const PdfRect& area, int row, int column) {
  const double overlap = kOverlapMm * kPointsPerMm;
  if (column > 0)
    page.guides.push_back(
        {{area.low.x + overlap, area.low.y}, {area.low.x + overlap, area.high.y}});
  if (row > 0)
    page.guides.push_back(
        {{area.low.x, area.low.y + overlap}, {area.high.x, area.low.y + overlap}});
}

std::string tileLabel(const PdfPlan& plan, Paper paper, int row, int column) {
  if (paper == Paper::Fit)
    return "scale " + formatted("%.1f", 100.0 * plan.scale) + "%, page 2 of 2";
  const int tiles = plan.rows * plan.columns;
  const int pageNumber = row * plan.columns + column + 2;  // the cover is page 1
  return "row " + std::to_string(row + 1) + ", column " + std::to_string(column + 1) + " of " +
         std::to_string(plan.rows) + " x " + std::to_string(plan.columns) + ", page " +
         std::to_string(pageNumber) + " of " + std::to_string(tiles + 1);
}

// The tile at `row`, `column`: its window of the pattern at real size, with cut marks and the
// neighbours' edges, or (to fit) the whole pattern scaled and centred.
PdfPage tilePage(const PageSetup& setup, const PdfPlan& plan, int row, int column) {
  const PdfRect& area = setup.area;
  PdfPage page;
  page.sizePt = setup.pagePt;
  page.clip = area;
  const glm::dvec2 stepMm = (area.high - area.low) / kPointsPerMm - glm::dvec2(kOverlapMm);
  const glm::dvec2 origin(column * stepMm.x, row * stepMm.y);
  if (setup.options.paper == Paper::Fit) {
    const glm::dvec2 drawn = plan.patternMm * plan.scale * kPointsPerMm;
    const glm::dvec2 at = area.low + 0.5 * ((area.high - area.low) - drawn);
    addPattern(page, setup.pattern, {origin, at, plan.scale}, setup.options.angles);
  } else {
    addPattern(page, setup.pattern, {origin, area.low, 1.0}, setup.options.angles);
    addCutMarks(page, area);
    addNeighbourGuides(page, area, row, column);
  }
  addFooter(page, tileLabel(plan, setup.options.paper, row, column),
            "50 mm: measure it to check the printer's scale");
  return page;
}

}  // namespace

PdfPlan planCreasePatternPdf(const Sheet& sheet, const PdfOptions& options) {
  const Pattern pattern = patternOf(sheet, options.angles);
  PdfPlan plan;
  plan.patternMm = (pattern.high - pattern.low) * kMmPerMetre;
  const PdfLayout layout = pdfLayout(plan.patternMm, options.paper);
  refuseTooManyPages(plan.patternMm, layout);
  plan.rows = int(layout.rows);
  plan.columns = int(layout.columns);
  plan.scale = layout.scale;
  plan.landscape = layout.landscape;
  const glm::dvec2 pagePt = layout.pageMm * kPointsPerMm;
  const PageSetup setup{pattern, options, pagePt, printableArea(pagePt)};
  plan.pages.push_back(coverPage(setup, plan));
  // The tiles, row by row.
  for (int row = 0; row < plan.rows; ++row)
    for (int column = 0; column < plan.columns; ++column)
      plan.pages.push_back(tilePage(setup, plan, row, column));
  return plan;
}

namespace {

cairo_status_t writeToStream(void* closure, const unsigned char* data, unsigned int length) {
  auto& out = *static_cast<std::ostream*>(closure);
  out.write(reinterpret_cast<const char*>(data), length);
  return out ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

void stroke(cairo_t* cr, const PdfSegment& s) {
  cairo_move_to(cr, s.a.x, s.a.y);
  cairo_line_to(cr, s.b.x, s.b.y);
  cairo_stroke(cr);
}

void setStyle(cairo_t* cr, const PdfLineStyle& style) {
  cairo_set_source_rgb(cr, style.red, style.green, style.blue);
  cairo_set_line_width(cr, style.widthMm * kPointsPerMm);
  std::vector<double> dashes;
  for (double d : style.dashMm) dashes.push_back(d * kPointsPerMm);
  cairo_set_dash(cr, dashes.data(), int(dashes.size()), 0.0);
}

// The folded form, scaled into the box, keeping its aspect.
void drawPicture(cairo_t* cr, const PdfPicture& picture, const PdfRect& box) {
  if (picture.width == 0 || picture.height == 0 ||
      picture.rgba.size() != std::size_t(picture.width) * picture.height * 4)
    return;
  cairo_surface_t* image =
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, int(picture.width), int(picture.height));
  const int stride = cairo_image_surface_get_stride(image);
  unsigned char* data = cairo_image_surface_get_data(image);
  cairo_surface_flush(image);
  for (std::uint32_t y = 0; y < picture.height; ++y)
    for (std::uint32_t x = 0; x < picture.width; ++x) {
      const std::uint8_t* p = picture.rgba.data() + (std::size_t(y) * picture.width + x) * 4;
      auto* pixel = reinterpret_cast<std::uint32_t*>(data + std::size_t(y) * stride + 4 * x);
      *pixel = 0xff000000u | std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2];
    }
  cairo_surface_mark_dirty(image);
  const glm::dvec2 size = box.high - box.low;
  const double scale = std::min(size.x / picture.width, size.y / picture.height);
  cairo_save(cr);
  cairo_translate(cr, box.low.x + 0.5 * (size.x - scale * picture.width),
                  box.low.y + 0.5 * (size.y - scale * picture.height));
  cairo_scale(cr, scale, scale);
  cairo_set_source_surface(cr, image, 0, 0);
  cairo_paint(cr);
  cairo_restore(cr);
  cairo_surface_destroy(image);
}

void drawPage(cairo_t* cr, const PdfPage& page, const PdfPicture* picture) {
  if (page.pictureBox && picture) drawPicture(cr, *picture, *page.pictureBox);
  cairo_save(cr);
  cairo_rectangle(cr, page.clip.low.x, page.clip.low.y, page.clip.high.x - page.clip.low.x,
                  page.clip.high.y - page.clip.low.y);
  cairo_clip(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  // Boundary and cuts first, then valleys, then mountains on top.
  for (const Assignment kind :
       {Assignment::Boundary, Assignment::Cut, Assignment::Valley, Assignment::Mountain}) {
    setStyle(cr, pdfLineStyle(kind));
    for (const PdfSegment& s : page.lines)
      if (s.assignment == kind) stroke(cr, s);
  }
  cairo_restore(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_set_line_width(cr, 0.15 * kPointsPerMm);
  for (const PdfSegment& s : page.marks) stroke(cr, s);
  const double guideDash[] = {1.0 * kPointsPerMm, 1.0 * kPointsPerMm};
  cairo_set_dash(cr, guideDash, 2, 0.0);
  cairo_set_source_rgb(cr, 0.55, 0.55, 0.55);
  for (const PdfSegment& s : page.guides) stroke(cr, s);
  // The scale bar: a 50 mm bar with a tick every 10 mm.
  cairo_set_dash(cr, nullptr, 0, 0.0);
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_set_line_width(cr, 0.3 * kPointsPerMm);
  const glm::dvec2 bar = page.scaleBarStart;
  stroke(cr, {bar, bar + glm::dvec2(page.scaleBarLengthPt, 0.0)});
  for (int tick = 0; tick <= 5; ++tick) {
    const double x = bar.x + tick * page.scaleBarLengthPt / 5.0;
    stroke(cr, {{x, bar.y - (tick % 5 == 0 ? 2.0 : 1.0) * kPointsPerMm}, {x, bar.y}});
  }
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  for (const PdfText& text : page.texts) {
    cairo_set_font_size(cr, text.sizePt);
    cairo_move_to(cr, text.at.x, text.at.y);
    cairo_show_text(cr, text.text.c_str());
  }
}

}  // namespace

void writeCreasePatternPdf(const Sheet& sheet, const std::filesystem::path& path,
                           const PdfOptions& options) {
  const PdfPlan plan = planCreasePatternPdf(sheet, options);
  writeFileAtomically(path, [&](std::ostream& out) {
    const glm::dvec2 first = plan.pages.front().sizePt;
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        cairo_pdf_surface_create_for_stream(writeToStream, &out, first.x, first.y),
        cairo_surface_destroy);
    // The cover's title is the document's too (a viewer's title bar).
    if (!options.title.empty())
      cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE,
                                     options.title.c_str());
    std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()),
                                                          cairo_destroy);
    for (const PdfPage& page : plan.pages) {
      cairo_pdf_surface_set_size(surface.get(), page.sizePt.x, page.sizePt.y);
      drawPage(cr.get(), page, options.picture ? &*options.picture : nullptr);
      cairo_show_page(cr.get());
    }
    cr.reset();
    cairo_surface_finish(surface.get());
    if (const cairo_status_t status = cairo_surface_status(surface.get());
        status != CAIRO_STATUS_SUCCESS)
      throw FileError("cannot write " + path.string() + ": " + cairo_status_to_string(status));
  });
}

}  // namespace curvefold
