#include "cases/body_surface_pressure.h"

#include "bodies/triangle_bvh.h"
#include "cases/nearest_over_ranks.h"
#include "cases/step_measurement.h"
#include "core/mesh_geometry.h"
#include "core/units.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace tightfit {

namespace {

double longest_edge_m(const DisplayMesh& mesh) {
  double longest = 0.0;
  for (const Triangle& t : mesh.triangles)
    for (int c = 0; c < 3; ++c)
      longest = std::max(longest, (mesh.vertices_m[t[c]] - mesh.vertices_m[t[(c + 1) % 3]]).norm());
  return longest;
}

// One split of every triangle into four at its edges' midpoints, moved onto the body.
DisplayMesh split_once(const RigidBody& body, const DisplayMesh& mesh) {
  DisplayMesh fine;
  fine.vertices_m = mesh.vertices_m;
  std::map<std::pair<int, int>, int> midpoint_of_edge;
  const auto midpoint = [&](int a, int b) {
    const std::pair<int, int> edge(std::min(a, b), std::max(a, b));
    const auto found = midpoint_of_edge.find(edge);
    if (found != midpoint_of_edge.end()) return found->second;
    const Vec3 middle = 0.5 * (mesh.vertices_m[a] + mesh.vertices_m[b]);
    fine.vertices_m.push_back(body.query(middle).closest_point_m);
    const int index = static_cast<int>(fine.vertices_m.size()) - 1;
    midpoint_of_edge.emplace(edge, index);
    return index;
  };
  fine.triangles.reserve(4 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
    fine.triangles.push_back({t[0], ab, ca});
    fine.triangles.push_back({ab, t[1], bc});
    fine.triangles.push_back({ca, bc, t[2]});
    fine.triangles.push_back({ab, bc, ca});
  }
  return fine;
}

// Whether body point b lies under the garment whose nearest point to it is q, in triangle t:
// q within `max_distance_m` and b - q along the triangle's normal (within 45 degrees), as under
// the cloth, not across its edge; if so `pressure_Pa` is the garment's there, interpolated
// linearly from t's corners (vertices out of contact count as zero).
bool read_garment(const Vec3& b, const Vec3& q, const Triangle& t, const std::vector<Vec3>& x,
                  const PressureField& field, double max_distance_m, double& pressure_Pa) {
  // cos 45 degrees: b - q along the garment's normal rather than across its boundary.
  const double min_cosine = std::sqrt(0.5);
  const Vec3 &x0 = x[t[0]], &x1 = x[t[1]], &x2 = x[t[2]];
  const Vec3 offset = b - q;
  const Vec3 normal = (x1 - x0).cross(x2 - x0);
  const double distance = offset.norm();
  if (distance > max_distance_m || !(normal.norm() > 0)) return false;
  if (distance > 1e-9 * max_distance_m &&
      std::abs(offset.dot(normal)) < min_cosine * distance * normal.norm())
    return false;
  // Barycentric coordinates of q in t (areas of the opposite sub-triangles).
  const Vec3 unit_normal = normal.normalized();
  const double twice_area = normal.norm();
  const double l1 = (x2 - x0).cross(q - x0).dot(-unit_normal) / twice_area;
  const double l2 = (x1 - x0).cross(q - x0).dot(unit_normal) / twice_area;
  const double l0 = 1.0 - l1 - l2;
  const auto p = [&](int corner) {
    return field.contact[t[corner]] ? field.pressure_Pa[t[corner]] : 0.0;
  };
  pressure_Pa = l0 * p(0) + l1 * p(1) + l2 * p(2);
  return true;
}

}  // namespace

DisplayMesh refined_body_surface(const RigidBody& body, const DisplayMesh& mesh, double max_edge_m,
                                 std::size_t max_triangles) {
  DisplayMesh refined = mesh;
  while (longest_edge_m(refined) > max_edge_m && 4 * refined.triangles.size() <= max_triangles)
    refined = split_once(body, refined);
  return refined;
}

