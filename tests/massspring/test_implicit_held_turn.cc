// The implicit route with the held turn (Constraints/Held groups = all: every vertex held along
// the axis, the garment's mean turn about it held too, core/held_turn.h). Its Newton increments
// are kept normal to the turn's mode w_i = m_i a x (x_i - c) (static_newton.h), its residual has
// the turn's reaction removed: the stiffness restricted to turn-free increments must be the
// derivative of that residual, and the held tube must reach the closed form and RK4's state.
#include "massspring/massspring_backend.h"
#include "tube_on_cylinder.h"

#include "core/constrained_directions.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <random>

namespace tightfit {
namespace {

// The tube held along the cylinder's axis at every vertex.
void hold_every_vertex(test::TubeOnCylinder& tube) {
  tube.problem.constraints.push_back(held_along(tube.mesh, "all", Vec3::UnitZ()));
}

// v - w (u . v) / (w . u): removes from a force field the turn's reaction, as HeldTurn does
// (u_i = a x (x_i - c), w_i = m_i u_i).
Eigen::VectorXd without_turn_reaction(const Eigen::VectorXd& v, const Eigen::VectorXd& w,
                                      const Eigen::VectorXd& u) {
  return v - w * (u.dot(v) / w.dot(u));
}

TEST(MassSpringImplicitHeldTurn, StiffnessIsTheDerivativeOfTheResidualWithTheTurnRemoved) {
  // The tube of test_stiffness.cc's finite-difference check, every vertex held along z, on a
  // cylinder 1.2 times its rest radius, moved at random radially (half of it into contact) and
  // along the surface. Directions: random, with no axial part (held) and no turn (w^T d = 0),
  // the increments StaticNewton makes. Compared: -K d and the central difference of the
  // residual along d, both without the turn's reaction (what the Newton system solves for).
  test::TubeOnCylinder tube(0.06, MeshSpacing{0.01, 0.06}, 0.3);
  tube.cylinder.set_radius(1.2 * tube.rest_radius_m());
  hold_every_vertex(tube);
  MassSpringParameters parameters;
  parameters.bending_rigidity_N_m = 0.0;
  // The exact tangent (the projected one drops the contact's curvature term).
  parameters.implicit_tangent = ImplicitTangent::exact;
  MassSpringBackend backend(tube.problem, parameters);
  std::vector<Vec3> x = tube.start_positions();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  int inside = 0;
  for (Vec3& p : x) {
    const double s = uniform(random);
    const Vec3 radial = Vec3(p.x(), p.y(), 0.0).normalized();
    p += (s < 0 ? -1.0 : 1.0) * (1e-4 + 2e-4 * std::abs(s)) * radial;
    p += 2e-3 * uniform(random) * Vec3::UnitZ().cross(radial);
    inside += s < 0;
  }
  ASSERT_GT(inside, 0);
  ASSERT_LT(inside, static_cast<int>(x.size()));
  const int n = static_cast<int>(x.size());
  Eigen::VectorXd w;
  backend.held_turn_mode(x, w);
  Eigen::VectorXd u = w;
  for (int i = 0; i < n; ++i) u.segment<3>(3 * i) /= backend.masses_kg()[i];
  SparseMatrix K;
  backend.stiffness(x, K);
  const double h_m = 1e-7;
  double largest_error = 0.0, largest = 0.0;
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd d(3 * n);
    for (int i = 0; i < n; ++i) d.segment<3>(3 * i) = Vec3(uniform(random), uniform(random), 0.0);
    d -= u * (w.dot(d) / w.dot(u));  // turn-free; u has no axial part either
    ASSERT_NEAR(w.dot(d), 0.0, 1e-12 * w.norm() * d.norm());
    std::vector<Vec3> plus = x, minus = x, f_plus(n), f_minus(n);
    for (int i = 0; i < n; ++i) {
      plus[i] += h_m * d.segment<3>(3 * i);
      minus[i] -= h_m * d.segment<3>(3 * i);
    }
    backend.residual_forces(plus, false, f_plus);
    backend.residual_forces(minus, false, f_minus);
    Eigen::VectorXd fd(3 * n);
    for (int i = 0; i < n; ++i) fd.segment<3>(3 * i) = -(f_plus[i] - f_minus[i]) / (2 * h_m);
    const Eigen::VectorXd Kd = without_turn_reaction(K * d, w, u);
    fd = without_turn_reaction(fd, w, u);
    largest_error = std::max(largest_error, (Kd - fd).cwiseAbs().maxCoeff());
    largest = std::max(largest, Kd.cwiseAbs().maxCoeff());
  }
  // Measured 8.0e-7 relative, the same at h = 1e-6, 1e-7 and 1e-8 m (so not the differences'
  // truncation or round-off: the reaction's own derivative, which the symmetric matrix leaves
  // out); bound 1e-5. Compared without removing the turn's reaction the two differ by 9e-5.
  EXPECT_LT(largest_error / largest, 1e-5);
}

struct HeldTube {
  double mean_pressure_Pa = 0.0;
  std::vector<Vec3> positions_m;
  int iterations = 0;
};

HeldTube settle_held_tube(Integrator integrator, double alpha, int contact_set_predictions = 0) {
  // Garment T's width on the paper's coarse spacing, Poisson ratio 0: Eq. 7 holds on it.
  test::TubeOnCylinder tube(0.157, MeshSpacing{0.008, 0.022});
  tube.cylinder.set_radius(alpha * tube.rest_radius_m());
  hold_every_vertex(tube);
  MassSpringParameters parameters;
  parameters.integrator = integrator;
  parameters.contact_set_predictions = contact_set_predictions;
  MassSpringBackend backend(tube.problem, parameters);
  backend.set_positions(tube.start_positions());
  const StepReport report = backend.solve(LoadStep{0, alpha, false});
  const SurfaceState s = backend.state();
  HeldTube out;
  out.iterations = report.iterations;
  out.positions_m = s.positions_m;
  double force_N = 0.0;
  for (std::size_t v = 0; v < s.size(); ++v) force_N += s.contact_force_N[v].norm();
  out.mean_pressure_Pa =
      force_N / (2 * M_PI * tube.cylinder.radius_m() * test::TubeOnCylinder::height_m);
  return out;
}

TEST(MassSpringImplicitHeldTurn, HeldTubeReachesLaplacesPressureAndRk4sState) {
  const double alpha = 1.3;
  const HeldTube implicit = settle_held_tube(Integrator::implicit, alpha);
  const HeldTube rk4 = settle_held_tube(Integrator::rk4, alpha);
  test::TubeOnCylinder reference(0.157, MeshSpacing{0.008, 0.022});
  // Laplace's law for the hoop tension of Eq. 7 (p = T / r, T = Y (1 - 1/alpha) r / R0). The
  // tube is a polygon of about 39 sides inscribed in the cylinder: its hoop stretch and the
  // force it turns into pressure both fall short by (pi/N)^2 / 6, so the mean reads low by
  // about (pi/N)^2 / 6 (1 / (alpha - 1) + 1) = 4.7e-3; measured -5.46e-3 on both routes.
  // One-sided: never high, and within 1.5 times the estimate.
  const double ratio = implicit.mean_pressure_Pa / reference.eq7_pressure_Pa(alpha);
  EXPECT_LT(ratio, 1.0);
  EXPECT_GT(ratio, 1.0 - 1.5 * 4.7e-3);
  // The same equilibrium as RK4's within the stop rule's bound: it leaves each state within
  // 1.4e-4 of the contact force (test_cylinder_pressure.cc), so the two within 2.8e-4;
  // measured 7.7e-5.
  EXPECT_NEAR(implicit.mean_pressure_Pa / rk4.mean_pressure_Pa, 1.0, 2.8e-4);
  // Neither route turns the tube about the axis: the mean angle of the vertices the same,
  // measured 1.5e-17 rad (a free turn left by the increments would show as the angle the
  // stop rule allows, 1e-4 of the strain over the radius, about 1e-6 rad); bound 1e-9 rad.
  ASSERT_EQ(implicit.positions_m.size(), rk4.positions_m.size());
  double turn_rad = 0.0;
  for (std::size_t v = 0; v < rk4.positions_m.size(); ++v) {
    const Vec3 &a = implicit.positions_m[v], &b = rk4.positions_m[v];
    turn_rad += std::remainder(std::atan2(a.y(), a.x()) - std::atan2(b.y(), b.x()), 2 * M_PI);
  }
  EXPECT_LT(std::abs(turn_rad / double(rk4.positions_m.size())), 1e-9);
  EXPECT_GT(implicit.iterations, 0);
  // With the contact set predicted (Contact set predictions) the same equilibrium, to the stop
  // rule's bound.
  const HeldTube predicted = settle_held_tube(Integrator::implicit, alpha, 3);
  EXPECT_NEAR(predicted.mean_pressure_Pa / rk4.mean_pressure_Pa, 1.0, 2.8e-4);
}

}  // namespace
}  // namespace tightfit
