#include "massspring/stable_time_step.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tightfit {

double stable_time_step_s(const std::vector<double>& stiffness_N_per_m,
                          const std::vector<double>& mass_kg, double safety) {
  double omega_squared_max = 0.0;
  for (std::size_t i = 0; i < mass_kg.size() && i < stiffness_N_per_m.size(); ++i)
    if (mass_kg[i] > 0)
      omega_squared_max = std::max(omega_squared_max, stiffness_N_per_m[i] / mass_kg[i]);
  if (!(omega_squared_max > 0) || !std::isfinite(omega_squared_max))
    throw std::invalid_argument(
        "mass spring: cannot choose a time step (no particle has mass and stiffness); set "
        "Mass spring/Time step");
  return safety * 2.0 * std::sqrt(2.0) / std::sqrt(omega_squared_max);
}

double damper_time_step_s(const std::vector<double>& damper_N_s_per_m,
                          const std::vector<double>& mass_kg, double safety) {
  double rate_max = 0.0;
  for (std::size_t i = 0; i < mass_kg.size() && i < damper_N_s_per_m.size(); ++i)
    if (mass_kg[i] > 0) rate_max = std::max(rate_max, damper_N_s_per_m[i] / mass_kg[i]);
  return rate_max > 0 ? safety * 2.7853 / rate_max : std::numeric_limits<double>::infinity();
}

std::vector<double> mass_scaled_kg(const std::vector<double>& stiffness,
                                   const std::vector<double>& mass, double ratio) {
  std::vector<double> scaled = mass;
  if (stiffness.empty()) return scaled;
  std::vector<double> over_mass(stiffness.size());
  for (std::size_t i = 0; i < stiffness.size(); ++i) over_mass[i] = stiffness[i] / mass[i];
  std::vector<double> sorted = over_mass;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double limit = ratio * sorted[sorted.size() / 2];
  if (limit > 0)
    for (std::size_t i = 0; i < stiffness.size(); ++i)
      if (over_mass[i] > limit) scaled[i] = stiffness[i] / limit;
  return scaled;
}

double critical_damping_per_s(double stiffness_N_per_m, double areal_density_kg_per_m2,
                              double size_m) {
  return 2.0 * M_PI * std::sqrt(stiffness_N_per_m / areal_density_kg_per_m2) / size_m;
}

}  // namespace tightfit
