// A tight tube on a cone (axis +z, widening upwards), with and without Coulomb friction.
//
// Where the tube presses on the cone with normal force N per vertex, the contact force has an
// axial component -N sin(a) towards the narrow end (a the half-angle); with no axial membrane
// force (free ends, nu = 0), the vertex stays only if friction supplies f = N tan(a) along the
// surface, so the tube holds where tan(a) <= mu and slides towards the apex otherwise, until it
// hangs loose. A tube that slides goes on until the cone's radius at its upper end is about R0:
// a distance (r(top) - R0) / tan(a) from the start, 3.2 cm here; the stop rule ends the slide
// in its slow tail, before that (measured: 0.93 of it without friction, 0.75 with mu = 0.8
// tan(a), at the relative tolerance 1e-3 used below), so a sliding tube must have gone half of
// it and come partly loose, while a holding one moves less than a tenth of it (measured 0.82 mm:
// it settles onto the cone from its start 1% outside). Checked on both sides of the threshold
// (mu = 0.8 and 1.25 tan(a)), the friction traction of the holding tube against N tan(a), and
// the regularisation: a tangential penalty ten times stiffer changes nothing that matters.
//
// The tube (garment T's circumference, 3 cm long, 20 vertices round by 3 along) is coarse
// so that the slide, about 3 cm of damped motion, is quick.
#include "tests/cases/body_case.h"

#include <cmath>

