#include "engine/geometry/symmetry.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/geometry/surface_point.hpp"
#include "engine/geometry/tolerances.hpp"
#include "engine/text/excerpt.hpp"

namespace curvefold {

namespace {

constexpr const char* kAxisNames[3] = {"x", "y", "z"};

glm::dvec3 unitAxis(int axis) {
  glm::dvec3 v(0.0);
  v[axis] = 1.0;
  return v;
}

Isometry about(const glm::dmat3& linear, const glm::dvec3& centre) {
  return {linear, centre - linear * centre};
}

Isometry mirror(int axis, const glm::dvec3& centre) {
  const glm::dvec3 n = unitAxis(axis);
  return about(glm::dmat3(1.0) - 2.0 * glm::outerProduct(n, n), centre);
}

Isometry rotation(int axis, double radians, const glm::dvec3& centre) {
  return about(glm::dmat3(glm::rotate(glm::dmat4(1.0), radians, unitAxis(axis))), centre);
}

// Grid keys and vertex numbers are regular: mixed (splitmix64's finaliser) so buckets stay short.
std::uint64_t mix(std::uint64_t h) {
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
  return h ^ (h >> 31);
}

struct CellHash {
  std::size_t operator()(const std::array<long long, 3>& k) const {
    return mix(mix(mix(std::uint64_t(k[0])) + std::uint64_t(k[1])) + std::uint64_t(k[2]));
  }
};

std::array<VertexIndex, 3> sorted(std::array<VertexIndex, 3> t) {
  std::sort(t.begin(), t.end());
  return t;
}

// What every test of an isometry against one sheet shares, built once: vertices on a hashed grid
// of the tolerance, each vertex's place (the first vertex at its position: a slit's two sides are
// one place) and the triangles by the sorted places of their corners, grouped by the smallest.
// Each image then costs one lookup per vertex and one per triangle, and stops at the first that
// misses. Lookups go in the mesh's order, which an isometry of it mostly keeps: a vertex's image
// is first sought next to the previous one's, and the triangles by their smallest place, so most
// lookups stay in the cache.
class SymmetryIndex {
 public:
  SymmetryIndex(const Sheet& sheet, SymmetryStats* stats)
      : sheet_(sheet),
        tolerance_(kRelativeContactTolerance * sheetSize(sheet)),
        cell_(64.0 * tolerance_),
        stats_(stats) {
    // Open addressing, at most half full: one allocation, where a map of lists makes one a cell.
    std::size_t capacity = 2;
    while (capacity < 2 * sheet.vertexCount()) capacity *= 2;
    cells_.assign(capacity, Cell{});
    nextInCell_.assign(sheet.vertexCount(), kNoIndex);
    for (std::uint32_t v = sheet.vertexCount(); v-- > 0;) {
      const std::array<long long, 3> k = key(sheet.positions[v]);
      Cell& cell = cellOf(k);
      cell.key = k;
      nextInCell_[v] = cell.first;  // backwards, so each cell lists its vertices in order
      cell.first = v;
    }
    place_.resize(sheet.vertexCount());
    for (VertexIndex v = 0; v < sheet.vertexCount(); ++v) place_[v] = *find(sheet.positions[v]);
    // Counting sort by the smallest place, in the triangles' order: the first of equal triples
    // is the one a lookup finds.
    firstAt_.assign(sheet.vertexCount() + 1, 0);
    for (const Triangle& tri : sheet.triangles) ++firstAt_[placesOf(tri)[0] + 1];
    for (std::size_t p = 0; p < sheet.vertexCount(); ++p) firstAt_[p + 1] += firstAt_[p];
    byPlaces_.resize(sheet.triangleCount());
    std::vector<std::uint32_t> next(firstAt_.begin(), firstAt_.end() - 1);
    for (TriangleIndex t = 0; t < sheet.triangleCount(); ++t) {
      const std::array<VertexIndex, 3> places = placesOf(sheet.triangles[t]);
      byPlaces_[next[places[0]]++] = {places, t};
    }
  }

  const Sheet& sheet() const { return sheet_; }
  double tolerance() const { return tolerance_; }

  // Each triangle's image under g corner by corner, or nothing at the first corner or triangle
  // that maps onto none (trianglePermutation).
  std::optional<std::vector<Triangle>> permutation(const Isometry& g) const {
    std::vector<Triangle> image(sheet_.triangleCount());
    if (!map(g, &image)) return std::nullopt;
    return image;
  }
  bool maps(const Isometry& g) const { return map(g, nullptr); }

