// The implicit route's projected tangent (triangle_elements.h, positive_part.h) against
// central finite differences of the membrane forces: where every triangle is in tension it is
// the exact stiffness; where the fabric is compressed it is positive semi-definite, while the
// exact one there is not.
#include "massspring/positive_part.h"
#include "massspring/triangle_elements.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <random>

namespace tightfit {
namespace {

Eigen::MatrixXd membrane_stiffness(const TriangleElements& elements, const std::vector<Vec3>& x,
                                   bool projected) {
  Triplets triplets;
  elements.add_stiffness(x, triplets, projected);
  SparseMatrix K(3 * Eigen::Index(x.size()), 3 * Eigen::Index(x.size()));
  K.setFromTriplets(triplets.begin(), triplets.end());
  return Eigen::MatrixXd(K);
}

// -df/dx by central differences of step h_m.
Eigen::MatrixXd finite_difference_stiffness(const TriangleElements& elements,
                                            const std::vector<Vec3>& x, double h_m) {
  const int n = static_cast<int>(x.size());
  Eigen::MatrixXd fd(3 * n, 3 * n);
  std::vector<Vec3> plus = x, minus = x, f_plus(n), f_minus(n);
  for (int j = 0; j < 3 * n; ++j) {
    plus[j / 3][j % 3] += h_m;
    minus[j / 3][j % 3] -= h_m;
    std::fill(f_plus.begin(), f_plus.end(), Vec3::Zero());
    std::fill(f_minus.begin(), f_minus.end(), Vec3::Zero());
    elements.add_forces(plus, f_plus);
    elements.add_forces(minus, f_minus);
    for (int i = 0; i < n; ++i) fd.block<3, 1>(3 * i, j) = -(f_plus[i] - f_minus[i]) / (2 * h_m);
    plus[j / 3][j % 3] = x[j / 3][j % 3];
    minus[j / 3][j % 3] = x[j / 3][j % 3];
  }
  return fd;
}

// The flat layout stretched by (sx, sy) in its plane, each vertex moved at random by up to
// jitter_m (out of the plane too).
std::vector<Vec3> stretched(const SimulationMesh& mesh, double sx, double sy, double jitter_m) {
  std::vector<Vec3> x = test::flat_positions(mesh);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (Vec3& p : x)
    p = Vec3(sx * p.x(), sy * p.y(), 0.0) +
        jitter_m * Vec3(uniform(random), uniform(random), uniform(random));
  return x;
}

TEST(ProjectedTangent, IsTheExactStiffnessInTension) {
  // 4 x 4 cm at 1 cm, stretched 10 % weft and 5 % warp, jittered by 0.2 mm: every triangle's
  // stress is tensile (checked below through the projection leaving K unchanged).
  test::PanelProblem panel(0.04, 0.04, MeshSpacing{0.01, 0.01});
  const TriangleElements elements(panel.mesh, *panel.law);
  const std::vector<Vec3> x = stretched(panel.mesh, 1.10, 1.05, 2e-4);
  const Eigen::MatrixXd projected = membrane_stiffness(elements, x, true);
  const Eigen::MatrixXd fd = finite_difference_stiffness(elements, x, 1e-7);
  const double scale = fd.cwiseAbs().maxCoeff();
  // The projection leaves a tensile state's tangent to the last bit.
  EXPECT_EQ((projected - membrane_stiffness(elements, x, false)).cwiseAbs().maxCoeff(), 0.0);
  // Against the differences: measured 2e-9 relative (their truncation and round-off at
  // h = 1e-7 m); margin 50.
  EXPECT_LT((projected - fd).cwiseAbs().maxCoeff() / scale, 1e-7);
}

TEST(ProjectedTangent, IsPositiveSemiDefiniteInCompression) {
  // The same panel compressed 10 % weft (stretched 5 % warp) and jittered out of its plane by
  // 1 mm, as a wrinkled row between two contacts: the exact tangent has negative eigenvalues
  // (the compressive stress's geometric term), the projected one none below round-off.
  test::PanelProblem panel(0.04, 0.04, MeshSpacing{0.01, 0.01});
  const TriangleElements elements(panel.mesh, *panel.law);
  const std::vector<Vec3> x = stretched(panel.mesh, 0.90, 1.05, 1e-3);
  const Eigen::MatrixXd exact = membrane_stiffness(elements, x, false);
  const Eigen::MatrixXd projected = membrane_stiffness(elements, x, true);
  const double scale = exact.cwiseAbs().maxCoeff();
  // The exact tangent is the differences' (so the state is what the forces say).
  EXPECT_LT((exact - finite_difference_stiffness(elements, x, 1e-7)).cwiseAbs().maxCoeff() / scale,
            1e-7);
  const double exact_smallest =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(exact).eigenvalues().minCoeff();
  const double projected_smallest =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(projected).eigenvalues().minCoeff();
  // Indefinite before: well below round-off (measured in the test's output).
  EXPECT_LT(exact_smallest, -1e-6 * scale) << "exact smallest " << exact_smallest;
  // Round-off of an eigen-decomposition of entries of size `scale`: 1e-12 of it (the
  // 48-dimensional matrix's rounding is about 1e-14 of it).
  EXPECT_GE(projected_smallest, -1e-12 * scale) << "projected smallest " << projected_smallest;
  // Symmetric, as the Cholesky factorisation needs.
  EXPECT_LT((projected - projected.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale);
}

TEST(ProjectedTangent, PositivePartOfABlockClampsOnlyNegativeEigenvalues) {
  // diag(3, -2, 1) turned by a rotation, plus a skew part: the positive part is the turned
  // diag(3, 0, 1), exactly the nearest positive semi-definite matrix to the symmetric part.
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  Mat3 skew;
  skew << 0, 1, -2, -1, 0, 0.5, 2, -0.5, 0;
  const Mat3 block = R * Vec3(3, -2, 1).asDiagonal() * R.transpose() + skew;
  const Mat3 expected = R * Vec3(3, 0, 1).asDiagonal() * R.transpose();
  EXPECT_LT((positive_part(block) - expected).cwiseAbs().maxCoeff(), 1e-14);
}

}  // namespace
}  // namespace tightfit
