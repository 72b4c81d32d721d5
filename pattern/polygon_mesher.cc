#include "pattern/polygon_mesher.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

namespace tightfit::pattern {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_2<Kernel>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Structure = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Structure>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Point = Cdt::Point;

Vec2 to_vec(const Point& p) {
  return Vec2(p.x(), p.y());
}

// Where point x lies on the outline's chords: the nearest chord and the fraction along it.
PolygonMesh::BoundaryPoint on_outline(const std::vector<Vec2>& outline, const Vec2& x) {
  PolygonMesh::BoundaryPoint best;
  double best_distance = std::numeric_limits<double>::infinity();
  const int n = static_cast<int>(outline.size());
  for (int k = 0; k < n; ++k) {
    const Vec2 a = outline[k], d = outline[(k + 1) % n] - a;
    const double t = std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const double distance = (a + t * d - x).norm();
    if (distance < best_distance) {
      best_distance = distance;
      best = {k, t};
    }
  }
  return best;
}

// An outline that runs back along itself (a turn of 180 degrees between consecutive chords)
// has a sliver of no area there: CGAL's constrained triangulation then dereferences a null face
// while inserting the overlapping constraints (found by fuzz_pattern_dxf). A corner only a
// little wider, a spike or a slit of a fraction of a degree, the angle bound refines towards
// its tip round after round, adding outline points each time (found by fuzz_pattern_svg: a
// 0.24-degree spike 12 m long, 47 s and then "did not settle"). No cut piece has a corner
// under a degree (a dart's tip is 5 to 20): refused before any constraint is inserted.
constexpr double sharpest_corner_deg = 1.0;

void require_no_needle_corner(const std::vector<Vec2>& outline_m) {
  const std::size_t n = outline_m.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2& x = outline_m[k];
    const Vec2 back = outline_m[(k + n - 1) % n] - x, on = outline_m[(k + 1) % n] - x;
    const double cross = back.x() * on.y() - back.y() * on.x();
    const double corner_deg = std::atan2(std::abs(cross), back.dot(on)) * 180.0 / M_PI;
    if (corner_deg < sharpest_corner_deg) {
      char where[160];
      std::snprintf(where, sizeof where,
                    "the outline turns back at (%.6g, %.6g) m in a corner of %.3g degrees (a "
                    "spike or slit under %g degree, which no mesh resolves)",
                    x.x(), x.y(), corner_deg, sharpest_corner_deg);
      throw std::invalid_argument(where);
    }
  }
}

}  // namespace

// 1000 more: a strip narrower than h (a waistband 1 m by 5 mm at h = 5 cm takes 322
// vertices: the angle bound makes its triangles as small as its width).
double mesh_vertex_budget(const std::vector<Vec2>& outline_m, double h) {
  double twice_area = 0.0, perimeter = 0.0;
  for (std::size_t i = 0; i < outline_m.size(); ++i) {
    const Vec2& a = outline_m[i];
    const Vec2& b = outline_m[(i + 1) % outline_m.size()];
    twice_area += a.x() * b.y() - b.x() * a.y();
    perimeter += (b - a).norm();
  }
  return 10 * (std::abs(twice_area) / (std::sqrt(3.0) * h * h) + perimeter / h +
               static_cast<double>(outline_m.size())) +
         1000;
}

