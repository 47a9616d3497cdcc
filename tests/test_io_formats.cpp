// Atomic writes and the export formats (FOLD, SVG, OBJ, glTF), each written and parsed back.
#include <charconv>
#include <cmath>
#include <map>
#include <regex>
#include <stdexcept>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "engine/fabrication/svg_crease_pattern.hpp"
#include "engine/geometry/creases.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/fold_format.hpp"
#include "engine/io/gltf_writer.hpp"
#include "engine/io/obj_writer.hpp"
#include "engine/surfaces/obj_surface.hpp"
#include "io_test_support.hpp"

namespace curvefold {
namespace {

using testing::ScratchDirectory;
using testing::testStrip;

TEST(TestStrip, IsAValidSheetWithTheIntendedFolds) {
  const Sheet sheet = testStrip();
  ASSERT_NO_THROW(validate(sheet));
  const std::vector<CreaseEdge> creases = creaseEdges(sheet, buildEdgeTopology(sheet));
  ASSERT_EQ(creases.size(), 3u);
  EXPECT_NEAR(creases[0].foldAngle, 90.0, 1e-9);
  EXPECT_EQ(creases[0].assignment, Assignment::Valley);
  EXPECT_NEAR(creases[1].foldAngle, -60.0, 1e-9);
  EXPECT_EQ(creases[1].assignment, Assignment::Mountain);
  EXPECT_EQ(creases[2].assignment, Assignment::Flat);
}

// --- atomic writes ------------------------------------------------------------------------------

using AtomicFile = ScratchDirectory;

TEST_F(AtomicFile, WritesAndReplacesLeavingNoTemporaryFile) {
  const auto path = dir() / "a.txt";
  writeFileAtomically(path, "old content");
  std::string big(300'000, 'x');  // several times the stream buffer
  big[123'456] = 'y';
  writeFileAtomically(path, big);
  EXPECT_EQ(readText(path), big);
  EXPECT_EQ(entries(), std::vector<std::string>{"a.txt"});
}

TEST_F(AtomicFile, MissingDirectoryThrowsFileErrorWithPathAndReason) {
  const auto path = dir() / "missing" / "y.svg";
  try {
    writeFileAtomically(path, "content");
    FAIL() << "no exception";
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot write " + path.string() + ": No such file or directory");
  }
  EXPECT_TRUE(entries().empty());
}

TEST_F(AtomicFile, FailedRenameRemovesTheTemporaryFile) {
  // The temporary file is written, then rename() fails: the target is a directory.
  const auto path = dir() / "target";
  std::filesystem::create_directory(path);
  try {
    writeFileAtomically(path, "content");
    FAIL() << "no exception";
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + path.string() + ": Is a directory");
  }
  EXPECT_EQ(entries(), std::vector<std::string>{"target"});
  EXPECT_TRUE(std::filesystem::is_empty(path));
}

TEST_F(AtomicFile, WriterExceptionKeepsTheOldFileAndPropagates) {
  const auto path = dir() / "keep.txt";
  writeFileAtomically(path, "old");
  EXPECT_THROW(writeFileAtomically(path,
                                   [](std::ostream& out) {
                                     out << std::string(100'000, 'z');
                                     throw std::logic_error("halfway");
                                   }),
               std::logic_error);
  EXPECT_EQ(readText(path), "old");
  EXPECT_EQ(entries(), std::vector<std::string>{"keep.txt"});
}

TEST_F(AtomicFile, NewFileHonoursTheUmaskNotMkstempsPrivateMode) {
  const auto path = dir() / "mode.txt";
  writeFileAtomically(path, "x");
  const auto permissions = std::filesystem::status(path).permissions();
  EXPECT_NE(permissions & std::filesystem::perms::others_read, std::filesystem::perms::none);
}

// --- FOLD ---------------------------------------------------------------------------------------

using FoldFormat = ScratchDirectory;

TEST_F(FoldFormat, KeyFrameIsTheCreasePatternAndFrameZeroTheFoldedForm) {
  const Sheet sheet = testStrip();
  const auto path = dir() / "strip.fold";
  writeFold(sheet, path);
  const nlohmann::json fold = nlohmann::json::parse(readText(path));

  EXPECT_EQ(fold["file_spec"], 1.2);
  EXPECT_EQ(fold["file_creator"], "curvefold");
  EXPECT_EQ(fold["frame_classes"], nlohmann::json({"creasePattern"}));
  EXPECT_EQ(fold["frame_unit"], "m");

  const auto& coords = fold["vertices_coords"];
  ASSERT_EQ(coords.size(), sheet.vertexCount());
  for (std::size_t v = 0; v < coords.size(); ++v) {
    ASSERT_EQ(coords[v].size(), 2u);
    EXPECT_EQ(coords[v][0].get<double>(), sheet.development[v].x);
    EXPECT_EQ(coords[v][1].get<double>(), sheet.development[v].y);
  }

  const auto& faces = fold["faces_vertices"];
  ASSERT_EQ(faces.size(), sheet.triangleCount());
  for (std::size_t t = 0; t < faces.size(); ++t) {
    const Triangle tri{faces[t][0].get<std::uint32_t>(), faces[t][1].get<std::uint32_t>(),
                       faces[t][2].get<std::uint32_t>()};
    EXPECT_EQ(tri, sheet.triangles[t]);
    glm::dvec2 p[3];
    for (int k = 0; k < 3; ++k) p[k] = {coords[tri[k]][0], coords[tri[k]][1]};
    const glm::dvec2 e1 = p[1] - p[0], e2 = p[2] - p[0];
    EXPECT_GT(e1.x * e2.y - e1.y * e2.x, 0.0) << "face " << t << " is not counter-clockwise";
  }

  const EdgeTopology topology = buildEdgeTopology(sheet);
  const auto& edges = fold["edges_vertices"];
  const auto& assignments = fold["edges_assignment"];
  const auto& angles = fold["edges_foldAngle"];
  ASSERT_EQ(edges.size(), topology.edges.size());
  ASSERT_EQ(assignments.size(), edges.size());
  ASSERT_EQ(angles.size(), edges.size());
  std::map<Edge, std::size_t> edgeIndex;
  std::map<std::string, int> counts;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    edgeIndex[Edge::of(edges[e][0].get<std::uint32_t>(), edges[e][1].get<std::uint32_t>())] = e;
    ++counts[assignments[e].get<std::string>()];
    if (assignments[e] != "M" && assignments[e] != "V") {
      EXPECT_EQ(angles[e], 0.0);
    }
  }
  EXPECT_EQ(edgeIndex.size(), edges.size());
  // 10 top and bottom edges + the right end; the left end is the slit.
  EXPECT_EQ(counts,
            (std::map<std::string, int>{{"B", 11}, {"C", 1}, {"F", 7}, {"M", 1}, {"V", 1}}));
  for (const CreaseEdge& crease : creaseEdges(sheet, topology)) {
    const std::size_t e = edgeIndex.at(crease.edge);
    EXPECT_EQ(assignments[e], std::string(1, static_cast<char>(crease.assignment)));
    if (crease.assignment != Assignment::Flat) {
      EXPECT_EQ(angles[e].get<double>(), crease.foldAngle);
    }
  }
  EXPECT_NEAR(angles[edgeIndex.at(Edge::of(2, 3))].get<double>(), 90.0, 1e-9);  // valley > 0
  EXPECT_NEAR(angles[edgeIndex.at(Edge::of(4, 5))].get<double>(), -60.0, 1e-9);

  EXPECT_EQ(fold["curvefold:creaseCurves"].size(), 3u);

  ASSERT_EQ(fold["file_frames"].size(), 1u);
  const auto& folded = fold["file_frames"][0];
  // Issue 18, 4: the folded form keeps every edge's measured dihedral, bends included (the 10
  // degree bend is F with fold angle 0 above), in the FOLD convention's sign.
  const auto& bends = folded["curvefold:edges_bendAngle"];
  ASSERT_EQ(bends.size(), edges.size());
  for (const EdgeTopology::EdgeSides& sides : topology.edges) {
    const std::size_t e = edgeIndex.at(sides.edge);
    EXPECT_EQ(bends[e].get<double>(), foldAngleDegrees(sheet, sides));
    if (assignments[e] == "M" || assignments[e] == "V") {
      EXPECT_EQ(bends[e], angles[e]);
    }
  }
  EXPECT_NEAR(std::abs(bends[edgeIndex.at(Edge::of(6, 7))].get<double>()), 10.0, 1e-9);
  EXPECT_EQ(angles[edgeIndex.at(Edge::of(6, 7))].get<double>(), 0.0);
  EXPECT_EQ(folded["frame_classes"], nlohmann::json({"foldedForm"}));
  EXPECT_EQ(folded["frame_attributes"], nlohmann::json({"3D"}));
  EXPECT_EQ(folded["frame_parent"], 0);
  EXPECT_EQ(folded["frame_inherit"], true);
  const auto& coords3d = folded["vertices_coords"];
  ASSERT_EQ(coords3d.size(), sheet.vertexCount());
  for (const auto& edge : edges) {
    const std::size_t a = edge[0], b = edge[1];
    ASSERT_EQ(coords3d[a].size(), 3u);
    const glm::dvec3 pa{coords3d[a][0], coords3d[a][1], coords3d[a][2]};
    const glm::dvec3 pb{coords3d[b][0], coords3d[b][1], coords3d[b][2]};
    const glm::dvec2 qa{coords[a][0], coords[a][1]};
    const glm::dvec2 qb{coords[b][0], coords[b][1]};
    EXPECT_NEAR(glm::distance(pa, pb), glm::distance(qa, qb), 1e-12);
  }
  // The folded form really is folded: the valley panel stands up.
  EXPECT_NEAR(coords3d[5][2].get<double>(), 0.05, 1e-12);
}

TEST_F(FoldFormat, UnwritablePathThrowsAndLeavesNothing) {
  EXPECT_THROW(writeFold(testStrip(), dir() / "no" / "x.fold"), FileError);
  EXPECT_TRUE(entries().empty());
}

// --- SVG ----------------------------------------------------------------------------------------

struct SvgLine {
  glm::dvec2 a, b;
  std::string colour;
  double opacity = 0.0;
};

std::vector<SvgLine> svgLines(const std::string& svg) {
  static const std::regex line(
      R"re(<line x1="([^"]+)" y1="([^"]+)" x2="([^"]+)" y2="([^"]+)" stroke="([^"]+)" stroke-opacity="([^"]+)")re");
  std::vector<SvgLine> lines;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), line); it != std::sregex_iterator();
       ++it) {
    const std::smatch& m = *it;
    lines.push_back({{std::stod(m[1]), std::stod(m[2])},
                     {std::stod(m[3]), std::stod(m[4])},
                     m[5],
                     std::stod(m[6])});
  }
  return lines;
}

