// Curved initial surfaces built as grids of planar quads, so each quad's development is exact:
// cylinders and swept curves (rectangles), cones (trapezoids of a fan), and the discrete tangent
// developable of a helix (wedges between consecutive rulings).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/gtx/exterior_product.hpp>

#include "engine/surfaces/surface_builders.hpp"

namespace curvefold::detail {
namespace {

using std::numbers::pi;

// Vertex (i, j) of a grid with cols x rows quads, i around/along the curve, j across.
struct Grid {
  int cols = 1;
  int rows = 1;
  VertexIndex base = 0;  // index of vertex (0, 0)

  VertexIndex at(int i, int j) const { return base + static_cast<VertexIndex>(i * (rows + 1) + j); }
};

// Appends the grid's vertices from vertexAt(i, j) -> {3D, 2D} and its triangles, with the
// diagonals alternating like a checkerboard so the mesh has no preferred direction.
template <typename VertexAt>
Grid appendGrid(Sheet& sheet, int cols, int rows, VertexAt&& vertexAt) {
  const Grid grid{cols, rows, static_cast<VertexIndex>(sheet.positions.size())};
  for (int i = 0; i <= cols; ++i) {
    for (int j = 0; j <= rows; ++j) {
      const auto [position, flat] = vertexAt(i, j);
      sheet.positions.push_back(position);
      sheet.development.push_back(flat);
    }
  }
  for (int i = 0; i < cols; ++i) {
    for (int j = 0; j < rows; ++j) {
      const VertexIndex a = grid.at(i, j), b = grid.at(i + 1, j), c = grid.at(i + 1, j + 1),
                        d = grid.at(i, j + 1);
      if ((i + j) % 2 == 0) {
        sheet.triangles.push_back({a, b, c});
        sheet.triangles.push_back({a, c, d});
      } else {
        sheet.triangles.push_back({a, b, d});
        sheet.triangles.push_back({b, c, d});
      }
    }
  }
  return grid;
}

// Reverses every triangle when the first one is clockwise in the development (all quads of a
// grid share one orientation).
void orientCounterClockwise(Sheet& sheet) {
  const Triangle& t = sheet.triangles.front();
  const glm::dvec2& a = sheet.development[t[0]];
  if (glm::cross(sheet.development[t[1]] - a, sheet.development[t[2]] - a) > 0.0) return;
  for (Triangle& triangle : sheet.triangles) std::swap(triangle[1], triangle[2]);
}

// Closes a full turn: column `cols` takes column 0's 3D positions bit for bit, and both seam
// columns become slit edges.
void makeSlit(Sheet& sheet, const Grid& grid) {
  for (int j = 0; j <= grid.rows; ++j)
    sheet.positions[grid.at(grid.cols, j)] = sheet.positions[grid.at(0, j)];
  for (int j = 0; j < grid.rows; ++j) {
    sheet.tags.push_back({Edge::of(grid.at(0, j), grid.at(0, j + 1)), EdgeKind::Slit});
    sheet.tags.push_back(
        {Edge::of(grid.at(grid.cols, j), grid.at(grid.cols, j + 1)), EdgeKind::Slit});
  }
}

void centreDevelopment(Sheet& sheet) {
  glm::dvec2 lo = sheet.development.front(), hi = lo;
  for (const glm::dvec2& p : sheet.development) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::dvec2 centre = 0.5 * (lo + hi);
  for (glm::dvec2& p : sheet.development) p -= centre;
}

}  // namespace

Segments segmentsFor(double first, double second, int resolution, int minFirst, int minSecond) {
  Segments s;
  if (first >= second) {
    s.alongFirst = std::max(minFirst, resolution);
    s.alongSecond = std::max(minSecond, static_cast<int>(std::lround(resolution * second / first)));
  } else {
    s.alongSecond = std::max(minSecond, resolution);
    s.alongFirst = std::max(minFirst, static_cast<int>(std::lround(resolution * first / second)));
  }
  return s;
}

Sheet makeCylinder(const std::string& surface, double radius, double height, double angleDegrees,
                   int resolution) {
  const double angle = angleDegrees * pi / 180.0;
  const Segments seg = segmentsFor(radius * angle, height, resolution, 3, 1);
  const int n = seg.alongFirst, m = seg.alongSecond;
  checkTriangleCount(surface, resolution, 2.0 * n * m);
  const double step = angle / n;
  const double chord = 2.0 * radius * std::sin(0.5 * step);  // the discrete circumference's unit
  Sheet sheet;
  const Grid grid = appendGrid(sheet, n, m, [&](int i, int j) {
    const double theta = -0.5 * angle + i * step;
    const double y = -0.5 * height + height * j / m;
    return std::pair{glm::dvec3(radius * std::sin(theta), y, radius * std::cos(theta)),
                     glm::dvec2((i - 0.5 * n) * chord, y)};
  });
  if (angleDegrees == 360.0) makeSlit(sheet, grid);
  orientCounterClockwise(sheet);
  sheet.normalizeTags();
  return sheet;
}

Sheet makeCone(const std::string& surface, double baseRadius, double height, double topRadius,
               double angleDegrees, int resolution) {
  if (topRadius >= baseRadius)
    failParameter(surface, "top_radius", topRadius,
                  "must be less than base_radius = " + formatNumber(baseRadius));
  // Radii this close put the apex so far away (slant / size ~ base_radius / difference) that the
  // development's coordinates lose the digits the 1e-9 isometry needs: that is a cylinder.
  if (baseRadius - topRadius < kMinConeTaper * baseRadius)
    failParameter(surface, "top_radius", topRadius,
                  "is within " + formatNumber(kMinConeTaper) +
                      " of base_radius: the apex is too far to develop exactly; use a cylinder");
  const double angle = angleDegrees * pi / 180.0;
  const double apexHeight = height * baseRadius / (baseRadius - topRadius);  // above the base
  const double slant = std::hypot(baseRadius, apexHeight);                   // apex to base
  const double topSlant = slant * topRadius / baseRadius;
  const Segments seg = segmentsFor(baseRadius * angle, slant - topSlant, resolution, 3, 1);
  const int n = seg.alongFirst, m = seg.alongSecond;
  checkTriangleCount(surface, resolution, 2.0 * n * m);
  const double step = angle / n;
  // Apex angle of one planar segment of the fan: its base chord 2 R sin(step/2) seen at slant S.
  const double beta = 2.0 * std::asin(baseRadius / slant * std::sin(0.5 * step));
  const double apexY = -0.5 * height + apexHeight;
  const bool withApex = topRadius == 0.0;
  auto vertexAt = [&](int i, double s) {
    const double theta = -0.5 * angle + i * step;
    const double rho = baseRadius * s / slant;
    const double phi = -0.5 * pi + (i - 0.5 * n) * beta;
    return std::pair{
        glm::dvec3(rho * std::sin(theta), apexY - apexHeight * s / slant, rho * std::cos(theta)),
        glm::dvec2(s * std::cos(phi), s * std::sin(phi))};
  };
  auto slantOfRing = [&](int ring) { return topSlant + (slant - topSlant) * ring / m; };

  Sheet sheet;
  // With an apex, ring 0 collapses to one vertex and the grid starts at ring 1.
  const int firstRing = withApex ? 1 : 0;
  const Grid grid = appendGrid(sheet, n, m - firstRing, [&](int i, int j) {
    return vertexAt(i, slantOfRing(j + firstRing));
  });
  if (angleDegrees == 360.0) makeSlit(sheet, grid);
  if (withApex) {
    const VertexIndex apex = static_cast<VertexIndex>(sheet.positions.size());
    sheet.positions.emplace_back(0.0, apexY, 0.0);
    sheet.development.emplace_back(0.0, 0.0);
    for (int i = 0; i < n; ++i) sheet.triangles.push_back({apex, grid.at(i + 1, 0), grid.at(i, 0)});
    if (angleDegrees == 360.0) {
      sheet.tags.push_back({Edge::of(apex, grid.at(0, 0)), EdgeKind::Slit});
      sheet.tags.push_back({Edge::of(apex, grid.at(n, 0)), EdgeKind::Slit});
    }
  }
  // The fan's grid runs clockwise in the development (i turns left, j points away from the apex);
  // the apex triangles were written to match the grid's first triangle's orientation.
  orientCounterClockwise(sheet);
  centreDevelopment(sheet);
  sheet.normalizeTags();
  return sheet;
}

Sheet makeSweptSine(const std::string& surface, double amplitude, double wavelength,
                    double curveWidth, double length, int resolution) {
  const double k = 2.0 * pi / wavelength;
  auto curve = [&](double x) { return glm::dvec2(x, amplitude * std::sin(k * x)); };
  // Fewer than kSamplesPerWave samples along each wave alias it into a zig-zag of the wrong
  // amplitude. The samples along the curve number at least resolution * min(1, width / length).
  if (amplitude > 0.0) {
    const double waves = curveWidth / wavelength;
    const double needed =
        std::ceil(kSweptSamplesPerWave * waves / std::min(1.0, curveWidth / length));
    if (resolution < needed)
      failParameter(
          surface, "resolution", resolution,
          "under-samples the curve: its " + formatApprox(waves) + " waves need " +
              std::to_string(int(kSweptSamplesPerWave)) +
              " samples each; the smallest resolution that works is " + formatApprox(needed) +
              (needed > kMaxResolution ? ", above the limit: lengthen the wavelength" : ""));
  }
  // Arc length from a dense polyline, to space the samples evenly along the curve.
  const int dense = 4096 + 64 * resolution;
  std::vector<double> arc(dense + 1, 0.0);
  for (int i = 1; i <= dense; ++i)
    arc[i] = arc[i - 1] + glm::distance(curve(curveWidth * ((i - 1.0) / dense - 0.5)),
                                        curve(curveWidth * (static_cast<double>(i) / dense - 0.5)));
  const Segments seg = segmentsFor(arc.back(), length, resolution, 1, 1);
  const int n = seg.alongFirst, m = seg.alongSecond;
  checkTriangleCount(surface, resolution, 2.0 * n * m);
  std::vector<glm::dvec2> samples(n + 1);
  for (int i = 0, cell = 0; i <= n; ++i) {
    const double target = arc.back() * i / n;
    while (cell + 1 < dense && arc[cell + 1] < target) ++cell;
    const double t = std::clamp((target - arc[cell]) / (arc[cell + 1] - arc[cell]), 0.0, 1.0);
    samples[i] = curve(curveWidth * ((cell + t) / dense - 0.5));
  }
  samples.front() = curve(-0.5 * curveWidth);
  samples.back() = curve(0.5 * curveWidth);
  // The development runs along the chords of the samples, not the smooth curve's arc.
  std::vector<double> chordLength(n + 1, 0.0);
  for (int i = 1; i <= n; ++i)
    chordLength[i] = chordLength[i - 1] + glm::distance(samples[i - 1], samples[i]);
  Sheet sheet;
  appendGrid(sheet, n, m, [&](int i, int j) {
    const double y = -0.5 * length + length * j / m;
    return std::pair{glm::dvec3(samples[i].x, y, samples[i].y),
                     glm::dvec2(chordLength[i] - 0.5 * chordLength[n], y)};
  });
  orientCounterClockwise(sheet);
  return sheet;
}

Sheet makeHelixTangent(const std::string& surface, double radius, double pitch, double turns,
                       double rulingStart, double rulingWidth, int resolution) {
  const double rise = pitch / (2.0 * pi);  // per radian
  const double helixLength = 2.0 * pi * turns * std::hypot(radius, rise);
  const Segments seg = segmentsFor(helixLength, rulingWidth, resolution, 2, 1);
  const int n = seg.alongFirst, m = seg.alongSecond;
  checkTriangleCount(surface, resolution, 2.0 * n * m);
  const double step = 2.0 * pi * turns / n;
  // Samples 0..n+1 give rulings 0..n along the chords P_i -> P_{i+1}; consecutive rulings meet at
  // P_{i+1}, so the strip between them is planar.
  std::vector<glm::dvec3> p(n + 2);
  for (int i = 0; i <= n + 1; ++i) {
    const double t = i * step;
    p[i] = glm::dvec3(radius * std::sin(t), rise * (t - pi * turns), radius * std::cos(t));
  }
  std::vector<glm::dvec3> d(n + 1);
  std::vector<double> chord(n + 1);
  for (int i = 0; i <= n; ++i) {
    chord[i] = glm::distance(p[i], p[i + 1]);
    d[i] = (p[i + 1] - p[i]) / chord[i];
  }
  if (!(rulingStart > chord[0]))
    failParameter(surface, "ruling_start", rulingStart,
                  "must exceed the helix sample spacing " + formatApprox(chord[0]) +
                      " at resolution " + std::to_string(resolution));
  // Lay the polyline flat with the same chords and turning angles, all turning left.
  std::vector<glm::dvec2> q(n + 1), e(n + 1);
  double heading = 0.0;
  q[0] = glm::dvec2(0.0);
  for (int i = 0; i <= n; ++i) {
    if (i > 0) {
      heading += std::atan2(glm::length(glm::cross(d[i - 1], d[i])), glm::dot(d[i - 1], d[i]));
      q[i] = q[i - 1] + chord[i - 1] * e[i - 1];
    }
    e[i] = glm::dvec2(std::cos(heading), std::sin(heading));
  }
  if (!(heading < 2.0 * pi))
    failParameter(surface, "turns", turns,
                  "turns the rulings by " + formatApprox(heading) +
                      " rad in the development, which must stay below 2 pi (keep turns below " +
                      formatApprox(std::hypot(radius, rise) / radius) + ")");
  Sheet sheet;
  appendGrid(sheet, n, m, [&](int i, int j) {
    const double u = rulingStart + rulingWidth * j / m;
    return std::pair{p[i] + u * d[i], q[i] + u * e[i]};
  });
  orientCounterClockwise(sheet);
  centreDevelopment(sheet);
  return sheet;
}

}  // namespace curvefold::detail
