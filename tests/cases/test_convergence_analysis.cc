// Grid-convergence arithmetic against manufactured sequences f(h) = f0 + C h^p (+ D h^q),
// whose order, limit and error are known by construction.
#include "cases/convergence_analysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tightfit {
namespace {

struct Manufactured {
  double f0, c, p, d = 0.0, q = 3.0;
  double operator()(double h) const { return f0 + c * std::pow(h, p) + d * std::pow(h, q); }
};

// Values on edge lengths h0, h0/r, h0/r^2, ... (coarse to fine).
std::vector<double> sample(const Manufactured& f, double h0, double ratio, int n) {
  std::vector<double> values;
  for (int i = 0; i < n; ++i) values.push_back(f(h0 / std::pow(ratio, i)));
  return values;
}

TEST(ConvergenceAnalysis, SafetyFactorsAreRoaches) {
  EXPECT_DOUBLE_EQ(gci_safety_factor(2), 3.0);
  EXPECT_DOUBLE_EQ(gci_safety_factor(3), 1.25);
  EXPECT_DOUBLE_EQ(gci_safety_factor(5), 1.25);
}

TEST(ConvergenceAnalysis, PurePowerGivesItsOrderForAnyRatio) {
  for (double ratio : {2.0, 1.5, 3.0})
    for (double p : {1.0, 2.0, 0.5}) {
      const Manufactured f{120.0, -35.0, p};
      const double h = 0.01;
      EXPECT_NEAR(observed_order(f(ratio * ratio * h), f(ratio * h), f(h), ratio), p, 1e-9)
          << "ratio " << ratio << ", order " << p;
    }
}

TEST(ConvergenceAnalysis, OrderDoesNotDependOnTheSignOfTheError) {
  const Manufactured rising{10.0, 4.0, 2.0}, falling{10.0, -4.0, 2.0};
  EXPECT_NEAR(observed_order(rising(0.4), rising(0.2), rising(0.1), 2.0), 2.0, 1e-12);
  EXPECT_NEAR(observed_order(falling(0.4), falling(0.2), falling(0.1), 2.0), 2.0, 1e-12);
}

TEST(ConvergenceAnalysis, RichardsonRecoversTheLimitOfAPurePower) {
  const Manufactured f{250.0, 80.0, 2.0};
  EXPECT_NEAR(richardson_extrapolate(f(0.02), f(0.01), 2.0, 2.0), 250.0, 1e-10);
  const Manufactured g{-3.0, 0.7, 1.0};
  EXPECT_NEAR(richardson_extrapolate(g(0.3), g(0.1), 3.0, 1.0), -3.0, 1e-12);
}

TEST(ConvergenceAnalysis, GciOfAPurePowerIsTheSafetyFactorTimesTheTrueRelativeError) {
  // f_medium - f_fine = C h^p (r^p - 1), so GCI = F_s |C h^p / f_fine| exactly.
  const Manufactured f{100.0, 50.0, 2.0};
  const double h = 0.05, true_error = std::abs(f(h) - 100.0) / f(h);
  EXPECT_NEAR(grid_convergence_index(f(2 * h), f(h), 2.0, 2.0, 1.25), 1.25 * true_error, 1e-14);
  EXPECT_NEAR(grid_convergence_index(f(2 * h), f(h), 2.0, 2.0, 3.0), 3.0 * true_error, 1e-14);
}

TEST(ConvergenceAnalysis, ErrorOrderFromTwoMeshes) {
  EXPECT_NEAR(error_order(0.04, 0.01, 2.0), 2.0, 1e-12);
  EXPECT_NEAR(error_order(-0.08, -0.01, 2.0), 3.0, 1e-12);  // signs do not matter
  EXPECT_NEAR(error_order(0.09, 0.01, 3.0), 2.0, 1e-12);
  EXPECT_TRUE(std::isnan(error_order(0.0, 0.01, 2.0)));
  EXPECT_TRUE(std::isnan(error_order(0.01, 0.0, 2.0)));
}

TEST(ConvergenceAnalysis, HigherOrderTermsFadeAsTheMeshIsRefined) {
  // f = f0 + C h^2 + D h^3: the observed order tends to 2 and the error of the Richardson
  // value falls like h^3.
  const Manufactured f{1000.0, 300.0, 2.0, 200.0, 3.0};
  double previous_order_gap = HUGE_VAL, previous_limit_error = HUGE_VAL;
  for (double h : {0.08, 0.04, 0.02, 0.01}) {
    const double p = observed_order(f(4 * h), f(2 * h), f(h), 2.0);
    const double limit = richardson_extrapolate(f(2 * h), f(h), 2.0, 2.0);
    const double order_gap = std::abs(p - 2.0), limit_error = std::abs(limit - 1000.0);
    EXPECT_LT(order_gap, previous_order_gap) << "h = " << h;
    EXPECT_LT(limit_error, previous_limit_error) << "h = " << h;
    previous_order_gap = order_gap;
    previous_limit_error = limit_error;
  }
  EXPECT_LT(previous_order_gap, 0.05);
  // Extrapolating with the formal order leaves only the D h^3 term: D h^3 r^2 (r - 1) / (r^2 - 1)
  // at h = 0.01 and r = 2, i.e. 200e-6 * 4 / 3.
  EXPECT_NEAR(previous_limit_error, 200e-6 * 4.0 / 3.0, 1e-9);
}

TEST(ConvergenceAnalysis, UndefinedWhereTheSequenceIsNotAsymptotic) {
  EXPECT_TRUE(std::isnan(observed_order(1.0, 2.0, 1.5, 2.0)));  // oscillates
  EXPECT_TRUE(std::isnan(observed_order(1.0, 1.0, 1.0, 2.0)));  // no change at all
  EXPECT_TRUE(std::isnan(observed_order(2.0, 1.0, 1.0, 2.0)));  // fine step zero
  EXPECT_TRUE(std::isnan(richardson_extrapolate(1.0, 2.0, 2.0, std::nan(""))));
  EXPECT_TRUE(std::isnan(richardson_extrapolate(1.0, 2.0, 2.0, -1.0)));
  EXPECT_TRUE(std::isnan(grid_convergence_index(1.0, 0.0, 2.0, 2.0, 1.25)));
}

TEST(ConvergenceAnalysis, EstimateFromThreeOrMoreMeshesUsesTheFinestThree) {
  // The coarsest value is far off the asymptote: it must not enter the estimate.
  const Manufactured f{500.0, -120.0, 2.0};
  std::vector<double> values = sample(f, 0.08, 2.0, 4);
  values.front() = 9999.0;
  const ConvergenceEstimate e = estimate_convergence(values, 2.0, 2.0, 500.0);
  EXPECT_EQ(e.n_meshes, 4);
  EXPECT_TRUE(e.order_observed);
  EXPECT_NEAR(e.order, 2.0, 1e-9);
  EXPECT_NEAR(e.extrapolated, 500.0, 1e-9);
  EXPECT_DOUBLE_EQ(e.safety_factor, 1.25);
  EXPECT_NEAR(e.gci_fine, 1.25 * std::abs(values.back() - 500.0) / values.back(), 1e-12);
  EXPECT_NEAR(e.error_order, 2.0, 1e-9);
}

TEST(ConvergenceAnalysis, EstimateFromTwoMeshesAssumesTheOrderWithSafetyFactorThree) {
  const Manufactured f{40.0, 10.0, 1.0};
  const ConvergenceEstimate e = estimate_convergence(sample(f, 0.2, 2.0, 2), 2.0, 2.0, {});
  EXPECT_EQ(e.n_meshes, 2);
  EXPECT_FALSE(e.order_observed);
  EXPECT_DOUBLE_EQ(e.order, 2.0);
  EXPECT_DOUBLE_EQ(e.safety_factor, 3.0);
  // Assuming order 2 for a first-order sequence: f_fine + (f_fine - f_medium) / 3.
  EXPECT_NEAR(e.extrapolated, f(0.1) + (f(0.1) - f(0.2)) / 3.0, 1e-12);
  EXPECT_TRUE(std::isnan(e.error_order));  // no closed form given
}

TEST(ConvergenceAnalysis, EstimateRejectsTooFewMeshesAndBadRatios) {
  EXPECT_THROW(estimate_convergence({1.0}, 2.0, 2.0, {}), std::invalid_argument);
  EXPECT_THROW(estimate_convergence({1.0, 2.0}, 1.0, 2.0, {}), std::invalid_argument);
}

}  // namespace
}  // namespace tightfit
