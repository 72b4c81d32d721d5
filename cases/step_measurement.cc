#include "cases/step_measurement.h"

#include <cmath>
#include <sstream>

namespace tightfit {

Measurements make_measurements(const CaseParameters& parameters) {
  Measurements measurements;
  for (const NamedMeasurement& m : parameters.measurements) measurements.push_back(m.make());
  return measurements;
}

std::vector<std::string> measurement_columns(const Measurements& measurements) {
  std::vector<std::string> columns;
  for (const auto& m : measurements)
    for (const std::string& c : m->columns()) columns.push_back(c);
  return columns;
}

void release_vertex_arrays(StepMeasurement& m) {
  // Assigning empty containers (not clear()) gives the memory back.
  m.state = SurfaceState{};
  PressureField definitions_only;
  definitions_only.area_definition = m.field.area_definition;
  definitions_only.definition = m.field.definition;
  m.field = std::move(definitions_only);
}

StepMeasurement solve_and_measure(Scenario& scenario, Backend& backend, int step,
                                  const Measurements& measurements) {
  const LoadStep load = scenario.prepare_step(step);
  StepMeasurement m;
  m.step = step;
  m.alpha = load.alpha;
  m.report = backend.solve(load);
  m.state = backend.state();
  const PressureSettings& pressure = scenario.parameters.pressure;
  m.field = extract_pressure(scenario.mesh.triangles, m.state, pressure.vertex_area,
                             &scenario.body->body(), pressure.definition);
  m.summary = summarize(m.field);

  for (const auto& measurement : measurements) {
    const std::optional<double> reference = measurement->reference_pressure_Pa(scenario, m);
    if (!reference) continue;
    m.p_theory_Pa = *reference;
    if (m.p_theory_Pa > 0) m.rel_error = (m.p_mean_Pa() - m.p_theory_Pa) / m.p_theory_Pa;
    break;
  }
  for (const auto& measurement : measurements)
    for (double value : measurement->values(scenario, m)) m.extra_values.push_back(value);

  // A garment stretched over the body must touch it; anywhere else it slipped off.
  if (scenario.body->must_touch(m.alpha) && m.summary.n_contact == 0) {
    std::ostringstream message;
    message << "load step " << step << " (alpha " << m.alpha
            << "): the garment touches the body nowhere although it is smaller than the body; "
               "it slipped off or the solver lost it";
    throw SolverError(StopReason::contact_lost, message.str());
  }
  return m;
}

}  // namespace tightfit
