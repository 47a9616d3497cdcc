// engine/io/crease_pattern.hpp
#pragma once
#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <string>
#include <vector>
namespace curvefold {
// What a crease-pattern edge is, as FOLD's edges_assignment names it (B, M, V, F, U, C).
enum class CreaseAssignment : std::uint8_t { Boundary, Mountain, Valley, Flat, Unassigned, Cut };
struct CreasePatternEdge {
  std::uint32_t a = 0, b = 0;  // vertex indices, a < b
  CreaseAssignment assignment = CreaseAssignment::Flat;
  double foldAngleDegrees = 0.0;  // target fold angle at 100%: FOLD's sign, + valley, - mountain
};
// A flat crease pattern, triangulated: every polygon face split into triangles whose new edges
// are Flat (facet) edges; cuts already opened (their vertices doubled) so a Cut edge is a boundary.
struct CreasePattern {
  std::vector<glm::dvec2> vertices;  // flat positions, the file's units
  // One of the file's units in metres, as the file states it (an SVG's width and height against
  // its viewBox; svg_crease_pattern.hpp), and how that was found, for the user. readCreasePattern
  // (crease_pattern_reader.hpp) scales the vertices by it, after which it is 1.
  double metresPerUnit = 1.0;
  std::string unitSource;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise
  std::vector<CreasePatternEdge> edges;                 // every edge of the triangles, once
  std::vector<std::string> notes;                       // things read but not used, one line each
};
}  // namespace curvefold
