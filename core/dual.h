// Forward-mode automatic differentiation with N directions.
//
// A material law is written once, as an energy W(C) templated on its scalar type; the stress
// 2 dW/dC comes from Dual<3> and the tangent from Dual<3, Dual<3>>, so stress and tangent
// can never disagree with the energy (tests still check them against finite differences).
#pragma once

#include <array>
#include <cmath>

namespace tightfit {

template <int N, class T = double>
struct Dual {
  T value{};
  std::array<T, N> grad{};

  Dual() = default;
  Dual(double v) : value(v) {}  // NOLINT: constants promote implicitly, as in plain arithmetic
  Dual(const T& v, const std::array<T, N>& g) : value(v), grad(g) {}

  // The independent variable number `direction` with value v.
  static Dual variable(const T& v, int direction) {
    Dual d(v, {});
    d.grad[direction] = T(1.0);
    return d;
  }
};

namespace dual_detail {
// Applies the chain rule: the result has value f and derivative df * a.grad.
template <int N, class T>
Dual<N, T> chain(const Dual<N, T>& a, const T& f, const T& df) {
  Dual<N, T> r(f, {});
  for (int i = 0; i < N; ++i) r.grad[i] = df * a.grad[i];
  return r;
}
}  // namespace dual_detail

template <int N, class T>
Dual<N, T> operator+(const Dual<N, T>& a, const Dual<N, T>& b) {
  Dual<N, T> r(a.value + b.value, {});
  for (int i = 0; i < N; ++i) r.grad[i] = a.grad[i] + b.grad[i];
  return r;
}
template <int N, class T>
Dual<N, T> operator-(const Dual<N, T>& a, const Dual<N, T>& b) {
  Dual<N, T> r(a.value - b.value, {});
  for (int i = 0; i < N; ++i) r.grad[i] = a.grad[i] - b.grad[i];
  return r;
}
template <int N, class T>
Dual<N, T> operator-(const Dual<N, T>& a) {
  return dual_detail::chain(a, T(-a.value), T(-1.0));
}
template <int N, class T>
Dual<N, T> operator*(const Dual<N, T>& a, const Dual<N, T>& b) {
  Dual<N, T> r(a.value * b.value, {});
  for (int i = 0; i < N; ++i) r.grad[i] = a.grad[i] * b.value + a.value * b.grad[i];
  return r;
}
template <int N, class T>
Dual<N, T> operator/(const Dual<N, T>& a, const Dual<N, T>& b) {
  const T inverse = T(1.0) / b.value;
  const T quotient = a.value * inverse;
  Dual<N, T> r(quotient, {});
  for (int i = 0; i < N; ++i) r.grad[i] = (a.grad[i] - quotient * b.grad[i]) * inverse;
  return r;
}

// Mixed operations with plain doubles.
template <int N, class T>
Dual<N, T> operator+(const Dual<N, T>& a, double b) {
  return a + Dual<N, T>(b);
}
template <int N, class T>
Dual<N, T> operator+(double a, const Dual<N, T>& b) {
  return Dual<N, T>(a) + b;
}
template <int N, class T>
Dual<N, T> operator-(const Dual<N, T>& a, double b) {
  return a - Dual<N, T>(b);
}
template <int N, class T>
Dual<N, T> operator-(double a, const Dual<N, T>& b) {
  return Dual<N, T>(a) - b;
}
template <int N, class T>
Dual<N, T> operator*(const Dual<N, T>& a, double b) {
  return a * Dual<N, T>(b);
}
template <int N, class T>
Dual<N, T> operator*(double a, const Dual<N, T>& b) {
  return Dual<N, T>(a) * b;
}
template <int N, class T>
Dual<N, T> operator/(const Dual<N, T>& a, double b) {
  return a / Dual<N, T>(b);
}
template <int N, class T>
Dual<N, T> operator/(double a, const Dual<N, T>& b) {
  return Dual<N, T>(a) / b;
}

// The plain number behind a scalar (a double, or the value of a Dual of any depth): what a
// piecewise function branches on.
inline double scalar_value(double x) {
  return x;
}
template <int N, class T>
double scalar_value(const Dual<N, T>& x) {
  return scalar_value(x.value);
}

template <int N, class T>
Dual<N, T> sqrt(const Dual<N, T>& a) {
  using std::sqrt;
  const T root = sqrt(a.value);
  return dual_detail::chain(a, root, T(0.5) / root);
}
template <int N, class T>
Dual<N, T> log(const Dual<N, T>& a) {
  using std::log;
  return dual_detail::chain(a, log(a.value), T(1.0) / a.value);
}
template <int N, class T>
Dual<N, T> pow(const Dual<N, T>& a, double exponent) {
  using std::pow;
  return dual_detail::chain(a, pow(a.value, exponent), exponent * pow(a.value, exponent - 1.0));
}

}  // namespace tightfit
