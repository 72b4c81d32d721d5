// Angular bending springs: forces are minus the gradient of the hinge energy, a flat or
// rigidly moved flat sheet carries none, and the dihedral angle is the geometric one.
#include "central_difference.h"
#include "massspring/bending_hinges.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace tightfit {
namespace {

constexpr double rigidity_N_m = 5e-6;

TEST(BendingHinges, DihedralAngleOfAFoldedPairIsTheGeometricAngle) {
  // Two unit-height triangles on the edge a-b; lifting both tips by h folds each wing by
  // atan(h), towards the normal of (a, b, c): a valley of angle 2 atan(h), negative.
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  for (double h : {0.0, 0.1, 1.0, 3.0}) {
    const Vec3 c(0.3, 1.0, h), d(0.6, -1.0, h);
    EXPECT_NEAR(BendingHinges::dihedral_angle_rad(a, b, c, d), -2.0 * std::atan(h), 1e-14);
    const Vec3 c_down(0.3, 1.0, -h), d_down(0.6, -1.0, -h);
    EXPECT_NEAR(BendingHinges::dihedral_angle_rad(a, b, c_down, d_down), 2.0 * std::atan(h), 1e-14);
  }
}

TEST(BendingHinges, ForcesAreMinusTheCentralDifferenceOfTheEnergy) {
  const SimulationMesh mesh = test::panel_mesh(0.05, 0.06, MeshSpacing{0.012, 0.015});
  const BendingHinges hinges(mesh, rigidity_N_m);
  ASSERT_GT(hinges.size(), 0u);
  // Fold the sheet over a cylinder-like bump, then jitter it: large angles of both signs.
  std::vector<Vec3> x = test::deformed_positions(mesh, 3e-3, 11);
  for (Vec3& p : x) p.z() += 0.02 * std::sin(60.0 * p.x()) + 0.01 * std::cos(40.0 * p.y());
  std::vector<Vec3> force(x.size(), Vec3::Zero());
  hinges.add_forces(x, force);
  double largest = 0.0;
  Vec3 sum = Vec3::Zero();
  for (const Vec3& f : force) {
    largest = std::max(largest, f.norm());
    sum += f;
  }
  ASSERT_GT(largest, 0.0);
  EXPECT_LT(sum.norm(), 1e-10 * largest);
  const double h = 1e-7;
  testing::expect_force_is_minus_energy_gradient(
      x, force, [&](const std::vector<Vec3>& y) { return hinges.energy_J(y); }, 1e-6 * largest, h);
}

TEST(BendingHinges, FlatAndRigidlyMovedFlatSheetsCarryNoBendingForce) {
  const SimulationMesh mesh = test::panel_mesh(0.05, 0.06, MeshSpacing{0.012, 0.015});
  const BendingHinges hinges(mesh, rigidity_N_m);
  // In-plane stretch keeps the sheet flat: no bending.
  std::vector<Vec3> x = test::flat_positions(mesh);
  for (Vec3& p : x) p = Vec3(1.3 * p.x() + 0.2 * p.y(), 0.9 * p.y(), 0.0);
  const Mat3 R = test::some_rotation();
  std::vector<Vec3> rotated = x;
  for (Vec3& p : rotated) p = R * p + Vec3(0.1, 0.2, 0.3);
  // Force scale of a fold by 0.1 rad at one hinge: k theta |grad theta| ~ 3 B 0.1 / h^2 ... / h.
  const double scale = rigidity_N_m * 0.1 / (0.012 * 0.012);
  for (const auto* state : {&x, &rotated}) {
    std::vector<Vec3> force(x.size(), Vec3::Zero());
    hinges.add_forces(*state, force);
    for (const Vec3& f : force) EXPECT_LT(f.norm(), 1e-9 * scale);
    EXPECT_LT(hinges.energy_J(*state), 1e-20);
  }
}

TEST(BendingHinges, SheetWrappedOnACylinderStoresTheContinuumEnergyToWithinAFactorThree) {
  // Continuum plate: bent to curvature 1/R it stores B / (2 R^2) per unit area. The hinge
  // energy converges to it only on meshes with special symmetry (Grinspun et al., "Computing
  // discrete shape operators on general meshes", 2006); on row meshes bent across their rows it
  // reads 1.5 to 3 times the continuum value, depending on how the cells are cut (the diagonal
  // hinges bend too). Bending is a regulariser here (a knit's B / R^3 is a millipascal against
  // pressures of hundreds of pascals), so the check is the order of magnitude.
  const double width = 0.1, height = 0.1, radius = 0.05;
  const SimulationMesh mesh = test::panel_mesh(width, height, MeshSpacing{});
  const BendingHinges hinges(mesh, rigidity_N_m);
  std::vector<Vec3> x = test::flat_positions(mesh);
  for (Vec3& p : x) {
    const double angle = p.x() / radius;
    p = Vec3(radius * std::sin(angle), p.y(), radius * (1.0 - std::cos(angle)));
  }
  const double continuum = 0.5 * rigidity_N_m / (radius * radius) * width * height;
  const double ratio = hinges.energy_J(x) / continuum;
  std::printf("hinge energy / continuum energy %.4f\n", ratio);
  // Measured 2.77 on this mesh. One-sided: the diagonal hinges bend besides the row hinges,
  // so the energy reads above the continuum's; the upper bound is the factor three, 8% above.
  EXPECT_GT(ratio, 1.0);
  EXPECT_LT(ratio, 3.0);
}

}  // namespace
}  // namespace tightfit
