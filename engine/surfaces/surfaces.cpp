// The surface catalog, parameter checking, and the flat named outlines.
#include "engine/surfaces/surfaces.hpp"
#include "engine/text/excerpt.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtx/exterior_product.hpp>

#include "engine/surfaces/surface_builders.hpp"

namespace curvefold {
namespace detail {

std::string formatNumber(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string formatApprox(double value) {
  char buffer[64];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 6);
  return std::string(buffer, result.ptr);
}

void failParameter(const std::string& surface, const std::string& parameter, double value,
                   const std::string& why) {
  throw SurfaceError("surface '" + surface + "': parameter '" + parameter +
                     "' = " + formatNumber(value) + " " + why);
}

void checkTriangleCount(const std::string& surface, int resolution, double triangles) {
  if (triangles > static_cast<double>(kMaxSurfaceTriangles))
    failParameter(surface, "resolution", resolution,
                  "gives about " + formatApprox(triangles) + " triangles, more than the limit of " +
                      std::to_string(kMaxSurfaceTriangles));
}

double signedArea(const std::vector<glm::dvec2>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2& a = polygon[i];
    const glm::dvec2& b = polygon[(i + 1) % polygon.size()];
    twice += glm::cross(a, b);
  }
  return 0.5 * twice;
}

}  // namespace detail

