// Volino's triangle element: forces are minus the gradient of the element energy, momentum is
// conserved and rigid motions give no force (invariants of any correct element).
#include "central_difference.h"
#include "massspring/triangle_elements.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

namespace tightfit {
namespace {

using test::deformed_positions;

class TriangleElementsForEveryLaw : public ::testing::TestWithParam<std::string> {};

TEST_P(TriangleElementsForEveryLaw, ForcesAreMinusTheCentralDifferenceOfTheEnergy) {
  FabricParameters fabric;  // orthotropic with Poisson coupling: the general case
  const auto law = make_material_law(GetParam(), fabric);
  const SimulationMesh mesh = test::panel_mesh(0.05, 0.06, MeshSpacing{0.012, 0.015}, 0.4);
  const TriangleElements elements(mesh, *law);
  std::vector<Vec3> x = deformed_positions(mesh, 1e-3, 7);
  std::vector<Vec3> force(x.size(), Vec3::Zero());
  elements.add_forces(x, force);

  const double h = 1e-7;  // m
  double largest = 0.0;
  for (const Vec3& f : force) largest = std::max(largest, f.norm());
  testing::expect_force_is_minus_energy_gradient(
      x, force, [&](const std::vector<Vec3>& y) { return elements.energy_J(y); }, 1e-6 * largest,
      h);
}

TEST_P(TriangleElementsForEveryLaw, ForcesSumToZeroAndRotateWithTheGarment) {
  const auto law = make_material_law(GetParam(), FabricParameters{});
  const SimulationMesh mesh = test::panel_mesh(0.05, 0.06, MeshSpacing{0.012, 0.015});
  const TriangleElements elements(mesh, *law);
  const std::vector<Vec3> x = deformed_positions(mesh, 2e-3, 3);
  std::vector<Vec3> force(x.size(), Vec3::Zero());
  elements.add_forces(x, force);

  // Momentum: the internal forces of a free body sum to zero, and so do their moments.
  Vec3 sum = Vec3::Zero(), moment = Vec3::Zero();
  double largest = 0.0;
  for (std::size_t v = 0; v < x.size(); ++v) {
    sum += force[v];
    moment += x[v].cross(force[v]);
    largest = std::max(largest, force[v].norm());
  }
  ASSERT_GT(largest, 0.0);
  EXPECT_LT(sum.norm(), 1e-12 * largest * x.size());
  EXPECT_LT(moment.norm(), 1e-12 * largest * x.size());

  // Objectivity: a rigid motion of the stretched state rotates its forces.
  const Mat3 R = test::some_rotation();
  const Vec3 shift(0.3, -0.2, 1.5);
  std::vector<Vec3> moved(x.size());
  for (std::size_t v = 0; v < x.size(); ++v) moved[v] = R * x[v] + shift;
  std::vector<Vec3> moved_force(x.size(), Vec3::Zero());
  elements.add_forces(moved, moved_force);
  for (std::size_t v = 0; v < x.size(); ++v)
    EXPECT_LT((moved_force[v] - R * force[v]).norm(), 1e-9 * largest);
}

TEST_P(TriangleElementsForEveryLaw, RigidlyMovedRestStateHasNoForceAndNoEnergy) {
  const auto law = make_material_law(GetParam(), FabricParameters{});
  const SimulationMesh mesh = test::panel_mesh(0.05, 0.06, MeshSpacing{0.012, 0.015}, 0.9);
  const TriangleElements elements(mesh, *law);
  const Mat3 R = test::some_rotation();
  std::vector<Vec3> x = test::flat_positions(mesh);
  for (Vec3& p : x) p = R * p + Vec3(-1.0, 2.0, 0.5);
  std::vector<Vec3> force(x.size(), Vec3::Zero());
  elements.add_forces(x, force);
  // Force scale of a 1% strain on one element: Y * strain * edge.
  const double scale = law->stiffness_scale() * 0.01 * 0.012;
  for (const Vec3& f : force) EXPECT_LT(f.norm(), 1e-9 * scale);
  EXPECT_NEAR(elements.energy_J(x), 0.0, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Laws, TriangleElementsForEveryLaw,
                         ::testing::Values("linear biot", "st venant kirchhoff", "neo hookean"));

TEST(TriangleElements, UniformStretchGivesTheLawsEnergyTimesTheArea) {
  // A uniform weft stretch a of the linear Biot law, nu = 0: W = Y1 (a - 1)^2 / 2 per unit
  // rest area (the closed forms' law, docs/model.md), independent of the mesh.
  FabricParameters fabric;
  fabric.poisson_weft_warp = 0.0;
  const auto law = make_material_law("linear biot", fabric);
  const SimulationMesh mesh = test::panel_mesh(0.05, 0.06, MeshSpacing{0.012, 0.015});
  const TriangleElements elements(mesh, *law);
  std::vector<Vec3> x = test::flat_positions(mesh);
  const double a = 1.4;
  for (Vec3& p : x) p.x() *= a;
  const double expected = 0.5 * fabric.stiffness_weft_N_per_m * (a - 1) * (a - 1) * 0.05 * 0.06;
  EXPECT_NEAR(elements.energy_J(x), expected, 1e-12 * expected);
}

}  // namespace
}  // namespace tightfit