 private:
  bool map(const Isometry& g, std::vector<Triangle>* image) const {
    // Each vertex's image place, looked up when a corner first needs it.
    std::vector<VertexIndex> imagePlace(sheet_.vertexCount(), kNoIndex);
    VertexIndex last = kNoIndex;
    for (TriangleIndex t = 0; t < sheet_.triangleCount(); ++t) {
      const Triangle& tri = sheet_.triangles[t];
      std::array<VertexIndex, 3> places{};
      for (int i = 0; i < 3; ++i) {
        VertexIndex& p = imagePlace[tri[i]];
        if (p == kNoIndex) {
          const std::optional<VertexIndex> found = find(g.apply(sheet_.positions[tri[i]]), last);
          if (!found) return false;
          last = *found;
          p = place_[*found];
        }
        places[i] = p;
      }
      const std::optional<TriangleIndex> match = triangleAt(sorted(places));
      if (!match) return false;
      if (!image) continue;
      const Triangle& other = sheet_.triangles[*match];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (place_[other[j]] == places[i]) (*image)[t][i] = other[j];
    }
    return true;
  }

  std::array<VertexIndex, 3> placesOf(const Triangle& tri) const {
    return sorted({place_[tri[0]], place_[tri[1]], place_[tri[2]]});
  }

  std::array<long long, 3> key(const glm::dvec3& p) const {
    return {std::llround(std::floor(p.x / cell_)), std::llround(std::floor(p.y / cell_)),
            std::llround(std::floor(p.z / cell_))};
  }

  // The first triangle whose corners are at these sorted places.
  std::optional<TriangleIndex> triangleAt(const std::array<VertexIndex, 3>& places) const {
    for (std::uint32_t k = firstAt_[places[0]]; k < firstAt_[places[0] + 1]; ++k)
      if (byPlaces_[k].places == places) return byPlaces_[k].triangle;
    return std::nullopt;
  }

  // A vertex within the tolerance of p: first the neighbours of `near` (the previous image),
  // then the cells the tolerance's box touches (one, mostly, as a cell is 64 tolerances wide).
  std::optional<VertexIndex> find(const glm::dvec3& p, VertexIndex near = kNoIndex) const {
    if (near != kNoIndex)
      for (std::uint32_t v : {std::uint32_t(near) + 1, std::uint32_t(near) - 1})
        if (v < sheet_.vertexCount()) {
          if (stats_) ++stats_->distanceTests;
          if (glm::distance(sheet_.positions[v], p) <= tolerance_) return VertexIndex(v);
        }
    const glm::dvec3 reach(tolerance_);
    const std::array<long long, 3> low = key(p - reach), high = key(p + reach);
    for (long long x = low[0]; x <= high[0]; ++x)
      for (long long y = low[1]; y <= high[1]; ++y)
        for (long long z = low[2]; z <= high[2]; ++z) {
          if (stats_) ++stats_->cellProbes;
          for (VertexIndex v = cellOf({x, y, z}).first; v != kNoIndex; v = nextInCell_[v]) {
            if (stats_) ++stats_->distanceTests;
            if (glm::distance(sheet_.positions[v], p) <= tolerance_) return v;
          }
        }
    return std::nullopt;
  }

