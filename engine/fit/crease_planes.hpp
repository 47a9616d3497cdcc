// The planes of a shape's creases (issue 27): where a target was folded by reflection, its creases
// are planar curves [Mitani & Igarashi 2011, Sec. 3.3] and each lies in the plane of the fold that
// made it (or that plane's image under a later fold), so a target's sharp edges name the folds'
// planes exactly. Sharp edges are those whose faces meet at more than a threshold angle.
//
// Each plane is found by consensus among plane hypotheses: through three points of sharp edges
// (a curved crease), and through each sharp edge and each line of collinear sharp edges, turned
// about it to mirror its faces (a straight crease, whose points alone leave the plane free to turn
// about it). An edge lies in a plane when it lies in it and the plane mirrors one face's normal
// onto the other's reversed, as a reflection turns a face over: a flap laid flat on the sheet
// (a fold of 150-180 degrees) leaves its crease in the sheet's plane, but names the plane across
// the two layers. The hypothesis that the longest total of sharp edges lies in (within
// `tolerance`) is kept and its edges removed, and so on. Deterministic for a seed.
//
// Known limits: a crease of a fold whose faces meet at less than the threshold is not seen; the
// bisector hypotheses assume the surface ran on smoothly across the crease before it was folded;
// the mesh must be consistently oriented (as a folded sheet written out is).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/geometry/reflection.hpp"
#include "engine/geometry/triangle_mesh.hpp"

namespace curvefold {

struct CreasePlane {
  ReflectionPlane plane;
  double support = 0.0;  // total length of the sharp edges in it, metres
};

struct CreasePlaneOptions {
  double minDihedralDegrees = 12.0;  // edges whose faces turn by more are sharp
  double tolerance = 0.0;   // metres; 0: 1e-4 of the mesh's diagonal (a file's 6 digits: 1e-6)
  double minSupport = 0.0;  // metres; 0: 0.5% of the mesh's diagonal
  std::size_t maxPlanes = 16;
  std::size_t hypotheses = 600;  // three-point hypotheses tried per plane
  std::uint64_t seed = 1;
};

// The planes, most supported first.
std::vector<CreasePlane> findCreasePlanes(const TriangleMesh& mesh,
                                          const CreasePlaneOptions& options = {});

// The largest angle, degrees, by which two faces of the mesh that share an edge turn: for a
// smooth initial surface, how much its facets bend (a sharp-edge threshold must lie above it).
double largestDihedralDegrees(const TriangleMesh& mesh);

// The largest angle, degrees, by which two faces of the mesh that share an edge turn, of those
// under `degrees` (0 where none): what a target's facets may bend where every bend under a
// sharp-edge threshold is taken for theirs.
double largestBendBelow(const TriangleMesh& mesh, double degrees);

// The sharp-edge threshold for targets folded from `initialSheet`: half as much again as its
// facets bend, two degrees more, and at least 4 degrees (a flat sheet's shallow folds).
double sharpEdgeThreshold(const TriangleMesh& initialSheet);

// How much a folded target's facets bend when its sheet is not known (degrees): the most that nine
// tenths of its edge length bends (a fold's creases are a small share of a gridded sheet's
// edges); sharpEdgeThreshold's rule applied to it is the target's own threshold. Limits: where
// creases are over a tenth of the edge length, or the sheet's facets bend unevenly (a swept
// curve, a helix), it may fall below the facets' largest bend.
double facetBendDegrees(const TriangleMesh& target);
// How much a folded target's facets bend where they bend unevenly (a swept curve's facets bend by
// its curvature, up to as much as nine tenths of its edges and more): the largest bend below the
// widest gap in its edges' bends (as a ratio: kFacetGap at least) above facetBendDegrees, the
// facets' bends below it and the creases' above. Empty where no such gap parts them (a shallow
// crease among the facets' bends). `above`: the gap's upper end (the least crease bend), degrees.
std::optional<double> facetBendBelowGap(const TriangleMesh& target, double* above = nullptr);
constexpr double kFacetGap = 2.0;
double sharpEdgeThresholdFor(double facetBendDegrees);

}  // namespace curvefold
