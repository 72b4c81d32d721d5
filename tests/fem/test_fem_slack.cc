// Slack in the FE membrane (docs/model.md, "Slack: the tension field"): a tube on a cylinder
// whose held ends are pushed together, so that it is too long for the body axially. Relaxed,
// it carries hoop tension only, and the pressure has a closed form; the membrane kernel's
// gradient and tangent on a wrinkled triangle against finite differences of its energy.
#include "core/material.h"
#include "fem/fem_backend.h"
#include "fem/membrane_kernel.h"
#include "tube_problem.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tightfit {
namespace {

using testing::TubeCase;

// The tube "4 5T" (46 vertices round) with held ends, placed round the cylinder of radius
// alpha R0 with its axial coordinates scaled by b: the held end rows keep the tube at the
// axial stretch b.
struct PushedTube {
  TubeCase tube{"linear biot", EndCondition::held_ends};
  double alpha, b;
  PushedTube(double alpha_, double b_) : alpha(alpha_), b(b_) { tube.grow_to(alpha); }
  std::vector<Vec3> start() const {
    std::vector<Vec3> x = tube.placed(alpha * tube.rest_radius_m);
    for (Vec3& p : x) p.z() *= b;
    return x;
  }
  // Vertices round one ring: those on the bottom row.
  int n_round() const {
    const std::vector<Vec3> x = start();
    double bottom = 0.0;
    for (const Vec3& p : x) bottom = std::min(bottom, p.z());
    return static_cast<int>(
        std::count_if(x.begin(), x.end(), [&](const Vec3& p) { return p.z() < bottom + 1e-9; }));
  }
};

// The uniform state: every triangle (right-angled at rest, one leg round, one along) has the
// Biot strains e1 = lambda - 1 round and e2 = b - 1 along, lambda the hoop stretch of the
// inscribed polygon, n r sin(pi/n) / (pi R0). Relaxed, the warp is wrinkled (sigma2 < 0): the
// hoop force per rest axial length is a weft strip's, Y1 e1 (the wrinkled law's stiffness along
// the grain is A11 - A12^2 / A22 = D11 - D12^2 / D22 = Y1), and nothing acts along the axis.
// With the fraction eps of the law kept, N = (1 - eps) Y1 e1 + eps (D11 e1 + D12 e2) round and
// eps (D12 e1 + D22 e2) along. A vertex feels 2 N sin(pi/n) per rest axial length from its two
// chords and has the area 2 r sin(pi/n) b per rest axial length, so p = N / (b r) with no
// polygon factor left; an end row's vertex carries the axial force over its rest hoop length
// 2 pi R0 / n.
struct ClosedForm {
  double pressure_Pa, end_axial_force_N;
};
ClosedForm closed_form(const PushedTube& t, double eps) {
  const FabricParameters& f = t.tube.fabric;
  const double r = t.alpha * t.tube.rest_radius_m;
  const int n = t.n_round();
  const double e1 = n * r * std::sin(M_PI / n) / (M_PI * t.tube.rest_radius_m) - 1.0;
  const double e2 = t.b - 1.0;
  const double nu21 = f.poisson_warp_weft(), denominator = 1.0 - f.poisson_weft_warp * nu21;
  const double d11 = f.stiffness_weft_N_per_m / denominator, d12 = nu21 * d11,
               d22 = f.stiffness_warp_N_per_m / denominator;
  const double hoop = (1.0 - eps) * f.stiffness_weft_N_per_m * e1 + eps * (d11 * e1 + d12 * e2);
  const double axial = eps * (d12 * e1 + d22 * e2);
  return {hoop / (t.b * r), std::abs(axial) * 2.0 * M_PI * t.tube.rest_radius_m / n};
}

TEST(FemSlack, TubeTooLongAxiallyCarriesHoopTensionOnly) {
  // At alpha 1.2 a free weft strip narrows to 1 - nu12 (lambda - 1) = 0.96: b = 0.9 leaves
  // the warp 6% slack, so the unrelaxed law would compress it (sigma2 = D12 e1 + D22 e2 < 0).
  // Pure relaxation (eps = 0) and the default eps = 1e-2.
  for (const double eps : {0.0, FemParameters{}.compression_stiffness_fraction})
    for (const double b : {0.9, 0.8}) {
      PushedTube t(1.2, b);
      FemParameters parameters;
      parameters.slack_treatment = SlackTreatment::tension_field;
      parameters.compression_stiffness_fraction = eps;
      FemBackend backend(t.tube.problem, parameters);
      backend.set_positions(t.start());
      const StepReport report = backend.solve({0, t.alpha, false});
      const SurfaceState state = backend.state();
      const PressureField field = extract_pressure(
          t.tube.mesh.triangles, state, VertexAreaDefinition::barycentric, t.tube.cylinder.get());
      double force = 0.0, area = 0.0, largest_axial_N = 0.0, largest_N = 0.0;
      for (int w = 0; w < t.tube.mesh.n_vertices; ++w) {
        force += field.normal_force_N[w];
        area += field.vertex_area_m2[w];
        largest_axial_N = std::max(largest_axial_N, std::abs(state.internal_force_N[w].z()));
        largest_N = std::max(largest_N, state.internal_force_N[w].norm());
      }
      const ClosedForm expected = closed_form(t, eps);
      std::printf(
          "eps %g, b %.2f: %d Newton iterations, p %.6f Pa, closed form %.6f Pa "
          "(%.2e), largest axial force %.6e N, closed form %.6e N\n",
          eps, b, report.iterations, force / area, expected.pressure_Pa,
          force / area / expected.pressure_Pa - 1.0, largest_axial_N, expected.end_axial_force_N);
      // Measured 6.6e-11 apart (Newton's stop rule and the 1e-9 m gap): 1e-8 margin.
      EXPECT_NEAR(force / area, expected.pressure_Pa, 1e-8 * expected.pressure_Pa)
          << "eps " << eps << ", b " << b;
      // The axial force on the held end rows: zero with eps = 0 (measured below 2e-15 N against
      // 7.7e-2 N in all), else eps times the law's compression (measured to 1e-7 of it). The
      // unrelaxed law (Slack treatment = none) pushes the end rows out with 3.5e-2 N at
      // b = 0.9 and 9.3e-2 N at 0.8, and reads the pressure 3.3% and 8.9% low.
      EXPECT_NEAR(largest_axial_N, expected.end_axial_force_N,
                  1e-9 * largest_N + 1e-6 * expected.end_axial_force_N)
          << "eps " << eps << ", b " << b;
    }
}

// A wrinkled linear triangle: pulled 30% along a direction 0.4 rad off the weft, shortened
// across it, lifted out of the plane. The kernel's gradient and tangent against central
// differences of the relaxed energy.
TEST(FemSlack, KernelOnAWrinkledTriangleMatchesFiniteDifferences) {
  const FabricParameters fabric;
  const auto law = make_tension_field_law("linear biot", fabric, 0.0);
  const Vec2 rest[3] = {Vec2(0, 0), Vec2(0.011, 0.001), Vec2(0.003, 0.009)};
  Mat2 Dm;
  Dm << rest[1] - rest[0], rest[2] - rest[0];
  const Mat2 inverse = Dm.inverse();
  const std::vector<Vec2> grad_N = {-inverse.row(0).transpose() - inverse.row(1).transpose(),
                                    inverse.row(0).transpose(), inverse.row(1).transpose()};
  const double area = 0.5 * std::abs(Dm.determinant());
  // F = R [Q diag(1.3, 0.8) Q^T; lift]: a 3x2 map with principal stretches 1.3 and 0.8.
  const double c = std::cos(0.4), s = std::sin(0.4);
  Mat2 Q;
  Q << c, -s, s, c;
  const Mat2 U = Q * Vec2(1.3, 0.8).asDiagonal() * Q.transpose();
  Mat32 F0;
  F0 << U(0, 0), U(0, 1), 0.6 * U(1, 0), 0.6 * U(1, 1), 0.8 * U(1, 0), 0.8 * U(1, 1);
  Eigen::VectorXd x(9);
  for (int a = 0; a < 3; ++a) x.segment<3>(3 * a) = F0 * rest[a] + Vec3(0.001, -0.002, 0.003);
  auto F_of = [&](const Eigen::VectorXd& y) {
    Mat32 F = Mat32::Zero();
    for (int a = 0; a < 3; ++a) F += y.segment<3>(3 * a) * grad_N[a].transpose();
    return F;
  };
  auto energy = [&](const Eigen::VectorXd& y) {
    const Mat32 F = F_of(y);
    return area * law->energy(F.transpose() * F);
  };
  auto gradient = [&](const Eigen::VectorXd& y, Eigen::MatrixXd* K) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(9);
    add_membrane_point(*law, grad_N, F_of(y), area, g, K);
    return g;
  };
  // The state is wrinkled: the relaxed energy is below the law's own (measured 0.915 of it).
  const Mat32 F = F_of(x);
  ASSERT_LT(law->energy(F.transpose() * F),
            0.95 * make_material_law("linear biot", fabric)->energy(F.transpose() * F));
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(9, 9);
  const Eigen::VectorXd g = gradient(x, &K);
  Eigen::VectorXd g_fd(9);
  Eigen::MatrixXd K_fd(9, 9);
  const double h = 1e-8;
  for (int j = 0; j < 9; ++j) {
    Eigen::VectorXd xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    g_fd[j] = (energy(xp) - energy(xm)) / (2 * h);
    K_fd.col(j) = (gradient(xp, nullptr) - gradient(xm, nullptr)) / (2 * h);
  }
  // Central differences with h = 1e-8 m on 1 cm edges: truncation and rounding near 1e-8
  // relative; 1e-6 leaves the margin.
  EXPECT_LT((g - g_fd).norm(), 1e-6 * g.norm());
  EXPECT_LT((K - K_fd).norm(), 1e-6 * K.norm());
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
}

}  // namespace
}  // namespace tightfit