BodySurfacePressure body_surface_pressure(DisplayMesh surface,
                                          const std::vector<Triangle>& garment_triangles,
                                          const std::vector<Vec3>& garment_positions_m,
                                          const PressureField& field, double max_distance_m,
                                          const RankShare& share) {
  BodySurfacePressure result;
  result.surface = std::move(surface);
  const std::vector<Vec3>& points = result.surface.vertices_m;
  const int n = static_cast<int>(points.size());
  result.pressure_Pa.assign(n, 0.0);
  result.under_garment.assign(n, 0);
  result.vertex_area_m2 =
      vertex_areas(result.surface.triangles, points, n, VertexAreaDefinition::barycentric);
  // This rank's nearest point in its block of the garment (the whole garment on one rank).
  const auto [first, end] = share.block(static_cast<int>(garment_triangles.size()));
  std::vector<NearestReading> nearest(n);
  if (first < end) {
    std::vector<Triangle> block;
    if (end - first < static_cast<int>(garment_triangles.size()))
      block.assign(garment_triangles.begin() + first, garment_triangles.begin() + end);
    TriangleBvh garment;
    garment.build(garment_positions_m, block.empty() ? garment_triangles : block);
    for (int b = 0; b < n; ++b) {
      const TriangleBvh::Hit hit = garment.closest(points[b]);
      if (hit.triangle < 0) continue;
      const int t = first + hit.triangle;
      NearestReading& r = nearest[b];
      r.query_m = {points[b].x(), points[b].y(), points[b].z()};
      r.point_m = {hit.point_m.x(), hit.point_m.y(), hit.point_m.z()};
      r.triangle = t;
      r.flag = read_garment(points[b], hit.point_m, garment_triangles[t], garment_positions_m,
                            field, max_distance_m, r.value);
    }
  }
  // The tree is gone; the nearest of the ranks' points is every rank's.
  keep_nearest_over_ranks(nearest, share);
  for (int b = 0; b < n; ++b) {
    if (!nearest[b].flag) continue;
    result.under_garment[b] = 1;
    result.pressure_Pa[b] = nearest[b].value;
    result.normal_force_N += result.pressure_Pa[b] * result.vertex_area_m2[b];
  }
  return result;
}

BodySurfacePressure body_surface_pressure(const Scenario& scenario, const StepMeasurement& m,
                                          const RankShare& share) {
  const double garment_edge_m = scenario.mean_edge_length_m;
  const double edge_m = scenario.parameters.output.body_edge_length_m > 0
                            ? scenario.parameters.output.body_edge_length_m
                            : 0.5 * garment_edge_m;
  const RigidBody& body = scenario.body->body();
  return body_surface_pressure(refined_body_surface(body, body.display_mesh(), edge_m),
                               scenario.mesh.triangles, m.state.positions_m, m.field,
                               garment_edge_m, share);
}

SurfaceVtu body_pressure_vtu(const BodySurfacePressure& body, const PressureField& field) {
  SurfaceVtu vtu(body.surface.vertices_m, body.surface.triangles);
  vtu.add_point_scalar("pressure_Pa", body.pressure_Pa);
  std::vector<double> mmHg(body.pressure_Pa.size());
  std::transform(body.pressure_Pa.begin(), body.pressure_Pa.end(), mmHg.begin(), units::to_mmHg);
  vtu.add_point_scalar("pressure_mmHg", mmHg);
  vtu.add_point_flag("under_garment", body.under_garment);
  vtu.add_point_scalar("vertex_area_m2", body.vertex_area_m2);
  double garment_force_N = 0.0;
  for (std::size_t v = 0; v < field.contact.size(); ++v)
    if (field.contact[v]) garment_force_N += field.pressure_Pa[v] * field.vertex_area_m2[v];
  vtu.add_field_scalar("normal_force_N", body.normal_force_N);
  vtu.add_field_scalar("garment_normal_force_N", garment_force_N);
  return vtu;
}

}  // namespace tightfit
