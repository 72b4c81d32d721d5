// return_onto_surface (bodies/surface_return.h): points a penalty left inside a body go back
// onto its surface, checked against the cylinder's own distance (a point at radius rho < R goes
// to radius R along its radius) and on a faceted cylinder, where a single step along the
// distance's gradient may fall short near an edge; a point deeper than allowed leaves every
// point where it was and is named.
#include "bodies/cylinder.h"
#include "bodies/mesh_body.h"
#include "bodies/surface_return.h"
#include "body_mesh_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace tightfit {
namespace {

const double R = 0.05;

Vec3 at_radius(double rho, double phi, double z) {
  return Vec3(rho * std::cos(phi), rho * std::sin(phi), z);
}

TEST(SurfaceReturn, PointsInsideACylinderGoOutAlongTheirRadius) {
  const Cylinder cylinder(Vec3::Zero(), Vec3::UnitZ(), R);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> depth(-1e-3, 1e-3), angle(0, 2 * M_PI), z(-0.1, 0.1);
  std::vector<Vec3> x, before;
  int inside = 0;
  double deepest = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double d = depth(random);  // > 0: inside
    x.push_back(at_radius(R - d, angle(random), z(random)));
    if (d > 0) ++inside, deepest = std::max(deepest, d);
  }
  before = x;
  const SurfaceReturn back = return_onto_surface(cylinder, x, 2e-3);
  EXPECT_EQ(back.points_moved, inside);
  EXPECT_NEAR(back.deepest_m, deepest, 1e-15);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double g = cylinder.query(x[i]).signed_distance_m;
    if (before[i].head<2>().norm() >= R) {
      EXPECT_EQ(x[i], before[i]) << i;  // outside: untouched
      continue;
    }
    // On the surface, just outside (the nanometre the return adds), along the radius: the
    // height and the angle kept.
    EXPECT_GE(g, 0.0) << i;
    EXPECT_LE(g, 2e-9) << i;
    EXPECT_NEAR(x[i].z(), before[i].z(), 1e-15) << i;
    EXPECT_NEAR(std::atan2(x[i].y(), x[i].x()), std::atan2(before[i].y(), before[i].x()), 1e-12)
        << i;
  }
}

TEST(SurfaceReturn, PointsInsideAFacetedCylinderEndOutsideIt) {
  // 16 facets round 5 cm; points 0.5 mm inside the facets' inscribed circle (radius R cos(pi /
  // 16)) at every angle, many of them near a facet's edge, where the distance's gradient turns
  // from one face's normal to the next.
  const int n = 16;
  const std::string path = testing::temporary_path("return_cylinder.stl");
  testing::write_stl(path,
                     testing::revolution_surface({-0.2, 0.0, 0.2}, std::vector<double>(3, R), n));
  MeshBodyOptions options;
  options.import.up_axis = "+z";
  const auto mesh = load_mesh_body(path, options);
  std::vector<Vec3> x;
  const double inscribed = R * std::cos(M_PI / n);
  for (int a = 0; a < 360; ++a) x.push_back(at_radius(inscribed - 5e-4, 2 * M_PI * a / 360, 0.05));
  const SurfaceReturn back = return_onto_surface(*mesh, x, 2e-3);  // the corners: 1.4 mm
  EXPECT_EQ(back.points_moved, 360);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double g = mesh->query(x[i]).signed_distance_m;
    EXPECT_GE(g, 0.0) << i;
    EXPECT_LE(g, 1e-8) << i;
  }
}

TEST(SurfaceReturn, APointDeeperThanAllowedLeavesEveryPointAndIsNamed) {
  const Cylinder cylinder(Vec3::Zero(), Vec3::UnitZ(), R);
  std::vector<Vec3> x = {at_radius(R - 1e-4, 0.1, 0), at_radius(R - 3e-3, 1.0, 0),
                         at_radius(R + 1e-3, 2.0, 0)};
  const std::vector<Vec3> before = x;
  const SurfaceReturn back = return_onto_surface(cylinder, x, 1e-3);
  EXPECT_EQ(back.deepest_point, 1);
  EXPECT_NEAR(back.deepest_m, 3e-3, 1e-15);
  EXPECT_EQ(back.points_moved, 0);
  EXPECT_EQ(x, before);
}

}  // namespace
}  // namespace tightfit
