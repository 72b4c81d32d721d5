// Runs a scenario on one backend (the generic driver of `tightfit run`): every load step
// solved, measured and written as soon as it finishes (a pressure.csv row, the measurements'
// own files, garment and body VTU, .pvd series), then each measurement's closing files.
//
// What the driver keeps of a finished step is its scalars (the pressure summary, the closed
// form, the measurements' columns, the solver's report): its per-vertex arrays (the backend's
// SurfaceState and the pressure field, about 140 bytes a vertex) are released once the step is
// written, so memory does not grow with the number of load steps. The last step that finished
// keeps them on the first rank only, for the measurements' closing files (Measurement::
// after_run: the angular profile, the pictures) and for the caller; a caller that needs every
// step's arrays takes them as each step finishes (StepObserver).
#pragma once

#include "cases/step_measurement.h"

#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace tightfit {

using BackendFactory = std::function<std::unique_ptr<Backend>(const Problem&)>;
// Called on every rank with each load step that finished, whole, once it is written.
using StepObserver = std::function<void(const StepMeasurement&)>;

struct RunResult {
  std::string backend;
  // The steps that finished. Their per-vertex arrays (state, field) are empty but for the last
  // step's on the first rank (StepMeasurement::holds_vertex_arrays).
  std::vector<StepMeasurement> steps;
  std::vector<std::string> columns;  // the measurements' extra pressure.csv columns
  std::vector<std::string> files;    // the files the measurements wrote
  std::vector<TextTable> tables;     // the measurements' tables for the screen
  bool completed = false;
  std::string failure;     // why the run stopped early, if it did
  int interrupted_by = 0;  // the signal (SIGINT, SIGTERM) that stopped it, if one did
};

// Writes into `output_dir` (created if needed): pressure.csv, solver.log (each step's
// StepReport::text()), what the case's measurements write, and with Output/Write VTU
// garment_NNNN.vtu, body_NNNN.vtu, garment.pvd, body.pvd and view.py, the run's ParaView view
// (io/paraview_view_script.h). Progress goes to `log`. A backend
// failure, or a SIGINT/SIGTERM (core/interruption.h), ends the run with completed = false and
// a note of where it stopped in `log` and solver.log; what was written stays. `on_step`, if
// set, sees every step that finished with its per-vertex arrays.
RunResult run_scenario(Scenario& scenario, const BackendFactory& make_backend,
                       const std::string& output_dir, std::ostream& log,
                       const StepObserver& on_step = {});

// The generic columns of pressure.csv, in order; the measurements' columns follow them.
std::vector<std::string> pressure_table_columns();

}  // namespace tightfit
