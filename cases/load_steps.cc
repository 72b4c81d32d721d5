#include "cases/load_steps.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace tightfit {

std::vector<double> alpha_schedule(double initial_alpha, double final_alpha, double increment) {
  if (!(increment > 0)) throw std::invalid_argument("Protocol/Alpha increment must be positive");
  if (!(final_alpha >= initial_alpha))
    throw std::invalid_argument(
        "Protocol/Final alpha (" + std::to_string(final_alpha) +
        ") is below the initial alpha r0/R0 = " + std::to_string(initial_alpha));
  // Multiples are rounded to the increment's grid so that 1.2, 1.5, 1.8 come out exactly.
  const double tolerance = 1e-9 * increment;
  std::vector<double> alphas{initial_alpha};
  for (long k = static_cast<long>(std::floor(initial_alpha / increment + 1e-9)) + 1;; ++k) {
    const double alpha = k * increment;
    if (alpha > final_alpha + tolerance) break;
    alphas.push_back(alpha);
  }
  if (final_alpha > alphas.back() + tolerance) alphas.push_back(final_alpha);
  return alphas;
}

}  // namespace tightfit