using SvgCreasePattern = ScratchDirectory;

TEST_F(SvgCreasePattern, ColoursCountsSizeAndYFlip) {
  const Sheet sheet = testStrip();
  const auto path = dir() / "strip.svg";
  writeSvgCreasePattern(sheet, path, {.marginMm = 10.0, .strokeWidthMm = 0.3});
  const std::string svg = readText(path);

  // 5 panels of 50 mm by 100 mm plus 10 mm margins.
  EXPECT_NE(svg.find(R"(width="270.0000mm" height="120.0000mm" viewBox="0 0 270.0000 120.0000")"),
            std::string::npos)
      << svg.substr(0, 300);
  EXPECT_EQ(svg.find("<g"), std::string::npos);
  // Every line is a direct child of <svg>: nothing but lines between its tags.
  const std::regex body(R"(^<\?xml[^>]*\?>\n<svg [^>]*>\n(<line [^>]*/>\n)*</svg>\n$)");
  EXPECT_TRUE(std::regex_match(svg, body));

  const std::vector<SvgLine> lines = svgLines(svg);
  std::map<std::string, int> counts;
  for (const SvgLine& l : lines) ++counts[l.colour];
  const EdgeTopology topology = buildEdgeTopology(sheet);
  int boundary = 0;
  for (const auto& sides : topology.edges)
    if (sides.isBoundary() && sheet.edgeKind(sides.edge) != EdgeKind::Slit) ++boundary;
  int mountains = 0, valleys = 0;
  for (const CreaseEdge& c : creaseEdges(sheet, topology)) {
    mountains += c.assignment == Assignment::Mountain;
    valleys += c.assignment == Assignment::Valley;
  }
  EXPECT_EQ(counts["#000000"], boundary);
  EXPECT_EQ(counts["#ff0000"], mountains);
  EXPECT_EQ(counts["#0000ff"], valleys);
  EXPECT_EQ(counts["#00ff00"], 1);
  EXPECT_EQ(lines.size(), static_cast<std::size_t>(boundary + mountains + valleys + 1));
  for (const SvgLine& l : lines) {
    if (l.colour == "#ff0000") {
      EXPECT_NEAR(l.opacity, 60.0 / 180.0, 1e-4);
    } else if (l.colour == "#0000ff") {
      EXPECT_NEAR(l.opacity, 0.5, 1e-4);
    } else {
      EXPECT_EQ(l.opacity, 1.0);
    }
  }

  // The slit runs from vertex 0 (development y = 0, lowest) to vertex 1 (y = 0.1, highest): in
  // SVG's y-down coordinates the highest point must have the smallest y.
  const auto slit = std::find_if(lines.begin(), lines.end(),
                                 [](const SvgLine& l) { return l.colour == "#00ff00"; });
  ASSERT_NE(slit, lines.end());
  EXPECT_EQ(slit->a, glm::dvec2(10.0, 110.0));
  EXPECT_EQ(slit->b, glm::dvec2(10.0, 10.0));
  // The valley crease at x = 50 mm.
  const auto valley = std::find_if(lines.begin(), lines.end(),
                                   [](const SvgLine& l) { return l.colour == "#0000ff"; });
  EXPECT_EQ(valley->a.x, 60.0);
}

