// From a drawing of lines to a triangulated crease pattern, the part the FOLD and SVG readers
// share (fold_crease_pattern.hpp, svg_crease_pattern.hpp).
//
// Method: what Origami Simulator does on import (Ghassaei, Demaine, Gershenfeld, 7OSME 2018;
// js/pattern.js): collapse near vertices, split lines where they cross or touch, find the faces of
// the planar graph, drop faces bounded only by border lines (holes), triangulate, open cuts. Here
// the faces and the triangulation come from one constrained Delaunay triangulation (CGAL's
// Constrained_Delaunay_triangulation_2, exact predicates) whose constraints are the lines: the
// regions between constraints are the graph's faces (concave ones, ones with dangling lines and
// ones with islands included), and its unconstrained edges are the new Flat edges.
//
// With faces given (FOLD faces_vertices) exactly those faces are paper.
// Which regions are paper without faces: as Origami Simulator (removeBorderFaces), every region
// but the outside, except a region bounded only by Boundary lines that does not touch the outside
// (a hole).
//
// Known limits: a hole bounded by lines other than Boundary ones reads as paper, and so does an
// island of paper inside a hole; a pattern with no Boundary lines takes its outline as its border.
// Coordinates are kept as given.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "engine/io/crease_pattern.hpp"

namespace curvefold {

// One line naming what is wrong with a crease pattern (or its file).
class CreasePatternError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct CreaseLine {
  std::uint32_t a = 0, b = 0;
  CreaseAssignment assignment = CreaseAssignment::Flat;
  double foldAngleDegrees = 0.0;
};

// Lines between points, as a file gives them (any order, maybe crossing, maybe duplicated).
struct CreaseDrawing {
  std::vector<glm::dvec2> vertices;
  std::vector<CreaseLine> lines;
  // Optional (FOLD faces_vertices): the paper's faces, either orientation. Empty: found.
  std::vector<std::vector<std::uint32_t>> faces;
  // How a message names line i ("edge 7", "line 12 of the file"); empty: "edge i".
  std::vector<std::string> lineNames;
  std::vector<std::string> notes;
};

// The one letter FOLD uses for an assignment (B M V F U C), and the name a message uses.
char foldLetter(CreaseAssignment assignment);
const char* assignmentName(CreaseAssignment assignment);

// How planarize treats lines that cross or touch.
struct PlanarizeOptions {
  // Points closer than this (relative to the drawing's bounding-box diagonal) are one point, and
  // an end this close to another line's inside splits that line.
  double relativeSnap = 1e-9;
  // true (FOLD): a crossing or a touch without a shared vertex is an error; false (SVG): lines
  // are split there, as Origami Simulator does.
  bool strict = true;
  // true (FOLD, which lists each vertex once): two vertices merged are worth a note however
  // close. false (SVG, where every line brings its own two ends): ends at one place are one
  // vertex without a note; only points moved more than 1e-9 of the diagonal are counted.
  bool noteCoincidentPoints = true;
};

// Snaps near points together, drops lines of zero length (a note), merges repeated lines (the
// stronger assignment wins: Boundary, Cut, Mountain/Valley, Unassigned, Flat), and, unless strict,
// splits lines where they cross or where one's end touches another. Unused points are dropped.
// Throws CreasePatternError: in strict mode "edges 3 and 9 cross at (x, y) without a vertex" or
// "edge 4 passes through vertex 7"; past kMaxCreasePatternEdges lines after splitting.
void planarize(CreaseDrawing& drawing, const PlanarizeOptions& options);

struct TriangulateOptions {
  // false (FOLD): a line in no face is an error; true (SVG, as Origami Simulator): dropped, a note.
  bool dropLinesWithoutFace = false;
  // A Boundary line with paper on both sides: false (FOLD, where such lines are the two sides of
  // an opened cut whose vertices were merged) opened as a cut; true (SVG, as Origami Simulator,
  // which gives them no crease) an Unassigned hinge that folds freely.
  bool innerBorderAsHinge = false;
};

// Triangulates a planar drawing (planarize's output: no crossings) into a CreasePattern: faces,
// triangles (counter-clockwise), Flat edges for the triangulation, creases on the paper's border
// read as Boundary (a note), Cut lines opened (and inner Boundary lines, see above), a line
// through another vertex split there (a note).
// A paper region whose triangulation has a triangle on three points of one smooth chain of lines
// (the inside of a circle drawn as segments, which would be a fan of lenses that collapse when it
// folds) gets a triangular lattice of points inside it, numbered after the drawing's (a note);
// every other region takes no new point.
// Throws CreasePatternError: "edge 5 has no face" (a line outside the paper), "no paper: ...",
// a given face whose sides are not edges, lines that cross after all.
CreasePattern triangulateCreaseDrawing(const CreaseDrawing& drawing,
                                       const TriangulateOptions& options = {});

// Checks the struct's promises: indices in range, triangles counter-clockwise with area, every
// triangle edge listed once with a < b and no other edge listed, finite angles in [-180, 180],
// each edge in one or two triangles (a Cut edge in one). Returns the first problem, or nothing.
std::optional<std::string> validateCreasePattern(const CreasePattern& pattern);

}  // namespace curvefold
