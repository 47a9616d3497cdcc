#include "engine/io/fold_crease_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "engine/io/crease_pattern_graph.hpp"
#include "engine/io/input_limits.hpp"
#include "engine/io/json_reader.hpp"

namespace curvefold {
namespace {

using nlohmann::json;

CreaseAssignment assignmentFor(const std::string& letter, const JsonReader& reader,
                               const std::string& where, bool& join) {
  if (letter.size() == 1) {
    switch (letter[0]) {
      case 'B':
      case 'b':
        return CreaseAssignment::Boundary;
      case 'M':
      case 'm':
        return CreaseAssignment::Mountain;
      case 'V':
      case 'v':
        return CreaseAssignment::Valley;
      case 'F':
      case 'f':
        return CreaseAssignment::Flat;
      case 'U':
      case 'u':
        return CreaseAssignment::Unassigned;
      case 'C':
      case 'c':
        return CreaseAssignment::Cut;
      case 'J':
      case 'j':
        join = true;
        return CreaseAssignment::Flat;
    }
  }
  reader.fail(where,
              "unknown assignment " + quotedExcerpt(letter) + " (expected B, M, V, F, U or C)");
}

void checkCount(const JsonReader& reader, const json& array, const char* key, std::uint64_t limit) {
  if (array.size() > limit)
    reader.fail(key, std::to_string(array.size()) +
                         " entries, more than a crease pattern may hold (" + std::to_string(limit) +
                         ")");
}

// Whether the points lie within `flatness` of one plane (three of them spanning it); gives its
// unit normal, signed as the nearest axis plane's reading (x, y for z; x, z for y; y, z for x)
// has it, and the first of that reading's axes projected into the plane.
bool tiltedPlane(const std::vector<glm::dvec3>& points, double flatness, glm::dvec3& normal,
                 glm::dvec3& along) {
  if (points.size() < 3) return false;
  const glm::dvec3 origin = points[0];
  std::size_t far = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (glm::distance(points[i], origin) > glm::distance(points[far], origin)) far = i;
  const glm::dvec3 span = points[far] - origin;
  glm::dvec3 best(0.0);
  for (const glm::dvec3& p : points) {
    const glm::dvec3 c = glm::cross(span, p - origin);
    if (glm::length(c) > glm::length(best)) best = c;
  }
  // Collinear within rounding: no plane to read (and no paper either).
  if (!(glm::length(best) > 1e-6 * glm::dot(span, span))) return false;
  normal = glm::normalize(best);
  for (const glm::dvec3& p : points)
    if (std::abs(glm::dot(p - origin, normal)) > flatness) return false;
  int axis = 0;  // the axis the normal is nearest: the one an axis plane would drop
  for (int k = 1; k < 3; ++k)
    if (std::abs(normal[k]) > std::abs(normal[axis])) axis = k;
  const int first = axis == 0 ? 1 : 0, second = axis == 2 ? 1 : 2;
  glm::dvec3 a(0.0), b(0.0);
  a[first] = 1.0;
  b[second] = 1.0;
  if (glm::dot(glm::cross(a, b), normal) < 0.0) normal = -normal;
  along = glm::normalize(a - glm::dot(a, normal) * normal);
  return true;
}

CreaseDrawing readDrawing(const json& document, const JsonReader& reader) {
  reader.object(document, "");
  CreaseDrawing drawing;

  // Vertices: 2D, or 3D in an axis plane.
  const json& coords =
      reader.array(reader.member(document, "vertices_coords", ""), "vertices_coords");
  checkCount(reader, coords, "vertices_coords", kMaxCreasePatternVertices);
  std::vector<glm::dvec3> points(coords.size());
  std::size_t dimension = 0;
  for (std::size_t i = 0; i < coords.size(); ++i) {
    const std::string where = JsonReader::item("vertices_coords", i);
    const json& c = coords[i];
    if (!c.is_array() || (c.size() != 2 && c.size() != 3))
      reader.fail(where, "must be 2 or 3 numbers, got " + jsonExcerpt(c));
    if (dimension == 0) dimension = c.size();
    if (c.size() != dimension)
      reader.fail(where, "has " + std::to_string(c.size()) + " coordinates, the first vertex " +
                             std::to_string(dimension));
    double xyz[3] = {0, 0, 0};
    reader.numbers(c, dimension, xyz, where);
    points[i] = {xyz[0], xyz[1], xyz[2]};
  }
  int dropped = 2;  // the axis left out: z for 2D files
  if (dimension == 3 && !points.empty()) {
    dropped = -1;
    glm::dvec3 low = points[0], high = points[0];
    for (const glm::dvec3& p : points) low = glm::min(low, p), high = glm::max(high, p);
    // Flat within rounding: Origami Simulator's files have y of 1e-21 here and there.
    const double flatness = 1e-9 * glm::length(high - low);
    for (int axis : {2, 1, 0}) {
      bool flat = true;
      for (const glm::dvec3& p : points)
        flat = flat && std::abs(p[axis] - points[0][axis]) <= flatness;
      if (flat) {
        dropped = axis;
        break;
      }
    }
    // Flat in a plane tilted to the axes (a sheet exported in a scene's frame): read in that
    // plane, with the axes of the plane nearest it (so a plane near z = constant reads near x, y).
    glm::dvec3 normal(0.0), along(0.0);
    if (dropped < 0 && tiltedPlane(points, flatness, normal, along)) dropped = 3;
    if (dropped < 0) {
      // Name the coordinate that varies least and the vertex furthest off its plane.
      int axis = 0;
      for (int k = 1; k < 3; ++k)
        if (high[k] - low[k] < high[axis] - low[axis]) axis = k;
      std::size_t worst = 0;
      for (std::size_t i = 0; i < points.size(); ++i)
        if (std::abs(points[i][axis] - points[0][axis]) >
            std::abs(points[worst][axis] - points[0][axis]))
          worst = i;
      reader.fail("vertices_coords",
                  "not a flat crease pattern: the 3D vertices lie in no plane (vertex " +
                      std::to_string(worst) + " has " + "xyz"[axis] + " = " +
                      shortestDouble(points[worst][axis]) + ", vertex 0 " +
                      shortestDouble(points[0][axis]) + "); a folded state is not read");
    }
    if (dropped == 3) {
      const glm::dvec3 across = glm::cross(normal, along);
      for (glm::dvec3& p : points) p = {glm::dot(p, along), glm::dot(p, across), 0.0};
      drawing.notes.push_back("vertices_coords: 3D in a plane tilted to the axes (normal " +
                              shortestDouble(normal.x) + ", " + shortestDouble(normal.y) + ", " +
                              shortestDouble(normal.z) + "); read in that plane");
      dropped = 2;
    } else if (dropped != 2) {
      drawing.notes.push_back(std::string("vertices_coords: 3D with every ") + "xyz"[dropped] +
                              " equal; read in the plane of the other two");
    }
  }
  drawing.vertices.reserve(points.size());
  for (const glm::dvec3& p : points) {
    if (dropped == 2) drawing.vertices.emplace_back(p.x, p.y);
    if (dropped == 1) drawing.vertices.emplace_back(p.x, p.z);
    if (dropped == 0) drawing.vertices.emplace_back(p.y, p.z);
  }

  // Edges.
  const json& edges = reader.array(reader.member(document, "edges_vertices", ""), "edges_vertices");
  checkCount(reader, edges, "edges_vertices", kMaxCreasePatternEdges);
  const json* assignments = reader.optionalMember(document, "edges_assignment", "");
  const json* angles = reader.optionalMember(document, "edges_foldAngle", "");
  const char* angleKey = "edges_foldAngle";
  if (!angles) {
    angles = reader.optionalMember(document, "edges_foldAngles", "");
    angleKey = "edges_foldAngles";
  }
  for (const auto& [array, key] : {std::pair{assignments, "edges_assignment"}, {angles, angleKey}})
    if (array) {
      reader.array(*array, key);
      if (array->size() != edges.size())
        reader.fail(key, "has " + std::to_string(array->size()) + " entries, edges_vertices " +
                             std::to_string(edges.size()));
    }
  bool join = false;
  std::size_t signDisagrees = 0, defaulted = 0, bySign = 0;
  drawing.lines.reserve(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const std::string where = JsonReader::item("edges_vertices", i);
    const json& e = edges[i];
    if (!e.is_array() || e.size() != 2)
      reader.fail(where, "must be 2 vertex indices, got " + jsonExcerpt(e));
    CreaseLine line;
    const std::uint64_t a = reader.unsignedInteger(e[0], JsonReader::item(where, 0));
    const std::uint64_t b = reader.unsignedInteger(e[1], JsonReader::item(where, 1));
    for (std::uint64_t v : {a, b})
      if (v >= points.size())
        reader.fail(where, "vertex " + std::to_string(v) + " out of range (" +
                               std::to_string(points.size()) + " vertices)");
    if (a == b) reader.fail(where, "joins vertex " + std::to_string(a) + " to itself");
    line.a = static_cast<std::uint32_t>(a);
    line.b = static_cast<std::uint32_t>(b);
    if (drawing.vertices[a] == drawing.vertices[b])
      reader.fail(where, "has length zero (vertices " + std::to_string(a) + " and " +
                             std::to_string(b) + " are at the same place)");
    line.assignment = CreaseAssignment::Unassigned;
    if (assignments) {
      const std::string at = JsonReader::item("edges_assignment", i);
      line.assignment = assignmentFor(reader.string((*assignments)[i], at), reader, at, join);
    }
    const bool crease = line.assignment == CreaseAssignment::Mountain ||
                        line.assignment == CreaseAssignment::Valley;
    const json* angle = angles ? &(*angles)[i] : nullptr;
    if (angle && !angle->is_null()) {
      line.foldAngleDegrees = reader.number(*angle, JsonReader::item(angleKey, i));
      if (std::abs(line.foldAngleDegrees) > 180.0)
        reader.fail(
            JsonReader::item(angleKey, i),
            "fold angle " + shortestDouble(line.foldAngleDegrees) + " outside [-180, 180] degrees");
      // FOLD makes edges_assignment optional: without it a fold angle's sign says which
      // (positive valley, negative mountain), as the specification defines it.
      if (!assignments && line.foldAngleDegrees != 0.0) {
        line.assignment =
            line.foldAngleDegrees < 0 ? CreaseAssignment::Mountain : CreaseAssignment::Valley;
        ++bySign;
      }
      if ((line.assignment == CreaseAssignment::Mountain && line.foldAngleDegrees > 0) ||
          (line.assignment == CreaseAssignment::Valley && line.foldAngleDegrees < 0))
        ++signDisagrees;
    } else if (crease) {
      line.foldAngleDegrees = line.assignment == CreaseAssignment::Mountain ? -180.0 : 180.0;
      ++defaulted;
    }
    drawing.lines.push_back(line);
    drawing.lineNames.push_back("edge " + std::to_string(i));
  }
  if (!assignments && !edges.empty())
    drawing.notes.push_back(
        bySign > 0 ? "no edges_assignment: " + std::to_string(bySign) +
                         " edges read as mountain or valley by their fold angle's sign, the "
                         "rest as unassigned (U)"
                   : std::string("no edges_assignment: every edge read as unassigned (U)"));
  if (join) drawing.notes.push_back("edges_assignment: J (join) edges read as flat (F)");
  if (defaulted > 0)
    drawing.notes.push_back(std::to_string(defaulted) +
                            " mountain and valley edges without a fold angle fold to -180 and "
                            "+180 degrees");
  if (signDisagrees > 0)
    drawing.notes.push_back(std::to_string(signDisagrees) +
                            " fold angles disagree in sign with their assignment; the angle "
                            "is kept");

  // Faces, when given; a side that is no edge becomes a Flat edge.
  if (const json* faces = reader.optionalMember(document, "faces_vertices", "")) {
    reader.array(*faces, "faces_vertices");
    std::unordered_set<std::uint64_t> listed;
    for (const CreaseLine& line : drawing.lines)
      listed.insert((std::uint64_t(std::min(line.a, line.b)) << 32) | std::max(line.a, line.b));
    std::uint64_t corners = 0;
    std::size_t added = 0;
    for (std::size_t f = 0; f < faces->size(); ++f) {
      const std::string where = JsonReader::item("faces_vertices", f);
      const json& face = reader.array((*faces)[f], where);
      corners += face.size();
      if (corners > kMaxCreasePatternFaceCorners)
        reader.fail("faces_vertices", "more than " + std::to_string(kMaxCreasePatternFaceCorners) +
                                          " face corners in all");
      if (face.size() < 3) reader.fail(where, "has fewer than 3 vertices");
      std::vector<std::uint32_t> loop;
      for (std::size_t k = 0; k < face.size(); ++k) {
        const std::uint64_t v = reader.unsignedInteger(face[k], JsonReader::item(where, k));
        if (v >= points.size())
          reader.fail(where, "vertex " + std::to_string(v) + " out of range (" +
                                 std::to_string(points.size()) + " vertices)");
        loop.push_back(static_cast<std::uint32_t>(v));
      }
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const std::uint32_t a = loop[k], b = loop[(k + 1) % loop.size()];
        if (a == b) continue;
        if (listed.insert((std::uint64_t(std::min(a, b)) << 32) | std::max(a, b)).second) {
          if (drawing.lines.size() >= kMaxCreasePatternEdges)
            reader.fail("faces_vertices", "more edges than a crease pattern may hold");
          drawing.lines.push_back({a, b, CreaseAssignment::Flat, 0.0});
          drawing.lineNames.push_back(where + "'s side " + std::to_string(a) + "-" +
                                      std::to_string(b));
          ++added;
        }
      }
      drawing.faces.push_back(std::move(loop));
    }
    if (added > 0)
      drawing.notes.push_back(std::to_string(added) +
                              " face sides that are not in edges_vertices added as flat edges");
  }