TEST_F(SvgCreasePattern, AsymmetricOutlineIsNotMirrored) {
  // A right triangle with its right angle at the development's top-left corner.
  Sheet sheet;
  sheet.development = {{0.0, 0.0}, {0.1, 0.1}, {0.0, 0.1}};
  sheet.positions = {{0.0, 0.0, 0.0}, {0.1, 0.1, 0.0}, {0.0, 0.1, 0.0}};
  sheet.triangles = {{0, 1, 2}};
  const auto path = dir() / "triangle.svg";
  writeSvgCreasePattern(sheet, path, {.marginMm = 0.0, .strokeWidthMm = 0.1});
  std::vector<glm::dvec2> ends;
  for (const SvgLine& l : svgLines(readText(path))) {
    ends.push_back(l.a);
    ends.push_back(l.b);
  }
  ASSERT_EQ(ends.size(), 6u);
  // Top-left in the development stays top-left on paper: SVG (0, 0).
  EXPECT_NE(std::find(ends.begin(), ends.end(), glm::dvec2(0.0, 0.0)), ends.end());
  EXPECT_NE(std::find(ends.begin(), ends.end(), glm::dvec2(0.0, 100.0)), ends.end());
  EXPECT_NE(std::find(ends.begin(), ends.end(), glm::dvec2(100.0, 0.0)), ends.end());
  EXPECT_EQ(std::find(ends.begin(), ends.end(), glm::dvec2(100.0, 100.0)), ends.end());
}

