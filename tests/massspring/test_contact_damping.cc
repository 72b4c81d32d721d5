// The contact spring's normal damper (Mass spring/Contact normal damping ratio): a particle
// pushed into a plane oscillates about its penalty depth as the damped oscillator
// m g'' + c g' + kA g = -F does, with c = 2 zeta sqrt(kA m); the damper leaves the stable
// state of a tube on a cylinder where it was (it acts on velocities only) and a slide along
// the body undamped.
#include "bodies/plane.h"
#include "contact/penalty_contact.h"
#include "massspring/damped_rk4.h"
#include "massspring/massspring_backend.h"
#include "massspring/stable_time_step.h"
#include "test_meshes.h"
#include "tube_on_cylinder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tightfit {
namespace {

// One particle of mass m on the plane z = 0, pushed down by F, starting on the surface at
// rest; integrated by the backend's RK4 with the contact force kA (-g) n and the damper.
struct PressedParticle {
  double mass_kg = 2e-5, penalty_N_per_m = 5e3, push_N = 0.04;
  Plane plane{Vec3::Zero(), Vec3::UnitZ()};
  double omega() const { return std::sqrt(penalty_N_per_m / mass_kg); }
  double depth_m() const { return push_N / penalty_N_per_m; }

  // Heights z(t) at every frame of dt = 0.02 / omega over `periods` undamped periods.
  std::vector<double> heights(double damping_ratio, double periods) const {
    const double c = contact_damper_N_s_per_m(damping_ratio, penalty_N_per_m, mass_kg);
    std::vector<Vec3> x{Vec3::Zero()}, v{Vec3::Zero()};
    const std::vector<double> mass{mass_kg};
    const double dt = 0.02 / omega();
    DampedRk4 rk4;
    std::vector<double> z;
    const int frames = int(periods * 2 * M_PI / 0.02);
    for (int frame = 0; frame <= frames; ++frame) {
      z.push_back(x[0].z());
      rk4.frame(
          x, v, mass, dt, 0.0,
          [&](const std::vector<Vec3>& xs, const std::vector<Vec3>& vs, std::vector<Vec3>& force) {
            const SurfacePoint s = plane.query(xs[0]);
            force[0] = penalty_force_N(s, penalty_N_per_m, 1.0) - push_N * Vec3::UnitZ();
            if (s.signed_distance_m < 0)
              force[0] -= c * s.outward_normal.dot(vs[0]) * s.outward_normal;
            return 0.0;
          });
    }
    return z;
  }
};

TEST(ContactNormalDamping, UnderdampedDecayMatchesTheLogarithmicDecrement) {
  // zeta = 0.2: successive deepest points, measured from the penalty depth F / kA, shrink by
  // exp(-2 pi zeta / sqrt(1 - zeta^2)) = 0.2773 a damped period 2 pi / (omega sqrt(1 -
  // zeta^2)). The particle starts on the surface at rest and never rises above it again.
  const PressedParticle p;
  const double zeta = 0.2;
  const std::vector<double> z = p.heights(zeta, 3.0);
  std::vector<int> deepest;  // frames of the local minima
  for (std::size_t i = 1; i + 1 < z.size(); ++i)
    if (z[i] < z[i - 1] && z[i] <= z[i + 1]) deepest.push_back(int(i));
  ASSERT_GE(deepest.size(), 2u);
  const double excursion0 = -z[deepest[0]] - p.depth_m(), excursion1 = -z[deepest[1]] - p.depth_m();
  const double expected = std::exp(-2 * M_PI * zeta / std::sqrt(1 - zeta * zeta));
  // A frame is 0.02 / omega: the sampled minimum misses the true one by (0.01)^2 / 2 of the
  // excursion at most, 5e-5; measured 1.6e-6 apart.
  EXPECT_NEAR(excursion1 / excursion0, expected, 1e-4 * expected);
  const double period_frames = 2 * M_PI / std::sqrt(1 - zeta * zeta) / 0.02;
  EXPECT_NEAR(deepest[1] - deepest[0], period_frames, 1.0);
  for (double height : z) EXPECT_LE(height, 1e-15);
}

TEST(ContactNormalDamping, CriticalDampingApproachesTheDepthWithoutOvershoot) {
  // zeta = 1: g(t) + F / kA = (F / kA)(1 + omega t) e^(-omega t), monotone to the depth.
  const PressedParticle p;
  const std::vector<double> z = p.heights(1.0, 2.0);
  for (std::size_t i = 0; i < z.size(); ++i) {
    const double omega_t = 0.02 * double(i);
    const double expected = -p.depth_m() + p.depth_m() * (1 + omega_t) * std::exp(-omega_t);
    // The first frame starts on the contact's kink (g = 0: its first stage feels no spring),
    // an error of about (omega dt)^2 / 8 = 5e-5 of the depth, which the frames after carry on
    // (RK4's own error at omega dt = 0.02 is of order (omega dt)^4); measured 4.9e-5 of it.
    EXPECT_NEAR(z[i], expected, 1e-4 * p.depth_m()) << "frame " << i;
    EXPECT_GE(z[i], -p.depth_m() * (1 + 1e-12));
  }
}

TEST(ContactNormalDamping, DamperTimeStepIsRk4sRealStabilityLimit) {
  // RK4's amplification of v' = -r v over a step dt, R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24
  // with z = -r dt, is 1 at the limit: the step returned at safety 1 sits on it, a step 1 %
  // longer grows the velocity. The largest rate c / m rules; no damper, no limit.
  auto amplification = [](double z) {
    return 1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24;
  };
  const std::vector<double> damper{0.2, 0.5, 0.1}, mass{1e-5, 1e-5, 2e-5};
  const double rate = 0.5 / 1e-5;
  const double dt = damper_time_step_s(damper, mass, 1.0);
  EXPECT_NEAR(amplification(-rate * dt), 1.0, 1e-4);
  EXPECT_GT(std::abs(amplification(-rate * dt * 1.01)), 1.0);
  EXPECT_DOUBLE_EQ(damper_time_step_s(damper, mass, 0.9), 0.9 * dt);
  EXPECT_TRUE(std::isinf(damper_time_step_s({0.0, 0.0, 0.0}, mass, 0.9)));
  // The coefficient: 2 zeta sqrt(kA m).
  EXPECT_DOUBLE_EQ(contact_damper_N_s_per_m(1.0, 4e3, 1e-4), 2.0 * std::sqrt(0.4));
}

// The tube of the paper's garment T settled on the cylinder at alpha 1.3 (plain penalty, so its
// depth stays in the state) without a damper and with one at zeta 1 (`set_damper` puts it in
// the parameters), with friction `mu` (its tangential penalty as stiff as the normal one):
// the ratio of the total contact forces and the largest distance between the two states.
struct DamperComparison {
  double force_ratio = 0.0, largest_shift_m = 0.0;
};
DamperComparison settle_with_and_without(void (*set_damper)(MassSpringParameters&, double),
                                         double mu, const char* name) {
  auto settle = [&](double zeta) {
    test::TubeOnCylinder tube(0.157, MeshSpacing{});
    tube.cylinder.set_radius(1.3 * tube.rest_radius_m());
    tube.problem.friction_coefficient = mu;
    tube.problem.tangential_stiffness_Pa_per_m = tube.problem.contact_stiffness_Pa_per_m;
    MassSpringParameters parameters;
    parameters.contact_updates = 0;
    set_damper(parameters, zeta);
    MassSpringBackend backend(tube.problem, parameters);
    backend.set_positions(tube.start_positions());
    const StepReport report = backend.solve(LoadStep{0, 1.3, false});
    return std::make_pair(backend.state(), report);
  };
  const auto [plain, plain_report] = settle(0.0);
  const auto [damped, damped_report] = settle(1.0);
  EXPECT_EQ(plain.size(), damped.size());
  double total_plain_N = 0.0, total_damped_N = 0.0;
  DamperComparison c;
  for (std::size_t v = 0; v < plain.size() && v < damped.size(); ++v) {
    total_plain_N += plain.contact_force_N[v].norm();
    total_damped_N += damped.contact_force_N[v].norm();
    c.largest_shift_m =
        std::max(c.largest_shift_m, (plain.positions_m[v] - damped.positions_m[v]).norm());
  }
  c.force_ratio = total_damped_N / total_plain_N;
  std::printf("frames: plain %d, %s zeta 1: %d; total contact force %.9g / %.9g N\n",
              plain_report.iterations, name, damped_report.iterations, total_plain_N,
              total_damped_N);
  return c;
}

TEST(ContactNormalDamping, LeavesTheStableStateOfATubeOnACylinder) {
  // The damper acts on velocities only: the tube settles on the cylinder to the same positions
  // and contact forces with it as without.
  const DamperComparison c = settle_with_and_without(
      [](MassSpringParameters& p, double zeta) { p.contact_normal_damping_ratio = zeta; }, 0.0,
      "contact damper");
  // Both within the stop rule of one equilibrium: a residual of 1e-4 Y h^2 / L against a
  // vertex's contact force of about 0.1 N (ContactMultipliersRemoveThePenaltyFromThePressure).
  EXPECT_NEAR(c.force_ratio, 1.0, 1.4e-4);
  EXPECT_LT(c.largest_shift_m, 1e-5);
}

// The friction spring's stick damper (Mass spring/Contact stick damping ratio) acts on the
// velocities of sticking vertices only: the tube held on the cylinder by friction settles to
// the same positions and contact forces with it (zeta 1) as without.
TEST(ContactStickDamping, LeavesTheStableStateOfATubeHeldByFriction) {
  const DamperComparison c = settle_with_and_without(
      [](MassSpringParameters& p, double zeta) { p.contact_stick_damping_ratio = zeta; }, 0.3,
      "stick damper");
  // The same bounds as the normal damper's test: two states within the stop rule of one
  // equilibrium (measured 8.7e-5 apart in the total contact force; friction lets the two paths
  // stop at slightly different anchors).
  EXPECT_NEAR(c.force_ratio, 1.0, 1.4e-4);
  EXPECT_LT(c.largest_shift_m, 1e-5);
}

}  // namespace
}  // namespace tightfit
