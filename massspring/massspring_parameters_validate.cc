// The checks of the mass-spring settings, kept apart from the deal.II parameter file code so
// that programs using the backend without a parameter file do not link deal.II.
#include "massspring/massspring_parameters.h"

#include <stdexcept>

namespace tightfit {

void MassSpringParameters::validate() const {
  auto require = [](bool ok, const char* entry, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("Mass spring/") + entry + " " + what);
  };
  require(time_step_s >= 0, "Time step", "must be >= 0 (s; 0 = automatic)");
  require(time_step_safety > 0 && time_step_safety <= 1.2, "Time step safety",
          "must be in (0, 1.2]");
  require(mass_scaling_ratio == 0 || mass_scaling_ratio >= 1, "Mass scaling",
          "must be 0 (off) or >= 1 (times the median particle's stiffness over mass)");
  require(damping_per_s >= 0, "Damping", "must be >= 0 (1/s; 0 = automatic)");
  require(slide_damping_per_s >= 0, "Slide damping", "must be >= 0 (1/s; 0 = off)");
  require(slide_damping_per_s == 0 || net_force_tolerance > 0, "Slide damping",
          "needs a Mass spring/Net force tolerance above 0 (the end of the slide is read on it)");
  require(creep_slide_damping_per_s >= 0, "Creep slide damping", "must be >= 0 (1/s; 0 = off)");
  require(creep_slide_damping_per_s == 0 || net_force_tolerance > 0, "Creep slide damping",
          "needs a Mass spring/Net force tolerance above 0 (the creep is read on it)");
  // Up to critical, the contact mode's eigenvalues keep the modulus omega the automatic time
  // step is chosen for (omega (-zeta +- i sqrt(1 - zeta^2))); beyond it one grows as
  // omega (zeta + sqrt(zeta^2 - 1)) and RK4 could leave its stability region.
  require(contact_normal_damping_ratio >= 0 && contact_normal_damping_ratio <= 1,
          "Contact normal damping ratio", "must be in [0, 1] (1 = critical)");
  require(contact_stick_damping_ratio >= 0 && contact_stick_damping_ratio <= 1,
          "Contact stick damping ratio", "must be in [0, 1] (1 = critical)");
  require(time_step_update_frames >= 0, "Time step update frames",
          "must be >= 0 (0 = once a step)");
  require(quasi_static_frames >= 0, "Quasi-static frames", "must be >= 0");
  stop.validate(false);
  require(net_force_tolerance >= 0, "Net force tolerance", "must be >= 0 (0 = off)");
  require(maximum_frames > 0, "Maximum frames", "must be positive");
  require(maximum_newton_iterations > 0, "Maximum Newton iterations", "must be positive");
  require(implicit_approach_factor >= 0, "Implicit RK4 approach", "must be >= 0 (0 = off)");
  require(contact_set_predictions >= 0, "Contact set predictions", "must be >= 0 (0 = off)");
  require(stall_window_frames > 0, "Stall window", "must be positive (frames)");
  require(stall_fall > 0 && stall_fall < 1, "Stall residual fall", "must be in (0, 1)");
  require(stall_halvings >= 0, "Stall time step halvings", "must be >= 0");
  require(contact_updates >= 0, "Contact multiplier updates", "must be >= 0 (0 = plain penalty)");
  require(inexact_round_fraction >= 0, "Inexact contact rounds", "must be >= 0 (0 = off)");
  require(bending_rigidity_N_m >= 0, "Bending rigidity", "must be >= 0 (N m)");
  require(placement_gap_m >= 0, "Placement gap", "must be >= 0 (m)");
  require(seam_stiffness_factor > 0, "Seam spring stiffness factor", "must be positive");
}

}  // namespace tightfit