TEST_F(SvgCreasePattern, BadOptionsAndUnwritablePath) {
  EXPECT_THROW(writeSvgCreasePattern(testStrip(), dir() / "x.svg", {.marginMm = -1.0}),
               std::invalid_argument);
  EXPECT_THROW(writeSvgCreasePattern(testStrip(), dir() / "x.svg", {.strokeWidthMm = 0.0}),
               std::invalid_argument);
  EXPECT_THROW(writeSvgCreasePattern(testStrip(), dir() / "no" / "x.svg"), FileError);
  EXPECT_TRUE(entries().empty());
}

// --- OBJ ----------------------------------------------------------------------------------------

struct ObjData {
  std::vector<glm::dvec3> v;
  std::vector<glm::dvec2> vt;
  std::vector<std::vector<std::pair<int, int>>> f;
  std::vector<std::vector<int>> l;
  std::vector<std::string> groups;
};

double parseDouble(std::istringstream& in) {
  std::string word;
  in >> word;
  double value = 0.0;
  const auto result = std::from_chars(word.data(), word.data() + word.size(), value);
  EXPECT_EQ(result.ptr, word.data() + word.size()) << word;
  return value;
}

ObjData parseObj(const std::string& text) {
  ObjData obj;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream in(line);
    std::string kind;
    in >> kind;
    if (kind == "v") {
      glm::dvec3 p;
      for (int i = 0; i < 3; ++i) p[i] = parseDouble(in);
      obj.v.push_back(p);
    } else if (kind == "vt") {
      glm::dvec2 p;
      for (int i = 0; i < 2; ++i) p[i] = parseDouble(in);
      obj.vt.push_back(p);
    } else if (kind == "f") {
      std::vector<std::pair<int, int>> face;
      std::string corner;
      while (in >> corner) {
        const auto slash = corner.find('/');
        face.emplace_back(std::stoi(corner.substr(0, slash)), std::stoi(corner.substr(slash + 1)));
      }
      obj.f.push_back(face);
    } else if (kind == "l") {
      std::vector<int> polyline;
      int v;
      while (in >> v) polyline.push_back(v);
      obj.l.push_back(polyline);
    } else if (kind == "g") {
      std::string name;
      in >> name;
      obj.groups.push_back(name);
    }
  }
  return obj;
}