namespace {

using detail::failParameter;
using detail::formatNumber;
using std::numbers::pi;

// Lengths from 0.1 mm to 10 km: below, triangles approach the degeneracy threshold; above, a
// value is a mistake rather than a sheet (architecture-sized sheets of 1 km are tested).
constexpr double kMinLength = 1e-4;
constexpr double kMaxLength = 1e4;
using detail::kMaxResolution;
// CGAL's mesher makes about 5 triangles per maxEdge^2 of area (measured); 6 leaves a margin.
constexpr double kMeshTrianglesPerArea = 6.0;
// A hole may use at most this fraction of the distance from the centre to the outline.
constexpr double kHoleMargin = 0.9;

SurfaceParameter length(std::string name, double value, std::string description) {
  return {std::move(name), value, kMinLength, kMaxLength, false, std::move(description)};
}
SurfaceParameter holeRadius() {
  return {"hole_radius", 0.0,   0.0,
          kMaxLength,    false, "radius of a circular hole in the middle, metres (0 = none)"};
}
SurfaceParameter resolution(double value) {
  return {"resolution",   value, 1.0,
          kMaxResolution, true,  "segments along the longer direction of the development"};
}
SurfaceParameter angle(double value) {
  return {"angle", value, 0.01, 360.0, false, "angle around the axis, degrees (360 = slit tube)"};
}

// Builds from checked parameters with a generator version from 1 to the entry's latest.
using Builder = std::function<Sheet(const SurfaceParameters&, int version)>;

struct CatalogEntry {
  SurfaceInfo info;
  Builder build;
};

int integer(const SurfaceParameters& p, const char* name) {
  return static_cast<int>(p.at(name));
}

// A length where 0 means "none" (no hole, no truncation) but anything else must be a real length:
// a hole or a top ring of 1e-20 m would only make degenerate triangles.
double zeroOrLength(const std::string& surface, const SurfaceParameters& p, const char* name) {
  const double value = p.at(name);
  if (value != 0.0 && value < kMinLength)
    failParameter(surface, name, value,
                  "must be 0 (none) or at least " + detail::formatApprox(kMinLength) + " m");
  return value;
}

// The highest rotation order a flat sheet's mesh is given: its centre then has 2 * 12 triangles
// of 15 degrees there (a 100-point star's 200 would be 1.8-degree slivers), and the symmetry
// finder looks for rotations up to 12.
constexpr int kMaxFlatOrder = 12;

// The largest divisor of n up to kMaxFlatOrder (1 for a prime above it: a mirror only).
int flatOrder(int n) {
  for (int m = std::min(n, kMaxFlatOrder); m > 1; --m)
    if (n % m == 0) return m;
  return 1;
}

// The most rotations a disk or star may be meshed with when asked (parseSymmetry's largest n):
// the centre of a disk then has 128 triangles of 2.8 degrees, still far from degenerate.
constexpr int kMaxAskedOrder = 64;

SurfaceParameter rotations(std::string automatic) {
  return {"rotations",
          0.0,
          0.0,
          kMaxAskedOrder,
          true,
          "n-fold rotation (and n mirrors) the mesh is made with, so that rotational:n is a "
          "symmetry; 0 = " +
              std::move(automatic)};
}

// Generator version 1 of the flat sheets (until 2026-12-04), kept so that designs saved then
// rebuild their sheet bit for bit: the whole outline and a circular hole meshed at once.
namespace version1 {

double polygonArea(const std::vector<glm::dvec2>& polygon) {
  return std::abs(detail::signedArea(polygon));
}

// A regular polygon inscribed in a circle, with edges no longer than maxEdge.
std::vector<glm::dvec2> circle(double radius, double maxEdge) {
  const int count = std::max(8, static_cast<int>(std::ceil(2.0 * pi * radius / maxEdge)));
  std::vector<glm::dvec2> points(count);
  for (int i = 0; i < count; ++i)
    points[i] = radius * glm::dvec2(std::cos(2.0 * pi * i / count), std::sin(2.0 * pi * i / count));
  return points;
}

// A flat outline with an optional central hole; inradius bounds the hole.
Sheet flatWithHole(const std::string& surface, const SurfaceParameters& p,
                   const std::vector<glm::dvec2>& outline, double longer, double inradius) {
  if (const auto asked = p.find("rotations"); asked != p.end() && asked->second != 0.0)
    failParameter(surface, "rotations", asked->second,
                  "needs generator version 2 (version 1 meshes the whole outline at once)");
  const double maxEdge = longer / integer(p, "resolution");
  const double hole = zeroOrLength(surface, p, "hole_radius");
  std::vector<std::vector<glm::dvec2>> holes;
  if (hole > 0.0) {
    if (!(hole < kHoleMargin * inradius))
      failParameter(surface, "hole_radius", hole,
                    "must be less than " + detail::formatApprox(kHoleMargin * inradius) +
                        " (90% of the distance from the centre to the outline)");
    holes.push_back(circle(hole, maxEdge));
  }
  detail::checkTriangleCount(surface, integer(p, "resolution"),
                             kMeshTrianglesPerArea * polygonArea(outline) / (maxEdge * maxEdge));
  return triangulateOutline(outline, holes, maxEdge);
}

Sheet diskSheet(const SurfaceParameters& p) {
  const double radius = p.at("radius");
  const std::vector<glm::dvec2> outline = circle(radius, 2.0 * radius / integer(p, "resolution"));
  const double inradius = radius * std::cos(pi / static_cast<double>(outline.size()));
  return flatWithHole("disk", p, outline, 2.0 * radius, inradius);
}

}  // namespace version1

// A flat outline with the dihedral symmetry of order `order` about the origin, meshed so that the
// mesh has it too: one half-wedge (between the rays at `start` and start + pi / order, each a
// mirror line of the outline) is meshed, mirrored across its second ray and the pair turned
// `order` times, vertices on the rays shared by index. `arc` runs along the outline from the
// first ray to the second; the whole outline sizes the mesh and bounds the hole.
Sheet symmetricFlat(const std::string& surface, const SurfaceParameters& p,
                    const std::vector<glm::dvec2>& outline, const std::vector<glm::dvec2>& arc,
                    double start, int order, double longer, double inradius) {
  const double maxEdge = longer / integer(p, "resolution");
  const double hole = zeroOrLength(surface, p, "hole_radius");
  if (hole > 0.0 && !(hole < kHoleMargin * inradius))
    failParameter(surface, "hole_radius", hole,
                  "must be less than " + detail::formatApprox(kHoleMargin * inradius) +
                      " (90% of the distance from the centre to the outline)");
  detail::checkTriangleCount(
      surface, integer(p, "resolution"),
      kMeshTrianglesPerArea * std::abs(detail::signedArea(outline)) / (maxEdge * maxEdge));
  const double wedge = pi / order;
  const glm::dvec2 first(std::cos(start), std::sin(start));
  const glm::dvec2 second(std::cos(start + wedge), std::sin(start + wedge));
  std::vector<glm::dvec2> half = arc;
  if (hole > 0.0) {
    // As many hole segments as a whole circle of at least 8 would give this half-wedge.
    const int total = std::max(8, static_cast<int>(std::ceil(2.0 * pi * hole / maxEdge)));
    const int segments = std::max(1, (total + 2 * order - 1) / (2 * order));
    for (int i = segments; i >= 0; --i) {
      const double a = start + wedge * i / segments;
      half.push_back(hole * glm::dvec2(std::cos(a), std::sin(a)));
    }
  } else {
    half.push_back({0.0, 0.0});
  }
  const Sheet piece = triangulateOutline(half, {}, maxEdge);

  // Which vertices lie on each ray: the mesher splits the rays at points on them, to rounding.
  const double tolerance = 1e-12 * longer;
  auto onRay = [&](const glm::dvec2& q, const glm::dvec2& ray) {
    return std::abs(glm::cross(ray, q)) <= tolerance && glm::dot(ray, q) >= -tolerance;
  };
  const std::size_t n = piece.vertexCount();
  std::vector<char> onFirst(n), onSecond(n);
  for (std::size_t v = 0; v < n; ++v) {
    onFirst[v] = onRay(piece.development[v], first);
    onSecond[v] = onRay(piece.development[v], second);
  }
  // Copy k turns by 2 pi k / order; side 1 is the mirror image across the second ray. A vertex on
  // the second ray is its own mirror image; one on the first ray is the mirror image of copy k - 1.
  auto canonical = [&](int k, int side, std::size_t v) -> std::size_t {
    if (onFirst[v] && onSecond[v]) return v;
    if (side == 1 && onSecond[v]) return (std::size_t(k) * 2) * n + v;
    if (side == 0 && onFirst[v]) return (std::size_t((k + order - 1) % order) * 2 + 1) * n + v;
    return (std::size_t(k) * 2 + side) * n + v;
  };
  auto placed = [&](std::size_t key) {
    const std::size_t v = key % n, k = key / n / 2;
    glm::dvec2 q = piece.development[v];
    if ((key / n) % 2 == 1) q = 2.0 * glm::dot(q, second) * second - q;
    const double turn = 2.0 * pi * static_cast<double>(k) / order;
    const double c = std::cos(turn), s = std::sin(turn);
    return glm::dvec2(c * q.x - s * q.y, s * q.x + c * q.y);
  };
  Sheet sheet;
  std::vector<VertexIndex> index(2 * order * n, kNoIndex);
  for (int k = 0; k < order; ++k)
    for (int side = 0; side < 2; ++side)
      for (const Triangle& t : piece.triangles) {
        Triangle out;
        for (int i = 0; i < 3; ++i) {
          const std::size_t key = canonical(k, side, t[i]);
          if (index[key] == kNoIndex) {
            index[key] = static_cast<VertexIndex>(sheet.positions.size());
            const glm::dvec2 q = placed(key);
            sheet.development.push_back(q);
            sheet.positions.emplace_back(q.x, q.y, 0.0);
          }
          out[i] = index[key];
        }
        if (side == 1) std::swap(out[1], out[2]);  // a mirror image turns the other way round
        sheet.triangles.push_back(out);
      }
  return sheet;
}

Sheet rectangleSheet(const std::string& surface, const SurfaceParameters& p, double width,
                     double height, int version) {
  const double x = 0.5 * width, y = 0.5 * height;
  const std::vector<glm::dvec2> outline{{-x, -y}, {x, -y}, {x, y}, {-x, y}};
  if (version == 1)
    return version1::flatWithHole(surface, p, outline, std::max(width, height), std::min(x, y));
  // A square is meshed with its four mirrors and turns, a rectangle with its two.
  const bool square = surface == "square";
  const std::vector<glm::dvec2> arc = square ? std::vector<glm::dvec2>{{x, 0.0}, {x, y}}
                                             : std::vector<glm::dvec2>{{x, 0.0}, {x, y}, {0.0, y}};
  return symmetricFlat(surface, p, outline, arc, 0.0, square ? 4 : 2, std::max(width, height),
                       std::min(x, y));
}

// Unless asked for another, a disk's polygon has a multiple of 24 sides, so its mesh has 12
// mirrors and 12-fold rotation.
constexpr int kDiskOrder = 12;

Sheet diskSheet(const SurfaceParameters& p, int version) {
  if (version == 1) return version1::diskSheet(p);
  const double radius = p.at("radius");
  const double maxEdge = 2.0 * radius / integer(p, "resolution");
  const int order = integer(p, "rotations") > 0 ? integer(p, "rotations") : kDiskOrder;
  const int steps = 2 * order;
  const int wanted = std::max(8, static_cast<int>(std::ceil(2.0 * pi * radius / maxEdge)));
  const int count = (wanted + steps - 1) / steps * steps;
  std::vector<glm::dvec2> outline(count);
  for (int i = 0; i < count; ++i)
    outline[i] =
        radius * glm::dvec2(std::cos(2.0 * pi * i / count), std::sin(2.0 * pi * i / count));
  const std::vector<glm::dvec2> arc(outline.begin(), outline.begin() + count / steps + 1);
  const double inradius = radius * std::cos(pi / static_cast<double>(count));
  return symmetricFlat("disk", p, outline, arc, 0.0, order, 2.0 * radius, inradius);
}

Sheet starSheet(const SurfaceParameters& p, int version) {
  const int points = integer(p, "points");
  const double outer = p.at("outer_radius"), inner = p.at("inner_radius");
  if (!(inner < outer))
    failParameter("star", "inner_radius", inner,
                  "must be less than outer_radius = " + formatNumber(outer));
  std::vector<glm::dvec2> outline(2 * points);
  for (int k = 0; k < 2 * points; ++k) {
    const double a = 0.5 * pi + k * pi / points;  // first point straight up
    outline[k] = (k % 2 == 0 ? outer : inner) * glm::dvec2(std::cos(a), std::sin(a));
  }
  // Distance from the centre to the line through an outer and the next inner point.
  const glm::dvec2 a = outline[0], b = outline[1];
  const double inradius = std::abs(glm::cross(a, b)) / std::hypot(b.x - a.x, b.y - a.y);
  if (version == 1) return version1::flatWithHole("star", p, outline, 2.0 * outer, inradius);
  const int asked = integer(p, "rotations");
  if (asked > 0 && points % asked != 0)
    failParameter("star", "rotations", asked,
                  "must divide points = " + std::to_string(points) +
                      " (a star turns onto itself only by a whole number of its points)");
  const int order = asked > 0 ? asked : flatOrder(points);
  const std::vector<glm::dvec2> arc(outline.begin(), outline.begin() + points / order + 1);
  return symmetricFlat("star", p, outline, arc, 0.5 * pi, order, 2.0 * outer, inradius);
}

const std::vector<CatalogEntry>& entries() {
  static const std::vector<CatalogEntry> catalog = [] {
    std::vector<CatalogEntry> list;
    list.push_back({{"square",
                     "flat square sheet in the plane z = 0",
                     {length("size", 0.2, "side length, metres"), holeRadius(), resolution(30)},
                     2},
                    [](const SurfaceParameters& p, int version) {
                      return rectangleSheet("square", p, p.at("size"), p.at("size"), version);
                    }});
    list.push_back(
        {{"rectangle",
          "flat rectangular sheet in the plane z = 0 (A4 landscape by default)",
          {length("width", 0.297, "extent along x, metres"),
           length("height", 0.21, "extent along y, metres"), holeRadius(), resolution(36)},
          2},
         [](const SurfaceParameters& p, int version) {
           return rectangleSheet("rectangle", p, p.at("width"), p.at("height"), version);
         }});
    list.push_back(
        {{"disk",
          "flat disk in the plane z = 0: a regular polygon of a multiple of 2n sides, meshed "
          "with n mirrors and n-fold rotation (n = rotations, 12 unless asked)",
          {length("radius", 0.1, "radius, metres"), holeRadius(), resolution(32), rotations("12")},
          2},
         diskSheet});
    list.push_back({{"star",
                     "flat star polygon in the plane z = 0, first point along +y; meshed with its "
                     "mirrors, and rotation by rotations (a divisor of points; unless asked, the "
                     "largest divisor of points up to 12)",
                     {{"points", 5.0, 3.0, 100.0, true, "number of points"},
                      length("outer_radius", 0.1, "radius of the points, metres"),
                      length("inner_radius", 0.045, "radius of the notches between points, metres"),
                      holeRadius(),
                      resolution(48),
                      rotations("the largest divisor of points up to 12")},
                     2},
                    starSheet});
    list.push_back(
        {{"cylinder",
          "cylinder around the y axis; angle 360 is a tube with a slit at -z",
          {length("radius", 0.045, "radius, metres"),
           length("height", 0.21, "extent along the axis, metres"), angle(360.0), resolution(48)}},
         [](const SurfaceParameters& p, int) {
           return detail::makeCylinder("cylinder", p.at("radius"), p.at("height"), p.at("angle"),
                                       integer(p, "resolution"));
         }});
    list.push_back({{"half_cylinder",
                     "half of a cylinder around the y axis (angle 180), bulging toward +z",
                     {length("radius", 0.06, "radius, metres"),
                      length("height", 0.21, "extent along the axis, metres"), resolution(48)}},
                    [](const SurfaceParameters& p, int) {
                      return detail::makeCylinder("half_cylinder", p.at("radius"), p.at("height"),
                                                  180.0, integer(p, "resolution"));
                    }});
    list.push_back(
        {{"cone",
          "cone around the y axis, apex up; top_radius > 0 truncates it; angle 360 has a slit",
          {length("base_radius", 0.08, "radius at the base, metres"),
           length("height", 0.12, "height of the (truncated) cone, metres"),
           {"top_radius", 0.0, 0.0, kMaxLength, false,
            "radius at the top, metres (0 = full cone with apex)"},
           angle(360.0),
           resolution(64)}},
         [](const SurfaceParameters& p, int) {
           return detail::makeCone("cone", p.at("base_radius"), p.at("height"),
                                   zeroOrLength("cone", p, "top_radius"), p.at("angle"),
                                   integer(p, "resolution"));
         }});
    list.push_back({{"swept_curve",
                     "sine curve z = amplitude sin(2 pi x / wavelength) swept along y",
                     {{"amplitude", 0.015, 0.0, kMaxLength, false, "amplitude of the sine, metres"},
                      length("wavelength", 0.1, "wavelength of the sine, metres"),
                      length("curve_width", 0.2, "extent of the curve along x, metres"),
                      length("length", 0.2, "extent of the sweep along y, metres"),
                      resolution(48)}},
                    [](const SurfaceParameters& p, int) {
                      return detail::makeSweptSine("swept_curve", p.at("amplitude"),
                                                   p.at("wavelength"), p.at("curve_width"),
                                                   p.at("length"), integer(p, "resolution"));
                    }});
    list.push_back(
        {{"helix_tangent",
          "tangent developable of a helix around the y axis (rulings along its chords)",
          {length("radius", 0.04, "radius of the helix, metres"),
           {"pitch", 0.12, 0.0, kMaxLength, false, "rise per turn, metres"},
           {"turns", 0.75, 0.01, 100.0, false, "turns of the helix"},
           length("ruling_start", 0.02,
                  "distance along each ruling where the sheet starts, metres (must exceed the "
                  "sample spacing)"),
           length("ruling_width", 0.08, "extent of the sheet along each ruling, metres"),
           resolution(64)}},
         [](const SurfaceParameters& p, int) {
           return detail::makeHelixTangent("helix_tangent", p.at("radius"), p.at("pitch"),
                                           p.at("turns"), p.at("ruling_start"),
                                           p.at("ruling_width"), integer(p, "resolution"));
         }});
    return list;
  }();
  return catalog;
}

}  // namespace

