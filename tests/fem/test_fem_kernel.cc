// The membrane kernel against finite differences of the energy it differentiates.
#include "core/material.h"
#include "fem/membrane_kernel.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <array>
#include <string>
#include <vector>

namespace tightfit {
namespace {

// A straight-sided triangle of degree 1 (3 nodes) or 2 (6 nodes: corners, then the midpoints
// of edges 01, 12, 20) in the panel's plane, with a quadrature rule: the kernel works point by
// point, so any rule checks it (the centroid for degree 1, the three-point rule for degree 2).
struct ReferenceTriangle {
  int degree = 1;
  std::array<Vec2, 3> rest{Vec2(0, 0), Vec2(0.011, 0.001), Vec2(0.003, 0.009)};
  struct Point {
    std::vector<Vec2> grad_N;  // 1/m
    double JxW_m2;
  };

  int n_nodes() const { return degree == 1 ? 3 : 6; }
  double area() const {
    const Vec2 e1 = rest[1] - rest[0], e2 = rest[2] - rest[0];
    return 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
  }
  std::vector<Point> points() const {
    Mat2 J;  // dX/dxi, constant on a straight-sided triangle
    J << rest[1] - rest[0], rest[2] - rest[0];
    const Mat2 J_inverse_transpose = J.inverse().transpose();
    // Barycentric coordinates l = (1 - xi - eta, xi, eta) and their xi-gradients.
    const Vec2 grad_l[3] = {Vec2(-1, -1), Vec2(1, 0), Vec2(0, 1)};
    std::vector<std::array<double, 3>> at;
    if (degree == 1)
      at = {{1.0 / 3, 1.0 / 3, 1.0 / 3}};
    else
      at = {{2.0 / 3, 1.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 3, 1.0 / 6}, {1.0 / 6, 1.0 / 6, 2.0 / 3}};
    std::vector<Point> result;
    for (const auto& l : at) {
      std::vector<Vec2> grad_xi;
      if (degree == 1) {
        grad_xi.assign(grad_l, grad_l + 3);
      } else {
        // Corners N_a = l_a (2 l_a - 1); midpoints N = 4 l_a l_b.
        for (int a = 0; a < 3; ++a) grad_xi.push_back((4 * l[a] - 1) * grad_l[a]);
        for (int a = 0; a < 3; ++a) {
          const int b = (a + 1) % 3;
          grad_xi.push_back(4 * (l[a] * grad_l[b] + l[b] * grad_l[a]));
        }
      }
      Point p{{}, area() / at.size()};
      for (const Vec2& g : grad_xi) p.grad_N.push_back(J_inverse_transpose * g);
      result.push_back(p);
    }
    return result;
  }
  static Mat32 F(const Point& p, const Eigen::VectorXd& x) {
    Mat32 F = Mat32::Zero();
    for (std::size_t a = 0; a < p.grad_N.size(); ++a)
      F += x.segment<3>(3 * a) * p.grad_N[a].transpose();
    return F;
  }
};

struct KernelCase {
  std::string law;
  int degree;
};

class KernelTest : public ::testing::TestWithParam<KernelCase> {};

TEST_P(KernelTest, GradientAndTangentMatchFiniteDifferences) {
  const FabricParameters fabric;
  const auto law = make_material_law(GetParam().law, fabric);
  const ReferenceTriangle t{GetParam().degree};
  const int n = 3 * t.n_nodes();
  // A stretched, sheared, lifted triangle (stretches 1.1 - 1.7: the tube's range); the
  // quadratic one's midpoints are moved off the chords, so its sides are curved.
  Eigen::VectorXd x(n);
  x.head<9>() << 0.001, -0.002, 0.0005, 0.017, 0.003, 0.004, 0.004, 0.013, -0.002;
  for (int m = 3; m < t.n_nodes(); ++m) {
    const int a = m - 3, b = (a + 1) % 3;
    x.segment<3>(3 * m) = 0.5 * (x.segment<3>(3 * a) + x.segment<3>(3 * b)) +
                          Vec3(0.0004 * m, -0.0003, 0.0006 * (m - 4));
  }
  auto gradient_at = [&](const Eigen::VectorXd& y, Eigen::MatrixXd* K) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
    for (const auto& p : t.points()) add_membrane_point(*law, p.grad_N, t.F(p, y), p.JxW_m2, g, K);
    return g;
  };
  auto energy_at = [&](const Eigen::VectorXd& y) {
    double energy = 0.0;
    for (const auto& p : t.points()) {
      const Mat32 F = t.F(p, y);
      energy += p.JxW_m2 * law->energy(F.transpose() * F);
    }
    return energy;
  };
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  const Eigen::VectorXd g = gradient_at(x, &K);
  const double h = 1e-7;
  Eigen::VectorXd g_fd(n);
  Eigen::MatrixXd K_fd(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    g_fd[j] = (energy_at(xp) - energy_at(xm)) / (2 * h);
    K_fd.col(j) = (gradient_at(xp, nullptr) - gradient_at(xm, nullptr)) / (2 * h);
  }
  EXPECT_LT((g - g_fd).norm(), 1e-6 * g.norm());
  EXPECT_LT((K - K_fd).norm(), 1e-6 * K.norm());
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
  // The shape functions sum to one, so the element's forces sum to zero.
  Vec3 sum = Vec3::Zero();
  for (int a = 0; a < t.n_nodes(); ++a) sum += g.segment<3>(3 * a);
  EXPECT_LT(sum.norm(), 1e-12 * g.norm());
  // A rigid rotation of the deformed triangle rotates the forces: no spurious force.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  Eigen::VectorXd xr(n);
  for (int a = 0; a < t.n_nodes(); ++a) xr.segment<3>(3 * a) = R * x.segment<3>(3 * a);
  const Eigen::VectorXd gr = gradient_at(xr, nullptr);
  for (int a = 0; a < t.n_nodes(); ++a)
    EXPECT_LT((gr.segment<3>(3 * a) - R * g.segment<3>(3 * a)).norm(), 1e-12 * g.norm());
}

INSTANTIATE_TEST_SUITE_P(
    LawsAndDegrees, KernelTest,
    ::testing::Values(KernelCase{"linear biot", 1}, KernelCase{"st venant kirchhoff", 1},
                      KernelCase{"neo hookean", 1}, KernelCase{"linear biot", 2},
                      KernelCase{"st venant kirchhoff", 2}, KernelCase{"neo hookean", 2}),
    [](const ::testing::TestParamInfo<KernelCase>& info) {
      std::string name = info.param.law + "_degree_" + std::to_string(info.param.degree);
      for (char& c : name)
        if (c == ' ') c = '_';
      return name;
    });

}  // namespace
}  // namespace tightfit