using ObjWriter = ScratchDirectory;

TEST_F(ObjWriter, RoundTripsExactlyWithCreaseLines) {
  // Coordinates that need all 17 digits.
  Sheet sheet = testStrip();
  for (auto& p : sheet.positions) p = p * (1.0 / 3.0) + glm::dvec3(0.1, 0.2, 0.3);
  for (auto& p : sheet.development) p = p * (1.0 / 3.0);
  const auto path = dir() / "strip.obj";
  writeObj(sheet, path);
  const ObjData obj = parseObj(readText(path));

  ASSERT_EQ(obj.v.size(), sheet.vertexCount());
  ASSERT_EQ(obj.vt.size(), sheet.vertexCount());
  for (std::size_t i = 0; i < obj.v.size(); ++i) {
    EXPECT_EQ(obj.v[i], sheet.positions[i]);
    EXPECT_EQ(obj.vt[i], sheet.development[i]);
  }
  ASSERT_EQ(obj.f.size(), sheet.triangleCount());
  for (std::size_t t = 0; t < obj.f.size(); ++t) {
    ASSERT_EQ(obj.f[t].size(), 3u);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(obj.f[t][k].first, static_cast<int>(sheet.triangles[t][k]) + 1);
      EXPECT_EQ(obj.f[t][k].second, obj.f[t][k].first);
    }
  }
  EXPECT_EQ(obj.groups, (std::vector<std::string>{"paper", "creases"}));
  // Three crease curves, each the single vertical crease edge of its column.
  ASSERT_EQ(obj.l.size(), 3u);
  std::vector<Edge> drawn;
  for (const auto& polyline : obj.l) {
    ASSERT_EQ(polyline.size(), 2u);
    drawn.push_back(Edge::of(polyline[0] - 1, polyline[1] - 1));
  }
  std::sort(drawn.begin(), drawn.end());
  EXPECT_EQ(drawn, (std::vector<Edge>{Edge::of(2, 3), Edge::of(4, 5), Edge::of(8, 9)}));
}

TEST_F(ObjWriter, CreaseLinesAreOptional) {
  const auto path = dir() / "plain.obj";
  writeObj(testStrip(), path, {.creaseLines = false});
  const ObjData obj = parseObj(readText(path));
  EXPECT_TRUE(obj.l.empty());
  EXPECT_EQ(obj.groups, std::vector<std::string>{"paper"});
  EXPECT_EQ(obj.f.size(), testStrip().triangleCount());
  EXPECT_THROW(writeObj(testStrip(), dir() / "no" / "x.obj"), FileError);
  EXPECT_EQ(entries(), std::vector<std::string>{"plain.obj"});
}

TEST_F(ObjWriter, ReadsBackThroughTheSurfaceImporter) {
  // Our own OBJ importer must accept what we write, crease polylines and groups included.
  const Sheet sheet = testing::testStrip();
  const auto path = dir() / "strip.obj";
  writeObj(sheet, path);
  const Sheet read = readObjSurface(path.string());
  ASSERT_EQ(read.vertexCount(), sheet.vertexCount());
  ASSERT_EQ(read.triangleCount(), sheet.triangleCount());
  // The importer numbers vertices its own way; compare triangle corners.
  for (std::size_t t = 0; t < read.triangleCount(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const VertexIndex r = read.triangles[t][k], v = sheet.triangles[t][k];
      EXPECT_EQ(read.positions[r], sheet.positions[v]);
      EXPECT_NEAR(glm::distance(read.development[r], sheet.development[v]), 0.0, 1e-12);
    }
  }
}

// --- glTF ---------------------------------------------------------------------------------------

template <typename T>
std::vector<T> accessorData(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& accessor = model.accessors.at(index);
  const tinygltf::BufferView& view = model.bufferViews.at(accessor.bufferView);
  const std::vector<unsigned char>& data = model.buffers.at(view.buffer).data;
  const int components = tinygltf::GetNumComponentsInType(accessor.type);
  std::vector<T> values(accessor.count * components);
  EXPECT_LE(view.byteOffset + accessor.byteOffset + values.size() * sizeof(T), data.size());
  std::memcpy(values.data(), data.data() + view.byteOffset + accessor.byteOffset,
              values.size() * sizeof(T));
  return values;
}

using GltfWriter = ScratchDirectory;