namespace tightfit {
namespace {

using testing::run_body_case;
using testing::setting;

const double kRestRadius = 2 * 0.157 / (2 * M_PI);
const double kTanHalfAngle = 0.3;
const double kHeight = 0.03;
const double kRadiusAtCentre = 1.1 * kRestRadius;  // the tube's middle; 1.01 to 1.19 R0 along it
const Vec3 kAxis = Vec3::UnitZ();

// The least slide of a tube that does not hold: until the cone at its upper end is R0 wide.
double slide_off_m() {
  return (kRadiusAtCentre + 0.5 * kHeight * kTanHalfAngle - kRestRadius) / kTanHalfAngle;
}

// `relative_tolerance` loosens the mass-spring stop rule for the tubes that slide: the last
// part of their way, as they come loose, is a slow tail of vanishing force, and the test only
// needs their position to a few percent.
testing::BodyCaseRun tube_on_cone(const std::string& backend, double mu,
                                  double tangential_ratio = 1.0, double relative_tolerance = 1e-4,
                                  int contact_set_predictions = 0, double tangent_shift = 0.0,
                                  int element_degree = 1) {
  const double start_radius = 1.01 * (kRadiusAtCentre + 0.5 * kHeight * kTanHalfAngle);
  return run_body_case({setting("Finite elements/Contact set predictions", contact_set_predictions),
                        setting("Finite elements/Element degree", element_degree),
                        setting("Finite elements/Tangent shift", tangent_shift),
                        "Garment/Name=T",
                        "Garment/Tube/Panel width=0.157",
                        setting("Garment/Tube/Panel height", kHeight),
                        "Garment/Edge length weft=0.0157",
                        "Garment/Edge length warp=0.015",
                        "Material/Law=linear biot",
                        "Material/Poisson ratio weft-warp=0",
                        "Body/Kind=cone",
                        "Body/Cone/Axis point=0,0,0",
                        "Body/Cone/Axis=0,0,1",
                        setting("Body/Cone/Radius at axis point", kRadiusAtCentre),
                        setting("Body/Cone/Half angle", std::atan(kTanHalfAngle) * 180 / M_PI),
                        "Placement/Kind=tube round axis",
                        "Placement/Tube round axis/Centre=0,0,0",
                        setting("Placement/Tube round axis/Radius", start_radius),
                        "Protocol/Final alpha=1",
                        setting("Contact/Friction coefficient", mu),
                        setting("Contact/Tangential penalty ratio", tangential_ratio),
                        setting("Solver/Relative tolerance", relative_tolerance)},
                       backend);
}

// The friction forces over the normal forces, summed over the vertices in contact.
double friction_over_normal_force(const StepMeasurement& m) {
  double friction_N = 0.0, normal_N = 0.0;
  for (std::size_t v = 0; v < m.field.pressure_Pa.size(); ++v)
    if (m.field.contact[v]) {
      friction_N += m.field.friction_traction_Pa[v] * m.field.vertex_area_m2[v];
      normal_N += m.field.normal_force_N[v];
    }
  return friction_N / normal_N;
}

class TubeOnCone : public ::testing::TestWithParam<const char*> {};

TEST_P(TubeOnCone, FrictionlessTubeSlidesOffTheNarrowEnd) {
  const testing::BodyCaseRun r = tube_on_cone(GetParam(), 0.0, 1.0, 1e-3);
  ASSERT_TRUE(r.run.completed) << r.run.failure << "\n" << r.log;
  const double shift = r.mean_shift_m(kAxis);
  std::printf("%s, mu 0: shift %.4f m (slide-off %.4f m), contact fraction %.3f\n", GetParam(),
              shift, slide_off_m(), r.last().summary.contact_fraction);
  // Measured -0.93 slide-off (the stop rule ends the slow tail as it comes loose); -0.8.
  EXPECT_LT(shift, -0.8 * slide_off_m());
  // Loose but for the ring at the narrow end: measured 1/3 (one ring of three touches).
  EXPECT_LT(r.last().summary.contact_fraction, 0.5);
}

// The tubes that hold have an equilibrium on the cone, which both backends reach; those that
// slide off end loose, with no equilibrium in contact: only the mass-spring backend's damped
// dynamics follows them (the FE backend's Newton stops with a failed solve).
class TubeHoldingOnCone : public ::testing::TestWithParam<const char*> {};

TEST_P(TubeHoldingOnCone, HoldsWhenTanHalfAngleIsBelowMu) {
  const testing::BodyCaseRun r = tube_on_cone(GetParam(), 1.25 * kTanHalfAngle);
  ASSERT_TRUE(r.run.completed) << r.run.failure << "\n" << r.log;
  const double shift = r.mean_shift_m(kAxis);
  const StepMeasurement& m = r.last();
  // The axial balance of the whole tube: with no axial membrane force at its free ends, the
  // friction forces (all up the meridian) add up to tan(a) times the normal forces.
  const double friction_ratio = friction_over_normal_force(m);
  std::printf(
      "%s, mu %.3f: shift %.2e m, contact fraction %.3f, friction / normal force %.5f "
      "(tan a %.3f)\n",
      GetParam(), 1.25 * kTanHalfAngle, shift, m.summary.contact_fraction, friction_ratio,
      kTanHalfAngle);
  EXPECT_LT(std::abs(shift), 0.1 * slide_off_m());
  EXPECT_EQ(m.summary.contact_fraction, 1.0);
  EXPECT_NEAR(friction_ratio, kTanHalfAngle, 1e-3 * kTanHalfAngle);
}

TEST_P(TubeOnCone, SlidesWhenTanHalfAngleIsAboveMu) {
  const testing::BodyCaseRun r = tube_on_cone(GetParam(), 0.8 * kTanHalfAngle, 1.0, 1e-3);
  ASSERT_TRUE(r.run.completed) << r.run.failure << "\n" << r.log;
  const double shift = r.mean_shift_m(kAxis);
  std::printf("%s, mu %.3f: shift %.4f m (slide-off %.4f m), contact fraction %.3f\n", GetParam(),
              0.8 * kTanHalfAngle, shift, slide_off_m(), r.last().summary.contact_fraction);
  // Measured -0.75 slide-off: friction slows the tail the stop rule ends; -0.6.
  EXPECT_LT(shift, -0.6 * slide_off_m());
  // Measured 1/3: only the ring at the narrow end still touches.
  EXPECT_LT(r.last().summary.contact_fraction, 0.5);
}

TEST_P(TubeHoldingOnCone, StifferTangentialPenaltyChangesNothing) {
  const testing::BodyCaseRun soft = tube_on_cone(GetParam(), 1.25 * kTanHalfAngle, 1.0);
  const testing::BodyCaseRun stiff = tube_on_cone(GetParam(), 1.25 * kTanHalfAngle, 10.0);
  ASSERT_TRUE(soft.run.completed && stiff.run.completed) << soft.log << stiff.log;
  const double p_soft = soft.last().p_mean_Pa(), p_stiff = stiff.last().p_mean_Pa();
  const double dshift = soft.mean_shift_m(kAxis) - stiff.mean_shift_m(kAxis);
  std::printf("%s: tangential penalty x1 / x10: p %.4f / %.4f Pa, shift difference %.2e m\n",
              GetParam(), p_soft, p_stiff, dshift);
  // Measured: the pressures 7e-5 apart (the stop rule's strain error of 1e-4 is of that order),
  // the positions 2.1e-6 m (the creep mu N / k_t of the softer spring); bounds about 4 times.
  EXPECT_LT(std::abs(p_soft - p_stiff), 3e-4 * p_stiff);
  EXPECT_LT(std::abs(dshift), 1e-5);
}

// The same law on both backends (contact/coulomb_friction.h, the same anchors and
// regularisation): the holding tube's pressure, position and friction against each other.
TEST(TubeOnConeBackends, HoldingTubeAgrees) {
  const double mu = 1.25 * kTanHalfAngle;
  const testing::BodyCaseRun ms = tube_on_cone("massspring", mu);
  const testing::BodyCaseRun fe = tube_on_cone("fem", mu);
  ASSERT_TRUE(ms.run.completed && fe.run.completed) << ms.log << fe.log;
  const double p_ms = ms.last().p_mean_Pa(), p_fe = fe.last().p_mean_Pa();
  const double dshift = ms.mean_shift_m(kAxis) - fe.mean_shift_m(kAxis);
  double largest_friction_ratio = 0.0;  // |friction traction| / (mu normal traction), FE
  const StepMeasurement& m = fe.last();
  for (std::size_t v = 0; v < m.field.pressure_Pa.size(); ++v)
    if (m.field.contact[v] && m.field.pressure_Pa[v] > 0)
      largest_friction_ratio = std::max(
          largest_friction_ratio, m.field.friction_traction_Pa[v] / (mu * m.field.pressure_Pa[v]));
  std::printf(
      "holding tube: p mass-spring %.4f Pa, fem %.4f Pa (%+.2e), shift difference %.2e m, "
      "fem friction / (mu p) at most %.4f\n%s\n",
      p_ms, p_fe, p_fe / p_ms - 1, dshift, largest_friction_ratio, fe.last().report.text().c_str());
  // Measured: the pressures 2.9e-4 apart (the mass-spring stop rule's strain error of 1e-4 and
  // its bending springs), the positions 8.5e-8 m; bounds about 3 and 10 times. No vertex's
  // friction exceeds the cone mu p (the slipping ones sit on it).
  EXPECT_LT(std::abs(p_fe / p_ms - 1), 1e-3);
  EXPECT_LT(std::abs(dshift), 1e-6);
  EXPECT_LE(largest_friction_ratio, 1.0 + 1e-6);
}

// The FE backend's plain Newton steps holding the tube (mu = 1.25 tan(a), Contact set
// predictions = 0: none, where the default with friction predicts each step once), solved once
// for the tests that compare another route to the same equilibrium with them.
const testing::BodyCaseRun& plain_fem_holding_tube() {
  static const testing::BodyCaseRun run = tube_on_cone("fem", 1.25 * kTanHalfAngle);
  return run;
}

// Expects `other` to stop where the plain steps stop: the mean pressure to 1e-8 relative and
// the mean shift along the axis to 1e-10 m, the stop rule's reach (2.3e-10 N on 60 nodes).
void expect_the_plain_steps_holding(const char* route, const testing::BodyCaseRun& other) {
  const testing::BodyCaseRun& plain = plain_fem_holding_tube();
  ASSERT_TRUE(plain.run.completed && other.run.completed) << plain.log << other.log;
  const double p_plain = plain.last().p_mean_Pa(), p_other = other.last().p_mean_Pa();
  const double dshift = plain.mean_shift_m(kAxis) - other.mean_shift_m(kAxis);
  std::printf("fem, plain / %s steps: p %.9f / %.9f Pa, shift difference %.2e m\n%s\n%s\n", route,
              p_plain, p_other, dshift, plain.last().report.text().c_str(),
              other.last().report.text().c_str());
  EXPECT_LT(std::abs(p_other / p_plain - 1), 1e-8);
  EXPECT_LT(std::abs(dshift), 1e-10);
}

// Newton's steps solved on the contact and friction branches they predict
// (fem/contact_set_prediction.h) reach the plain steps' equilibrium: the tube slides onto the
// cone from 1 % outside, every node coming into contact and sticking or slipping at once.
// Measured: the pressures equal to the 9 digits printed, the positions 2e-19 m apart, in 10
// Newton iterations against 12 (without friction in the step's model the predicted steps
// stalled at 2.7e-3 N).
TEST(TubeOnConeBackends, ContactSetPredictionsHoldTheTubeWhereThePlainStepsDo) {
  expect_the_plain_steps_holding("predicted",
                                 tube_on_cone("fem", 1.25 * kTanHalfAngle, 1.0, 1e-4, 1));
}

// A constant shift of the tangent (Finite elements/Tangent shift, beside Newton's adaptive one,
// docs/backends.md) changes Newton's path, not the equilibrium it stops
// at: the residual is never shifted. The holding tube, every node coming into contact and
// sticking or slipping, with a shift of 10 N/m against the plain steps.
// Measured: the pressures 4e-10 apart, the positions 2.5e-12 m, in 40 Newton iterations
// against 12 (the shifted steps converge linearly on this stiff tube until the residual's own
// shift takes over).
TEST(TubeOnConeBackends, TangentShiftHoldsTheTubeWhereThePlainStepsDo) {
  expect_the_plain_steps_holding("shifted-tangent",
                                 tube_on_cone("fem", 1.25 * kTanHalfAngle, 1.0, 1e-4, 0, 10.0));
}

// Friction on quadratic triangles: every node (corners and edge midpoints) carries its own
// anchor and return mapping, and the friction traction is recovered from the nodal forces as
// the normal one is (fem/fem_state.h). The holding tube's axial balance, friction = tan(a)
// times the normal force, then holds for the recovered tractions, and it stops where the linear
// triangles stop.
TEST(TubeOnConeBackends, QuadraticTrianglesHoldTheTubeAsLinearOnesDo) {
  const testing::BodyCaseRun quadratic =
      tube_on_cone("fem", 1.25 * kTanHalfAngle, 1.0, 1e-4, 0, 0.0, 2);
  const testing::BodyCaseRun& linear = plain_fem_holding_tube();
  ASSERT_TRUE(quadratic.run.completed && linear.run.completed) << quadratic.log << linear.log;
  const StepMeasurement& m = quadratic.last();
  const double friction_ratio = friction_over_normal_force(m);
  const double p_quadratic = m.p_mean_Pa(), p_linear = linear.last().p_mean_Pa();
  // Linear triangles inscribe each ring of n = 20 vertices in its circle: the hoop stretch
  // reads lambda s and a vertex feels its chords' force times s, s = sin(pi/n) / (pi/n), so the
  // hoop force Y (lambda - 1) at radius r reads Y (lambda s - 1) s (docs/model.md, "Closed
  // forms"; tests/cases/test_laplace_on_cone.cc). Their ratio, averaged over the quadratic
  // tube's vertices (lambda = r / R0) with the weights of its mean pressure, is what the linear
  // triangles' pressure should read against the quadratic ones'.
  const double n_round = 20, s = std::sin(M_PI / n_round) / (M_PI / n_round);
  double linear_read = 0.0, exact_read = 0.0;
  for (std::size_t v = 0; v < m.state.positions_m.size(); ++v) {
    const Vec3& x = m.state.positions_m[v];
    const double r = std::hypot(x.x(), x.y()), lambda = r / kRestRadius;
    linear_read += m.field.vertex_area_m2[v] * (lambda * s - 1) * s / r;
    exact_read += m.field.vertex_area_m2[v] * (lambda - 1) / r;
  }
  const double polygon_ratio = linear_read / exact_read;
  const double shift = quadratic.mean_shift_m(kAxis);
  std::printf(
      "holding tube, fem quadratic / linear: p %.4f / %.4f Pa, linear / quadratic %.5f against "
      "the polygon's %.5f; shift %.2e m (linear %.2e m), friction / normal force %.5f (tan a "
      "%.3f)\n%s\n",
      p_quadratic, p_linear, p_linear / p_quadratic, polygon_ratio, shift,
      linear.mean_shift_m(kAxis), friction_ratio, kTanHalfAngle, m.report.text().c_str());
  // Measured: 160 nodes in contact, 140 slipping, in 43 Newton iterations; the tube settles
  // 0.65 mm down the cone (linear: 0.82 mm), held as the linear one is.
  EXPECT_EQ(m.summary.contact_fraction, 1.0);
  EXPECT_LT(std::abs(shift), 0.1 * slide_off_m());
  // Measured 0.30088: the nodal forces balance exactly, their recovered tractions summed over
  // the flat vertex areas to 2.9e-3 (the friction traction, largest at the slipping ends, is
  // recovered less smoothly than the pressure); 6e-3 allowed.
  EXPECT_NEAR(friction_ratio, kTanHalfAngle, 6e-3 * kTanHalfAngle);
  // Measured 0.95750 against 0.95268 (the remainder: the meridian's stretch, which friction
  // leaves here and the estimate leaves out, and the two tubes' slightly different places);
  // 1e-2 allowed.
  EXPECT_NEAR(p_linear / p_quadratic, polygon_ratio, 1e-2);
}

INSTANTIATE_TEST_SUITE_P(Backends, TubeOnCone, ::testing::Values("massspring"));
INSTANTIATE_TEST_SUITE_P(Backends, TubeHoldingOnCone, ::testing::Values("massspring", "fem"));

}  // namespace
}  // namespace tightfit
