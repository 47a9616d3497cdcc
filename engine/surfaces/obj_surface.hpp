// A sheet from a Wavefront OBJ file [Mitani & Igarashi 2011, Sec. 3.1]: `v` positions, `f` faces
// (triangles or convex polygons, fanned), and optionally `vt` as the development. Without `vt`
// the development is unfolded from the mesh, and a surface that is not developable is refused
// with its largest angle defect.
#pragma once

#include <cstddef>
#include <istream>
#include <stdexcept>
#include <string>

#include "engine/geometry/sheet.hpp"
#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {

// A file that cannot become a sheet; one line: "file:line: problem" (or "file: problem").
class ObjError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An imported sheet passes validate() with ValidationOptions{.relativeLengthTolerance =
// kObjRelativeTolerance} (engine/geometry/tolerances.hpp).

// A mesh whose centre lies farther from the origin than this many times its size is moved to the
// origin on import (its coordinates would leave too few digits for the folds otherwise).
inline constexpr double kObjRecentreDistance = 1000.0;

// What an OBJ may hold, checked as it is read (before it is held): the generators' triangle limit,
// as many vertices and texture coordinates, and lines of at most 1 MiB.
inline constexpr std::size_t kMaxObjElements = 4'000'000;
inline constexpr std::size_t kMaxObjLineBytes = 1 << 20;

// With `vt`: each distinct (v, vt) pair is a vertex; vt may be in any unit (one uniform scale
// factor is fitted) and mirrored (it is flipped when faces run clockwise in it). Without `vt`:
// each used `v` is a vertex and the development is unfolded. Either way, boundary edges that
// coincide in 3D with another boundary edge (a seam cut open) are tagged EdgeKind::Slit.
// A development that overlaps itself (a cone wrapping twice around) is refused, naming two
// crossing edges. Throws ObjError naming the file, the line and the problem.
Sheet parseObjSurface(std::istream& in, const std::string& nameForErrors);
Sheet readObjSurface(const std::string& path);

// A folded state as written with its flat sheet (simulate --obj, export --obj: `v` folded, `vt`
// the development in metres), read as it is: each distinct (v, vt) pair a vertex, no scale fitted
// and no length, manifold or overlap check, so a strained or self-intersecting state can be
// measured (`check` of a simulated state). Throws ObjError for a file without `vt` on its faces.
Sheet parseObjState(std::istream& in, const std::string& nameForErrors);
Sheet readObjState(const std::string& path);

// Any triangle mesh from an OBJ (a target shape: a scan, a surface of revolution), read by the
// same parser with the same limits: `v` and `f` only (polygons fanned), in the file's own frame
// (never recentred), with no check of manifoldness or developability. Throws ObjError naming the
// file (and line): unreadable, malformed, or without faces.
TriangleMesh parseObjMesh(std::istream& in, const std::string& nameForErrors);
TriangleMesh readObjMesh(const std::string& path);

}  // namespace curvefold
