// Builders behind makeSurface(); their parameters are already range-checked, they check only how
// parameters combine. Internal to curvefold_surfaces.
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "engine/geometry/sheet.hpp"

namespace curvefold::detail {

// "surface 'cone': parameter 'top_radius' = 0.1 <why>" as a SurfaceError.
[[noreturn]] void failParameter(const std::string& surface, const std::string& parameter,
                                double value, const std::string& why);
// Shortest exact form, for values the user gave; 6 significant digits for derived limits.
std::string formatNumber(double value);
std::string formatApprox(double value);

// A polygon's area, positive where it runs counter-clockwise (the shoelace formula).
double signedArea(const std::vector<glm::dvec2>& polygon);

// The largest "resolution" a generator accepts.
inline constexpr int kMaxResolution = 2000;
// The least taper a truncated cone may have, (base_radius - top_radius) / base_radius: closer
// radii would put its apex beyond the digits its development needs (found by fuzz_fold).
inline constexpr double kMinConeTaper = 1e-3;

// The fewest samples per wave of the swept sine that still show its shape (4: a sine sampled at
// its peaks and zeros); fewer alias it into a zig-zag of the wrong amplitude.
inline constexpr double kSweptSamplesPerWave = 4.0;

// Segments along the longer and shorter of two development lengths (see surfaces.hpp).
struct Segments {
  int alongFirst = 1;
  int alongSecond = 1;
};
Segments segmentsFor(double first, double second, int resolution, int minFirst, int minSecond);

// Throws when a grid of that many quads would exceed kMaxSurfaceTriangles.
void checkTriangleCount(const std::string& surface, int resolution, double triangles);

Sheet makeCylinder(const std::string& surface, double radius, double height, double angleDegrees,
                   int resolution);
Sheet makeCone(const std::string& surface, double baseRadius, double height, double topRadius,
               double angleDegrees, int resolution);
Sheet makeSweptSine(const std::string& surface, double amplitude, double wavelength,
                    double curveWidth, double length, int resolution);
Sheet makeHelixTangent(const std::string& surface, double radius, double pitch, double turns,
                       double rulingStart, double rulingWidth, int resolution);

}  // namespace curvefold::detail
