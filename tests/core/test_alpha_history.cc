// The secant predictor's history (core/load_step.h) against the closed form: states and
// multipliers linear in alpha are extrapolated exactly, the multipliers kept non-negative.
#include "core/load_step.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace tightfit {
namespace {

// x_i(alpha) = a_i + b_i alpha, lambda_i(alpha) = c_i + d_i alpha.
const std::vector<double> a = {0.05, -0.02, 0.3}, b = {0.01, 0.04, -0.2};
const std::vector<double> c = {0.5, 2.0, 0.1}, d = {1.0, -1.5, -0.9};

std::vector<double> linear(const std::vector<double>& p, const std::vector<double>& q,
                           double alpha) {
  std::vector<double> y(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) y[i] = p[i] + q[i] * alpha;
  return y;
}

void record(AlphaHistory<std::vector<double>>& history, double alpha, bool in_contact = true) {
  history.record(alpha, in_contact, linear(a, b, alpha), linear(c, d, alpha));
}

// The backend's extrapolation, last + ratio (last - before), into `x`.
double predict(const AlphaHistory<std::vector<double>>& history, double alpha,
               std::vector<double>& x, std::vector<double>& multiplier_N) {
  return history.predict(
      alpha, multiplier_N,
      [&](double ratio, const std::vector<double>& last, const std::vector<double>& before) {
        for (std::size_t i = 0; i < x.size(); ++i) x[i] = last[i] + ratio * (last[i] - before[i]);
      });
}

TEST(AlphaHistory, ExtrapolatesLinearStatesExactly) {
  AlphaHistory<std::vector<double>> history;
  // Three steps: the first is dropped, the prediction goes through the last two.
  record(history, 0.9);
  record(history, 1.0);
  record(history, 1.05);
  std::vector<double> x(3, 0.0), multiplier_N(3, 0.0);
  const double alpha = 1.15;
  // (1.15 - 1.05) / (1.05 - 1.0) = 2, to rounding (measured 4.4e-15 off; margin 200x).
  EXPECT_NEAR(predict(history, alpha, x, multiplier_N), 2.0, 1e-12);
  const std::vector<double> x_exact = linear(a, b, alpha), lambda = linear(c, d, alpha);
  for (int i = 0; i < 3; ++i) {
    // Rounding of a few operations on numbers below 2: measured up to 3.3e-16 (a multiplier);
    // margin 30x.
    EXPECT_NEAR(x[i], x_exact[i], 1e-14) << i;
    // The secant's multiplier, kept non-negative (lambda_2(1.15) = -0.935 < 0 becomes 0).
    EXPECT_NEAR(multiplier_N[i], std::max(0.0, lambda[i]), 1e-14) << i;
  }
  EXPECT_LT(lambda[2], 0.0);
  EXPECT_EQ(multiplier_N[2], 0.0);
}

TEST(AlphaHistory, PredictsNothingWithoutTwoStepsInContact) {
  const std::vector<double> untouched = {7.0, 8.0, 9.0};
  std::vector<double> x = untouched, multiplier_N = untouched;
  AlphaHistory<std::vector<double>> history;
  record(history, 1.0);
  EXPECT_EQ(predict(history, 1.1, x, multiplier_N), 0.0);  // one step only
  record(history, 1.05, false);                            // out of contact: the secant breaks
  record(history, 1.1);
  EXPECT_EQ(predict(history, 1.2, x, multiplier_N), 0.0);
  record(history, 1.15);
  history.forget();  // a garment placed anew
  EXPECT_EQ(predict(history, 1.2, x, multiplier_N), 0.0);
  EXPECT_EQ(x, untouched);
  EXPECT_EQ(multiplier_N, untouched);
}

TEST(AlphaHistory, PredictsNothingBackwardOrFarBeyondFourIntervals) {
  AlphaHistory<std::vector<double>> history;
  record(history, 1.0);
  record(history, 1.1);
  std::vector<double> x(3, 0.0), multiplier_N(3, 0.0);
  EXPECT_EQ(predict(history, 1.05, x, multiplier_N), 0.0);  // backward
  EXPECT_EQ(predict(history, 1.6, x, multiplier_N), 0.0);   // five intervals on
  EXPECT_NEAR(predict(history, 1.5, x, multiplier_N), 4.0, 1e-12);
}

}  // namespace
}  // namespace tightfit
