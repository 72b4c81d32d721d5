// Runs a case given as "Path/Entry=value" settings on one backend, writing nothing: what the
// body scenario tests (cone, mesh body, friction) share.
#pragma once

#include "cases/case_parameters.h"
#include "cases/scenario.h"
#include "cases/scenario_run.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace tightfit::testing {

// "Path/Entry=value" with the value printed to round-trip.
inline std::string setting(const std::string& entry, double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  return entry + "=" + text;
}

struct BodyCaseRun {
  RunResult run;
  std::vector<Vec3> start_m;  // the placement's positions
  std::string log;
  const StepMeasurement& last() const { return run.steps.back(); }
  // Mean displacement of the garment's vertices along `axis` from the start, m.
  double mean_shift_m(const Vec3& axis) const {
    const std::vector<Vec3>& x = last().state.positions_m;
    double sum = 0.0;
    for (std::size_t v = 0; v < x.size(); ++v) sum += (x[v] - start_m[v]).dot(axis);
    return sum / double(x.size());
  }
};

inline BodyCaseRun run_body_case(const std::vector<std::string>& settings,
                                 const std::string& backend) {
  CaseFile file;
  file.set("Output/Write VTU=false");
  file.set("Measurements/List=");
  for (const std::string& s : settings) file.set(s);
  CaseParameters parameters = file.parameters();
  parameters.output.write_files = false;
  std::unique_ptr<Scenario> scenario = make_scenario(parameters);
  BodyCaseRun result;
  scenario->prepare_step(0);
  result.start_m = scenario->initial_positions();
  std::ostringstream log;
  result.run = run_scenario(
      *scenario, [&](const Problem& problem) { return file.create_backend(backend, problem); }, "",
      log);
  result.log = log.str();
  return result;
}

// A case file already read (with its overrides) run on one backend, writing nothing; the
// scenario is kept for checks that need its mesh or parameters.
struct CaseFileRun {
  std::unique_ptr<Scenario> scenario;
  RunResult run;
  std::string log;
};

// `on_step` sees each step whole (the run keeps the last one's per-vertex arrays only).
inline CaseFileRun run_case_file(const CaseFile& file, const std::string& backend,
                                 const StepObserver& on_step = {}) {
  CaseParameters parameters = file.parameters();
  parameters.output.write_files = false;
  CaseFileRun result;
  result.scenario = make_scenario(parameters);
  std::ostringstream log;
  result.run = run_scenario(
      *result.scenario,
      [&](const Problem& problem) { return file.create_backend(backend, problem); }, "", log,
      on_step);
  result.log = log.str();
  return result;
}

}  // namespace tightfit::testing
