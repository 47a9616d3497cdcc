// Symmetric folding (issue 17, docs/design.md 7b): a mirror plane or an n-fold rotation of the
// initial surface, through its centre, and the images of a fold under it. Each image is a
// reflection fold of its own, through the image of the fold's plane and seeded at the image of the
// grabbed point in the development, so the closure of Mitani & Igarashi's Sec. 3.3 holds for each
// and each passes the same invariants. A symmetry is one the initial mesh has: every vertex and
// every triangle maps onto one (within 1e-9 of the size), which also finds the image of a
// development point exactly (through the triangle it lies in).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/sheet.hpp"

namespace curvefold {

class InvalidSymmetry : public std::invalid_argument {
 public:
  // surfaceLacksIt: the text was a symmetry, but the surface does not have it (the front end can
  // say where the surfaces' symmetries are listed); otherwise the text was not one.
  explicit InvalidSymmetry(const std::string& message, bool surfaceLacksIt = false)
      : std::invalid_argument(message), surfaceLacksIt_(surfaceLacksIt) {}
  bool surfaceLacksIt() const { return surfaceLacksIt_; }

 private:
  bool surfaceLacksIt_;
};

// x -> linear * x + offset, with linear orthogonal.
struct Isometry {
  glm::dmat3 linear{1.0};
  glm::dvec3 offset{0.0};
  glm::dvec3 apply(const glm::dvec3& p) const { return linear * p + offset; }
};

struct Symmetry {
  enum class Kind { None, Mirror, Rotational };
  Kind kind = Kind::None;
  int order = 1;  // a rotation's n; 2 for a mirror
  int axis = 0;   // 0 x, 1 y, 2 z: the mirror's normal or the rotation's axis
  glm::dvec3 centre{0.0};

  // The isometries of the group other than the identity (a mirror: one; n-fold: n - 1).
  std::vector<Isometry> images() const;
  // "mirror:x", "rotational:6:y", "none".
  std::string name() const;
};

// The middle of the initial surface's bounding box: the centre symmetries go through, or where a
// symmetry does not hold about it (an odd rotation: a five-pointed star), the centroid of its area.
glm::dvec3 surfaceCentre(const Sheet& initial);

// "mirror:x|y|z" or "rotational:N[:x|y|z]" (N from 2 to 64; without an axis, the first of x, y, z
// the surface has it about). Throws InvalidSymmetry with one line, an excerpt of text and what is
// wrong with it, also when the surface lacks the symmetry; the caller names where text came from.
Symmetry parseSymmetry(const std::string& text, const Sheet& initial);

// Each triangle's image under g, corner by corner (the triangle whose corners lie where g puts
// its corners), when every triangle maps onto one; vertices at one place (a slit's two sides) are
// told apart by the triangle they belong to.
std::optional<std::vector<Triangle>> trianglePermutation(const Sheet& initial, const Isometry& g);

// The work of finding symmetries (issue 28), to show it stays near-linear: each vertex and each
// image of one looks at about one cell of a grid and one vertex in it.
struct SymmetryStats {
  std::uint64_t cellProbes = 0;     // cells of the vertex grid looked up
  std::uint64_t distanceTests = 0;  // vertices measured against a point looked up
};

// The symmetries the sheet has, among mirrors normal to x, y, z and rotations of order 2 to 12
// about them (each rotation by its largest order, then its divisors are implied). `stats`, when
// given, receives the work done.
std::vector<std::string> symmetriesOf(const Sheet& initial, SymmetryStats* stats = nullptr);

// Every symmetry a design on the sheet may take, for a list to choose from: the mirrors, and each
// rotation with every order that divides it ("rotational:12:y", "rotational:6:y", ...).
std::vector<std::string> symmetryChoices(const Sheet& initial, SymmetryStats* stats = nullptr);

// What a group's images left out or overlapped, for a message: "" when nothing, else
// " (1 skipped: ...; 2 overlap ...)".
std::string imageNotes(std::size_t skipped, std::size_t overlapping);

// Applies the images of a fold. Made once per design from its initial sheet and symmetry.
//
// An image's part is the image of the fold's part. Grown from the image of the seed alone it can
// fall short: the slit of a tube or a cone is not where the rotation puts it, so the image of a
// whole part may lie across the slit, in two pieces. So each image also grows from the images of
// the fold's reflected vertices, and records one more seed per extra piece (FoldRecord::moreSeeds,
// so a replay needs no symmetry). A fold whose own part ends at the slit has images that reach
// on where the paper goes on: they are not its exact images there, so such a fold is refused
// (applyImages throws InvalidSheet saying where), unless its group is already noted as not exact.
class SymmetricFolder {
 public:
  SymmetricFolder(const Sheet& initial, const Symmetry& symmetry);
  SymmetricFolder(std::shared_ptr<const Sheet> initial, const Symmetry& symmetry);
  const Symmetry& symmetry() const { return symmetry_; }

  struct Result {
    std::vector<FoldRecord> applied;  // the images folded, in order
    std::size_t skipped = 0;          // images whose seed an earlier fold of the group had moved
    // Images made whose part shares vertices with the part of an earlier fold of the group: the
    // later one moves them again, so the design is not exactly symmetric there.
    std::size_t overlapping = 0;
  };
  // `before`: the sheet the fold was made on; `sheet`: with the fold applied, to which the images
  // are applied in turn. Throws InvalidSheet (one line: where and why) when the images cannot be
  // made or, in a group with none skipped or overlapping, the result is not symmetric.
  Result applyImages(const Sheet& before, Sheet& sheet, const FoldRecord& fold) const;
  // What a drag shows of the images before its commit, on any triangulation of the same surface
  // (a display's coarse sheet): each image seeded and reflected as applyImages does, skipped by
  // the same rule, without the extra pieces across a slit. Adds each image's reflected triangles
  // to `reflected`.
  void previewImages(const Sheet& before, Sheet& sheet, const FoldRecord& fold,
                     std::vector<TriangleIndex>& reflected) const;

 private:
  // The image of the fold under images_[k] (seed, plane and drag), or nothing when `sheet` (the
  // fold and the images before it made) no longer has its seed where `before` had it.
  std::optional<FoldRecord> imageOf(const Sheet& before, const Sheet& sheet, const FoldRecord& fold,
                                    std::size_t k) const;
  // Throws InvalidSheet, saying where and why, when an initial vertex `moved` by the group (the
  // fold and its images, on `sheet`) and its image under some element no longer correspond as they
  // did on `before`. `byFold`: the vertices the fold itself moved.
  void expectSymmetric(const Sheet& before, const Sheet& sheet, const std::vector<char>& moved,
                       const std::vector<char>& byFold) const;
  // The vertices the fold reflects on `before`.
  static std::vector<VertexIndex> verticesMoved(const Sheet& before, const FoldRecord& fold);
  struct Pieces {
    std::vector<glm::dvec2> moreSeeds;  // beyond the image's seed
    std::vector<VertexIndex> moved;     // the vertices the image reflects
  };
  // The seeds that grow an image's part over every piece holding one of `wanted`.
  static Pieces piecesOf(const Sheet& sheet, const FoldRecord& image,
                         const std::vector<VertexIndex>& wanted);

  std::shared_ptr<const Sheet> initial_;
  Symmetry symmetry_;
  std::vector<Isometry> images_;
  std::vector<std::vector<Triangle>> permutations_;
  std::vector<std::vector<VertexIndex>> vertexImages_;  // per image, each initial vertex's image
};

}  // namespace curvefold
