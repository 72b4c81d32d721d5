#include "cases/step_measurement.h"

#include "cases/cylinder_theory.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace tightfit {

StepMeasurement solve_and_measure(CylinderSetup& setup, Backend& backend, int step) {
  const LoadStep load = setup.prepare_step(step);
  StepMeasurement m;
  m.step = step;
  m.alpha = load.alpha;
  m.radius_m = setup.body->radius_m();
  m.report = backend.solve(load);
  m.state = backend.state();
  m.field = extract_pressure(setup.mesh.triangles, m.state, setup.parameters.pressure.vertex_area,
                             setup.body.get());
  m.summary = summarize(m.field);

  const CaseParameters& c = setup.parameters;
  m.p_theory_Pa = closed_form_pressure_Pa(c.law, c.protocol.end_condition, c.fabric,
                                          setup.rest_radius_m, m.alpha);
  m.p_eq7_Pa = paper_eq7_pressure_Pa(c.fabric.stiffness_weft_N_per_m, setup.rest_radius_m, m.alpha);
  m.rel_error = m.p_theory_Pa > 0 ? (m.p_mean_Pa() - m.p_theory_Pa) / m.p_theory_Pa
                                  : std::numeric_limits<double>::quiet_NaN();

  // A tube stretched over the body must touch it; anywhere else it slipped off.
  if (m.alpha > 1.001 && m.summary.n_contact == 0) {
    std::ostringstream message;
    message << "load step " << step << " (alpha " << m.alpha
            << "): the garment touches the body nowhere although it is smaller than the body; "
               "it slipped off or the solver lost it";
    throw SolverError(message.str());
  }
  return m;
}

}  // namespace tightfit
