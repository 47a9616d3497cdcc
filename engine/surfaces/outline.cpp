// Flat outlines meshed with CGAL's 2D constrained Delaunay triangulation and Delaunay mesher.
#include <cmath>
#include <deque>
#include <sstream>
#include <unordered_map>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "engine/surfaces/surface_builders.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Delaunay_mesh_vertex_base_2<Kernel>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Point = Cdt::Point;

// Angle bound B = 1/(4 sin^2 a) for a minimum angle a of about 20.7 degrees, CGAL's default.
constexpr double kShapeBound = 0.125;
// Triangles per (area / maxEdgeLength^2) that the mesher makes: about 5 measured, 6 with margin.
constexpr double kTrianglesPerSquareEdge = 6.0;

void checkPolygon(const std::vector<glm::dvec2>& polygon, const std::string& what) {
  if (polygon.size() < 3)
    throw SurfaceError("outline: " + what + " has " + std::to_string(polygon.size()) +
                       " points, at least 3 are needed");
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2& p = polygon[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw SurfaceError("outline: " + what + " point " + std::to_string(i) +
                         " has a non-finite coordinate");
    if (p == polygon[(i + 1) % polygon.size()])
      throw SurfaceError("outline: " + what + " repeats point " + std::to_string(i));
  }
  if (detail::signedArea(polygon) == 0.0) throw SurfaceError("outline: " + what + " has zero area");
}

void insertPolygon(Cdt& cdt, const std::vector<glm::dvec2>& polygon) {
  std::vector<Cdt::Vertex_handle> handles;
  handles.reserve(polygon.size());
  for (const glm::dvec2& p : polygon) handles.push_back(cdt.insert(Point(p.x, p.y)));
  for (std::size_t i = 0; i < handles.size(); ++i)
    cdt.insert_constraint(handles[i], handles[(i + 1) % handles.size()]);
}

// Marks faces inside an odd number of constraint loops as the domain (outline minus holes).
void markDomain(Cdt& cdt) {
  std::unordered_map<Cdt::Face_handle, int> level;
  std::deque<Cdt::Face_handle> border{cdt.infinite_face()};
  level[cdt.infinite_face()] = 0;
  while (!border.empty()) {
    // Flood one region at the level of its first face; faces across constraints go one deeper.
    const Cdt::Face_handle start = border.front();
    border.pop_front();
    const int depth = level.at(start);
    std::deque<Cdt::Face_handle> region{start};
    while (!region.empty()) {
      const Cdt::Face_handle f = region.front();
      region.pop_front();
      f->set_in_domain(depth % 2 == 1);
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle n = f->neighbor(i);
        if (level.count(n)) continue;
        if (cdt.is_constrained(Cdt::Edge(f, i))) {
          level[n] = depth + 1;
          border.push_back(n);
        } else {
          level[n] = depth;
          region.push_back(n);
        }
      }
    }
  }
}

}  // namespace

Sheet triangulateOutline(const std::vector<glm::dvec2>& outline,
                         const std::vector<std::vector<glm::dvec2>>& holes, double maxEdgeLength) {
  checkPolygon(outline, "the outline");
  for (std::size_t h = 0; h < holes.size(); ++h)
    checkPolygon(holes[h], "hole " + std::to_string(h));
  double expectedArea = std::abs(detail::signedArea(outline));
  for (const auto& hole : holes) expectedArea -= std::abs(detail::signedArea(hole));
  if (!(maxEdgeLength > 0.0) || !std::isfinite(maxEdgeLength)) {
    std::ostringstream out;
    out << "outline: maxEdgeLength = " << maxEdgeLength << " must be positive and finite";
    throw SurfaceError(out.str());
  }
  const double estimate = kTrianglesPerSquareEdge * std::abs(detail::signedArea(outline)) /
                          (maxEdgeLength * maxEdgeLength);
  if (!(estimate <= static_cast<double>(kMaxSurfaceTriangles))) {
    std::ostringstream out;
    out << "outline: maxEdgeLength = " << maxEdgeLength << " would give about " << estimate
        << " triangles, more than " << kMaxSurfaceTriangles;
    throw SurfaceError(out.str());
  }

  Cdt cdt;
  try {
    insertPolygon(cdt, outline);
    for (const auto& hole : holes) insertPolygon(cdt, hole);
  } catch (const Cdt::Intersection_of_constraints_exception&) {
    throw SurfaceError("outline: the outline or a hole crosses itself or another hole");
  }
  markDomain(cdt);
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(kShapeBound, maxEdgeLength), true);

  Sheet sheet;
  std::unordered_map<Cdt::Vertex_handle, VertexIndex> index;
  double area = 0.0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    Triangle triangle;
    for (int i = 0; i < 3; ++i) {  // CGAL's faces are counter-clockwise
      const Cdt::Vertex_handle v = f->vertex(i);
      auto [it, added] = index.emplace(v, static_cast<VertexIndex>(sheet.positions.size()));
      if (added) {
        const glm::dvec2 p(v->point().x(), v->point().y());
        sheet.development.push_back(p);
        sheet.positions.emplace_back(p.x, p.y, 0.0);
      }
      triangle[i] = it->second;
    }
    sheet.triangles.push_back(triangle);
    area +=
        std::abs(CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
  }
  // Holes outside the outline, overlapping or nested show up as a wrong meshed area.
  if (sheet.triangles.empty() ||
      std::abs(area - expectedArea) > 1e-9 * std::abs(detail::signedArea(outline)))
    throw SurfaceError("outline: holes must lie inside the outline without overlapping");
  return sheet;
}

}  // namespace curvefold
