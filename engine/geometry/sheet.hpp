// The sheet: a triangle mesh of paper with a 3D position and a 2D development position per
// vertex (docs/design.md 1). Flat index arrays, as in geometry-central; everything derived from
// them (vertex-to-triangle references, edges, boundary loops) lives in topology.hpp.
#pragma once

#include <array>
#include <compare>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "engine/geometry/tolerances.hpp"

namespace curvefold {

inline constexpr std::uint32_t kNoIndex = 0xffffffffu;

// An index into one kind of element, as geometry-central's element handles are: a vertex index
// and a triangle index are different types, so passing one where the other is meant does not
// compile (that would take two user conversions, index to integer to index, and C++ allows one).
// It is made from an integer and read as one implicitly (to index the flat arrays, to count), and
// stepped with ++ and -- in loops.
template <typename Tag>
struct ElementIndex {
  std::uint32_t value = 0;

  constexpr ElementIndex() = default;
  constexpr ElementIndex(std::uint32_t index) : value(index) {}
  constexpr operator std::uint32_t() const { return value; }
  constexpr ElementIndex& operator++() {
    ++value;
    return *this;
  }
  constexpr ElementIndex operator++(int) { return ElementIndex(value++); }
  constexpr ElementIndex& operator--() {
    --value;
    return *this;
  }
  constexpr ElementIndex& operator+=(std::uint32_t step) {
    value += step;
    return *this;
  }
  constexpr ElementIndex& operator-=(std::uint32_t step) {
    value -= step;
    return *this;
  }
  // Compared as the integers they are (kNoIndex included).
};
// Comparing a vertex with a triangle is a mistake, not a comparison.
template <typename A, typename B>
requires(!std::is_same_v<A, B>) bool operator==(ElementIndex<A>, ElementIndex<B>) = delete;

using VertexIndex = ElementIndex<struct VertexTag>;
using TriangleIndex = ElementIndex<struct TriangleTag>;

// Three vertex indices, counter-clockwise in the development: that order defines the front side.
using Triangle = std::array<VertexIndex, 3>;

// An undirected edge, always stored with a < b.
struct Edge {
  VertexIndex a = 0;
  VertexIndex b = 0;

  static Edge of(VertexIndex u, VertexIndex v) { return u < v ? Edge{u, v} : Edge{v, u}; }
  auto operator<=>(const Edge&) const = default;
};

// Edges that carry meaning beyond the mesh: creases made by folds, and the slit of a tube or cone
// (a boundary edge that the paper glues shut).
enum class EdgeKind : std::uint8_t { Crease = 0, Slit = 1 };

struct TaggedEdge {
  Edge edge;
  EdgeKind kind = EdgeKind::Crease;

  auto operator<=>(const TaggedEdge&) const = default;
};

struct Sheet {
  std::vector<glm::dvec3> positions;    // 3D, metres
  std::vector<glm::dvec2> development;  // flat paper, metres
  std::vector<Triangle> triangles;
  std::vector<TaggedEdge> tags;  // sorted by edge, one entry per edge

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return triangles.size(); }

  // Kind of an edge, or nothing for a plain (bending or boundary) edge. O(log tags).
  std::optional<EdgeKind> edgeKind(Edge edge) const;
  // Sorts the tags and drops duplicates (a later entry for the same edge loses).
  void normalizeTags();
};

// Bit-for-bit equality of every array (positions compared by their bytes, so -0.0 != 0.0).
bool identical(const Sheet& a, const Sheet& b);

// Bytes the sheet's arrays hold (their capacity), for memory accounting.
std::size_t sheetBytes(const Sheet& sheet);

// The development's bounding box (both corners 0 for an empty sheet).
struct DevelopmentBounds {
  glm::dvec2 low{0.0}, high{0.0};
};
DevelopmentBounds developmentBounds(const Sheet& sheet);

// Diagonal of the development's bounding box: the sheet's size, invariant under folding.
double sheetSize(const Sheet& sheet);

// The on-plane tolerance in metres (kRelativeEpsilon, tolerances.hpp).
inline double sheetEpsilon(const Sheet& sheet) {
  return kRelativeEpsilon * sheetSize(sheet);
}

// Thrown by validate() and by every operation handed an impossible sheet.
class InvalidSheet : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace curvefold
