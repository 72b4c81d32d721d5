// What one load step measured: the backend's state, the shared extractor's pressure field and
// its summary beside the closed forms.
#pragma once

#include "cases/cylinder_setup.h"
#include "contact/pressure_extractor.h"

namespace tightfit {

struct StepMeasurement {
  int step = 0;
  double alpha = 0.0;
  double radius_m = 0.0;
  StepReport report;
  SurfaceState state;
  PressureField field;
  PressureSummary summary;
  double p_theory_Pa = 0.0;  // the closed form for the case's law and end condition
  double p_eq7_Pa = 0.0;     // the paper's Eq. 7 with the hoop (weft) stiffness
  double rel_error = 0.0;    // (p_mean - p_theory) / p_theory; NaN where p_theory is 0

  double p_mean_Pa() const { return summary.mean_Pa; }
};

// Solves load step `step` of `setup` with `backend` and measures it. Throws SolverError when
// the backend fails, or when the garment should press on the body (alpha > 1) but touches it
// nowhere.
StepMeasurement solve_and_measure(CylinderSetup& setup, Backend& backend, int step);

}  // namespace tightfit
