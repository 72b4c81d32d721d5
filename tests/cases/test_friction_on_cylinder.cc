// A tube on a growing cylinder with Coulomb friction, on both backends. The tube (linear Biot,
// Poisson ratio 0.2021, free ends) starts touching the cylinder at its rest radius (alpha 1)
// and the cylinder grows to alpha 1.3. The growing body carries each vertex's anchor outwards
// (contact/coulomb_friction.h), so:
//   mu = 0:      nothing holds the tube along the axis; it contracts as its Poisson ratio asks,
//                to the free-end axial stretch b(alpha) of the closed form, and reads the
//                free-end pressure;
//   mu = 10:     friction holds every vertex at its anchor's axial place: b stays 1, the
//                held-end closed form (docs/model.md, "Closed forms"). The end rows carry the
//                axial force the held tube needs (about 8 N/m at alpha 1.3) over half a row
//                (7.5 mm) against a pressure of about 600 Pa: a friction coefficient above
//                about 2 holds them, 10 with room;
// and for any mu no vertex's friction traction exceeds mu times its normal traction. The
// backends apply the same law and must agree.
#include "cases/cylinder_theory.h"
#include "tests/cases/body_case.h"

#include <cmath>

namespace tightfit {
namespace {

using testing::run_body_case;
using testing::setting;

const double kPanelWidth = 0.157;
const double kRestRadius = 2 * kPanelWidth / (2 * M_PI);
const double kHeight = 0.06;
const double kAlpha = 1.3;

std::vector<std::string> tube_settings(double mu) {
  return {"Garment/Name=T",
          setting("Garment/Tube/Panel width", kPanelWidth),
          setting("Garment/Tube/Panel height", kHeight),
          "Garment/Edge length weft=0.008",
          "Garment/Edge length warp=0.015",
          "Material/Law=linear biot",
          "Material/Stiffness weft=130",
          "Material/Stiffness warp=70",
          "Material/Poisson ratio weft-warp=0.2021",
          "Body/Kind=cylinder",
          "Body/Cylinder/Axis=0,0,1",
          setting("Body/Cylinder/Initial radius", kRestRadius),
          "Protocol/Alpha increment=0.1",
          setting("Protocol/Final alpha", kAlpha),
          setting("Contact/Friction coefficient", mu)};
}

FabricParameters fabric() {
  CaseFile file;
  for (const std::string& s : tube_settings(0.0)) file.set(s);
  return file.parameters().fabric;
}

struct Reading {
  double p_mean_Pa = 0.0;
  double largest_axial_move_m = 0.0;    // of any vertex from its start
  double largest_friction_ratio = 0.0;  // friction traction / (mu normal traction)
  std::string detail;
};

Reading tube_on_cylinder(const std::string& backend, double mu) {
  const testing::BodyCaseRun r = run_body_case(tube_settings(mu), backend);
  EXPECT_TRUE(r.run.completed) << r.run.failure << "\n" << r.log;
  Reading reading;
  if (r.run.steps.empty()) return reading;
  const StepMeasurement& m = r.last();
  EXPECT_NEAR(m.alpha, kAlpha, 1e-12);
  EXPECT_EQ(m.summary.contact_fraction, 1.0);
  reading.p_mean_Pa = m.p_mean_Pa();
  for (std::size_t v = 0; v < m.state.positions_m.size(); ++v) {
    reading.largest_axial_move_m = std::max(
        reading.largest_axial_move_m, std::abs(m.state.positions_m[v].z() - r.start_m[v].z()));
    if (mu > 0 && m.field.contact[v] && m.field.pressure_Pa[v] > 0)
      reading.largest_friction_ratio =
          std::max(reading.largest_friction_ratio,
                   m.field.friction_traction_Pa[v] / (mu * m.field.pressure_Pa[v]));
  }
  reading.detail = m.report.text();
  return reading;
}

double closed_form_Pa(EndCondition ends) {
  return closed_form_pressure_Pa("linear biot", ends, fabric(), kRestRadius, kAlpha);
}

// How far the free-end tube's end rows contract along the axis from alpha 1, m.
double free_end_move_m() {
  return (1 - axial_stretch("linear biot", EndCondition::free_ends, fabric(), kAlpha)) * kHeight /
         2;
}

class FrictionOnGrowingCylinder : public ::testing::TestWithParam<const char*> {};

TEST_P(FrictionOnGrowingCylinder, FrictionlessTubeContractsLikeFreeEnds) {
  const Reading r = tube_on_cylinder(GetParam(), 0.0);
  const double p_free = closed_form_Pa(EndCondition::free_ends);
  const double end_move = free_end_move_m();
  std::printf(
      "%s, mu 0: p %.4f Pa (free ends %.4f, %+.2e), end rows moved %.4e m (free ends "
      "%.4e)\n",
      GetParam(), r.p_mean_Pa, p_free, r.p_mean_Pa / p_free - 1, r.largest_axial_move_m, end_move);
  // Linear triangles inscribe a 40-sided polygon: the hoop stretch is under-read by
  // (pi/40)^2 / 6 = 1.0e-3, the pressure by about 4.4 times that with this law at alpha 1.3.
  // Measured -4.80e-3 (mass spring) and -4.74e-3 (fem); one-sided, bound 1.25 times. The end
  // rows: measured 0.4% short of the closed form's contraction; within 2%.
  EXPECT_LT(r.p_mean_Pa / p_free - 1, 0.0);
  EXPECT_GT(r.p_mean_Pa / p_free - 1, -6e-3);
  EXPECT_NEAR(r.largest_axial_move_m, end_move, 0.02 * end_move);
}

TEST_P(FrictionOnGrowingCylinder, LargeFrictionHoldsTheTubeLikeHeldEnds) {
  const double mu = 10.0;
  const Reading r = tube_on_cylinder(GetParam(), mu);
  const double p_held = closed_form_Pa(EndCondition::held_ends);
  const double free_end_move = free_end_move_m();
  std::printf(
      "%s, mu %.0f: p %.4f Pa (held ends %.4f, %+.2e), largest axial move %.2e m (free "
      "ends %.2e), friction / (mu p) at most %.4f\n%s\n",
      GetParam(), mu, r.p_mean_Pa, p_held, r.p_mean_Pa / p_held - 1, r.largest_axial_move_m,
      free_end_move, r.largest_friction_ratio, r.detail.c_str());
  // The same polygon error (measured -4.44e-3 and -4.27e-3; the free-end pressure is 4% above
  // this one, so the test tells them apart); the vertices stay put but for the tangential
  // penalty's creep (measured 7.5e-6 and 7.1e-6 m, 0.4% of the free ends' contraction); every
  // vertex sticks, far inside the cone (measured 0.072 mu p at most).
  EXPECT_LT(r.p_mean_Pa / p_held - 1, 0.0);
  EXPECT_GT(r.p_mean_Pa / p_held - 1, -6e-3);
  EXPECT_LT(r.largest_axial_move_m, 0.01 * free_end_move);
  EXPECT_LE(r.largest_friction_ratio, 1.0 + 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Backends, FrictionOnGrowingCylinder,
                         ::testing::Values("massspring", "fem"));

// Friction that holds part of the way (mu 0.3, the end rows slip): the backends against each
// other, and the cone bound on each.
TEST(FrictionOnGrowingCylinderBackends, PartialSlipAgrees) {
  const double mu = 0.3;
  const Reading ms = tube_on_cylinder("massspring", mu);
  const Reading fe = tube_on_cylinder("fem", mu);
  std::printf(
      "mu %.1f: p mass-spring %.4f Pa, fem %.4f Pa (%+.2e); largest axial move %.4e / "
      "%.4e m; friction / (mu p) at most %.4f / %.4f\n%s\n",
      mu, ms.p_mean_Pa, fe.p_mean_Pa, fe.p_mean_Pa / ms.p_mean_Pa - 1, ms.largest_axial_move_m,
      fe.largest_axial_move_m, ms.largest_friction_ratio, fe.largest_friction_ratio,
      fe.detail.c_str());
  // Measured: pressures 1.66e-4 apart (the mass-spring stop rule's strain error is 1e-4),
  // the largest axial moves (5.38e-4 m, the end rows slip) 1.9e-4 apart; bounds 6 and 50 times.
  EXPECT_NEAR(fe.p_mean_Pa / ms.p_mean_Pa - 1, 0.0, 1e-3);
  EXPECT_NEAR(fe.largest_axial_move_m, ms.largest_axial_move_m, 0.01 * ms.largest_axial_move_m);
  EXPECT_LE(fe.largest_friction_ratio, 1.0 + 1e-6);
  EXPECT_LE(ms.largest_friction_ratio, 1.0 + 1e-6);
}

}  // namespace
}  // namespace tightfit
