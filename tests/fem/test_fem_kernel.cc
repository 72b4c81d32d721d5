// The membrane kernel and the nodal contact against finite differences of what they
// differentiate (the energy, the contact force).
#include "contact/cylinder.h"
#include "core/material.h"
#include "fem/membrane_kernel.h"
#include "fem/nodal_contact.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

namespace tightfit {
namespace {

// One linear triangle: shape gradients from its rest corners, energy A0 W(C) of its
// deformed corners x (node-major, 9 values).
struct Triangle1 {
  std::array<Vec2, 3> rest{Vec2(0, 0), Vec2(0.011, 0.001), Vec2(0.003, 0.009)};
  std::vector<Vec2> grad_N() const {
    Mat2 Dm;
    Dm << rest[1] - rest[0], rest[2] - rest[0];
    const Mat2 inverse = Dm.inverse();
    const Vec2 g1 = inverse.row(0).transpose(), g2 = inverse.row(1).transpose();
    return {-g1 - g2, g1, g2};
  }
  double area() const {
    const Vec2 e1 = rest[1] - rest[0], e2 = rest[2] - rest[0];
    return 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
  }
  Mat32 F(const Eigen::VectorXd& x) const {
    const auto g = grad_N();
    Mat32 F = Mat32::Zero();
    for (int a = 0; a < 3; ++a) F += x.segment<3>(3 * a) * g[a].transpose();
    return F;
  }
};

class KernelTest : public ::testing::TestWithParam<std::string> {};

TEST_P(KernelTest, GradientAndTangentMatchFiniteDifferences) {
  const FabricParameters fabric;
  const auto law = make_material_law(GetParam(), fabric);
  const Triangle1 t;
  Eigen::VectorXd x(9);
  // A stretched, sheared, lifted triangle (stretches 1.1 - 1.7: the tube's range).
  x << 0.001, -0.002, 0.0005, 0.017, 0.003, 0.004, 0.004, 0.013, -0.002;
  auto gradient_at = [&](const Eigen::VectorXd& y, Eigen::MatrixXd* K) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(9);
    add_membrane_point(*law, t.grad_N(), t.F(y), t.area(), g, K);
    return g;
  };
  auto energy_at = [&](const Eigen::VectorXd& y) {
    const Mat32 F = t.F(y);
    return t.area() * law->energy(F.transpose() * F);
  };
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(9, 9);
  const Eigen::VectorXd g = gradient_at(x, &K);
  const double h = 1e-7;
  Eigen::VectorXd g_fd(9);
  Eigen::MatrixXd K_fd(9, 9);
  for (int j = 0; j < 9; ++j) {
    Eigen::VectorXd xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    g_fd[j] = (energy_at(xp) - energy_at(xm)) / (2 * h);
    K_fd.col(j) = (gradient_at(xp, nullptr) - gradient_at(xm, nullptr)) / (2 * h);
  }
  EXPECT_LT((g - g_fd).norm(), 1e-6 * g.norm());
  EXPECT_LT((K - K_fd).norm(), 1e-6 * K.norm());
  // A rigid rotation of the deformed triangle rotates the forces: no spurious force.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  Eigen::VectorXd xr(9);
  for (int a = 0; a < 3; ++a) xr.segment<3>(3 * a) = R * x.segment<3>(3 * a);
  const Eigen::VectorXd gr = gradient_at(xr, nullptr);
  for (int a = 0; a < 3; ++a)
    EXPECT_LT((gr.segment<3>(3 * a) - R * g.segment<3>(3 * a)).norm(), 1e-12 * g.norm());
}

INSTANTIATE_TEST_SUITE_P(Laws, KernelTest,
                         ::testing::Values("linear biot", "st venant kirchhoff", "neo hookean"));

TEST(NodalContact, StiffnessIsMinusTheForceDerivative) {
  const Cylinder cylinder(Vec3(0.01, 0, 0), Vec3(1, 1, 3).normalized(), 0.05);
  const double penalty = 2e4, multiplier = 0.3;
  const Vec3 x(0.04, 0.031, 0.02);  // inside, near the surface
  const NodalContact c = nodal_contact(cylinder, x, multiplier, penalty, 1e-8);
  ASSERT_GT(c.multiplier_N, 0.0);
  const double h = 1e-7;
  Mat3 K_fd;
  for (int j = 0; j < 3; ++j) {
    const Vec3 e = h * Vec3::Unit(j);
    K_fd.col(j) = -(nodal_contact(cylinder, x + e, multiplier, penalty, 0).force_N -
                    nodal_contact(cylinder, x - e, multiplier, penalty, 0).force_N) /
                  (2 * h);
  }
  EXPECT_LT((c.stiffness_N_per_m - K_fd).norm(), 1e-5 * c.stiffness_N_per_m.norm());
  // The potential's derivative: lambda = max(0, lambda_bar - kA g).
  EXPECT_NEAR(c.multiplier_N, multiplier - penalty * c.gap_m, 1e-12);
  // Outside by more than lambda_bar / kA: no force.
  const Vec3 outside = cylinder.query(x).closest_point_m + 1e-3 * cylinder.query(x).outward_normal;
  EXPECT_EQ(nodal_contact(cylinder, outside, multiplier, penalty, 1e-8).multiplier_N, 0.0);
}

}  // namespace
}  // namespace tightfit
