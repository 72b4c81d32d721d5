// Starts a cylinder case's tube on a cylinder already at alpha = r / R0, so that a test runs
// only the load steps it checks.
#pragma once

#include "cases/case_parameters.h"
#include "cases/scenario.h"
#include "cases/scenario_run.h"

#include <cstdio>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace tightfit::testing {

// Sets Body/Cylinder/Initial radius to alpha R0, R0 the tube's rest radius (m).
inline void start_cylinder_at(CaseFile& file, double alpha, double rest_radius_m) {
  char initial_radius[96];
  std::snprintf(initial_radius, sizeof initial_radius, "Body/Cylinder/Initial radius=%.17g",
                alpha * rest_radius_m);
  file.set(initial_radius);
}

// Runs the case of `file` on `backend` at `alphas` only, the tube starting on the cylinder at
// the first of them, writing no files; the run's progress goes to `log`, each step whole to
// `on_step`.
inline RunResult run_on_cylinder(CaseFile& file, const std::string& backend,
                                 const std::vector<double>& alphas, double rest_radius_m,
                                 std::ostream& log, const StepObserver& on_step = {}) {
  start_cylinder_at(file, alphas.front(), rest_radius_m);
  CaseParameters parameters = file.parameters();
  parameters.output.write_files = false;
  std::unique_ptr<Scenario> setup = make_scenario(parameters);
  setup->alphas = alphas;
  return run_scenario(
      *setup, [&](const Problem& problem) { return file.create_backend(backend, problem); }, "",
      log, on_step);
}

}  // namespace tightfit::testing
