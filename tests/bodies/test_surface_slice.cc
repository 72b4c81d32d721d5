// Slices of body surfaces (bodies/surface_slice.h) against the geometry they were built from: a
// faceted cylinder's section is its polygon (perimeter, area, centroid on the axis), a faceted
// cone's is the polygon of its radius at that height, two legs side by side give the loop round
// the point asked for, and a plane that misses the body is refused naming its height; a tube
// placed round such a limb goes round its sections.
#include "bodies/mesh_import.h"
#include "bodies/surface_slice.h"
#include "bodies/tube_placement.h"
#include "core/tube_garment.h"
#include "tests/bodies/body_mesh_files.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>

namespace tightfit {
namespace {

TriangleSurface z_up(const PolygonMesh& mesh, const Vec3& shift = Vec3::Zero()) {
  MeshImportOptions options;
  options.up_axis = "+z";
  options.translation_m = shift;
  return import_surface(mesh, options);
}

// Two surfaces as one (two legs side by side).
TriangleSurface merged(const TriangleSurface& a, const TriangleSurface& b) {
  TriangleSurface both = a;
  const int offset = static_cast<int>(a.vertices_m.size());
  both.vertices_m.insert(both.vertices_m.end(), b.vertices_m.begin(), b.vertices_m.end());
  for (Triangle t : b.triangles)
    both.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return both;
}

// Perimeter and area of the regular n-gon inscribed in a circle of radius r.
double polygon_perimeter(double r, int n) {
  return 2 * n * r * std::sin(M_PI / n);
}
double polygon_area(double r, int n) {
  return 0.5 * n * r * r * std::sin(2 * M_PI / n);
}

TEST(SurfaceSlice, CylinderSectionIsItsPolygon) {
  const int n = 48;
  const TriangleSurface s = z_up(testing::revolution_surface({0.0, 0.4}, {0.05, 0.05}, n));
  const SliceLoop loop = slice_surface(s, Vec3::UnitZ(), 0.13, Vec3::Zero());
  EXPECT_EQ(loop.n_points, 2 * n);  // each quad is two triangles: its diagonal is cut too
  EXPECT_NEAR(loop.perimeter_m, polygon_perimeter(0.05, n), 1e-12);
  EXPECT_NEAR(loop.hull_perimeter_m, polygon_perimeter(0.05, n), 1e-12);
  EXPECT_NEAR(loop.area_m2, polygon_area(0.05, n), 1e-14);
  EXPECT_LT((loop.centroid_m - Vec3(0, 0, 0.13)).norm(), 1e-12);
}

TEST(SurfaceSlice, ConeSectionHasTheRadiusOfItsHeight) {
  const int n = 40;
  const TriangleSurface s = z_up(testing::revolution_surface({0.0, 0.5}, {0.03, 0.08}, n));
  for (const double h : {0.05, 0.25, 0.45}) {
    const double r = 0.03 + 0.1 * h;  // linear between the rings
    const SliceLoop loop = slice_surface(s, Vec3(0, 0, 2), h, Vec3(0.01, 0, 0));
    EXPECT_NEAR(loop.perimeter_m, polygon_perimeter(r, n), 1e-12) << h;
    EXPECT_NEAR(loop.area_m2, polygon_area(r, n), 1e-14) << h;
  }
}

TEST(SurfaceSlice, PicksTheLegRoundThePoint) {
  // Two "legs" of different radii 0.2 m apart, merged into one surface.
  const TriangleSurface a =
      z_up(testing::revolution_surface({0.0, 0.4}, {0.05, 0.05}, 32), Vec3(0.1, 0, 0));
  const TriangleSurface b =
      z_up(testing::revolution_surface({0.0, 0.4}, {0.06, 0.06}, 32), Vec3(-0.1, 0, 0));
  const TriangleSurface both = merged(a, b);
  const SliceLoop right = slice_surface(both, Vec3::UnitZ(), 0.2, Vec3(0.12, 0.01, 0));
  const SliceLoop left = slice_surface(both, Vec3::UnitZ(), 0.2, Vec3(-0.3, 0, 0));  // outside both
  EXPECT_NEAR(right.perimeter_m, polygon_perimeter(0.05, 32), 1e-12);
  EXPECT_NEAR(right.centroid_m.x(), 0.1, 1e-12);
  EXPECT_NEAR(left.perimeter_m, polygon_perimeter(0.06, 32), 1e-12);
  EXPECT_NEAR(left.centroid_m.x(), -0.1, 1e-12);
}

// Along a ray from the centroid of a regular n-gon section the boundary lies at the circumradius
// towards a corner and at r cos(pi / n) towards the middle of an edge; the other leg's nearest
// point is its distance from the axis less its radius.
TEST(SurfaceSlice, BoundaryAlongARayAndTheOtherLoop) {
  const int n = 8;
  const TriangleSurface a =
      z_up(testing::revolution_surface({0.0, 0.4}, {0.05, 0.05}, n), Vec3(0.1, 0, 0));
  const TriangleSurface b =
      z_up(testing::revolution_surface({0.0, 0.4}, {0.06, 0.06}, 64), Vec3(-0.1, 0, 0));
  const TriangleSurface both = merged(a, b);
  const SliceLoop right = slice_surface(both, Vec3::UnitZ(), 0.2, Vec3(0.1, 0, 0));
  // The section's corners lie where the mesh's vertices do: find one's direction.
  Vec3 corner = right.points_m.front() - right.centroid_m;
  for (const Vec3& p : right.points_m)
    if ((p - right.centroid_m).norm() > corner.norm()) corner = p - right.centroid_m;
  const Vec3 to_corner = corner.normalized();
  const Vec3 to_edge_middle = Eigen::AngleAxisd(M_PI / n, Vec3::UnitZ()) * to_corner;
  EXPECT_NEAR(boundary_distance_m(right, to_corner), 0.05, 1e-12);
  EXPECT_NEAR(boundary_distance_m(right, to_edge_middle), 0.05 * std::cos(M_PI / n), 1e-12);
  // b's 64-gon comes nearest at its corner on the x axis: 0.2 - 0.06.
  EXPECT_NEAR(right.other_loops_distance_m, 0.2 - 0.06, 1e-12);
  const SliceLoop alone = slice_surface(a, Vec3::UnitZ(), 0.2, Vec3(0.1, 0, 0));
  EXPECT_TRUE(std::isinf(alone.other_loops_distance_m));
}

TEST(SurfaceSlice, PlaneMissingTheBodyIsRefused) {
  const TriangleSurface s = z_up(testing::revolution_surface({0.0, 0.4}, {0.05, 0.05}, 16));
  try {
    slice_surface(s, Vec3::UnitZ(), 0.7, Vec3::Zero());
    FAIL() << "a plane above the body was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("0.700000"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tightfit

namespace tightfit {
namespace {

// A tube placed round a limb (bodies/tube_placement.h) that is off the axis given: every ring
// goes round the section's centroid, its farthest point (the polygon's circumradius) plus the
// clearance away.
TEST(TubeRoundLimb, RingsCentreOnTheSections) {
  const int n = 36;
  const TriangleSurface leg =
      z_up(testing::revolution_surface({-0.2, 0.3}, {0.05, 0.05}, n), Vec3(0.02, -0.01, 0));
  const Garment tube = make_tube_garment("sleeve", 0.1, 0.2, 2, MeshSpacing{0.01, 0.02});
  const SimulationMesh mesh = weld(tube);
  const std::vector<Vec3> x =
      place_tube_round_limb(tube, mesh, Vec3::Zero(), Vec3::UnitZ(), leg, 0.01);
  ASSERT_EQ(static_cast<int>(x.size()), mesh.n_vertices);
  for (const Vec3& p : x) {
    EXPECT_NEAR(std::hypot(p.x() - 0.02, p.y() + 0.01), 0.06, 1e-12);
    EXPECT_LE(std::abs(p.z()), 0.1 + 1e-12);
  }
}

// Two legs 12 mm apart: a circle 1 cm outside one leg's section would reach into the other, so
// each ring is the section offset by the clearance: every vertex 1 cm outside its own leg (to
// the 64-gon's sagitta) and clear of the other.
TEST(TubeRoundLimb, RingsBesideAnotherLegFollowTheSection) {
  const int n = 64;
  const double r = 0.05, half_gap = 0.006, clearance = 0.01;
  const TriangleSurface a =
      z_up(testing::revolution_surface({-0.2, 0.3}, {r, r}, n), Vec3(r + half_gap, 0, 0));
  const TriangleSurface b =
      z_up(testing::revolution_surface({-0.2, 0.3}, {r, r}, n), Vec3(-r - half_gap, 0, 0));
  const TriangleSurface both = merged(a, b);
  const Garment tube = make_tube_garment("leg", 0.1, 0.2, 2, MeshSpacing{0.01, 0.02});
  const SimulationMesh mesh = weld(tube);
  const std::vector<Vec3> x =
      place_tube_round_limb(tube, mesh, Vec3(r + half_gap, 0, 0), Vec3::UnitZ(), both, clearance);
  const double sagitta = r * (1 - std::cos(M_PI / n));
  for (const Vec3& p : x) {
    const double from_own = std::hypot(p.x() - r - half_gap, p.y());
    EXPECT_LE(from_own, r + clearance + 1e-12);
    EXPECT_GE(from_own, r + clearance - sagitta - 1e-12);
    EXPECT_GT(std::hypot(p.x() + r + half_gap, p.y()), r);  // outside the other leg
  }
}

}  // namespace
}  // namespace tightfit
