// Garment T of cases/cylinder_T.prm (free ends, mass-spring backend, its own 480-vertex mesh)
// settled on the cylinder at alpha 1.2 and grown to 1.5, run once per test program and shared
// by the tests that measure its output: the tube presses uniformly at the closed form's
// pressure (within 0.9% on this mesh, test_verification_matrix).
#pragma once

#include "cases/case_parameters.h"
#include "cases/scenario.h"
#include "cases/scenario_run.h"
#include "cylinder_start.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <vector>

namespace tightfit {

struct GarmentTRun {
  static constexpr double rest_radius_m = 2 * 0.157 / (2 * M_PI);  // R0, alpha = r / R0
  std::unique_ptr<Scenario> scenario;
  RunResult result;
  // Every step whole, per-vertex arrays included (the run keeps the last one's only).
  std::vector<StepMeasurement> measured;
};

// The run ends with the body shaped for its last step: prepare_step() reshapes it.
inline GarmentTRun& garment_t_run() {
  static GarmentTRun run = [] {
    CaseFile file;
    file.read(TIGHTFIT_SOURCE_DIR "/cases/cylinder_T.prm", {"Output/Write VTU=false"});
    testing::start_cylinder_at(file, 1.2, GarmentTRun::rest_radius_m);
    CaseParameters parameters = file.parameters();
    parameters.output.write_files = false;
    GarmentTRun r;
    r.scenario = make_scenario(parameters);
    r.scenario->alphas = {1.2, 1.5};
    std::ostringstream log;
    r.result = run_scenario(
        *r.scenario,
        [&](const Problem& problem) { return file.create_backend("massspring", problem); }, "", log,
        [&](const StepMeasurement& m) { r.measured.push_back(m); });
    if (!r.result.completed) ADD_FAILURE() << r.result.failure << "\n" << log.str();
    return r;
  }();
  return run;
}

}  // namespace tightfit
