#include "engine/surfaces/obj_surface.hpp"
#include "engine/text/excerpt.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <new>
#include <numbers>
#include <optional>
#include <sstream>
#include <string_view>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/gtx/exterior_product.hpp>

#include "engine/geometry/development_overlap.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/geometry/unfold.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/text/bounded_line.hpp"
#include "engine/text/input_path.hpp"

namespace curvefold {
namespace {

// One corner of a face: 0-based indices into the file's v and vt lists (vt = -1 when absent).
struct Corner {
  long v = 0;
  long vt = -1;
};

struct ObjTriangle {
  std::array<Corner, 3> corners;
  std::size_t line = 0;
};

struct ObjData {
  std::vector<glm::dvec3> v;
  std::vector<glm::dvec2> vt;
  std::vector<std::size_t> vLine;
  std::vector<ObjTriangle> triangles;
};

class Parser {
 public:
  explicit Parser(std::string name) : name_(std::move(name)) {}

  [[noreturn]] void fail(const std::string& problem) const {
    throw ObjError(name_ + ":" + std::to_string(line_) + ": " + problem);
  }

  ObjData parse(std::istream& in) {
    ObjData data;
    std::string text;
    std::optional<bool> facesHaveVt;
    for (LineRead read; (read = readBoundedLine(in, text, kMaxObjLineBytes)) != LineRead::End;) {
      ++line_;
      if (read == LineRead::TooLong) fail("line longer than an OBJ line may be (1 MiB)");
      if (auto hash = text.find('#'); hash != std::string::npos) text.resize(hash);
      // The token and corner lists keep their capacity from line to line: a scan of 100k
      // faces allocated two lists a line.
      split(text, tokens_);
      const std::vector<std::string_view>& tokens = tokens_;
      if (tokens.empty()) continue;
      const std::string_view keyword = tokens[0];
      if (keyword == "v") {
        if (tokens.size() < 4) fail("a vertex needs 3 coordinates");
        if (data.v.size() == kMaxObjElements) fail(tooMany("vertices"));
        data.v.emplace_back(number(tokens[1]), number(tokens[2]), number(tokens[3]));
        data.vLine.push_back(line_);
      } else if (keyword == "vt") {
        if (tokens.size() < 3) fail("a texture coordinate needs 2 coordinates");
        if (data.vt.size() == kMaxObjElements) fail(tooMany("texture coordinates"));
        data.vt.emplace_back(number(tokens[1]), number(tokens[2]));
      } else if (keyword == "f") {
        if (tokens.size() < 4) fail("a face needs at least 3 vertices");
        std::vector<Corner>& corners = corners_;
        corners.clear();
        for (std::size_t i = 1; i < tokens.size(); ++i)
          corners.push_back(corner(tokens[i], data.v.size(), data.vt.size()));
        const bool hasVt = corners[0].vt >= 0;
        for (const Corner& c : corners)
          if ((c.vt >= 0) != hasVt)
            fail("a face mixes corners with and without texture coordinates");
        if (facesHaveVt && *facesHaveVt != hasVt)
          fail("faces with and without texture coordinates are mixed");
        facesHaveVt = hasVt;
        // Convex polygons become a fan from their first corner.
        if (data.triangles.size() + corners.size() - 2 > kMaxObjElements)
          fail(tooMany("triangles"));
        for (std::size_t k = 1; k + 1 < corners.size(); ++k)
          data.triangles.push_back({{corners[0], corners[k], corners[k + 1]}, line_});
      }
      // Normals, groups, materials, smoothing, lines and points do not shape the sheet.
    }
    if (in.bad()) throw ObjError(name_ + ": read error");
    if (data.triangles.empty()) throw ObjError(name_ + ": no faces");
    return data;
  }

 private:
  static std::string tooMany(const char* what) {
    return std::string("more ") + what + " than an OBJ may hold (" +
           std::to_string(kMaxObjElements) + ")";
  }

  static void split(std::string_view text, std::vector<std::string_view>& tokens) {
    tokens.clear();
    std::size_t i = 0;
    while (i < text.size()) {
      while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
      std::size_t j = i;
      while (j < text.size() && !std::isspace(static_cast<unsigned char>(text[j]))) ++j;
      if (j > i) tokens.push_back(text.substr(i, j - i));
      i = j;
    }
  }

  double number(std::string_view token) const {
    std::string_view digits = token;
    if (!digits.empty() && digits[0] == '+') digits.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc() || end != digits.data() + digits.size() || digits.empty())
      fail("malformed number " + quotedExcerpt(token));
    if (!std::isfinite(value)) fail("non-finite coordinate " + quotedExcerpt(token));
    return value;
  }

