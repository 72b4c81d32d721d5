#include "synthetic_body.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <map>
#include <stdexcept>

namespace tightfit::testing {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
constexpr double pi = 3.14159265358979323846;

Mesh to_mesh(const TriangleSurface& s) {
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  for (const Vec3& x : s.vertices_m)
    v.push_back(m.add_vertex(Kernel::Point_3(x.x(), x.y(), x.z())));
  for (const Triangle& t : s.triangles) m.add_face(v[t[0]], v[t[1]], v[t[2]]);
  return m;
}

}  // namespace

TriangleSurface elliptic_frustum(const Vec3& base, const Vec3& axis, const Vec3& across,
                                 double length, double a0, double b0, double a1, double b1, int n) {
  const Vec3 w = axis.normalized();
  const Vec3 u = (across - across.dot(w) * w).normalized();
  const Vec3 v = w.cross(u);
  TriangleSurface s;
  for (int end = 0; end < 2; ++end)
    for (int i = 0; i < n; ++i) {
      const double t = 2 * pi * i / n;
      const double a = end ? a1 : a0, b = end ? b1 : b0;
      s.vertices_m.push_back(base + end * length * w + a * std::cos(t) * u + b * std::sin(t) * v);
    }
  s.vertices_m.push_back(base);
  s.vertices_m.push_back(base + length * w);
  const int bottom = 2 * n, top = 2 * n + 1;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    s.triangles.push_back({i, j, n + j});
    s.triangles.push_back({i, n + j, n + i});
    s.triangles.push_back({bottom, j, i});
    s.triangles.push_back({top, n + i, n + j});
  }
  return s;
}

TriangleSurface elliptic_cylinder(const Vec3& base, const Vec3& axis, const Vec3& across,
                                  double length, double a, double b, int n) {
  return elliptic_frustum(base, axis, across, length, a, b, a, b, n);
}

TriangleSurface sphere(const Vec3& centre, double r, int n_around, int n_rings) {
  TriangleSurface s;
  s.vertices_m.push_back(centre - r * Vec3::UnitZ());
  for (int k = 1; k < n_rings; ++k) {
    const double polar = pi * (1.0 - static_cast<double>(k) / n_rings);
    for (int i = 0; i < n_around; ++i) {
      const double t = 2 * pi * i / n_around;
      s.vertices_m.push_back(centre + r * Vec3(std::sin(polar) * std::cos(t),
                                               std::sin(polar) * std::sin(t), std::cos(polar)));
    }
  }
  s.vertices_m.push_back(centre + r * Vec3::UnitZ());
  const int last = static_cast<int>(s.vertices_m.size()) - 1;
  const auto ring = [&](int k, int i) { return 1 + (k - 1) * n_around + (i % n_around); };
  for (int i = 0; i < n_around; ++i) {
    s.triangles.push_back({0, ring(1, i + 1), ring(1, i)});
    s.triangles.push_back({last, ring(n_rings - 1, i), ring(n_rings - 1, i + 1)});
    for (int k = 1; k < n_rings - 1; ++k) {
      s.triangles.push_back({ring(k, i), ring(k, i + 1), ring(k + 1, i + 1)});
      s.triangles.push_back({ring(k, i), ring(k + 1, i + 1), ring(k + 1, i)});
    }
  }
  return s;
}

TriangleSurface surface_union(const std::vector<TriangleSurface>& parts) {
  Mesh whole = to_mesh(parts.front());
  for (std::size_t i = 1; i < parts.size(); ++i) {
    Mesh other = to_mesh(parts[i]);
    Mesh result;
    if (!CGAL::Polygon_mesh_processing::corefine_and_compute_union(whole, other, result))
      throw std::runtime_error("the union of the synthetic body's parts failed");
    whole = std::move(result);
  }
  TriangleSurface s;
  std::map<Mesh::Vertex_index, int> index;
  for (const auto v : whole.vertices()) {
    index[v] = static_cast<int>(s.vertices_m.size());
    const auto& p = whole.point(v);
    s.vertices_m.emplace_back(p.x(), p.y(), p.z());
  }
  for (const auto f : whole.faces()) {
    Triangle t;
    int k = 0;
    for (const auto v : whole.vertices_around_face(whole.halfedge(f))) t[k++] = index[v];
    s.triangles.push_back(t);
  }
  return s;
}

double SyntheticPerson::armpit_z(double angle_deg) {
  const double t = angle_deg * pi / 180;
  // The underside line joint + s d - r n (d = (sin t, 0, -cos t), n = (cos t, 0, sin t)) meets
  // the torso's side x = a.
  const double s = (torso_a - joint_x + arm_r * std::cos(t)) / std::sin(t);
  return joint_z - s * std::cos(t) - arm_r * std::sin(t);
}

Vec3 SyntheticLegs::up(int side) const {
  const double t = tilt_deg * pi / 180;
  return Vec3((side == 0 ? -1 : 1) * std::sin(t), 0, std::cos(t));
}

Vec3 SyntheticLegs::foot(int side) const {
  const double t = tilt_deg * pi / 180;
  return Vec3((side == 0 ? 1 : -1) * (top_x + top_z * std::tan(t)), 0, 0);
}

TriangleSurface synthetic_person(double angle_deg, bool legs) {
  return synthetic_person(angle_deg, SyntheticLegs{}, legs);
}

TriangleSurface synthetic_person(double angle_deg, const SyntheticLegs& leg, bool legs) {
  using P = SyntheticPerson;
  const double t = angle_deg * pi / 180;
  std::vector<TriangleSurface> parts;
  parts.push_back(elliptic_cylinder(Vec3(0, 0, P::crotch_m), Vec3::UnitZ(), Vec3::UnitX(),
                                    1.40 - P::crotch_m, P::torso_a, P::torso_b, 256));
  if (legs)
    for (const int side : {0, 1}) {
      const double length = leg.top_z / leg.up(side).z();
      parts.push_back(elliptic_frustum(leg.foot(side), leg.up(side), Vec3::UnitX(), length,
                                       leg.foot_r, leg.foot_r, leg.top_r, leg.top_r, 128));
    }
  parts.push_back(
      elliptic_cylinder(Vec3(0, 0, 1.35), Vec3::UnitZ(), Vec3::UnitX(), 0.17, 0.05, 0.05, 64));
  parts.push_back(sphere(Vec3(0, 0, 1.55), 0.1, 64, 32));
  for (const double side : {1.0, -1.0})
    parts.push_back(elliptic_cylinder(Vec3(side * P::joint_x, 0, P::joint_z),
                                      Vec3(side * std::sin(t), 0, -std::cos(t)), Vec3::UnitY(), 0.6,
                                      P::arm_r, P::arm_r, 96));
  return surface_union(parts);
}

}  // namespace tightfit::testing
