#include "engine/io/gltf_writer.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <ostream>

#include <tiny_gltf.h>
#include <glm/geometric.hpp>

#include "engine/geometry/creases.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/io/atomic_file.hpp"

namespace curvefold {
namespace {

// Corners (triangle * 3 + k) of one vertex joined across every shared edge that is not a crease:
// each resulting group becomes one output vertex with one smooth normal.
struct CornerGroups {
  std::vector<std::uint32_t> groupOfCorner;
  std::vector<VertexIndex> vertexOfGroup;
};

CornerGroups groupCorners(const Sheet& sheet, const EdgeTopology& topology) {
  std::vector<std::uint32_t> parent(sheet.triangleCount() * 3);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t c) {
    while (parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  };
  auto cornerOf = [&](TriangleIndex t, VertexIndex v) {
    const Triangle& tri = sheet.triangles[t];
    const std::uint32_t k = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
    return t * 3 + k;
  };
  for (const EdgeTopology::EdgeSides& sides : topology.edges) {
    if (sides.left == kNoIndex || sides.right == kNoIndex) continue;
    if (sheet.edgeKind(sides.edge) == EdgeKind::Crease) continue;
    for (VertexIndex v : {sides.edge.a, sides.edge.b})
      parent[find(cornerOf(sides.left, v))] = find(cornerOf(sides.right, v));
  }
  CornerGroups groups;
  groups.groupOfCorner.resize(parent.size());
  std::vector<std::uint32_t> groupOfRoot(parent.size(), kNoIndex);
  for (std::uint32_t c = 0; c < parent.size(); ++c) {
    std::uint32_t& group = groupOfRoot[find(c)];
    if (group == kNoIndex) {
      group = static_cast<std::uint32_t>(groups.vertexOfGroup.size());
      groups.vertexOfGroup.push_back(sheet.triangles[c / 3][c % 3]);
    }
    groups.groupOfCorner[c] = group;
  }
  return groups;
}

template <typename T>
int appendView(tinygltf::Model& model, const std::vector<T>& values, int target) {
  std::vector<unsigned char>& data = model.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();  // every element is 4-byte aligned, so views stay aligned
  view.byteLength = values.size() * sizeof(T);
  view.target = target;
  data.resize(data.size() + view.byteLength);
  if (view.byteLength > 0)
    std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size() - 1);
}

int appendAccessor(tinygltf::Model& model, int view, int componentType, std::size_t count,
                   int type) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.componentType = componentType;
  accessor.count = count;
  accessor.type = type;
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size() - 1);
}

int appendMaterial(tinygltf::Model& model, const char* name, std::vector<double> colour,
                   double roughness) {
  tinygltf::Material material;
  material.name = name;
  material.pbrMetallicRoughness.baseColorFactor = std::move(colour);
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = roughness;
  material.doubleSided = true;
  model.materials.push_back(material);
  return static_cast<int>(model.materials.size() - 1);
}

