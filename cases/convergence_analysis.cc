#include "cases/convergence_analysis.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace tightfit {

namespace {

constexpr double not_defined = std::numeric_limits<double>::quiet_NaN();

bool usable_order(double order) {
  return std::isfinite(order) && order > 0.0;
}

}  // namespace

double gci_safety_factor(int n_meshes) {
  return n_meshes >= 3 ? 1.25 : 3.0;
}

double observed_order(double f_coarse, double f_medium, double f_fine, double ratio) {
  const double coarse_step = f_coarse - f_medium;
  const double fine_step = f_medium - f_fine;
  // A zero step or a change of sign says the sequence is not in its asymptotic range.
  if (coarse_step == 0.0 || fine_step == 0.0) return not_defined;
  const double quotient = coarse_step / fine_step;
  if (quotient <= 0.0) return not_defined;
  return std::log(quotient) / std::log(ratio);  // Roache 1998, Ch. 5
}

double richardson_extrapolate(double f_medium, double f_fine, double ratio, double order) {
  if (!usable_order(order)) return not_defined;
  return f_fine + (f_fine - f_medium) / (std::pow(ratio, order) - 1.0);  // Richardson 1911
}

double grid_convergence_index(double f_medium, double f_fine, double ratio, double order,
                              double safety_factor) {
  if (!usable_order(order) || f_fine == 0.0) return not_defined;
  const double relative_change = std::abs((f_medium - f_fine) / f_fine);
  return safety_factor * relative_change / (std::pow(ratio, order) - 1.0);  // Roache 1994
}

double error_order(double error_coarse, double error_fine, double ratio) {
  if (error_coarse == 0.0 || error_fine == 0.0) return not_defined;
  return std::log(std::abs(error_coarse) / std::abs(error_fine)) / std::log(ratio);
}

ConvergenceEstimate estimate_convergence(const std::vector<double>& values, double ratio,
                                         double assumed_order, std::optional<double> exact) {
  const std::size_t n = values.size();
  if (n < 2) throw std::invalid_argument("a convergence estimate needs at least two meshes");
  if (!(ratio > 1.0)) throw std::invalid_argument("the refinement ratio must exceed 1");
  const double fine = values[n - 1], medium = values[n - 2];

  ConvergenceEstimate e;
  e.n_meshes = static_cast<int>(n);
  e.order_observed = n >= 3;
  e.order = e.order_observed ? observed_order(values[n - 3], medium, fine, ratio) : assumed_order;
  e.safety_factor = gci_safety_factor(e.n_meshes);
  e.extrapolated = richardson_extrapolate(medium, fine, ratio, e.order);
  e.gci_fine = grid_convergence_index(medium, fine, ratio, e.order, e.safety_factor);
  e.error_order = exact ? error_order(medium - *exact, fine - *exact, ratio) : not_defined;
  return e;
}

}  // namespace tightfit