  const Sheet& sheet_;
  double tolerance_;
  double cell_;
  SymmetryStats* stats_;
  struct Cell {
    std::array<long long, 3> key{};
    VertexIndex first = kNoIndex;  // kNoIndex: an empty slot
  };
  // The slot of a key: its own, or the empty one where it would go.
  Cell& cellOf(const std::array<long long, 3>& key) {
    return const_cast<Cell&>(std::as_const(*this).cellOf(key));
  }
  const Cell& cellOf(const std::array<long long, 3>& key) const {
    const std::size_t mask = cells_.size() - 1;
    for (std::size_t slot = CellHash()(key) & mask;; slot = (slot + 1) & mask) {
      const Cell& cell = cells_[slot];
      if (cell.first == kNoIndex || cell.key == key) return cell;
    }
  }
  std::vector<Cell> cells_;
  std::vector<VertexIndex> nextInCell_;  // the next vertex in the same cell
  std::vector<VertexIndex> place_;
  struct Placed {
    std::array<VertexIndex, 3> places;
    TriangleIndex triangle;
  };
  std::vector<std::uint32_t> firstAt_;  // per place, where its triangles start in byPlaces_
  std::vector<Placed> byPlaces_;
};

}  // namespace

std::vector<Isometry> Symmetry::images() const {
  std::vector<Isometry> result;
  if (kind == Kind::Mirror) result.push_back(mirror(axis, centre));
  if (kind == Kind::Rotational)
    for (int k = 1; k < order; ++k)
      result.push_back(rotation(axis, 2.0 * std::numbers::pi * k / order, centre));
  return result;
}

std::string Symmetry::name() const {
  switch (kind) {
    case Kind::Mirror:
      return std::string("mirror:") + kAxisNames[axis];
    case Kind::Rotational:
      return "rotational:" + std::to_string(order) + ":" + kAxisNames[axis];
    default:
      return "none";
  }
}

glm::dvec3 surfaceCentre(const Sheet& initial) {
  glm::dvec3 low(INFINITY), high(-INFINITY);
  for (const glm::dvec3& p : initial.positions) low = glm::min(low, p), high = glm::max(high, p);
  return initial.positions.empty() ? glm::dvec3(0.0) : 0.5 * (low + high);
}

std::optional<std::vector<Triangle>> trianglePermutation(const Sheet& initial, const Isometry& g) {
  return SymmetryIndex(initial, nullptr).permutation(g);
}

namespace {

bool has(const SymmetryIndex& index, const Symmetry& symmetry) {
  const std::vector<Isometry> images = symmetry.images();
  // A mirror that fixes every vertex (a flat sheet's own plane) is no symmetry to fold by.
  if (symmetry.kind == Symmetry::Kind::Mirror) {
    const std::vector<glm::dvec3>& positions = index.sheet().positions;
    if (std::none_of(positions.begin(), positions.end(), [&](const glm::dvec3& p) {
          return glm::distance(images[0].apply(p), p) > index.tolerance();
        }))
      return false;
  }
  return std::all_of(images.begin(), images.end(),
                     [&](const Isometry& g) { return index.maps(g); });
}

// The centroid of the area: every symmetry of the mesh fixes it, where the bounding box's middle
// is off the axis of an odd rotation (a five-pointed star's box reaches further up than down).
glm::dvec3 areaCentroid(const Sheet& sheet) {
  glm::dvec3 sum(0.0);
  double total = 0.0;
  for (const Triangle& t : sheet.triangles) {
    const glm::dvec3 a = sheet.positions[t[0]], b = sheet.positions[t[1]],
                     c = sheet.positions[t[2]];
    const double area = glm::length(glm::cross(b - a, c - a));
    sum += area * (a + b + c);
    total += 3.0 * area;
  }
  return total > 0.0 ? sum / total : surfaceCentre(sheet);
}

// Places the symmetry through the bounding box's middle, else through the area's centroid, and
// says whether the sheet has it there (the box first: the centre designs made before had).
bool hasThroughACentre(const SymmetryIndex& index, Symmetry& symmetry) {
  symmetry.centre = surfaceCentre(index.sheet());
  if (has(index, symmetry)) return true;
  symmetry.centre = areaCentroid(index.sheet());
  if (has(index, symmetry)) return true;
  symmetry.centre = surfaceCentre(index.sheet());
  return false;
}

}  // namespace

Symmetry parseSymmetry(const std::string& text, const Sheet& initial) {
  Symmetry symmetry;
  symmetry.centre = surfaceCentre(initial);
  // Messages quote an excerpt: the text may be long or hold a newline.
  const std::string quoted = quotedExcerpt(text, 40);
  const std::string expected = "expected mirror:x|y|z or rotational:N[:x|y|z]";
  if (text.empty()) throw InvalidSymmetry("\"\": " + expected);
  auto axisOf = [&](const std::string& name) {
    for (int a = 0; a < 3; ++a)
      if (name == kAxisNames[a]) return a;
    throw InvalidSymmetry(quoted + ": the axis must be x, y or z, not " + quotedExcerpt(name, 12));
  };
  const auto colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  const std::string rest = colon == std::string::npos ? "" : text.substr(colon + 1);
  if (kind == "mirror") {
    symmetry.kind = Symmetry::Kind::Mirror;
    symmetry.order = 2;
    symmetry.axis = axisOf(rest);
  } else if (kind == "rotational") {
    symmetry.kind = Symmetry::Kind::Rotational;
    const auto second = rest.find(':');
    const std::string order = rest.substr(0, second);
    // Digits only: no sign, no spaces, no hexadecimal.
    int n = 0;
    const auto [end, error] = std::from_chars(order.data(), order.data() + order.size(), n);
    if (order.empty() || !std::isdigit(static_cast<unsigned char>(order[0])) ||
        error != std::errc() || end != order.data() + order.size() || n < 2 || n > 64)
      throw InvalidSymmetry(quoted + ": the order must be a whole number from 2 to 64");
    symmetry.order = n;
    if (second != std::string::npos) {
      symmetry.axis = axisOf(rest.substr(second + 1));
    } else {
      const SymmetryIndex index(initial, nullptr);
      for (symmetry.axis = 0; symmetry.axis < 3; ++symmetry.axis)
        if (hasThroughACentre(index, symmetry)) return symmetry;
      throw InvalidSymmetry(quoted + ": the surface has no " + std::to_string(n) +
                                "-fold rotational symmetry about x, y or z through its centre",
                            /*surfaceLacksIt=*/true);
    }
  } else {
    throw InvalidSymmetry(quoted + ": " + expected);
  }
  if (!hasThroughACentre(SymmetryIndex(initial, nullptr), symmetry))
    throw InvalidSymmetry(
        quoted + ": the surface does not have " + symmetry.name() + " through its centre",
        /*surfaceLacksIt=*/true);
  return symmetry;
}

std::vector<std::string> symmetriesOf(const Sheet& initial, SymmetryStats* stats) {
  std::vector<std::string> found;
  const SymmetryIndex index(initial, stats);
  for (int axis = 0; axis < 3; ++axis) {
    Symmetry mirrored{Symmetry::Kind::Mirror, 2, axis, {}};
    if (hasThroughACentre(index, mirrored)) found.push_back(mirrored.name());
  }
  for (int axis = 0; axis < 3; ++axis)
    for (int n = 12; n >= 2; --n) {
      Symmetry turned{Symmetry::Kind::Rotational, n, axis, {}};
      if (hasThroughACentre(index, turned)) {
        found.push_back(turned.name());
        break;
      }
    }
  return found;
}

std::vector<std::string> symmetryChoices(const Sheet& initial, SymmetryStats* stats) {
  std::vector<std::string> choices;
  for (const std::string& name : symmetriesOf(initial, stats)) {
    const std::string rotational = "rotational:";
    if (!name.starts_with(rotational)) {
      choices.push_back(name);
      continue;
    }
    const std::size_t colon = name.rfind(':');
    const int order = std::stoi(name.substr(rotational.size(), colon - rotational.size()));
    for (int n = order; n >= 2; --n)
      if (order % n == 0) choices.push_back(rotational + std::to_string(n) + name.substr(colon));
  }
  return choices;
}

std::string imageNotes(std::size_t skipped, std::size_t overlapping) {
  std::string notes;
  if (skipped > 0)
    notes += std::to_string(skipped) + " skipped: their seeds lie in a part this fold moved";
  if (overlapping > 0)
    notes += (notes.empty() ? "" : "; ") + std::to_string(overlapping) +
             " overlap the part of an earlier fold of the group: not exactly symmetric there";
  return notes.empty() ? notes : " (" + notes + ")";
}

SymmetricFolder::SymmetricFolder(const Sheet& initial, const Symmetry& symmetry)
    : SymmetricFolder(std::make_shared<const Sheet>(initial), symmetry) {}

SymmetricFolder::SymmetricFolder(std::shared_ptr<const Sheet> initial, const Symmetry& symmetry)
    : initial_(std::move(initial)), symmetry_(symmetry), images_(symmetry.images()) {
  const SymmetryIndex index(*initial_, nullptr);
  for (const Isometry& g : images_) {
    std::optional<std::vector<Triangle>> permutation = index.permutation(g);
    if (!permutation)
      throw InvalidSymmetry("the surface does not have " + symmetry.name() + " through its centre");
    std::vector<VertexIndex> vertexImage(initial_->vertexCount(), kNoIndex);
    for (std::size_t t = 0; t < initial_->triangleCount(); ++t)
      for (int i = 0; i < 3; ++i) vertexImage[initial_->triangles[t][i]] = (*permutation)[t][i];
    permutations_.push_back(std::move(*permutation));
    vertexImages_.push_back(std::move(vertexImage));
  }
}

std::vector<VertexIndex> SymmetricFolder::verticesMoved(const Sheet& before,
                                                        const FoldRecord& fold) {
  const VertexInsertion grab = insertVertexAt(before, fold.seed);
  const std::vector<VertexIndex> more = verticesAtDevelopment(grab.sheet, fold.moreSeeds);
  ReflectionWorkspace workspace;
  Sheet out = grab.sheet;
  workspace.apply(grab.sheet, buildAdjacency(grab.sheet), grab.vertex, fold.plane,
                  sheetEpsilon(grab.sheet), out, more);
  return workspace.changes().movedVertices;
}

SymmetricFolder::Pieces SymmetricFolder::piecesOf(const Sheet& sheet, const FoldRecord& image,
                                                  const std::vector<VertexIndex>& wanted) {
  const VertexInsertion grab = insertVertexAt(sheet, image.seed);
  const SheetAdjacency adjacency = buildAdjacency(grab.sheet);
  const double epsilon = sheetEpsilon(grab.sheet);
  ReflectionWorkspace workspace;
  Sheet out = grab.sheet;
  std::vector<VertexIndex> more;
  std::vector<char> reached(grab.sheet.vertexCount());
  // One reflection per piece: each round adds a wanted vertex the part does not reach yet.
  for (std::size_t round = 0; round <= wanted.size(); ++round) {
    if (round > 0) workspace.restore(grab.sheet, out);
    workspace.apply(grab.sheet, adjacency, grab.vertex, image.plane, epsilon, out, more);
    const ReflectionChanges& changes = workspace.changes();
    const ReflectionPlane plane{image.plane.point + changes.planeShift * image.plane.normal,
                                image.plane.normal};
    std::fill(reached.begin(), reached.end(), 0);
    for (VertexIndex v : changes.movedVertices) reached[v] = 1;
    const auto missing = std::find_if(wanted.begin(), wanted.end(), [&](VertexIndex v) {
      return !reached[v] && plane.signedDistance(grab.sheet.positions[v]) < -epsilon;
    });
    if (missing == wanted.end()) break;
    // Refused here, while the fold is made: a design cannot record more (it was found only when
    // the design was saved).
    if (more.size() == kMaxMoreSeeds)
      throw InvalidSheet("an image of this fold falls into more than " +
                         std::to_string(kMaxMoreSeeds) +
                         " pieces across the surface's slits, more than a design records; a fold "
                         "a little elsewhere avoids it");
    more.push_back(*missing);
  }
  Pieces pieces;
  for (VertexIndex v : more) pieces.moreSeeds.push_back(grab.sheet.development[v]);
  pieces.moved = workspace.changes().movedVertices;
  return pieces;
}

std::optional<FoldRecord> SymmetricFolder::imageOf(const Sheet& before, const Sheet& sheet,
                                                   const FoldRecord& fold, std::size_t k) const {
  const Sheet& initial = *initial_;
  const double size = sheetSize(initial);
  const std::optional<SurfacePoint> seed =
      locateDevelopmentPoint(initial, fold.seed, kRelativeEpsilon * size);
  if (!seed) return std::nullopt;
  const Isometry& g = images_[k];
  glm::dvec2 imageSeed(0.0);
  for (int i = 0; i < 3; ++i)
    imageSeed += seed->barycentric[i] * initial.development[permutations_[k][seed->triangle][i]];
  // The image seed must still be where the symmetric sheet had it: a fold of this group that
  // already moved it (its part overlaps this image's) leaves the image out.
  const double tolerance = kRelativeContactTolerance * size;
  const std::optional<SurfacePoint> now = locateDevelopmentPoint(sheet, imageSeed, tolerance);
  const std::optional<SurfacePoint> then = locateDevelopmentPoint(before, imageSeed, tolerance);
  if (!now || !then ||
      glm::distance(positionOf(sheet, *now), positionOf(before, *then)) >
          kRelativeImageSeedMoved * size)
    return std::nullopt;
  FoldRecord image;
  image.seed = imageSeed;
  image.plane.point = g.apply(fold.plane.point);
  image.plane.normal = glm::normalize(g.linear * fold.plane.normal);
  image.grabbed = g.apply(fold.grabbed);
  image.target = g.apply(fold.target);
  return image;
}

SymmetricFolder::Result SymmetricFolder::applyImages(const Sheet& before, Sheet& sheet,
                                                     const FoldRecord& fold) const {
  Result result;
  // The fold's part: its vertices of the initial sheet, whose images each image's part must hold
  // (folds only append vertices, so those keep their numbers in every sheet folded from it), and
  // all of them, to tell an image whose part overlaps it.
  const std::vector<VertexIndex> part = verticesMoved(before, fold);
  std::vector<char> movedByGroup(sheet.vertexCount());
  for (VertexIndex v : part) movedByGroup[v] = 1;
  for (std::size_t k = 0; k < images_.size(); ++k) {
    std::optional<FoldRecord> image = imageOf(before, sheet, fold, k);
    if (!image) {
      ++result.skipped;
      continue;
    }
    std::vector<VertexIndex> wanted;
    for (VertexIndex v : part)
      if (v < initial_->vertexCount()) wanted.push_back(vertexImages_[k][v]);
    Pieces pieces = piecesOf(sheet, *image, wanted);
    image->moreSeeds = std::move(pieces.moreSeeds);
    sheet = applyFold(sheet, *image);
    // Overlapping: the image of the fold's part holds a vertex a fold of the group already moved
    // (away, perhaps, so this image's plane no longer reaches it), or this image moves one again.
    bool overlaps = std::any_of(wanted.begin(), wanted.end(),
                                [&](VertexIndex v) { return movedByGroup[v] != 0; });
    movedByGroup.resize(sheet.vertexCount());
    for (VertexIndex v : pieces.moved) {
      overlaps = overlaps || movedByGroup[v];
      movedByGroup[v] = 1;
    }
    result.overlapping += overlaps;
    result.applied.push_back(std::move(*image));
  }
  // A group that claims to be exact (nothing skipped, nothing overlapping) must be: refused here,
  // before anything is kept, when the fold's part and an image's differ.
  if (result.skipped == 0 && result.overlapping == 0) {
    std::vector<char> byFold(sheet.vertexCount());
    for (VertexIndex v : part) byFold[v] = 1;
    expectSymmetric(before, sheet, movedByGroup, byFold);
  }
  return result;
}

void SymmetricFolder::expectSymmetric(const Sheet& before, const Sheet& sheet,
                                      const std::vector<char>& moved,
                                      const std::vector<char>& byFold) const {
  // The initial vertices keep their numbers and each has its image (vertexImages_), so a pair the
  // symmetry matched before the group and no longer does is found vertex for vertex. Pairs
  // already apart (an earlier group noted as not exact) are not this fold's doing.
  const double tolerance = kRelativeContactTolerance * sheetSize(*initial_);
  double worst = tolerance;
  VertexIndex stayed = kNoIndex, went = kNoIndex;
  for (VertexIndex v = 0; v < initial_->vertexCount(); ++v) {
    if (!moved[v]) continue;
    for (std::size_t k = 0; k < images_.size(); ++k) {
      const VertexIndex w = vertexImages_[k][v];
      const Isometry& g = images_[k];
      const double now = glm::distance(sheet.positions[w], g.apply(sheet.positions[v]));
      if (now <= worst ||
          glm::distance(before.positions[w], g.apply(before.positions[v])) > tolerance)
        continue;
      worst = now;
      // The one of the pair left where it was lies in the piece one part has and the other lacks.
      stayed = moved[w] ? v : w;
      went = moved[w] ? w : v;
    }
  }
  if (stayed == kNoIndex) return;
  const glm::dvec3 p = sheet.positions[stayed];
  char where[96];
  std::snprintf(where, sizeof where, "%.4g,%.4g,%.4g", p.x, p.y, p.z);
  char distance[32];
  std::snprintf(distance, sizeof distance, "%.3g mm", worst * 1000.0);
  const bool foldShort = !byFold[went];
  // Short enough for one line of the command line's error (225 characters).
  throw InvalidSheet(std::string("not symmetric under ") + symmetry_.name() + ": " +
                     (foldShort
                          ? "the fold's part is cut short by the sheet's slit, its image's is not"
                          : "an image's part is cut short by the sheet's slit, the fold's is not") +
                     ", so the paper near " + where + " lies " + distance +
                     " from its image; a fold farther from the slit avoids it");
}

void SymmetricFolder::previewImages(const Sheet& before, Sheet& sheet, const FoldRecord& fold,
                                    std::vector<TriangleIndex>& reflected) const {
  for (std::size_t k = 0; k < images_.size(); ++k) {
    const std::optional<FoldRecord> image = imageOf(before, sheet, fold, k);
    if (!image) continue;
    const VertexInsertion grab = insertVertexAt(sheet, image->seed);
    ReflectionResult result = reflect(grab.sheet, grab.vertex, image->plane);
    reflected.insert(reflected.end(), result.reflectedTriangles.begin(),
                     result.reflectedTriangles.end());
    sheet = std::move(result.sheet);
  }
}

}  // namespace curvefold