  // What is read but not used.
  std::vector<std::string> ignored, frameKeys;
  for (const auto& [key, value] : document.items()) {
    static const std::unordered_set<std::string> used = {"vertices_coords",  "edges_vertices",
                                                         "edges_assignment", "edges_foldAngle",
                                                         "edges_foldAngles", "faces_vertices"};
    if (used.count(key)) continue;
    if (key == "file_frames")
      drawing.notes.push_back("file_frames (" +
                              std::to_string(value.is_array() ? value.size() : 0) +
                              " frames) ignored: only the key frame is read");
    else if (key.rfind("frame_", 0) == 0) {
      if (key != "frame_unit")     // read with the size
        frameKeys.push_back(key);  // title, classes, attributes: a note
    } else if (key.rfind("file_", 0) == 0)
      continue;  // spec, creator, author, title, classes: about the file, nothing to fold
    else
      ignored.push_back(key);
  }
  if (!frameKeys.empty()) {
    std::string line = "key frame metadata ignored:";
    for (std::size_t k = 0; k < frameKeys.size() && k < 8; ++k)
      line += (k ? ", " : " ") + quotedExcerpt(frameKeys[k], 40);
    drawing.notes.push_back(line);
  }
  if (!ignored.empty()) {
    std::string line = "ignored:";
    for (std::size_t k = 0; k < ignored.size() && k < 8; ++k)
      line += (k ? ", " : " ") + quotedExcerpt(ignored[k], 40);
    if (ignored.size() > 8) line += " and " + std::to_string(ignored.size() - 8) + " more";
    drawing.notes.push_back(line);
  }
  return drawing;
}

// The frame to read: the key frame (the file's top level), or, where it holds no vertices (a
// file that keeps every frame in file_frames, which FOLD allows), the first frame of file_frames
// with vertices and edges, one whose frame_classes names a crease pattern first; its index in
// `index`, SIZE_MAX for the key frame.
const json& frameToRead(const json& document, std::size_t& index) {
  index = SIZE_MAX;
  if (!document.is_object() || document.contains("vertices_coords")) return document;
  const auto frames = document.find("file_frames");
  if (frames == document.end() || !frames->is_array()) return document;
  for (std::size_t k = 0; k < frames->size(); ++k) {
    const json& frame = (*frames)[k];
    if (!frame.is_object() || !frame.contains("vertices_coords") ||
        !frame.contains("edges_vertices"))
      continue;
    const auto classes = frame.find("frame_classes");
    const bool creasePattern =
        classes != frame.end() && classes->is_array() &&
        std::find(classes->begin(), classes->end(), json("creasePattern")) != classes->end();
    if (index == SIZE_MAX || creasePattern) index = k;
    if (creasePattern) break;
  }
  return index == SIZE_MAX ? document : (*frames)[index];
}

}  // namespace

