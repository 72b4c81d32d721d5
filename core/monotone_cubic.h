// A monotone, continuously differentiable interpolant of measured points (x_k, y_k): a
// piecewise cubic Hermite curve whose knot slopes follow Fritsch and Butland (a weighted
// harmonic mean of the neighbouring secants, zero where the data turn), so that monotone data
// give a monotone curve without overshoot. Beyond the data it goes on as a straight line with
// the end slope (Ends::linear) or stays at the end value (Ends::flat, the end slopes set to
// zero so that the curve stays C1).
//
// A tension curve interpolated this way has a non-negative slope everywhere, so its integral
// (a strain energy) is convex; C1 continuity keeps Newton's tangent continuous.
// Evaluation is templated on the scalar so that automatic differentiation (core/dual.h) passes
// through it; the knot is chosen by the scalar's plain value.
#pragma once

#include "core/dual.h"

#include <vector>

namespace tightfit {

class MonotoneCubic {
 public:
  enum class Ends { linear, flat };

  // Strictly increasing x. One point gives a constant. Throws std::invalid_argument when the
  // x are not strictly increasing or there is no point.
  MonotoneCubic(std::vector<double> x, std::vector<double> y, Ends ends);

  template <class S>
  S value(const S& x) const;
  // The integral of the curve from 0 to x (negative for x < 0).
  template <class S>
  S integral_from_zero(const S& x) const;
  double slope(double x) const;

  const std::vector<double>& knots() const { return x_; }
  const std::vector<double>& knot_values() const { return y_; }
  const std::vector<double>& knot_slopes() const { return m_; }

 private:
  // The segment holding x: -1 left of the data, n - 1 right of it.
  int segment(double x) const;
  // The integral from x_0 to x.
  template <class S>
  S integral_from_first_knot(const S& x) const;

  std::vector<double> x_, y_, m_;
  // The integral from x_0 to each knot.
  std::vector<double> cumulative_;
  double integral_at_zero_ = 0.0;
};

template <class S>
S MonotoneCubic::value(const S& x) const {
  const int k = segment(scalar_value(x));
  const int n = static_cast<int>(x_.size());
  if (k < 0) return y_[0] + m_[0] * (x - x_[0]);
  if (k >= n - 1) return y_[n - 1] + m_[n - 1] * (x - x_[n - 1]);
  const double h = x_[k + 1] - x_[k];
  const S t = (x - x_[k]) / h;
  const S t2 = t * t, t3 = t2 * t;
  // Hermite basis h00, h10, h01, h11.
  return (2.0 * t3 - 3.0 * t2 + 1.0) * y_[k] + (t3 - 2.0 * t2 + t) * (h * m_[k]) +
         (3.0 * t2 - 2.0 * t3) * y_[k + 1] + (t3 - t2) * (h * m_[k + 1]);
}

template <class S>
S MonotoneCubic::integral_from_first_knot(const S& x) const {
  const int k = segment(scalar_value(x));
  const int n = static_cast<int>(x_.size());
  if (k < 0 || k >= n - 1) {
    const int end = k < 0 ? 0 : n - 1;
    const S d = x - x_[end];
    return cumulative_[end] + y_[end] * d + 0.5 * m_[end] * d * d;
  }
  const double h = x_[k + 1] - x_[k];
  const S t = (x - x_[k]) / h;
  const S t2 = t * t, t3 = t2 * t, t4 = t3 * t;
  // Integrals from 0 to t of the Hermite basis.
  const S H00 = t - t3 + 0.5 * t4;
  const S H10 = 0.5 * t2 - (2.0 / 3.0) * t3 + 0.25 * t4;
  const S H01 = t3 - 0.5 * t4;
  const S H11 = 0.25 * t4 - (1.0 / 3.0) * t3;
  return cumulative_[k] +
         h * (y_[k] * H00 + (h * m_[k]) * H10 + y_[k + 1] * H01 + (h * m_[k + 1]) * H11);
}

template <class S>
S MonotoneCubic::integral_from_zero(const S& x) const {
  return integral_from_first_knot(x) - integral_at_zero_;
}

}  // namespace tightfit
