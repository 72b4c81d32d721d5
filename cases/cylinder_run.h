// Runs a cylinder case on one backend: every load step solved, measured and written as soon
// as it finishes (pressure.csv row, garment and body VTU, .pvd series), then the angular
// profile of the last step.
#pragma once

#include "cases/step_measurement.h"

#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace tightfit {

using BackendFactory = std::function<std::unique_ptr<Backend>(const Problem&)>;

struct RunResult {
  std::string backend;
  std::vector<StepMeasurement> steps;  // the steps that finished
  bool completed = false;
  std::string failure;  // why the run stopped early, if it did
};

// Writes into `output_dir` (created if needed): pressure.csv, pressure_theta.csv, solver.log
// (each step's StepReport::detail), and with
// Output/Write VTU garment_NNNN.vtu, body_NNNN.vtu, garment.pvd, body.pvd. Progress goes to
// `log`. A backend failure ends the run with completed = false; what was written stays.
RunResult run_cylinder_case(CylinderSetup& setup, const BackendFactory& make_backend,
                            const std::string& output_dir, std::ostream& log);

// The columns of pressure.csv, in order.
std::vector<std::string> pressure_table_columns();

}  // namespace tightfit