  // A 1-based (or negative, relative) index into a list of `count` entries, as 0-based.
  long index(std::string_view token, std::size_t count, const char* what) const {
    long value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || token.empty())
      fail(std::string("malformed ") + what + " index " + quotedExcerpt(token));
    if (value == 0) fail(std::string(what) + " index 0 is invalid (OBJ indices start at 1)");
    const long resolved = value > 0 ? value - 1 : static_cast<long>(count) + value;
    if (resolved < 0 || resolved >= static_cast<long>(count))
      fail(std::string(what) + " index " + quotedExcerpt(token, 24) + " is out of range (" +
           std::to_string(count) + " defined so far)");
    return resolved;
  }

  Corner corner(std::string_view token, std::size_t vCount, std::size_t vtCount) const {
    // v, v/vt, v//vn or v/vt/vn; normals are ignored. With no vt line before it, a face's vt
    // indices are dropped: a file whose vt lines were deleted (its faces still `v/vt`) is read by
    // its positions, as one written without them.
    const std::size_t slash = token.find('/');
    Corner c;
    c.v = index(token.substr(0, slash), vCount, "vertex");
    if (slash != std::string_view::npos && vtCount > 0) {
      std::string_view rest = token.substr(slash + 1);
      const std::string_view vt = rest.substr(0, rest.find('/'));
      if (!vt.empty()) c.vt = index(vt, vtCount, "texture coordinate");
    }
    return c;
  }

  std::string name_;
  std::size_t line_ = 0;
  std::vector<std::string_view> tokens_;
  std::vector<Corner> corners_;
};

double pointsDiagonal(const std::vector<glm::dvec3>& points) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const glm::dvec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

// Tags boundary edges whose endpoints coincide in 3D with another boundary edge's: a seam.
void tagSeams(Sheet& sheet) {
  const EdgeTopology edges = buildEdgeTopology(sheet);
  std::map<std::array<double, 3>, std::uint32_t> pointIds;
  std::vector<std::uint32_t> pointOf(sheet.vertexCount());
  for (VertexIndex v = 0; v < sheet.vertexCount(); ++v) {
    const glm::dvec3& p = sheet.positions[v];
    pointOf[v] = pointIds.emplace(std::array{p.x, p.y, p.z}, pointIds.size()).first->second;
  }
  std::map<Edge, std::vector<Edge>> byPoints;
  for (const auto& sides : edges.edges)
    if (sides.isBoundary())
      byPoints[Edge::of(pointOf[sides.edge.a], pointOf[sides.edge.b])].push_back(sides.edge);
  for (const auto& [points, group] : byPoints)
    if (group.size() >= 2)
      for (const Edge& e : group) sheet.tags.push_back({e, EdgeKind::Slit});
  sheet.normalizeTags();
}

// A sheet read from an OBJ, with what its messages name: the file, each triangle's line and each
// sheet vertex's 0-based OBJ v.
struct ObjSheet {
  std::string name;
  Sheet sheet;
  std::vector<long> objVertex;  // sheet vertex -> 0-based OBJ v
  std::vector<std::size_t> triangleLine;

  std::string lineText(std::size_t line) const { return name + ":" + std::to_string(line) + ": "; }
  std::string edgeText(VertexIndex a, VertexIndex b) const {
    return "edge between vertices " + std::to_string(objVertex[a] + 1) + " and " +
           std::to_string(objVertex[b] + 1);
  }
};

// Sheet vertices: one per distinct v (without vt) or (v, vt) pair; a face that repeats a vertex
// is refused.
ObjSheet sheetOfObj(const ObjData& data, const std::string& name, bool withVt) {
  ObjSheet obj{name, {}, {}, {}};
  Sheet& sheet = obj.sheet;
  std::map<std::pair<long, long>, VertexIndex> vertexOf;
  for (const ObjTriangle& t : data.triangles) {
    Triangle triangle;
    for (int i = 0; i < 3; ++i) {
      const Corner& c = t.corners[i];
      auto [it, added] =
          vertexOf.emplace(std::pair{c.v, c.vt}, static_cast<VertexIndex>(obj.objVertex.size()));
      if (added) {
        obj.objVertex.push_back(c.v);
        sheet.positions.push_back(data.v[c.v]);
        sheet.development.push_back(withVt ? data.vt[c.vt] : glm::dvec2(0.0));
      }
      triangle[i] = it->second;
    }
    if (triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[0] == triangle[2])
      throw ObjError(obj.lineText(t.line) + "a face repeats a vertex");
    sheet.triangles.push_back(triangle);
    obj.triangleLine.push_back(t.line);
  }
  return obj;
}

