// Initial surfaces [Mitani & Igarashi 2011, Sec. 3.1, Fig. 5], each with an exact development of
// its discrete mesh: every triangle is congruent to its flat image to rounding (~1e-15 relative).
//
// Conventions (all surfaces):
// - Metres; paper-sized by default (0.2-0.3 m across).
// - Flat sheets lie in the plane z = 0 with 3D = (x, y, 0) and development = (x, y), centred on
//   the origin; their front side faces +z.
// - Curved sheets bend around the y axis (y is the axis of cylinders, cones and the helix, and
//   the sweep direction of swept curves), are centred on the origin, and their development maps
//   x to the direction around / along the curve and y to the axis, so the middle of each curved
//   sheet faces +z with its front side, like a flat sheet (the outside of tubes and cones).
// - A full tube or cone (angle 360) has a slit at its back (-z side): the seam vertices are
//   duplicated with bit-identical 3D positions and the seam edges are tagged EdgeKind::Slit.
// - `resolution` is the number of segments along the longer direction of the development; the
//   other direction gets max(1, round(resolution * shorter / longer)) segments, so grid cells
//   are near-square (flat outlines use a Delaunay mesh with edges <= longer / resolution).
//
// Cylinder triangle count: with arc = radius * angle (radians), n segments around and m along,
//   arc >= height: n = max(3, resolution), m = max(1, round(resolution * height / arc))
//   arc <  height: m = resolution,         n = max(3, round(resolution * arc / height))
//   triangles = 2 * n * m.
// For the default cylinder (radius 0.045, height 0.21, angle 360: arc = 0.2827) that is about
// 1.486 * resolution^2, so resolution 82 / 259 / 820 gives ~10k / ~100k / ~1M triangles.
#pragma once

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

// A bad surface name, parameter or outline; the message names the surface, parameter and value.
class SurfaceError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// One parameter; min and max are inclusive, integer parameters accept whole numbers only.
struct SurfaceParameter {
  std::string name;
  double defaultValue = 0.0;
  double min = 0.0;
  double max = 0.0;
  bool integer = false;
  std::string description;
};

struct SurfaceInfo {
  std::string name;
  std::string description;
  std::vector<SurfaceParameter> parameters;
  // The generator's latest version (see makeSurface).
  int generatorVersion = 1;
};

// Every named surface, in a fixed order: square, rectangle, disk, star, cylinder, half_cylinder,
// cone, swept_curve, helix_tangent.
const std::vector<SurfaceInfo>& surfaceCatalog();

using SurfaceParameters = std::map<std::string, double>;

// Builds a named surface; omitted parameters take their defaults. Throws SurfaceError for an
// unknown surface or parameter, a value out of range or not whole, geometric nonsense, or a
// resolution that would exceed kMaxSurfaceTriangles.
//
// generatorVersion picks the meshing (0: the latest). A design records the version that made its
// sheet, so a design saved before a generator changed rebuilds the very sheet it was folded on
// (its seeds lie where they did). The versions, from the history of engine/surfaces:
// - square, rectangle, disk, star: 1, the whole outline meshed at once by CGAL (a disk a polygon
//   of max(8, ceil(pi * resolution)) sides, a hole a circle of its own), until 2026-12-04;
//   2, one half-wedge meshed and mirrored and turned (symmetricFlat), the disk's polygon rounded up
//   to a multiple of 2 * its rotations; its "rotations" parameter came with it.
// - cylinder, half_cylinder, cone, swept_curve, helix_tangent: 1 (never changed).
// A version above the latest, or one that lacks a parameter given, throws SurfaceError.
Sheet makeSurface(const std::string& name, const SurfaceParameters& overrides = {},
                  int generatorVersion = 0);

// The latest generator version of a named surface; throws SurfaceError for an unknown one.
int latestGeneratorVersion(const std::string& name);

inline constexpr std::size_t kMaxSurfaceTriangles = 4'000'000;

// Flat sheet from a simple polygon outline with simple polygon holes inside it (either
// orientation), meshed by CGAL's constrained Delaunay mesher with edges no longer than
// maxEdgeLength and angles of at least about 20 degrees. 3D = (x, y, 0), development = (x, y).
// Throws SurfaceError for fewer than 3 points, non-finite or repeated points, crossing edges,
// holes outside the outline or overlapping, or a mesh that would exceed kMaxSurfaceTriangles.
Sheet triangulateOutline(const std::vector<glm::dvec2>& outline,
                         const std::vector<std::vector<glm::dvec2>>& holes, double maxEdgeLength);

}  // namespace curvefold
