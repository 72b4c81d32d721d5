// The implicit integrator's stiffness K = -df/dx against central finite differences of the
// backend's own residual forces: exact for the triangles (with the law's Poisson coupling) and
// the contact on a deformed tube half pressed into a cylinder; for the bending hinges the
// Gauss-Newton matrix equals the Hessian where the sheet is flat.
#include "massspring/massspring_backend.h"
#include "test_meshes.h"
#include "tube_on_cylinder.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <random>

namespace tightfit {
namespace {

// Largest |K - K_fd| over the largest |K|, K_fd from central differences of step h_m.
double relative_jacobian_error(const MassSpringBackend& backend, const std::vector<Vec3>& x,
                               double h_m) {
  const int n = static_cast<int>(x.size());
  SparseMatrix K;
  backend.stiffness(x, K);
  const Eigen::MatrixXd dense = Eigen::MatrixXd(K);
  Eigen::MatrixXd fd(3 * n, 3 * n);
  std::vector<Vec3> plus = x, minus = x, f_plus(n), f_minus(n);
  for (int j = 0; j < 3 * n; ++j) {
    plus[j / 3][j % 3] += h_m;
    minus[j / 3][j % 3] -= h_m;
    backend.residual_forces(plus, false, f_plus);
    backend.residual_forces(minus, false, f_minus);
    for (int i = 0; i < n; ++i) fd.block<3, 1>(3 * i, j) = -(f_plus[i] - f_minus[i]) / (2 * h_m);
    plus[j / 3][j % 3] = x[j / 3][j % 3];
    minus[j / 3][j % 3] = x[j / 3][j % 3];
  }
  return (dense - fd).cwiseAbs().maxCoeff() / dense.cwiseAbs().maxCoeff();
}

TEST(MassSpringStiffness, MembraneAndContactMatchFiniteDifferences) {
  // A short tube (6 x 4 cells a panel) with Poisson coupling, on a cylinder 1.2 times its rest
  // radius, each vertex moved at random radially by 0.1 to 0.3 mm in or out (half of them in
  // contact, none within the difference step of the contact's kink) and along the surface.
  test::TubeOnCylinder tube(0.06, MeshSpacing{0.01, 0.06}, 0.3);
  tube.cylinder.set_radius(1.2 * tube.rest_radius_m());
  MassSpringParameters parameters;
  parameters.bending_rigidity_N_m = 0.0;
  // The exact tangent (the projected one drops the contact's curvature term).
  parameters.implicit_tangent = ImplicitTangent::exact;
  MassSpringBackend backend(tube.problem, parameters);
  std::vector<Vec3> x = tube.start_positions();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  int inside = 0;
  for (Vec3& p : x) {
    const double u = uniform(random);
    const Vec3 radial = Vec3(p.x(), p.y(), 0.0).normalized();
    p += (u < 0 ? -1.0 : 1.0) * (1e-4 + 2e-4 * std::abs(u)) * radial;
    p += 2e-3 * Vec3(uniform(random), uniform(random), uniform(random)).cross(radial);
    inside += u < 0;
  }
  ASSERT_GT(inside, 0);
  ASSERT_LT(inside, static_cast<int>(x.size()));
  // Measured 3.3e-11 (the differences' truncation and round-off at h = 1e-7 m); margin 300.
  EXPECT_LT(relative_jacobian_error(backend, x, 1e-7), 1e-8);
}

TEST(MassSpringStiffness, BendingGaussNewtonIsTheHessianOfAFlatSheet) {
  // A flat panel at rest, bending rigidity on: the membrane has no stress and every hinge angle
  // is zero, where k grad(theta) grad(theta)^T is the hinge energy's whole Hessian.
  test::PanelProblem panel(0.04, 0.04, MeshSpacing{0.01, 0.01});
  const SimulationMesh& mesh = panel.mesh;
  Problem& problem = panel.problem;
  MassSpringParameters parameters;
  parameters.bending_rigidity_N_m = 1e-3;
  MassSpringBackend backend(problem, parameters);
  // Measured 1.8e-10; margin 50. (Bending's entries are about a tenth of the largest here, so
  // a wrong hinge matrix would show as 1e-1.)
  EXPECT_LT(relative_jacobian_error(backend, test::flat_positions(mesh), 1e-7), 1e-8);
}

}  // namespace
}  // namespace tightfit
