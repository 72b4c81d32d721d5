// The tension-field relaxation of the linear Biot law (docs/model.md, "Slack: the tension
// field"): stress and tangent against finite differences of its energy in every regime, the
// law unchanged where taut, and the closed forms of a strip pulled with slack across it.
#include "core/material.h"
#include "tests/core/stress_difference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tightfit {
namespace {

// C = F^T F for principal stretches l1 along the direction at `angle` from the weft and l2
// across it, with a rigid rotation out of the plane (which C does not see).
Mat2 principal_C(double l1, double l2, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Mat2 Q;
  Q << c, -s, s, c;
  const Mat2 U = Q * Vec2(l1, l2).asDiagonal() * Q.transpose();
  return U * U;
}

struct State {
  const char* regime;
  Mat2 C;
};

// States well inside each regime (finite differences do not cross a boundary between them):
// the fabric's natural width under a weft strain e1 is 1 - nu12 e1 (0.94 at e1 = 0.3).
std::vector<State> states() {
  return {{"taut", principal_C(1.3, 1.05, 0.2)},
          {"taut, compressed a little", principal_C(1.3, 0.96, 0.0)},
          {"wrinkled along the weft", principal_C(1.3, 0.85, 0.0)},
          {"wrinkled along the warp", principal_C(0.8, 1.25, 0.0)},
          {"wrinkled off the grain", principal_C(1.25, 0.8, 0.5)},
          {"wrinkled off the grain, steeply", principal_C(1.15, 0.9, 1.1)},
          {"slack", principal_C(0.9, 0.8, 0.3)}};
}

class TensionField : public ::testing::Test {
 protected:
  FabricParameters fabric;
  std::unique_ptr<MaterialLaw> law = make_tension_field_law("linear biot", fabric, 0.0);
  std::unique_ptr<MaterialLaw> taut_law = make_material_law("linear biot", fabric);
};

TEST_F(TensionField, StressIsTwiceTheEnergyGradient) {
  for (const State& state : states()) {
    const Mat2 S = law->stress(state.C);
    const double h = 1e-6;
    for (int i = 0; i < 2; ++i)
      for (int j = i; j < 2; ++j) {
        Mat2 dC = Mat2::Zero();
        dC(i, j) = dC(j, i) = h;
        const double dW = (law->energy(state.C + dC) - law->energy(state.C - dC)) / (2.0 * h);
        // dW = S : dC / 2 = S_ij h (i != j) or S_ii h / 2.
        const double expected = i == j ? 0.5 * S(i, i) : S(i, j);
        // Central differences: error h^2 W''' ~ 1e-12 Y; 1e-7 Y leaves a wide margin.
        EXPECT_NEAR(dW, expected, 1e-7 * law->stiffness_scale()) << state.regime << " " << i << j;
      }
  }
}

TEST_F(TensionField, TangentIsTheStressDerivative) {
  for (const State& state : states()) {
    const Mat3 D = law->tangent(state.C);
    const double h = 1e-6;
    for (int j = 0; j < 3; ++j) {
      const Mat2 dS = testing::stress_derivative_along(*law, state.C, j, h);
      EXPECT_NEAR(D(0, j), dS(0, 0), 1e-6 * law->stiffness_scale()) << state.regime << j;
      EXPECT_NEAR(D(1, j), dS(1, 1), 1e-6 * law->stiffness_scale()) << state.regime << j;
      EXPECT_NEAR(D(2, j), dS(0, 1), 1e-6 * law->stiffness_scale()) << state.regime << j;
    }
    EXPECT_LT((D - D.transpose()).norm(), 1e-9 * law->stiffness_scale()) << state.regime;
  }
}

TEST_F(TensionField, UnchangedWhereTaut) {
  // Both principal stresses tensile: the relaxed law is the law itself, to rounding.
  for (const Mat2& C : {principal_C(1.3, 1.05, 0.2), principal_C(1.3, 0.96, 0.0),
                        principal_C(1.8, 1.2, -0.7), principal_C(1.2, 1.2, 0.0)}) {
    EXPECT_NEAR(law->energy(C), taut_law->energy(C), 1e-14 * taut_law->energy(C));
    EXPECT_LT((law->stress(C) - taut_law->stress(C)).norm(), 1e-12 * taut_law->stress(C).norm());
    EXPECT_LT((law->tangent(C) - taut_law->tangent(C)).norm(), 1e-12 * taut_law->tangent(C).norm());
  }
}

TEST_F(TensionField, StripPulledAlongTheGrainWithSlackAcross) {
  // A weft strip at strain e1 narrowed below its natural width 1 - nu12 e1: tension
  // T11 = Y1 e1 (nominal; S11 = T11 / l1) and nothing across, whatever the width.
  const double e1 = 0.3;
  for (const double width : {0.93, 0.85, 0.6}) {
    const Mat2 S = law->stress(principal_C(1.0 + e1, width, 0.0));
    EXPECT_NEAR(S(0, 0), fabric.stiffness_weft_N_per_m * e1 / (1.0 + e1), 1e-12 * S(0, 0));
    EXPECT_NEAR(S(1, 1), 0.0, 1e-12 * S(0, 0)) << width;
    EXPECT_NEAR(S(0, 1), 0.0, 1e-12 * S(0, 0)) << width;
  }
  // A warp strip likewise, T22 = Y2 e2; its natural width is 1 - nu21 e2.
  const double e2 = 0.4;
  const Mat2 S = law->stress(principal_C(0.9, 1.0 + e2, 0.0));
  EXPECT_NEAR(S(1, 1), fabric.stiffness_warp_N_per_m * e2 / (1.0 + e2), 1e-12 * S(1, 1));
  EXPECT_NEAR(S(0, 0), 0.0, 1e-12 * S(1, 1));
}

TEST_F(TensionField, NoStressAcrossWrinklesOffTheGrain) {
  // Pulled at 0.5 rad from the weft with slack across: the normal stress across the wrinkles
  // vanishes (the principal frame's shear does not: the approximation, docs/model.md).
  const double angle = 0.5;
  const Vec2 across(-std::sin(angle), std::cos(angle)), along(std::cos(angle), std::sin(angle));
  const Mat2 S = law->stress(principal_C(1.25, 0.8, angle));
  EXPECT_NEAR(across.dot(S * across), 0.0, 1e-12 * law->stiffness_scale());
  EXPECT_GT(along.dot(S * along), 0.1 * law->stiffness_scale());
}

TEST_F(TensionField, NothingWhereSlack) {
  const Mat2 C = principal_C(0.9, 0.97, 0.4);
  EXPECT_EQ(law->energy(C), 0.0);
  EXPECT_EQ(law->stress(C).norm(), 0.0);
  EXPECT_EQ(law->tangent(C).norm(), 0.0);
}

TEST_F(TensionField, RelaxationLowersTheEnergyAndIsContinuous) {
  // W_rel <= W (it is a minimum over states that include the apparent one) and >= 0 everywhere
  // on a grid of stretches and angles; across the taut-wrinkled boundary (the natural width
  // 1 - nu12 e1) the stress is continuous: C1, so Newton's residual has no jump.
  for (double l1 = 0.7; l1 < 1.6; l1 += 0.05)
    for (double l2 = 0.7; l2 < 1.6; l2 += 0.05)
      for (double angle = 0.0; angle < 3.2; angle += 0.35) {
        const Mat2 C = principal_C(l1, l2, angle);
        EXPECT_LE(law->energy(C), taut_law->energy(C) * (1.0 + 1e-14));
        EXPECT_GE(law->energy(C), 0.0);
      }
  const double e1 = 0.3, natural = 1.0 - fabric.poisson_weft_warp * e1;
  const Mat2 inside = law->stress(principal_C(1.0 + e1, natural + 1e-9, 0.0));
  const Mat2 outside = law->stress(principal_C(1.0 + e1, natural - 1e-9, 0.0));
  // The stress changes by its slope (~Y2) times 2e-9 across: 1e-6 Y bounds it.
  EXPECT_LT((inside - outside).norm(), 1e-6 * law->stiffness_scale());
}

TEST_F(TensionField, KeptCompressionStiffnessBlendsTheTwoEnergies) {
  // W_eps = W_rel + eps (W - W_rel): in every regime, energy and stress; its tangent against
  // finite differences of its stress (the blend is differentiated, not assembled).
  const double eps = 1e-3;
  const auto blended = make_tension_field_law("linear biot", fabric, eps);
  for (const State& state : states()) {
    const Mat2& C = state.C;
    const double w_rel = law->energy(C), w = taut_law->energy(C);
    EXPECT_NEAR(blended->energy(C), w_rel + eps * (w - w_rel), 1e-14 * w) << state.regime;
    const Mat2 S = law->stress(C) + eps * (taut_law->stress(C) - law->stress(C));
    EXPECT_LT((blended->stress(C) - S).norm(), 1e-12 * law->stiffness_scale()) << state.regime;
    const Mat3 D = law->tangent(C) + eps * (taut_law->tangent(C) - law->tangent(C));
    EXPECT_LT((blended->tangent(C) - D).norm(), 1e-11 * law->stiffness_scale()) << state.regime;
  }
  // Across wrinkles the stress is eps times the law's own compression.
  const Mat2 C = principal_C(1.3, 0.85, 0.0);
  EXPECT_NEAR(blended->stress(C)(1, 1), eps * taut_law->stress(C)(1, 1),
              1e-12 * law->stiffness_scale());
  EXPECT_LT(taut_law->stress(C)(1, 1), -0.05 * law->stiffness_scale());
}

TEST_F(TensionField, OtherLawsAreRejected) {
  EXPECT_THROW(make_tension_field_law("neo hookean", fabric, 0.0), std::invalid_argument);
  EXPECT_THROW(make_tension_field_law("linear biot", fabric, -0.1), std::invalid_argument);
  EXPECT_THROW(make_tension_field_law("linear biot", fabric, 1.5), std::invalid_argument);
}

}  // namespace
}  // namespace tightfit
