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

// RK4 is stable for a damper alone, v' = -r v, while r dt < 2.7853 (where the stability region
// meets the negative real axis: the amplification 1 + z + z^2/2 + z^3/6 + z^4/24 of z = -r dt
// is 1 at z = -2.7853). A vertex at the contact's kink feels its normal damper c_i with its contact
// spring not yet pushing, so the step must keep the rates r_i = c_i / m_i (dampers in N s/m,
// masses in kg) in that interval too: returns safety * 2.7853 / max_i r_i, s, or +infinity
// when no particle has a damper.
double damper_time_step_s(const std::vector<double>& damper_N_s_per_m,
                          const std::vector<double>& mass_kg, double safety);

// Mass scaling for a motion whose path need not be true in time (the dressing, the settle):
// each particle whose stiffness bound over mass exceeds `ratio` (> 0) times the median
// particle's gets the mass that brings it to that bound, the others keep theirs. The few
// stiffest, lightest particles (small triangles at a pattern's short edges) then do not set the
// whole garment's time step; an equilibrium does not depend on the masses.
std::vector<double> mass_scaled_kg(const std::vector<double>& stiffness_N_per_m,
                                   const std::vector<double>& mass_kg, double ratio);

// Mass-proportional damping that critically damps the slowest membrane wave of a garment,
// 1/s: a wave of speed sqrt(Y / rho) (Y the membrane stiffness, N/m; rho the areal density,
// kg/m^2) across the garment's size L (m) has omega = pi sqrt(Y / rho) / L, and the damping
// c = 2 omega makes it critical.
double critical_damping_per_s(double stiffness_N_per_m, double areal_density_kg_per_m2,
                              double size_m);

}  // namespace tightfit
