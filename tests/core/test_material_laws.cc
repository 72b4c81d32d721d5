// Every law's stress and tangent against finite differences of its energy, and the laws'
// defining properties (stress-free at rest, small-strain stiffness, uniaxial closed forms).
#include "core/material.h"
#include "tests/core/stress_difference.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit {
namespace {

Mat2 sample_C(double a, double b, double shear) {
  Mat32 F;
  F << a, shear, 0.1 * shear, b, 0.05, -0.02;
  return F.transpose() * F;
}

// Stretched and sheared states, in tension and compression; for the tensile curves law of
// Table 2 they fall between its knots (weft strain 0.3), on them (0.35, 0.6), beyond them
// (0.8, 0.9) and in compression (-0.05).
std::vector<Mat2> sample_states() {
  return {sample_C(1.3, 0.9, 0.1),   sample_C(1.8, 1.0, -0.2),   sample_C(0.95, 1.2, 0.0),
          sample_C(1.4, 0.95, 0.15), sample_C(1.35, 0.88, 0.05), sample_C(1.6, 1.3, -0.1),
          sample_C(1.9, 1.9, 0.2)};
}

class EveryLaw : public ::testing::TestWithParam<std::string> {
 protected:
  FabricParameters fabric;
  std::unique_ptr<MaterialLaw> law = make_material_law(GetParam(), fabric);
};

TEST_P(EveryLaw, StressIsTwiceTheEnergyGradient) {
  for (const Mat2& C : sample_states()) {
    const Mat2 S = law->stress(C);
    const double h = 1e-6;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        // Perturb C symmetrically: dW = S : dC / 2.
        Mat2 dC = Mat2::Zero();
        dC(i, j) += h;
        dC(j, i) += h;
        dC /= (i == j ? 2.0 : 1.0);
        const double dW = (law->energy(C + dC) - law->energy(C - dC)) / (2.0 * h);
        const double expected = 0.5 * (S.cwiseProduct(dC / h)).sum();
        EXPECT_NEAR(dW, expected, 1e-6 * law->stiffness_scale()) << i << j;
      }
  }
}

TEST_P(EveryLaw, TangentIsTheStressDerivative) {
  for (const Mat2& C : sample_states()) {
    const Mat3 D = law->tangent(C);
    const double h = 1e-6;
    for (int j = 0; j < 3; ++j) {
      const Mat2 dS = testing::stress_derivative_along(*law, C, j, h);
      EXPECT_NEAR(D(0, j), dS(0, 0), 1e-5 * law->stiffness_scale());
      EXPECT_NEAR(D(1, j), dS(1, 1), 1e-5 * law->stiffness_scale());
      EXPECT_NEAR(D(2, j), dS(0, 1), 1e-5 * law->stiffness_scale());
    }
    EXPECT_LT((D - D.transpose()).norm(), 1e-9 * law->stiffness_scale());
  }
}

TEST_P(EveryLaw, StressFreeAtRest) {
  EXPECT_LT(law->stress(Mat2::Identity()).norm(), 1e-12 * law->stiffness_scale());
  EXPECT_NEAR(law->energy(Mat2::Identity()), 0.0, 1e-15);
}

INSTANTIATE_TEST_SUITE_P(MaterialLaws, EveryLaw, ::testing::ValuesIn(material_law_names()),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (c == ' ') c = '_';
                           return n;
                         });

TEST(LinearBiot, NominalStressIsLinearInStretchAlongTheWeft) {
  // Uniaxial stretch a along x with the warp held (C22 = 1): the nominal (1st P-K) stress is
  // P11 = a S11 = D11 (a - 1), D11 = Y1 / (1 - nu12 nu21).
  FabricParameters f;
  const auto law = make_material_law("linear biot", f);
  const double a = 1.6;
  Mat2 C = Mat2::Identity();
  C(0, 0) = a * a;
  const double d11 = f.stiffness_weft_N_per_m / (1.0 - f.poisson_weft_warp * f.poisson_warp_weft());
  EXPECT_NEAR(a * law->stress(C)(0, 0), d11 * (a - 1.0), 1e-9 * d11);
}

TEST(StVenantKirchhoff, SecondPiolaKirchhoffIsLinearInGreenStrain) {
  FabricParameters f;
  f.poisson_weft_warp = 0.0;
  const auto law = make_material_law("st venant kirchhoff", f);
  const double a = 1.8;
  Mat2 C = Mat2::Identity();
  C(0, 0) = a * a;
  EXPECT_NEAR(law->stress(C)(0, 0), f.stiffness_weft_N_per_m * 0.5 * (a * a - 1.0), 1e-9);
}

TEST(NeoHookean, SmallStrainStiffnessIsThreeGt) {
  FabricParameters f;
  const auto law = make_material_law("neo hookean", f);
  // Uniaxial stress (free contraction) at small strain: tension = 3 G t0 e.
  const double e = 1e-5;
  // Free lateral stretch b from S22 = 0: incompressible membrane, b = a^(-1/2).
  const double a = 1.0 + e, b = 1.0 / std::sqrt(a);
  Mat2 C = Mat2::Zero();
  C(0, 0) = a * a;
  C(1, 1) = b * b;
  EXPECT_NEAR(law->stress(C)(1, 1), 0.0, 1e-9);
  const double nominal = a * law->stress(C)(0, 0);
  EXPECT_NEAR(nominal / e, 3.0 * f.neo_hookean_shear_modulus_Pa * f.thickness_m, 1e-3);
}

TEST(MaterialLaw, UnknownNameIsRefusedWithTheKnownNames) {
  try {
    make_material_law("hooke", FabricParameters{});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("linear biot"), std::string::npos);
  }
}

TEST(MaterialLaw, NegativeThicknessIsRefused) {
  FabricParameters f;
  f.thickness_m = -1e-3;
  EXPECT_THROW(make_material_law("neo hookean", f), std::invalid_argument);
}

}  // namespace
}  // namespace tightfit
