// Whether a development overlaps itself: two of its edges cross in the plane. A development that
// does (an OBJ of a cone sweeping twice around, unfolded) cannot be cut from one sheet of paper:
// its crease pattern crosses itself. Folds never change the development, so this is checked where
// a development is made (OBJ import) and by `check`, not after every fold.
//
// A Shamos-Hoey sweep: a line sweeps the plane in (x, y) order, holding the edges it meets sorted
// along it, and each edge is tested only against its neighbours there: when it enters, and when
// an edge between two leaves. Edges are never tested for lying near each other, so a fan of long
// spokes meeting at one vertex (quadratic for any uniform grid: every cell near the centre holds
// many spokes) costs what a mesh of short edges does: O(E log E) for E edges, with at most three
// crossing tests per edge.
//
// Ties: the sweep's order is decided in doubles, to the same tolerance as a crossing. An edge
// starting on another within it (a shared point, a T-junction, pieces laid edge to edge) is
// ordered as exact geometry orders it just past the start, by where it heads; edges from one
// point by their exact angle; vertical edges run up the sweep line. The sweep runs in a frame
// turned by 17 degrees, so that the rows and columns of grids, whose vertices line up only to
// within rounding, do not lie along the sweep line, where rounding would decide their order.
//
// Limits: two edges that cross by less than the tolerance (so it does not count) swap places
// unseen, and a crossing the sweep meets before the first of them ends can then go unseen. In
// random tests that took vertices within rounding of each other and of each other's edges, lined
// up along the turned sweep line (1 or 2 in 10,000 such grids missed one), or edges crowded within
// 1e-13 of the size of one line (about 1 in 7,000); never otherwise.
#pragma once

#include <cstdint>
#include <optional>

#include "engine/geometry/sheet.hpp"

namespace curvefold {

struct EdgeCrossing {
  Edge first, second;
};

// The work a search did, for tests that hold it to O(E log E) without timing it.
struct CrossingSearchStats {
  std::uint64_t pairTests = 0;   // pairs of edges tested for a crossing
  std::uint64_t orderTests = 0;  // comparisons placing an edge in the sweep's order
};

// A pair of edges (of the development) that cross properly, or nothing. Edges sharing a vertex
// never count; crossings are decided with a tolerance of 1e-12 of the size squared, so edges that
// only touch within rounding do not count either. `stats`, when given, receives the work done.
std::optional<EdgeCrossing> findDevelopmentCrossing(const Sheet& sheet,
                                                    CrossingSearchStats* stats = nullptr);

// Two pieces (connected components) of the development where one lies on the other with no edges
// crossing, which findDevelopmentCrossing cannot see: a piece inside a face of another (not in a
// hole of it), or two coincident pieces. `inner` is a triangle of the piece lying on the other,
// `outer` the triangle of the other it lies in.
struct PieceOverlap {
  TriangleIndex inner = kNoIndex, outer = kNoIndex;
};

// With no edges crossing, a piece lies wholly on or wholly off another (their boundaries may
// touch: pieces laid edge to edge), so one point inside each piece (the centroid of its largest
// triangle) is tested against the other pieces' triangles, beyond the crossing tolerance. The
// points are sorted by x and each triangle looks at those within its extent: O(T log P) for T
// triangles and P pieces, nothing for one piece. Limit: pieces whose edges overlap along a line
// (collinear, not crossing) in part only are seen only when such a point falls in the overlap.
std::optional<PieceOverlap> findPieceOverlap(const Sheet& sheet);

namespace detail {
// The sweep's order of two edges of the development that one sweep line crosses (the later one
// starts within the other's extent): whether `a` runs below `b` there. For tests that hold it to
// a strict weak ordering; false for an edge that is not in the development.
bool sweepRunsBelow(const Sheet& sheet, Edge a, Edge b);
}  // namespace detail

}  // namespace curvefold