tinygltf::Model buildModel(const Sheet& sheet) {
  const EdgeTopology topology = buildEdgeTopology(sheet);
  const CornerGroups groups = groupCorners(sheet, topology);
  const std::size_t vertexCount = groups.vertexOfGroup.size();

  // Angle-weighted normals, so the result does not depend on how the surface is triangulated.
  std::vector<glm::dvec3> normalSums(vertexCount, glm::dvec3(0.0));
  std::vector<std::uint32_t> indices(sheet.triangleCount() * 3);
  for (TriangleIndex t = 0; t < sheet.triangleCount(); ++t) {
    const Triangle& tri = sheet.triangles[t];
    const glm::dvec3 a = sheet.positions[tri[0]], b = sheet.positions[tri[1]],
                     c = sheet.positions[tri[2]];
    const glm::dvec3 cross = glm::cross(b - a, c - a);
    const double length = glm::length(cross);
    const glm::dvec3 normal = length > 0.0 ? cross / length : glm::dvec3(0.0);
    const glm::dvec3 corners[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 e1 = corners[(k + 1) % 3] - corners[k];
      const glm::dvec3 e2 = corners[(k + 2) % 3] - corners[k];
      const double angle = std::atan2(glm::length(glm::cross(e1, e2)), glm::dot(e1, e2));
      const std::uint32_t group = groups.groupOfCorner[t * 3 + k];
      normalSums[group] += angle * normal;
      indices[t * 3 + k] = group;
    }
  }

  std::vector<float> positions, normals, texcoords;
  positions.reserve(vertexCount * 3);
  normals.reserve(vertexCount * 3);
  texcoords.reserve(vertexCount * 2);
  std::vector<double> lo(3, std::numeric_limits<double>::infinity());
  std::vector<double> hi(3, -std::numeric_limits<double>::infinity());
  for (std::uint32_t g = 0; g < vertexCount; ++g) {
    const VertexIndex v = groups.vertexOfGroup[g];
    const glm::vec3 p(sheet.positions[v]);
    const double length = glm::length(normalSums[g]);
    const glm::vec3 n(length > 0.0 ? normalSums[g] / length : glm::dvec3(0.0, 0.0, 1.0));
    for (int i = 0; i < 3; ++i) {
      positions.push_back(p[i]);
      normals.push_back(n[i]);
      // glTF requires POSITION bounds; they describe the stored floats exactly.
      lo[i] = std::min(lo[i], static_cast<double>(p[i]));
      hi[i] = std::max(hi[i], static_cast<double>(p[i]));
    }
    texcoords.push_back(static_cast<float>(sheet.development[v].x));
    texcoords.push_back(static_cast<float>(sheet.development[v].y));
  }

  // Crease lines index the same vertices: any output vertex of an original vertex will do.
  std::vector<std::uint32_t> anyGroupOf(sheet.vertexCount(), kNoIndex);
  for (std::uint32_t g = 0; g < vertexCount; ++g)
    if (anyGroupOf[groups.vertexOfGroup[g]] == kNoIndex) anyGroupOf[groups.vertexOfGroup[g]] = g;
  std::vector<std::uint32_t> mountains, valleys;
  for (const CreaseEdge& crease : creaseEdges(sheet, topology)) {
    std::vector<std::uint32_t>* lines = crease.assignment == Assignment::Mountain ? &mountains
                                        : crease.assignment == Assignment::Valley ? &valleys
                                                                                  : nullptr;
    if (lines == nullptr) continue;
    lines->push_back(anyGroupOf[crease.edge.a]);
    lines->push_back(anyGroupOf[crease.edge.b]);
  }

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "curvefold";
  model.buffers.emplace_back();

  const int position =
      appendAccessor(model, appendView(model, positions, TINYGLTF_TARGET_ARRAY_BUFFER),
                     TINYGLTF_COMPONENT_TYPE_FLOAT, vertexCount, TINYGLTF_TYPE_VEC3);
  model.accessors[position].minValues = lo;
  model.accessors[position].maxValues = hi;
  const int normal = appendAccessor(model, appendView(model, normals, TINYGLTF_TARGET_ARRAY_BUFFER),
                                    TINYGLTF_COMPONENT_TYPE_FLOAT, vertexCount, TINYGLTF_TYPE_VEC3);
  const int texcoord =
      appendAccessor(model, appendView(model, texcoords, TINYGLTF_TARGET_ARRAY_BUFFER),
                     TINYGLTF_COMPONENT_TYPE_FLOAT, vertexCount, TINYGLTF_TYPE_VEC2);

  tinygltf::Mesh mesh;
  mesh.name = "sheet";
  tinygltf::Primitive paper;
  paper.mode = TINYGLTF_MODE_TRIANGLES;
  paper.attributes = {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", texcoord}};
  paper.indices =
      appendAccessor(model, appendView(model, indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, indices.size(), TINYGLTF_TYPE_SCALAR);
  paper.material = appendMaterial(model, "paper", {1.0, 1.0, 1.0, 1.0}, 0.9);
  mesh.primitives.push_back(paper);

  auto addLines = [&](const std::vector<std::uint32_t>& lines, const char* name,
                      std::vector<double> colour) {
    if (lines.empty()) return;
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_LINE;
    primitive.attributes = {{"POSITION", position}};
    primitive.indices =
        appendAccessor(model, appendView(model, lines, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                       TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, lines.size(), TINYGLTF_TYPE_SCALAR);
    primitive.material = appendMaterial(model, name, std::move(colour), 1.0);
    mesh.primitives.push_back(primitive);
  };
  addLines(mountains, "mountain", {1.0, 0.0, 0.0, 1.0});
  addLines(valleys, "valley", {0.0, 0.0, 1.0, 1.0});
  model.meshes.push_back(mesh);

  tinygltf::Node node;
  node.name = "sheet";
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  return model;
}

}  // namespace

void writeGlb(const Sheet& sheet, const std::filesystem::path& path) {
  const tinygltf::Model model = buildModel(sheet);
  writeFileAtomically(path, [&](std::ostream& out) {
    tinygltf::TinyGLTF gltf;
    if (!gltf.WriteGltfSceneToStream(&model, out, false, true))
      throw FileError("cannot write " + path.string() + ": glTF serialisation failed");
  });
}

}  // namespace curvefold
