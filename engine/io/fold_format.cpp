#include "engine/io/fold_format.hpp"
#include "engine/io/json_reader.hpp"

#include <nlohmann/json.hpp>

#include "engine/geometry/creases.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/io/atomic_file.hpp"

namespace curvefold {
namespace {

using nlohmann::json;

json foldJson(const Sheet& sheet) {
  const EdgeTopology topology = buildEdgeTopology(sheet);

  json coords2d = json::array();
  for (const glm::dvec2& p : sheet.development) coords2d.push_back({p.x, p.y});
  json coords3d = json::array();
  for (const glm::dvec3& p : sheet.positions) coords3d.push_back({p.x, p.y, p.z});

  json edgesVertices = json::array();
  json assignments = json::array();
  json foldAngles = json::array();
  json bendAngles = json::array();
  for (const EdgeTopology::EdgeSides& sides : topology.edges) {
    edgesVertices.push_back({sides.edge.a, sides.edge.b});
    const double angle = foldAngleDegrees(sheet, sides);
    const Assignment assignment = assignmentOf(sheet, sides, angle);
    assignments.push_back(std::string(1, static_cast<char>(assignment)));
    // FOLD: the angle is zero for flat, unassigned and boundary edges; bending shows in 3D only.
    const bool folded = assignment == Assignment::Mountain || assignment == Assignment::Valley;
    foldAngles.push_back(folded ? angle : 0.0);
    // The measured dihedral of every edge in the folded form, bends included: what a consumer
    // that folds from angles alone needs to reach this shape (README, "FOLD").
    bendAngles.push_back(angle);
  }

  json faces = json::array();
  for (const Triangle& t : sheet.triangles) faces.push_back({t[0], t[1], t[2]});

  json curves = json::array();
  for (const CreaseCurve& curve : creaseCurves(sheet, topology))
    curves.push_back({{"vertices", curve.vertices},
                      {"closed", curve.closed},
                      {"planarityError", curve.planarityError}});

  json folded = {{"frame_classes", {"foldedForm"}},
                 {"frame_attributes", {"3D"}},
                 {"frame_parent", 0},
                 {"frame_inherit", true},
                 {"vertices_coords", std::move(coords3d)},
                 {"curvefold:edges_bendAngle", std::move(bendAngles)}};

  return {{"file_spec", 1.2},
          {"file_creator", "curvefold"},
          {"file_classes", {"singleModel"}},
          {"frame_classes", {"creasePattern"}},
          {"frame_attributes", {"2D"}},
          {"frame_unit", "m"},
          {"vertices_coords", std::move(coords2d)},
          {"edges_vertices", std::move(edgesVertices)},
          {"edges_assignment", std::move(assignments)},
          {"edges_foldAngle", std::move(foldAngles)},
          {"faces_vertices", std::move(faces)},
          {"curvefold:creaseCurves", std::move(curves)},
          {"file_frames", json::array({std::move(folded)})}};
}

}  // namespace

std::string foldText(const Sheet& sheet) {
  return foldJson(sheet).dump() + '\n';
}

void writeFold(const Sheet& sheet, const std::filesystem::path& path) {
  writeFileAtomically(path, foldText(sheet));
}

}  // namespace curvefold
