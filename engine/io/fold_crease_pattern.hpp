// Crease patterns in FOLD 1.1 / 1.2 (Demaine, Ku, Lang: github.com/edemaine/fold, the format of
// Origami Simulator, Rabbit Ear and ORIPA), read into a triangulated CreasePattern.
//
// Read: vertices_coords (2D, or 3D lying in one plane z, y or x = constant, as Origami Simulator
// writes its [x, 0, z] files, or in a plane tilted to the axes, read in that plane with a note),
// edges_vertices, edges_assignment (B M V F U C, either case; J, a
// join, reads as F), edges_foldAngle (degrees, + valley, - mountain; null or absent: -180 for M,
// +180 for V, 0 for the rest, as Origami Simulator folds an SVG line of full opacity; an
// assignment without edges_assignment is U), faces_vertices (optional: without it the faces are
// found from the planar graph of the edges; with it, exactly those faces are paper and a face side
// that is no edge is added as a Flat edge). The older edges_foldAngles (FOLD 1.0) is read too.
// frame_unit (m, cm, mm, um, nm, in, pt) gives CreasePattern::metresPerUnit; "unit" or none: 1.
// Ignored, each with a note: file_frames, the key frame's other frame_* and any other *_ arrays
// (faces_edges, vertices_vertices...), which are derived from the above.
//
// Refused with one line (CreasePatternError, or FileError when the file cannot be read): malformed
// JSON, a key given twice, a wrong type, an index out of range, an unknown assignment, arrays of
// different lengths, an angle outside [-180, 180], a 3D file that lies in no plane, two edges
// crossing without a vertex, an edge through another vertex, an edge of length zero, an edge with
// no face, counts past kMaxCreasePattern* (input_limits.hpp).
#pragma once

#include <filesystem>
#include <string_view>

#include "engine/io/crease_pattern.hpp"

namespace curvefold {

// name starts every message (a file name).
CreasePattern readFoldCreasePatternText(std::string_view text, std::string_view name);
CreasePattern readFoldCreasePattern(const std::filesystem::path& path);

}  // namespace curvefold