CreasePattern readFoldCreasePatternText(std::string_view text, std::string_view name) {
  try {
    const json document = parseJsonText(text, name);
    std::size_t frameIndex = SIZE_MAX;
    const json& frame = frameToRead(document, frameIndex);
    const JsonReader reader(frameIndex == SIZE_MAX ? std::string{name}
                                                   : std::string{name} + ": file_frames[" +
                                                         std::to_string(frameIndex) + "]");
    CreaseDrawing drawing = readDrawing(frame, reader);
    if (frameIndex != SIZE_MAX)
      drawing.notes.insert(drawing.notes.begin(),
                           "the key frame has no vertices_coords: file_frames[" +
                               std::to_string(frameIndex) + "] read as the crease pattern");
    PlanarizeOptions options;
    options.strict = true;
    planarize(drawing, options);
    CreasePattern pattern = triangulateCreaseDrawing(drawing);
    // FOLD's frame_unit: the units it names scale to metres; "unit" (FOLD's default: no physical
    // size) and anything else leave the coordinates as metres, the stated default. A value that
    // is no unit this reader knows is said in a note, so the size it falls back to is not silent.
    static const std::unordered_map<std::string, double> metres = {
        {"m", 1.0},   {"cm", 1e-2},   {"mm", 1e-3},       {"um", 1e-6},
        {"nm", 1e-9}, {"in", 0.0254}, {"pt", 0.0254 / 72}};
    pattern.unitSource = "FOLD coordinates read as metres";
    const json& unitFrame = frame.contains("frame_unit") ? frame : document;
    if (const auto unit = unitFrame.find("frame_unit"); unit != unitFrame.end()) {
      const auto found = unit->is_string() ? metres.find(unit->get<std::string>()) : metres.end();
      if (found != metres.end()) {
        pattern.metresPerUnit = found->second;
        pattern.unitSource = "FOLD frame_unit " + found->first;
      } else if (unit->is_string() && unit->get<std::string>() == "unit") {
        pattern.unitSource = "FOLD frame_unit \"unit\" (no physical size): read as metres";
      } else {
        pattern.notes.push_back("frame_unit " + jsonExcerpt(*unit) +
                                ": not a unit this reader knows (m, cm, mm, um, nm, in, pt or "
                                "unit); the coordinates are read as metres");
        pattern.unitSource = "FOLD frame_unit " + jsonExcerpt(*unit) + " unknown: read as metres";
      }
    }
    return pattern;
  } catch (const JsonReadError& error) {
    throw CreasePatternError(error.what());
  } catch (const CreasePatternError& error) {
    const std::string message = error.what();
    if (message.rfind(std::string(name) + ": ", 0) == 0) throw;
    throw CreasePatternError(std::string(name) + ": " + message);
  } catch (const std::bad_alloc&) {
    throw CreasePatternError(std::string(name) + ": out of memory reading it");
  }
}

CreasePattern readFoldCreasePattern(const std::filesystem::path& path) {
  const std::string text = readWholeFile(path, kMaxCreasePatternBytes, "crease pattern");
  return readFoldCreasePatternText(text, path.string());
}

}  // namespace curvefold
