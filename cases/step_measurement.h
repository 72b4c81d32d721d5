// What one load step measured: the backend's state, the shared extractor's pressure field and
// its summary, the scenario's closed form where it has one, and the values of the columns its
// measurements add to pressure.csv.
#pragma once

#include "cases/measurement.h"
#include "cases/scenario.h"
#include "contact/pressure_extractor.h"

#include <limits>
#include <memory>
#include <vector>

namespace tightfit {

struct StepMeasurement {
  int step = 0;
  double alpha = 0.0;  // the body's morph parameter
  StepReport report;
  SurfaceState state;
  PressureField field;
  PressureSummary summary;
  // The closed form of the scenario's reference measurement; NaN where there is none.
  double p_theory_Pa = std::numeric_limits<double>::quiet_NaN();
  double rel_error = std::numeric_limits<double>::quiet_NaN();  // (p_mean - p_theory) / p_theory
  std::vector<double> extra_values;  // the measurements' columns (measurement_columns), in order

  double p_mean_Pa() const { return summary.mean_Pa; }
  // Whether the step still holds its per-vertex arrays (state, field): run_scenario releases
  // them once the step is written, but for the last step on the first rank.
  bool holds_vertex_arrays() const { return state.size() > 0 || !field.pressure_Pa.empty(); }
};

// Frees the step's per-vertex arrays (state and field: about 140 bytes a vertex), keeping its
// scalars (summary, closed form, the measurements' columns) and the field's definitions.
void release_vertex_arrays(StepMeasurement& m);

using Measurements = std::vector<std::unique_ptr<Measurement>>;

// The measurements the case lists (Measurements/List), fresh for one run.
Measurements make_measurements(const CaseParameters& parameters);
// The columns they add to pressure.csv, in order.
std::vector<std::string> measurement_columns(const Measurements& measurements);

// Solves load step `step` of `scenario` with `backend` and measures it. Throws SolverError
// when the backend fails, or when the garment must touch the body (ScenarioBody::must_touch)
// but touches it nowhere.
StepMeasurement solve_and_measure(Scenario& scenario, Backend& backend, int step,
                                  const Measurements& measurements);

}  // namespace tightfit
