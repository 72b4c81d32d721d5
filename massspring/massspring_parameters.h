// Settings of the mass-spring backend: the "Mass spring" subsection of a parameter file.
// Plain data here; declaring and parsing live in the .cc, the only file that sees deal.II.
#pragma once

#include <string>

namespace dealii {
class ParameterHandler;
}

namespace tightfit {

// How the garment starts its first load step.
enum class Placement {
  // The caller places the already sewn tube (Backend::set_positions): the fast default.
  sewn_tube,
  // The paper's Section 4.3: the panels lie flat on opposite sides of the body at a small,
  // equal distance and seam springs of zero rest length pull them together until the seams
  // close; the solve then continues on the welded mesh.
  flat_panels,
};

struct MassSpringParameters {
  // RK4 time step, s; 0 chooses it from the stiffest vertex (membrane, bending and penalty
  // contact) at the start of every load step.
  double time_step_s = 0.0;
  // Fraction of the RK4 stability limit (2.8 / omega_max) the automatic step uses.
  double time_step_safety = 0.9;
  // Mass-proportional damping c (the acceleration gets -c v), 1/s; 0 chooses it from the
  // garment's slowest membrane wave (see MassSpringBackend).
  double damping_per_s = 0.0;
  // Frames of the paper's quasi-static start (velocity reset to zero every frame) before the
  // damped RK4 integration takes over.
  int quasi_static_frames = 30;
  // Stop rule: the largest residual force on a vertex below this times the tension scale
  // (law stiffness scale x mean rest edge length).
  double relative_tolerance = 1e-4;
  // Guard against non-convergence: a load step that has not met the stop rule after this
  // many frames fails with an error.
  int maximum_frames = 200000;
  // Bending rigidity B of the fabric, N m (a knit: about 1e-6 to 1e-5 N m).
  double bending_rigidity_N_m = 1e-6;
  Placement placement = Placement::sewn_tube;
  // Flat-panel placement: gap between each panel and the body, m.
  double placement_gap_m = 0.005;
  // Flat-panel placement: seam spring stiffness as a multiple of the law's stiffness scale
  // (N/m per N/m).
  double seam_stiffness_factor = 10.0;

  // Throws std::invalid_argument naming the entry when a value is out of range.
  void validate() const;

  static void declare_parameters(dealii::ParameterHandler& prm);
  // Reads the "Mass spring" subsection.
  void parse_parameters(dealii::ParameterHandler& prm);
};

const char* to_string(Placement placement);

}  // namespace tightfit
