// Mesh bodies read from files the test writes: the signed distance of a faceted cylinder and
// cone against the analytic bodies within the predicted chord error, the pseudo-normal sign
// near edges and vertices, the smooth normal field's continuity, the skin offset, and the
// surface locations kept for friction.
#include "bodies/cone.h"
#include "bodies/cylinder.h"
#include "bodies/mesh_body.h"
#include "body_mesh_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace tightfit {
namespace {

using namespace tightfit::testing;

MeshBodyOptions z_up() {
  MeshBodyOptions o;
  o.import.up_axis = "+z";
  return o;
}

// The largest |g_mesh - g_exact| over points round the middle of the body (|z| <= 0.05 m,
// 2 cm either side of the surface), where the caps at |z| = 0.2 m are never the nearest part.
double largest_distance_error(const RigidBody& mesh, const RigidBody& exact,
                              const std::function<double(double)>& radius_at_z) {
  double largest = 0.0;
  for (int k = 0; k <= 10; ++k)
    for (int a = 0; a < 256; ++a)
      for (double offset : {-0.02, -0.005, 0.0, 0.005, 0.02}) {
        const double z = -0.05 + 0.01 * k, phi = 2.0 * M_PI * (a + 0.37) / 256;
        const double rho = radius_at_z(z) + offset;
        const Vec3 x(rho * std::cos(phi), rho * std::sin(phi), z);
        largest = std::max(
            largest, std::abs(mesh.query(x).signed_distance_m - exact.query(x).signed_distance_m));
      }
  return largest;
}

TEST(MeshBodyDistance, FacetedCylinderFromStlWithinTheChordError) {
  // 32 facets round a 5 cm circle: each flat facet lies at most the sagitta
  // R (1 - cos(pi / 32)) = 0.241 mm inside the circle, and two surfaces that far apart (their
  // Hausdorff distance) have signed distances at most that far apart.
  const int n = 32;
  const double R = 0.05, sagitta = R * (1 - std::cos(M_PI / n));
  const std::string path = temporary_path("cylinder.stl");
  write_stl(path, revolution_surface({-0.2, -0.1, 0.0, 0.1, 0.2}, std::vector<double>(5, R), n));
  const auto mesh = load_mesh_body(path, z_up());
  EXPECT_EQ(mesh->surface().triangles.size(), 4u * 2 * n + 2 * n);  // STL: welded, triangles
  const Cylinder exact(Vec3::Zero(), Vec3::UnitZ(), R);
  const double error = largest_distance_error(*mesh, exact, [&](double) { return R; });
  // VTK's readers keep coordinates as floats: 2^-24 of 5 cm moves a vertex up to 3e-9 m.
  EXPECT_LE(error, sagitta + 5e-9);
  // Points at a facet's middle outside it are a full sagitta off: the bound is reached.
  EXPECT_GT(error, 0.99 * sagitta);
}

TEST(MeshBodyDistance, FacetedConeOfQuadsWithinTheChordError) {
  // The quads between two rings are planar (both generators meet at the apex), so the facets
  // only cut the circles: at a ring of radius r a facet lies r (1 - cos(pi/n)) inside radially,
  // r (1 - cos(pi/n)) cos(alpha) normal to the cone. Over |z| <= 0.05 m with 2 cm round the
  // surface, the facets that can be nearest have r <= r(0.08 m).
  const int n = 24;
  ConeOptions o;
  o.half_angle_deg = 20.0;
  o.radius_at_point_m = 0.06;
  const Cone exact(o);
  std::vector<double> z, r;
  for (int k = 0; k <= 8; ++k) {  // from z = -0.12 m (radius 16 mm) to 0.2 m
    z.push_back(-0.12 + 0.04 * k);
    r.push_back(exact.radius_at_m(z.back()));
  }
  const std::string path = temporary_path("cone.obj");
  write_obj(path, revolution_surface(z, r, n));
  const auto mesh = load_mesh_body(path, z_up());
  EXPECT_EQ(mesh->surface().triangles.size(), 8u * 2 * n + 2 * n);  // quads split in two
  const double alpha = o.half_angle_deg * M_PI / 180;
  const double bound = exact.radius_at_m(0.08) * (1 - std::cos(M_PI / n)) * std::cos(alpha);
  const double error =
      largest_distance_error(*mesh, exact, [&](double zz) { return exact.radius_at_m(zz); });
  EXPECT_LE(error, bound + 5e-9);  // float coordinates, as for the cylinder
  // Outside a facet's middle at z = 0.05 the error is the sagitta there, r(0.05)/r(0.08) of
  // the bound (0.85).
  EXPECT_GT(error, 0.8 * bound);
}

TEST(MeshBodyDistance, PlyReadsTheSameSurfaceAsObj) {
  const PolygonMesh file = revolution_surface({-0.1, 0.1}, {0.04, 0.05}, 12);
  write_ply(temporary_path("frustum.ply"), file);
  write_obj(temporary_path("frustum.obj"), file);
  const auto ply = load_mesh_body(temporary_path("frustum.ply"), z_up());
  const auto obj = load_mesh_body(temporary_path("frustum.obj"), z_up());
  ASSERT_EQ(ply->surface().vertices_m.size(), obj->surface().vertices_m.size());
  // VTK's PLY reader keeps coordinates as floats: 6e-8 relative of 5 cm, 3e-9 m.
  for (std::size_t i = 0; i < file.vertices.size(); ++i)
    EXPECT_LT((ply->surface().vertices_m[i] - file.vertices[i]).norm(), 5e-9);
  EXPECT_EQ(ply->surface().triangles, obj->surface().triangles);
}

// Whether x is inside the tetrahedron: behind all four face planes (the ground truth).
bool inside_tetrahedron(const PolygonMesh& t, const Vec3& x) {
  for (const auto& f : t.faces) {
    const Vec3 &a = t.vertices[f[0]], &b = t.vertices[f[1]], &c = t.vertices[f[2]];
    if ((b - a).cross(c - a).dot(x - a) > 0) return false;
  }
  return true;
}

TEST(MeshBodySign, PseudoNormalsSignCorrectlyNearEdgesAndVertices) {
  // A regular tetrahedron: its face normals are 109.5 degrees apart, so beside an edge or a
  // vertex a point outside can lie behind one adjacent face's plane; that face's normal alone
  // would call it inside.
  const PolygonMesh tetra = regular_tetrahedron(0.1);
  write_obj(temporary_path("tetrahedron.obj"), tetra);
  const auto body = load_mesh_body(temporary_path("tetrahedron.obj"), z_up());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int wrong = 0, face_normal_alone_wrong = 0, n_points = 0;
  std::vector<Vec3> features = tetra.vertices;  // the vertices and the edges' midpoints
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      features.push_back(0.5 * (tetra.vertices[a] + tetra.vertices[b]));
  for (const Vec3& feature : features)
    for (int k = 0; k < 500; ++k) {
      const Vec3 x = feature + 1e-3 * Vec3(unit(random), unit(random), unit(random));
      const SurfacePoint s = body->query(x);
      ++n_points;
      if ((s.signed_distance_m < 0) != inside_tetrahedron(tetra, x)) ++wrong;
      // Any face holding the closest point, the one the tree returned included, can have the
      // wrong sign where the closest point is on an edge or a vertex.
      const Triangle& t = body->surface().triangles[s.location.face];
      const Vec3& p0 = body->surface().vertices_m[t[0]];
      const Vec3 face_normal =
          (body->surface().vertices_m[t[1]] - p0).cross(body->surface().vertices_m[t[2]] - p0);
      if (((x - s.closest_point_m).dot(face_normal) < 0) != inside_tetrahedron(tetra, x))
        ++face_normal_alone_wrong;
    }
  EXPECT_EQ(wrong, 0) << "of " << n_points;
  // The test reaches the hard cases: the face normal alone fails on some of these points.
  EXPECT_GT(face_normal_alone_wrong, 0);
}

TEST(MeshBodyNormal, ContinuousAcrossAnEdgeWhereTheFaceNormalsJump) {
  // 12 facets round: the face normals jump by 30 degrees across the edge at angle 0. Points on
  // the two facets 1e-8 m from that edge get interpolated normals that differ by O(1e-8 m /
  // facet width), while the face normals (the gap's gradient) differ by 2 sin(15 degrees).
  write_obj(temporary_path("prism.obj"), revolution_surface({-0.1, 0.1}, {0.05, 0.05}, 12));
  const auto body = load_mesh_body(temporary_path("prism.obj"), z_up());
  const Vec3 on_edge(0.05, 0.0, 0.01);
  const double c = std::cos(M_PI / 12), s = std::sin(M_PI / 12);
  // Along each facet away from the edge, and a hair inside it.
  const Vec3 along_up(-s, c, 0), along_down(-s, -c, 0), normal_up(c, s, 0), normal_down(c, -s, 0);
  const SurfacePoint a = body->query(on_edge + 1e-8 * along_up - 1e-10 * normal_up);
  const SurfacePoint b = body->query(on_edge + 1e-8 * along_down - 1e-10 * normal_down);
  ASSERT_NE(a.location.face, b.location.face);
  EXPECT_LT((a.outward_normal - b.outward_normal).norm(), 1e-6);
  // The face normals come from float coordinates (VTK's reader): 6e-8 relative on a 5 cm
  // radius over a 2.6 cm facet turns them by about 1e-7.
  EXPECT_NEAR((a.gap_gradient - b.gap_gradient).norm(), 2 * s, 1e-6);
  // By symmetry the field on the edge has no component across it.
  EXPECT_LT(std::abs(a.outward_normal.y()), 1e-6);
}

TEST(MeshBodySkin, OffsetMovesTheSurfaceOutAlongTheNormal) {
  write_obj(temporary_path("skin.obj"), revolution_surface({-0.1, 0.1}, {0.05, 0.05}, 12));
  MeshBodyOptions bare = z_up(), skinned = z_up();
  skinned.skin_offset_m = 0.003;
  const auto plain = load_mesh_body(temporary_path("skin.obj"), bare);
  const auto skin = load_mesh_body(temporary_path("skin.obj"), skinned);
  for (const Vec3& x : {Vec3(0.06, 0.01, 0.02), Vec3(0.03, -0.02, -0.05), Vec3(0.05, 0, 0.12)}) {
    const SurfacePoint p = plain->query(x), s = skin->query(x);
    EXPECT_NEAR(s.signed_distance_m, p.signed_distance_m - 0.003, 1e-15);
    EXPECT_LT((s.closest_point_m - (p.closest_point_m + 0.003 * p.outward_normal)).norm(), 1e-15);
    EXPECT_LT((skin->surface_point_m(s.location) - s.closest_point_m).norm(), 1e-15);
  }
  MeshBodyOptions negative = z_up();
  negative.skin_offset_m = -0.001;
  EXPECT_THROW(load_mesh_body(temporary_path("skin.obj"), negative), std::invalid_argument);
}

TEST(MeshBodyLocation, FaceAndBarycentricCoordinatesGiveTheClosestPoint) {
  write_obj(temporary_path("location.obj"),
            revolution_surface({-0.1, 0.0, 0.1}, {0.04, 0.05, 0.03}, 10));
  const auto body = load_mesh_body(temporary_path("location.obj"), z_up());
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(-0.08, 0.08);
  for (int k = 0; k < 200; ++k) {
    const Vec3 x(unit(random), unit(random), 1.5 * unit(random));
    const SurfacePoint s = body->query(x);
    EXPECT_NEAR(s.location.coordinates.sum(), 1.0, 1e-14);
    EXPECT_GE(s.location.coordinates.minCoeff(), 0.0);
    EXPECT_LT((body->surface_point_m(s.location) - s.closest_point_m).norm(), 1e-14);
    EXPECT_NEAR(std::abs(s.signed_distance_m), (x - s.closest_point_m).norm(), 1e-14);
  }
}

}  // namespace
}  // namespace tightfit
