// Crease patterns drawn as SVG in Origami Simulator's convention (Ghassaei, Demaine, Gershenfeld,
// 7OSME 2018; origamisimulator.org, "Design Tips"; js/pattern.js), read into a triangulated
// CreasePattern.
//
// The stroke colour says what a line is: black border (B), red mountain (M), blue valley (V),
// green cut (C), yellow facet / triangulation (F), magenta undriven hinge (U); as Origami
// Simulator, only these exact colours count (#000 or #000000 or rgb(0,0,0) or the name, any case;
// lime and fuchsia too), any other colour is ignored with a note naming it. The fold angle of a
// mountain or valley is its opacity times its stroke-opacity times 180 degrees (- mountain,
// + valley); the other lines have angle 0.
//
// Read: line, polyline, polygon, rect, circle and ellipse (64 segments each), path (M L H V Z,
// absolute and relative; C S Q T and A curves flattened into straight segments, at most 64 per
// curve, each within 0.2% of the curve's control polygon length of the curve), in any nesting of g,
// a, switch and svg elements; the transform attribute (matrix, translate, scale, rotate, skewX,
// skewY) of each element and its ancestors; stroke, stroke-opacity and opacity from attributes,
// style="..." and the document's <style> rules of the forms .class, tag and tag.class. stroke and
// stroke-opacity are inherited, opacity is not (as a browser computes them). display:none hides an
// element and its children. Ignored (with a note): text, image, use and other elements; everything
// inside defs, symbol, clipPath, mask, marker, pattern, metadata. Units after numbers inside the
// drawing are dropped (coordinates stay in the file's user units); the root's width and height
// against its viewBox give CreasePattern::metresPerUnit, SVG's px being 1/96 inch (unitless is px,
// and a file with no absolute width or height, or no viewBox, is read at one px a user unit).
//
// Then, as Origami Simulator does: points within SvgReadOptions::relativeSnap of each other are
// one, lines are split where they cross or where a line's end touches another, and the planar
// graph's faces (holes are faces bounded only by border lines) are triangulated; lines outside
// the paper (in no face) are dropped with a note, as Origami Simulator leaves them out, and a
// border line with paper on both sides is an unassigned hinge (Origami Simulator gives it no
// crease, so it folds freely).
// SVG's y axis points down; vertices are (x, -y), so the pattern seen from +z looks as it does on
// screen and a valley (blue) folds toward the viewer.
//
// Refused with one line (CreasePatternError, or FileError when the file cannot be read): malformed
// XML, a root that is not <svg>, a malformed number, point list, path or transform, a line with
// no face, no lines of a crease colour, counts past kMaxCreasePattern* (input_limits.hpp), and
// what libxml2 refuses without XML_PARSE_HUGE: an attribute or text over kMaxSvgTokenBytes (10
// MB), or as much read ahead through long attributes (the message names that limit).
#pragma once

#include <filesystem>
#include <string_view>

#include "engine/io/crease_pattern.hpp"

namespace curvefold {

struct SvgReadOptions {
  // Points closer than this fraction of the drawing's bounding-box diagonal are one point
  // (Origami Simulator's default is 3 user units, about 0.3% of its examples' size).
  double relativeSnap = 1e-3;
};

// name starts every message (a file name).
CreasePattern readSvgCreasePatternText(std::string_view text, std::string_view name,
                                       const SvgReadOptions& options = {});
CreasePattern readSvgCreasePattern(const std::filesystem::path& path,
                                   const SvgReadOptions& options = {});

}  // namespace curvefold