// Each directed edge once, each undirected edge at most twice: a consistently oriented manifold.
void checkOrientedManifold(const ObjSheet& obj) {
  const Sheet& sheet = obj.sheet;
  std::map<std::pair<VertexIndex, VertexIndex>, TriangleIndex> directed;
  std::map<Edge, int> uses;
  for (TriangleIndex t = 0; t < sheet.triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const VertexIndex a = sheet.triangles[t][i], b = sheet.triangles[t][(i + 1) % 3];
      if (++uses[Edge::of(a, b)] > 2)
        throw ObjError(obj.lineText(obj.triangleLine[t]) + obj.edgeText(a, b) +
                       " belongs to more than two faces (non-manifold mesh)");
      if (!directed.emplace(std::pair{a, b}, t).second)
        throw ObjError(obj.lineText(obj.triangleLine[t]) + obj.edgeText(a, b) +
                       " runs the same way in two faces (non-manifold or inconsistently "
                       "oriented mesh)");
    }
  }
}

// A mesh far from the origin (a survey's coordinates, 1e9 m out) keeps only a few digits of its
// size in each coordinate, and every reflection there rounds at that scale: recentre it.
void recentreFarMesh(std::vector<glm::dvec3>& positions) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const glm::dvec3& p : positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::dvec3 centre = 0.5 * (lo + hi);
  if (glm::length(centre) > kObjRecentreDistance * glm::length(hi - lo))
    for (glm::dvec3& p : positions) p -= centre;
}

// The development from the texture coordinates: one scale factor from texture units to metres
// fitted, a clockwise layout mirrored, then every edge checked against its 3D length.
void developmentFromTexture(ObjSheet& obj) {
  Sheet& sheet = obj.sheet;
  double length3 = 0.0, length2 = 0.0, area = 0.0;
  for (const Triangle& t : sheet.triangles) {
    for (int i = 0; i < 3; ++i) {
      length3 += glm::distance(sheet.positions[t[i]], sheet.positions[t[(i + 1) % 3]]);
      length2 += glm::distance(sheet.development[t[i]], sheet.development[t[(i + 1) % 3]]);
    }
    area += glm::cross(sheet.development[t[1]] - sheet.development[t[0]],
                       sheet.development[t[2]] - sheet.development[t[0]]);
  }
  if (!(length2 > 0.0)) throw ObjError(obj.name + ": all texture coordinates coincide");
  const double scale = length3 / length2;
  const double mirror = area < 0.0 ? -1.0 : 1.0;
  for (glm::dvec2& p : sheet.development) p = scale * glm::dvec2(mirror * p.x, p.y);
  // Measured like validate(): relative to the development's size.
  const double tolerance = kObjRelativeTolerance * sheetSize(sheet);
  double worst = -1.0;
  TriangleIndex worstTriangle = 0;
  int worstCorner = 0;
  for (TriangleIndex t = 0; t < sheet.triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const VertexIndex a = sheet.triangles[t][i], b = sheet.triangles[t][(i + 1) % 3];
      const double error = std::abs(glm::distance(sheet.positions[a], sheet.positions[b]) -
                                    glm::distance(sheet.development[a], sheet.development[b]));
      if (error > worst) {
        worst = error;
        worstTriangle = t;
        worstCorner = i;
      }
    }
  }
  if (worst > tolerance) {
    const Triangle& t = sheet.triangles[worstTriangle];
    const VertexIndex a = t[worstCorner], b = t[(worstCorner + 1) % 3];
    std::ostringstream out;
    out.precision(6);
    out << obj.lineText(obj.triangleLine[worstTriangle])
        << "texture coordinates are not a development of the mesh: " << obj.edgeText(a, b) << " is "
        << glm::distance(sheet.positions[a], sheet.positions[b]) << " long in 3D but "
        << glm::distance(sheet.development[a], sheet.development[b]) << " in vt (scaled by "
        << scale << "), more than " << kObjRelativeTolerance << " of the size";
    throw ObjError(out.str());
  }
}

// The development unfolded from the mesh (no texture coordinates); a surface that is not
// developable is refused naming its largest angle defect's vertex and line.
void developmentByUnfolding(ObjSheet& obj, const ObjData& data) {
  Sheet& sheet = obj.sheet;
  try {
    sheet.development = unfoldDevelopment(sheet.positions, sheet.triangles, kObjRelativeTolerance);
  } catch (const NotDevelopable& error) {
    const AngleDefect defect = largestAngleDefect(sheet.positions, sheet.triangles);
    if (defect.vertex == kNoIndex || std::abs(defect.radians) <= kObjRelativeTolerance)
      throw ObjError(obj.name + ": " + error.what());
    std::ostringstream out;
    out.precision(6);
    out << obj.name << ":" << data.vLine[obj.objVertex[defect.vertex]]
        << ": surface is not developable: largest angle defect "
        << defect.radians * 180.0 / std::numbers::pi << " degrees (" << defect.radians
        << " rad) at vertex " << obj.objVertex[defect.vertex] + 1;
    throw ObjError(out.str());
  }
}