TEST_F(GltfWriter, LoadsBackWithSplitCreasesAndTheRightBounds) {
  const Sheet sheet = testStrip();
  const auto path = dir() / "strip.glb";
  writeGlb(sheet, path);
  EXPECT_EQ(readText(path).substr(0, 4), "glTF");

  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, path.string())) << error;
  ASSERT_EQ(model.meshes.size(), 1u);
  const auto& primitives = model.meshes[0].primitives;
  ASSERT_EQ(primitives.size(), 3u);  // paper, mountain lines, valley lines

  const tinygltf::Primitive& paper = primitives[0];
  EXPECT_EQ(paper.mode, TINYGLTF_MODE_TRIANGLES);
  EXPECT_TRUE(model.materials.at(paper.material).doubleSided);
  const int position = paper.attributes.at("POSITION");
  const int normal = paper.attributes.at("NORMAL");
  const int texcoord = paper.attributes.at("TEXCOORD_0");
  // Each of the 3 crease columns (2 vertices each) is split in two; the bend is not.
  const std::size_t vertices = sheet.vertexCount() + 6;
  EXPECT_EQ(model.accessors[position].count, vertices);
  EXPECT_EQ(model.accessors[normal].count, vertices);
  EXPECT_EQ(model.accessors[texcoord].count, vertices);
  EXPECT_EQ(model.accessors[position].componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(model.accessors[texcoord].type, TINYGLTF_TYPE_VEC2);
  EXPECT_EQ(model.accessors[paper.indices].count, 3 * sheet.triangleCount());
  EXPECT_EQ(model.accessors[paper.indices].componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);

  // Bounds: the sheet's 3D box, and the stored floats lie within them, touching every side.
  glm::dvec3 lo(1e9), hi(-1e9);
  for (const glm::dvec3& p : sheet.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const std::vector<float> positions = accessorData<float>(model, position);
  glm::dvec3 storedLo(1e9), storedHi(-1e9);
  for (std::size_t i = 0; i < vertices; ++i) {
    const glm::dvec3 p(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
    storedLo = glm::min(storedLo, p);
    storedHi = glm::max(storedHi, p);
  }
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(model.accessors[position].minValues.at(i), lo[i], 1e-7);
    EXPECT_NEAR(model.accessors[position].maxValues.at(i), hi[i], 1e-7);
    EXPECT_EQ(model.accessors[position].minValues[i], storedLo[i]);
    EXPECT_EQ(model.accessors[position].maxValues[i], storedHi[i]);
  }

  // Every output vertex is a sheet vertex (3D and development agree), and the first, flat panel
  // faces +z.
  const std::vector<float> uvs = accessorData<float>(model, texcoord);
  const std::vector<float> normals = accessorData<float>(model, normal);
  const std::vector<std::uint32_t> indices = accessorData<std::uint32_t>(model, paper.indices);
  for (std::size_t c = 0; c < indices.size(); ++c) {
    const std::uint32_t i = indices[c];
    ASSERT_LT(i, vertices);
    const VertexIndex v = sheet.triangles[c / 3][c % 3];
    EXPECT_EQ(positions[3 * i], static_cast<float>(sheet.positions[v].x));
    EXPECT_EQ(positions[3 * i + 2], static_cast<float>(sheet.positions[v].z));
    EXPECT_EQ(uvs[2 * i], static_cast<float>(sheet.development[v].x));
    EXPECT_EQ(uvs[2 * i + 1], static_cast<float>(sheet.development[v].y));
    if (c < 6) {
      EXPECT_NEAR(normals[3 * i + 2], 1.0f, 1e-6f);
    }
  }

  std::map<std::string, std::size_t> lineIndexCounts;
  for (std::size_t p = 1; p < primitives.size(); ++p) {
    EXPECT_EQ(primitives[p].mode, TINYGLTF_MODE_LINE);
    EXPECT_EQ(primitives[p].attributes.at("POSITION"), position);
    lineIndexCounts[model.materials.at(primitives[p].material).name] =
        model.accessors.at(primitives[p].indices).count;
  }
  EXPECT_EQ(lineIndexCounts, (std::map<std::string, std::size_t>{{"mountain", 2}, {"valley", 2}}));
  EXPECT_EQ(model.materials[primitives[1].material].pbrMetallicRoughness.baseColorFactor,
            (std::vector<double>{1.0, 0.0, 0.0, 1.0}));
}

TEST_F(GltfWriter, UnwritablePathThrowsAndLeavesNothing) {
  EXPECT_THROW(writeGlb(testStrip(), dir() / "no" / "x.glb"), FileError);
  EXPECT_TRUE(entries().empty());
}

}  // namespace
}  // namespace curvefold
