// Automatic time step and damping of the explicit integrator.
#pragma once

#include <vector>

namespace tightfit {

// Fourth-order Runge-Kutta is stable for an undamped oscillator while omega dt < 2 sqrt(2)
// (the stability region meets the imaginary axis at 2.83). With omega_i^2 = K_i / m_i from
// an upper bound K_i of each particle's stiffness (N/m) and its mass m_i (kg), returns
// safety * 2 sqrt(2) / max_i omega_i, s. Throws std::invalid_argument when no particle has
// both a positive mass and a positive stiffness.
double stable_time_step_s(const std::vector<double>& stiffness_N_per_m,
                          const std::vector<double>& mass_kg, double safety);

// Mass-proportional damping that critically damps the slowest membrane wave of a garment,
// 1/s: a wave of speed sqrt(Y / rho) (Y the membrane stiffness, N/m; rho the areal density,
// kg/m^2) across the garment's size L (m) has omega = pi sqrt(Y / rho) / L, and the damping
// c = 2 omega makes it critical.
double critical_damping_per_s(double stiffness_N_per_m, double areal_density_kg_per_m2,
                              double size_m);

}  // namespace tightfit