const std::vector<SurfaceInfo>& surfaceCatalog() {
  static const std::vector<SurfaceInfo> infos = [] {
    std::vector<SurfaceInfo> list;
    for (const CatalogEntry& entry : entries()) list.push_back(entry.info);
    return list;
  }();
  return infos;
}

namespace {

const CatalogEntry& entryNamed(const std::string& name) {
  const auto& catalog = entries();
  auto entry = std::find_if(catalog.begin(), catalog.end(),
                            [&](const CatalogEntry& e) { return e.info.name == name; });
  if (entry == catalog.end()) {
    std::string known;
    for (const CatalogEntry& e : catalog) known += (known.empty() ? "" : ", ") + e.info.name;
    throw SurfaceError("unknown surface " + quotedExcerpt(name) + " (known: " + known + ")");
  }
  return *entry;
}

}  // namespace

int latestGeneratorVersion(const std::string& name) {
  return entryNamed(name).info.generatorVersion;
}

Sheet makeSurface(const std::string& name, const SurfaceParameters& overrides,
                  int generatorVersion) {
  const CatalogEntry* entry = &entryNamed(name);
  const SurfaceInfo& info = entry->info;
  if (generatorVersion == 0) generatorVersion = info.generatorVersion;
  if (generatorVersion < 1 || generatorVersion > info.generatorVersion)
    throw SurfaceError("surface '" + name + "': generator version " +
                       std::to_string(generatorVersion) + " is not one this build has (1 to " +
                       std::to_string(info.generatorVersion) + ")");
  for (const auto& override : overrides) {
    const std::string& key = override.first;  // a plain name: lambdas cannot capture bindings
    if (std::none_of(info.parameters.begin(), info.parameters.end(),
                     [&](const SurfaceParameter& p) { return p.name == key; })) {
      std::string known;
      for (const SurfaceParameter& p : info.parameters)
        known += (known.empty() ? "" : ", ") + p.name;
      throw SurfaceError("surface '" + name + "' has no parameter " + quotedExcerpt(key) +
                         " (parameters: " + known + ")");
    }
  }
  SurfaceParameters values;
  for (const SurfaceParameter& p : info.parameters) {
    auto given = overrides.find(p.name);
    const double value = given == overrides.end() ? p.defaultValue : given->second;
    if (!std::isfinite(value)) failParameter(name, p.name, value, "must be a finite number");
    if (value < p.min || value > p.max)
      failParameter(name, p.name, value,
                    "must be in [" + formatNumber(p.min) + ", " + formatNumber(p.max) + "]");
    if (p.integer && value != std::floor(value))
      failParameter(name, p.name, value, "must be a whole number");
    values[p.name] = value;
  }
  return entry->build(values, generatorVersion);
}

}  // namespace curvefold
