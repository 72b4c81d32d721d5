// The tensile-curves law (core/tensile_curves.h): the monotone cubic it interpolates with, its
// equality with the linear Biot law for straight curves, its derivatives against finite
// differences across knots and beyond the data, and free strips against the measured points
// of the paper's Table 2 (the numbers the law was given).
#include "core/material.h"
#include "core/monotone_cubic.h"
#include "core/tensile_curves.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>

namespace tightfit {
namespace {

TEST(MonotoneCubic, PassesThroughThePointsAndStaysMonotone) {
  const std::vector<double> x = {0.0, 0.35, 0.6, 1.0}, y = {0.0, 24.5, 49.0, 50.0};
  const MonotoneCubic curve(x, y, MonotoneCubic::Ends::linear);
  for (std::size_t k = 0; k < x.size(); ++k) EXPECT_DOUBLE_EQ(curve.value(x[k]), y[k]);
  double previous = curve.value(-0.5);
  for (double e = -0.5; e < 1.5; e += 1e-3) {
    EXPECT_GE(curve.value(e), previous) << e;
    EXPECT_GE(curve.slope(e), 0.0) << e;
    previous = curve.value(e);
  }
}

TEST(MonotoneCubic, SlopeIsContinuousAtTheKnotsAndStraightBeyond) {
  const MonotoneCubic curve({0.0, 0.35, 0.6}, {0.0, 24.5, 49.0}, MonotoneCubic::Ends::linear);
  const double h = 1e-7;
  for (double knot : {0.0, 0.35, 0.6}) {
    const double left = (curve.value(knot) - curve.value(knot - h)) / h;
    const double right = (curve.value(knot + h) - curve.value(knot)) / h;
    EXPECT_NEAR(left, right, 1e-4 * std::abs(right)) << knot;
  }
  // Beyond the data: the straight line with the end secant (49 - 24.5) / 0.25 = 98 N/m.
  EXPECT_NEAR(curve.value(1.0), 49.0 + 98.0 * 0.4, 1e-9);
  EXPECT_NEAR(curve.value(-0.1), -70.0 * 0.1, 1e-9);  // first secant 24.5 / 0.35 = 70 N/m
}

TEST(MonotoneCubic, IntegralMatchesQuadrature) {
  const MonotoneCubic curve({0.0, 0.35, 0.6}, {0.0, 24.5, 49.0}, MonotoneCubic::Ends::linear);
  for (double end : {-0.2, 0.2, 0.5, 0.9}) {
    // Composite midpoint rule with 20000 panels (error ~ 1e-8 of the integral).
    const int n = 20000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += curve.value((i + 0.5) * end / n);
    EXPECT_NEAR(curve.integral_from_zero(end), sum * end / n, 1e-7) << end;
  }
}

TEST(MonotoneCubic, RefusesStrainsThatDoNotIncrease) {
  EXPECT_THROW(MonotoneCubic({0.0, 0.3, 0.3}, {0, 1, 2}, MonotoneCubic::Ends::linear),
               std::invalid_argument);
}

Mat2 sample_C(double a, double b, double shear) {
  Mat32 F;
  F << a, shear, 0.1 * shear, b, 0.05, -0.02;
  return F.transpose() * F;
}

TEST(TensileCurves, StraightCurvesGiveTheLinearBiotLaw) {
  FabricParameters fabric;  // Y1 130, Y2 70, nu12 0.2021, G 30 N/m
  fabric.tension_curve_weft = {{0.0, 0.0}, {1.0, fabric.stiffness_weft_N_per_m}};
  fabric.tension_curve_warp = {{0.0, 0.0}, {1.0, fabric.stiffness_warp_N_per_m}};
  fabric.poisson_curve = {{0.0, fabric.poisson_weft_warp}};
  const auto curves = make_material_law("tensile curves", fabric);
  const auto linear = make_material_law("linear biot", fabric);
  EXPECT_NEAR(curves->stiffness_scale(), linear->stiffness_scale(), 1e-9);
  for (const Mat2& C : {sample_C(1.3, 0.9, 0.1), sample_C(1.8, 1.0, -0.2), sample_C(0.95, 1.2, 0.0),
                        sample_C(2.5, 0.7, 0.3)}) {
    const double W = linear->energy(C);
    ASSERT_TRUE(std::isfinite(W) && std::isfinite(curves->energy(C)));
    EXPECT_NEAR(curves->energy(C), W, 1e-12 * std::abs(W));
    EXPECT_LT((curves->stress(C) - linear->stress(C)).norm(), 1e-10 * linear->stress(C).norm());
    EXPECT_LT((curves->tangent(C) - linear->tangent(C)).norm(), 1e-10 * linear->tangent(C).norm());
  }
}

// The law of Table 2 (the defaults); its derivatives are checked with every law's in
// test_material_laws.cc, at states on its knots, between them and beyond the data.
class Table2Law : public ::testing::Test {
 protected:
  FabricParameters fabric;
  std::unique_ptr<MaterialLaw> law = make_material_law("tensile curves", fabric);
};

// Along a free weft strip (the cylinder's hoop with free ends) the tangent stays positive
// definite: the energy is convex on every state the cylinder cases reach.
TEST_F(Table2Law, TangentIsPositiveDefiniteAlongTheFreeWeftStrip) {
  const TensileCurves curves(fabric.tensile_curves());
  for (double e = 0.0; e <= 1.0; e += 0.01) {
    const double b = 1.0 - curves.lateral_contraction(e);
    Mat2 C = Mat2::Zero();
    C(0, 0) = (1 + e) * (1 + e);
    C(1, 1) = b * b;
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(law->tangent(C));
    EXPECT_GT(eigen.eigenvalues().minCoeff(), 0.0) << "weft strain " << e;
  }
}

// A free weft strip at each of Table 2's course strains carries the measured force per unit
// rest width and narrows by the measured Poisson coefficient: S22 = 0 there, and the nominal
// stress a S11 is the force.
TEST_F(Table2Law, FreeWeftStripReadsTable2) {
  const struct {
    double strain, force_N_per_m, poisson;
  } course[] = {{0.35, 24.5, 0.3499}, {0.60, 49.0, 0.2021}};
  for (const auto& point : course) {
    const double a = 1.0 + point.strain, b = 1.0 - point.poisson * point.strain;
    Mat2 C = Mat2::Zero();
    C(0, 0) = a * a;
    C(1, 1) = b * b;
    const Mat2 S = law->stress(C);
    EXPECT_NEAR(S(1, 1), 0.0, 1e-9 * point.force_N_per_m);
    EXPECT_NEAR(a * S(0, 0), point.force_N_per_m, 1e-9 * point.force_N_per_m);
  }
}

// A free warp strip at Table 2's wale strains: the weft width that makes S11 vanish is found
// here by bisection, and the nominal warp stress b S22 is the measured force.
TEST_F(Table2Law, FreeWarpStripReadsTable2) {
  const struct { double strain, force_N_per_m; } wale[] = {{0.575, 24.5}, {0.825, 49.0}};
  for (const auto& point : wale) {
    const double b = 1.0 + point.strain;
    auto weft_stress = [&](double a) {
      Mat2 C = Mat2::Zero();
      C(0, 0) = a * a;
      C(1, 1) = b * b;
      return law->stress(C);
    };
    double low = 0.3, high = 1.0;  // S11 < 0 at low, > 0 at rest width
    ASSERT_LT(weft_stress(low)(0, 0), 0.0);
    ASSERT_GT(weft_stress(high)(0, 0), 0.0);
    for (int i = 0; i < 100; ++i) {
      const double mid = 0.5 * (low + high);
      (weft_stress(mid)(0, 0) > 0.0 ? high : low) = mid;
    }
    EXPECT_NEAR(b * weft_stress(low)(1, 1), point.force_N_per_m, 1e-9 * point.force_N_per_m);
  }
}

TEST(TensileCurves, BadCurvesAreRefusedNamingTheEntry) {
  auto message = [](const std::string& text, const std::string& entry) {
    try {
      parse_curve_points(text, entry);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message("0:0, 0.3;24", "Material/Tension curve weft").find("Tension curve weft"),
            std::string::npos);
  EXPECT_NE(message("0:0, x:1", "Material/Poisson curve").find("'x:1'"), std::string::npos);
  FabricParameters fabric;
  fabric.tension_curve_weft = {{0.0, 0.0}, {0.5, 20.0}, {0.7, 10.0}};  // falls
  try {
    make_material_law("tensile curves", fabric);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Tension curve weft"), std::string::npos);
  }
  fabric = FabricParameters{};
  fabric.tension_curve_warp = {{0.2, 5.0}, {0.5, 20.0}};  // no origin
  EXPECT_THROW(make_material_law("tensile curves", fabric), std::invalid_argument);
}

}  // namespace
}  // namespace tightfit
