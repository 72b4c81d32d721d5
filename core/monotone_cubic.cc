#include "core/monotone_cubic.h"

#include <algorithm>
#include <stdexcept>

namespace tightfit {

MonotoneCubic::MonotoneCubic(std::vector<double> x, std::vector<double> y, Ends ends)
    : x_(std::move(x)), y_(std::move(y)) {
  const int n = static_cast<int>(x_.size());
  if (n == 0 || y_.size() != x_.size())
    throw std::invalid_argument("a curve needs at least one point");
  for (int k = 0; k + 1 < n; ++k)
    if (!(x_[k + 1] > x_[k]))
      throw std::invalid_argument("the strains of a curve must increase strictly");
  m_.assign(n, 0.0);
  if (n > 1) {
    std::vector<double> h(n - 1), secant(n - 1);
    for (int k = 0; k + 1 < n; ++k) {
      h[k] = x_[k + 1] - x_[k];
      secant[k] = (y_[k + 1] - y_[k]) / h[k];
    }
    // Fritsch and Butland (1984): the weighted harmonic mean keeps every slope within three
    // times the neighbouring secants, Fritsch and Carlson's (1980) bound for monotonicity.
    for (int k = 1; k + 1 < n; ++k) {
      const double a = secant[k - 1], b = secant[k];
      if (a * b <= 0.0) continue;
      const double w1 = 2.0 * h[k] + h[k - 1], w2 = h[k] + 2.0 * h[k - 1];
      m_[k] = (w1 + w2) / (w1 / a + w2 / b);
    }
    if (ends == Ends::linear) {
      // The end secant: a single segment is then exactly the straight line through its points.
      m_[0] = secant[0];
      m_[n - 1] = secant[n - 2];
    }
  }
  cumulative_.assign(n, 0.0);
  for (int k = 0; k + 1 < n; ++k) {
    const double h = x_[k + 1] - x_[k];
    // Simpson's rule is exact on cubics.
    cumulative_[k + 1] =
        cumulative_[k] + h / 6.0 * (y_[k] + 4.0 * value(0.5 * (x_[k] + x_[k + 1])) + y_[k + 1]);
  }
  integral_at_zero_ = integral_from_first_knot(0.0);
}

int MonotoneCubic::segment(double x) const {
  const int n = static_cast<int>(x_.size());
  if (x < x_[0]) return -1;
  if (x >= x_[n - 1]) return n - 1;
  return static_cast<int>(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin()) - 1;
}

double MonotoneCubic::slope(double x) const {
  return value(Dual<1>::variable(x, 0)).grad[0];
}

}  // namespace tightfit