// The sheet's invariants (validate), then a development that lies flat without overlapping.
void checkFlatSheet(const ObjSheet& obj) {
  const Sheet& sheet = obj.sheet;
  try {
    validate(sheet, ValidationOptions{.relativeLengthTolerance = kObjRelativeTolerance});
  } catch (const InvalidSheet& error) {
    throw ObjError(obj.name + ": " + error.what());
  }
  // Developable piece by piece is not enough: the pieces must lie flat without overlapping, or
  // the crease pattern crosses itself and cannot be cut from one sheet.
  if (const std::optional<EdgeCrossing> crossing = findDevelopmentCrossing(sheet))
    throw ObjError(obj.name + ": the development overlaps itself: the " +
                   obj.edgeText(crossing->first.a, crossing->first.b) + " crosses the " +
                   obj.edgeText(crossing->second.a, crossing->second.b) +
                   " (cut the mesh open where it wraps over itself)");
  // Without crossing edges, a piece may still lie inside another or on it (coincident pieces).
  if (const std::optional<PieceOverlap> overlap = findPieceOverlap(sheet))
    throw ObjError(obj.lineText(obj.triangleLine[overlap->inner]) +
                   "the development overlaps itself: this face's piece lies on the piece of the "
                   "face on line " +
                   std::to_string(obj.triangleLine[overlap->outer]) +
                   " (lay the pieces' texture coordinates apart)");
}

}  // namespace

Sheet parseObjSurface(std::istream& in, const std::string& name) {
  const ObjData data = Parser(name).parse(in);
  const bool withVt = data.triangles.front().corners[0].vt >= 0;
  ObjSheet obj = sheetOfObj(data, name, withVt);
  checkOrientedManifold(obj);
  if (!(pointsDiagonal(obj.sheet.positions) > 0.0))
    throw ObjError(name + ": all vertices coincide");
  recentreFarMesh(obj.sheet.positions);
  if (withVt)
    developmentFromTexture(obj);
  else
    developmentByUnfolding(obj, data);
  tagSeams(obj.sheet);
  checkFlatSheet(obj);
  return std::move(obj.sheet);
}

namespace {

template <typename Parse>
auto readObjFile(const std::string& path, Parse parse) {
  // Only a regular file: a FIFO would block the open, a folder fail inside the stream.
  if (const std::optional<std::string> why = notRegularFile(path))
    throw ObjError(path + ": cannot open: " + *why);
  std::ifstream in(path);
  if (!in) throw ObjError(path + ": cannot open: " + std::strerror(errno));
  try {
    return parse(in, path);
  } catch (const std::bad_alloc&) {
    throw ObjError(path + ": out of memory reading it");
  }
}

}  // namespace

Sheet readObjSurface(const std::string& path) {
  return readObjFile(path, parseObjSurface);
}

Sheet parseObjState(std::istream& in, const std::string& name) {
  const ObjData data = Parser(name).parse(in);
  if (data.triangles.front().corners[0].vt < 0)
    throw ObjError(name +
                   ": no texture coordinates (vt) on the faces: a folded state is measured "
                   "against its flat sheet, which vt holds");
  Sheet sheet;
  std::map<std::pair<long, long>, VertexIndex> vertexOf;
  for (const ObjTriangle& t : data.triangles) {
    Triangle triangle;
    for (int i = 0; i < 3; ++i) {
      const Corner& c = t.corners[i];
      auto [it, added] =
          vertexOf.emplace(std::pair{c.v, c.vt}, static_cast<VertexIndex>(sheet.positions.size()));
      if (added) {
        sheet.positions.push_back(data.v[c.v]);
        sheet.development.push_back(data.vt[c.vt]);
      }
      triangle[i] = it->second;
    }
    if (triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[0] == triangle[2])
      throw ObjError(name + ":" + std::to_string(t.line) + ": a face repeats a vertex");
    sheet.triangles.push_back(triangle);
  }
  return sheet;
}

Sheet readObjState(const std::string& path) {
  return readObjFile(path, parseObjState);
}

TriangleMesh parseObjMesh(std::istream& in, const std::string& name) {
  const ObjData data = Parser(name).parse(in);
  TriangleMesh mesh;
  mesh.positions = data.v;
  mesh.triangles.reserve(data.triangles.size());
  for (const ObjTriangle& t : data.triangles)
    mesh.triangles.push_back({static_cast<std::uint32_t>(t.corners[0].v),
                              static_cast<std::uint32_t>(t.corners[1].v),
                              static_cast<std::uint32_t>(t.corners[2].v)});
  return mesh;
}

TriangleMesh readObjMesh(const std::string& path) {
  return readObjFile(path, parseObjMesh);
}

}  // namespace curvefold
