#include "engine/render/color_legend.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <cairo.h>

namespace curvefold {
namespace {

// A number as a legend shows it: 3 significant digits, no exponent for everyday sizes.
std::string numberText(double value) {
  char text[32];
  const double magnitude = std::abs(value);
  if (value == 0.0 || (magnitude >= 1e-3 && magnitude < 1e5))
    std::snprintf(text, sizeof text, "%.3g", value);
  else
    std::snprintf(text, sizeof text, "%.2e", value);
  return text;
}

}  // namespace

std::uint32_t legendWidth(std::uint32_t imageWidth) {
  return std::clamp<std::uint32_t>(imageWidth / 7, 110, 220);
}

void drawColorLegend(RgbaImage& image, const ColorLegend& legend) {
  if (image.width < 120 || image.height < 80) return;
  const int width = int(image.width), height = int(image.height);
  // Cairo's ARGB32 is native-endian 0xAARRGGBB, premultiplied; the picture is opaque.
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface);
    return;  // no memory for it: the picture goes without its legend rather than fail
  }
  const int stride = cairo_image_surface_get_stride(surface);
  cairo_surface_flush(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  for (int y = 0; y < height; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + std::size_t(y) * stride);
    for (int x = 0; x < width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      row[x] = 0xff000000u | (std::uint32_t(p[0]) << 16) | (std::uint32_t(p[1]) << 8) | p[2];
    }
  }
  cairo_surface_mark_dirty(surface);

  cairo_t* cr = cairo_create(surface);
  // Fixed font options: left to the defaults, the glyphs depend on what Cairo drew before in the
  // process (a PDF export's unhinted fonts changed a later legend's pixels).
  cairo_font_options_t* fontOptions = cairo_font_options_create();
  cairo_font_options_set_antialias(fontOptions, CAIRO_ANTIALIAS_GRAY);
  cairo_font_options_set_hint_style(fontOptions, CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(fontOptions, CAIRO_HINT_METRICS_OFF);
  cairo_set_font_options(cr, fontOptions);
  cairo_font_options_destroy(fontOptions);
  const double strip = legendWidth(image.width);
  const double left = width - strip;
  const double font = std::clamp(height / 40.0, 10.0, 18.0);
  const double margin = font;
  // A light card under the legend, so it reads on any background.
  cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, 0.85);
  cairo_rectangle(cr, left + 0.25 * margin, 0.5 * margin, strip - 0.5 * margin, height - margin);
  cairo_fill(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, font);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);

  // Title (wrapped at its spaces to the strip's width), then the unit.
  double y = margin + 1.2 * font;
  std::string line, word;
  const auto flush = [&] {
    if (line.empty()) return;
    cairo_move_to(cr, left + 0.6 * margin, y);
    cairo_show_text(cr, line.c_str());
    y += 1.25 * font;
    line.clear();
  };
  const std::string words = legend.title + " ";
  for (char c : words) {
    if (c != ' ') {
      word += c;
      continue;
    }
    const std::string candidate = line.empty() ? word : line + " " + word;
    cairo_text_extents_t extents;
    cairo_text_extents(cr, candidate.c_str(), &extents);
    if (!line.empty() && extents.x_advance > strip - 1.2 * margin) {
      flush();
      line = word;
    } else {
      line = candidate;
    }
    word.clear();
  }
  flush();
  if (!legend.unit.empty()) {
    line = "(" + legend.unit + ")";
    flush();
  }

  // The bar: high at the top, as a thermometer reads.
  // On whole pixels: a row's rectangle straddling two rows would blend with the card beneath.
  const double barTop = std::round(y + 0.3 * font), barBottom = std::round(height - 1.5 * margin);
  const double barLeft = std::round(left + 0.6 * margin);
  const double barWidth = std::round(std::max(8.0, strip * 0.2));
  if (barBottom - barTop > 2.0 * font) {
    const int rows = int(barBottom - barTop);
    for (int r = 0; r < rows; ++r) {
      const glm::u8vec4 c = colorAt(legend.map, 1.0 - (r + 0.5) / rows);
      cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0);
      cairo_rectangle(cr, barLeft, barTop + r, barWidth, 1.0);
      cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, barLeft + 0.5, barTop + 0.5, barWidth - 1.0, rows - 1.0);
    cairo_stroke(cr);
    // Ticks and numbers at the top, middle and bottom.
    for (int k = 0; k <= 2; ++k) {
      const double t = 1.0 - 0.5 * k;
      const double ty = barTop + (1.0 - t) * (rows - 1) + 0.5;
      const double value = legend.low + t * (legend.high - legend.low);
      cairo_move_to(cr, barLeft + barWidth, ty);
      cairo_line_to(cr, barLeft + barWidth + 0.4 * font, ty);
      cairo_stroke(cr);
      cairo_move_to(cr, barLeft + barWidth + 0.6 * font, ty + 0.35 * font);
      cairo_show_text(cr, numberText(value).c_str());
    }
  }
  cairo_destroy(cr);
  cairo_surface_flush(surface);

  for (int yy = 0; yy < height; ++yy) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + std::size_t(yy) * stride);
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixels.data() + (std::size_t(yy) * width + x) * 4;
      p[0] = std::uint8_t(row[x] >> 16);
      p[1] = std::uint8_t(row[x] >> 8);
      p[2] = std::uint8_t(row[x]);
      p[3] = 255;
    }
  }
  cairo_surface_destroy(surface);
}

}  // namespace curvefold