PolygonMesh mesh_polygon(const std::vector<Vec2>& outline_m, double edge_length_m,
                         double min_angle_deg, double max_vertices) {
  if (outline_m.size() < 3) throw std::invalid_argument("an outline needs three points");
  if (!(edge_length_m > 0)) throw std::invalid_argument("the mesh edge length must be positive");
  if (!(min_angle_deg > 0) || min_angle_deg > 33)
    throw std::invalid_argument("the minimum angle must be in (0, 33] degrees");
  require_no_needle_corner(outline_m);
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> outline_vertex;
  for (const Vec2& x : outline_m) outline_vertex.push_back(cdt.insert(Point(x.x(), x.y())));
  const std::size_t n = outline_m.size();
  // Before any constraint: a constraint from a vertex to itself (a segment of no length) makes
  // CGAL dereference a null face (found by fuzz_pattern_dxf).
  if (cdt.number_of_vertices() != n)
    throw std::invalid_argument("the outline passes twice through one point");
  try {
    for (std::size_t k = 0; k < n; ++k)
      cdt.insert_constraint(outline_vertex[k], outline_vertex[(k + 1) % n]);
  } catch (const Cdt::Intersection_of_constraints_exception&) {
    throw std::invalid_argument("the outline crosses itself");
  }

  // CGAL's shape bound is sin^2 of the smallest angle; its size bound the longest edge.
  const double sine = std::sin(min_angle_deg * M_PI / 180.0);
  CGAL::Delaunay_mesher_2<Cdt, Criteria> mesher(cdt, Criteria(sine * sine, edge_length_m));
  mesher.init();
  const double most_vertices =
      max_vertices > 0 ? max_vertices : mesh_vertex_budget(outline_m, edge_length_m);
  while (!mesher.is_refinement_done()) {
    mesher.step_by_step_refine_mesh();
    if (cdt.number_of_vertices() > most_vertices)
      throw std::invalid_argument(
          "meshing at edge length " + std::to_string(edge_length_m) + " m took more than " +
          std::to_string(static_cast<long>(most_vertices)) +
          " vertices, ten times what the outline's area and perimeter call for and 1000 "
          "more: the outline has a corner or a neck far narrower than the edge length (a "
          "spike, or two parts almost touching)");
  }

  PolygonMesh mesh;
  mesh.points_m = outline_m;
  std::map<Cdt::Vertex_handle, int> index;
  for (std::size_t k = 0; k < n; ++k) index[outline_vertex[k]] = static_cast<int>(k);
  auto index_of = [&](Cdt::Vertex_handle v) {
    const auto found = index.find(v);
    if (found != index.end()) return found->second;
    const int i = static_cast<int>(mesh.points_m.size());
    mesh.points_m.push_back(to_vec(v->point()));
    index.emplace(v, i);
    return i;
  };
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    mesh.triangles.push_back(
        {index_of(f->vertex(0)), index_of(f->vertex(1)), index_of(f->vertex(2))});
  }
  // Points added on a constrained edge lie on the outline.
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    if (!cdt.is_constrained(*e)) continue;
    for (int end : {1, 2}) {
      const Cdt::Vertex_handle v = e->first->vertex((e->second + end) % 3);
      const int i = index.at(v);
      if (i < static_cast<int>(n)) continue;
      const auto point = on_outline(outline_m, mesh.points_m[i]);
      bool known = false;
      for (const auto& p : mesh.added_on_outline)
        known = known || (p.chord == point.chord && std::abs(p.along - point.along) < 1e-12);
      if (!known) mesh.added_on_outline.push_back(point);
    }
  }
  if (mesh.triangles.empty()) throw std::invalid_argument("the outline encloses no area");
  return mesh;
}

MeshQuality mesh_quality(const std::vector<Vec2>& points, const std::vector<Triangle>& triangles) {
  MeshQuality q;
  q.min_angle_deg = 180.0;
  q.min_edge_m = std::numeric_limits<double>::infinity();
  double sum = 0.0;
  int count = 0;
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec2 a = points[t[k]], b = points[t[(k + 1) % 3]], c = points[t[(k + 2) % 3]];
      const double length = (b - a).norm();
      q.min_edge_m = std::min(q.min_edge_m, length);
      q.max_edge_m = std::max(q.max_edge_m, length);
      sum += length;
      ++count;
      const Vec2 u = b - a, v = c - a;
      const double angle = std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));
      q.min_angle_deg = std::min(q.min_angle_deg, angle * 180.0 / M_PI);
    }
  q.mean_edge_m = count > 0 ? sum / count : 0.0;
  return q;
}

}  // namespace tightfit::pattern
