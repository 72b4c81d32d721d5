// The closed forms (docs/model.md, "Closed forms") against an independent route: the uniform state
// of the tube solved numerically from the material law's own stress (hoop stretch a, axial stretch
// b from zero axial stress or b = 1), then p = n / r with n = a S11 / b the hoop tension per
// current length and r = a R0, so p = S11 / (b R0).
#include "cases/cylinder_theory.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit {
namespace {

double axial_stress(const MaterialLaw& law, double a, double b) {
  Mat2 C = Mat2::Zero();
  C(0, 0) = a * a;
  C(1, 1) = b * b;
  return law.stress(C)(1, 1);
}

// Bisection on S22(a, b) = 0 for b in (0.05, 1.5): the axial stress rises with b.
double free_axial_stretch(const MaterialLaw& law, double a) {
  double lo = 0.05, hi = 1.5;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (axial_stress(law, a, mid) > 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

double pressure_from_law(const MaterialLaw& law, EndCondition ends, double R0, double a) {
  const double b = ends == EndCondition::held_ends ? 1.0 : free_axial_stretch(law, a);
  Mat2 C = Mat2::Zero();
  C(0, 0) = a * a;
  C(1, 1) = b * b;
  return law.stress(C)(0, 0) / (b * R0);
}

struct Case {
  std::string law;
  EndCondition ends;
};

class ClosedForm : public ::testing::TestWithParam<Case> {};

TEST_P(ClosedForm, MatchesTheUniformStateOfTheLaw) {
  FabricParameters fabric;
  fabric.poisson_weft_warp = 0.3;  // a Poisson coupling, so the end condition matters
  const auto law = make_material_law(GetParam().law, fabric);
  const double R0 = 0.0598;
  for (double a : {1.05, 1.2, 1.5, 1.8}) {
    const double expected = pressure_from_law(*law, GetParam().ends, R0, a);
    const double closed = closed_form_pressure_Pa(GetParam().law, GetParam().ends, fabric, R0, a);
    EXPECT_NEAR(closed, expected, 1e-9 * expected) << "alpha " << a;
    if (GetParam().ends == EndCondition::free_ends) {
      EXPECT_NEAR(axial_stretch(GetParam().law, GetParam().ends, fabric, a),
                  free_axial_stretch(*law, a), 1e-9);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(SixClosedForms, ClosedForm,
                         ::testing::Values(Case{"linear biot", EndCondition::free_ends},
                                           Case{"linear biot", EndCondition::held_ends},
                                           Case{"st venant kirchhoff", EndCondition::free_ends},
                                           Case{"st venant kirchhoff", EndCondition::held_ends},
                                           Case{"neo hookean", EndCondition::free_ends},
                                           Case{"neo hookean", EndCondition::held_ends},
                                           Case{"tensile curves", EndCondition::free_ends},
                                           Case{"tensile curves", EndCondition::held_ends}));

TEST(ClosedForm, BiotWithoutPoissonIsThePapersEquation7) {
  FabricParameters fabric;
  fabric.poisson_weft_warp = 0.0;
  for (EndCondition ends : {EndCondition::free_ends, EndCondition::held_ends})
    for (double a : {1.2, 1.5, 1.8})
      EXPECT_NEAR(closed_form_pressure_Pa("linear biot", ends, fabric, 0.05, a),
                  paper_eq7_pressure_Pa(fabric.stiffness_weft_N_per_m, 0.05, a), 1e-12);
}

TEST(ClosedForm, SmallStrainLimitIsStiffnessTimesStrainOverRadius) {
  // docs/model.md, "Closed forms": p ~ Y e / R0 for free ends (Y = 3 G t0 for neo-Hookean).
  FabricParameters fabric;
  const double e = 1e-6, R0 = 0.05;
  for (const std::string& name : material_law_names()) {
    const auto law = make_material_law(name, fabric);
    // Tensile curves: the weft curve's slope at rest, its first secant (Table 2: 24.5 N/m at
    // strain 0.35, 70 N/m).
    const double Y = name == "neo hookean"
                         ? 3.0 * fabric.neo_hookean_shear_modulus_Pa * fabric.thickness_m
                     : name == "tensile curves"
                         ? fabric.tension_curve_weft[1].value / fabric.tension_curve_weft[1].strain
                         : fabric.stiffness_weft_N_per_m;
    EXPECT_NEAR(closed_form_pressure_Pa(name, EndCondition::free_ends, fabric, R0, 1.0 + e),
                Y * e / R0, 1e-4 * Y * e / R0)
        << name;
  }
}

TEST(ClosedForm, AtAlpha18StVenantKirchhoffIsTwoAndAHalfTimesEquation7) {
  FabricParameters fabric;
  fabric.poisson_weft_warp = 0.0;
  const double ratio =
      closed_form_pressure_Pa("st venant kirchhoff", EndCondition::free_ends, fabric, 0.05, 1.8) /
      paper_eq7_pressure_Pa(fabric.stiffness_weft_N_per_m, 0.05, 1.8);
  // (1.8^2 - 1) / 2 / (1 - 1/1.8) = 2.52 exactly: rounding only.
  EXPECT_NEAR(ratio, 2.52, 1e-12);
}

TEST(ClosedForm, NoContactBelowAlphaOne) {
  EXPECT_EQ(closed_form_pressure_Pa("linear biot", EndCondition::free_ends, FabricParameters{},
                                    0.05, 0.9),
            0.0);
}

}  // namespace
}  // namespace tightfit
