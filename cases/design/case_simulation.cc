#include "cases/design/case_simulation.h"

#include "cases/design/band_pressure.h"
#include "cases/design/stocking_cut.h"
#include "cases/scenario.h"
#include "cases/scenario_run.h"

#include <filesystem>
#include <fstream>

namespace tightfit {

std::vector<BandPressure> simulate_cut(const CaseSimulationSetup& setup,
                                       const std::vector<double>& circumferences_m,
                                       const std::string& backend, const std::string& output_dir) {
  CaseFile file;
  file.read(setup.case_file, setup.case_overrides);
  const std::vector<CutKnot> cut = design_cut(setup.limb_girths_m, setup.points, circumferences_m);
  file.set("Garment/Tapered tube/Girths=" + relaxed_girths_setting(cut));
  file.set("Garment/Tapered tube/Negative ease=");
  file.set("Output/Directory=" + output_dir);
  if (!backend.empty()) file.set("Solver/Backend=" + backend);
  const CaseParameters parameters = file.parameters();
  std::unique_ptr<Scenario> scenario = make_scenario(parameters);
  std::filesystem::create_directories(output_dir);
  std::ofstream log((std::filesystem::path(output_dir) / "run.log").string());
  const RunResult run = run_scenario(
      *scenario,
      [&](const Problem& problem) { return file.create_backend(parameters.backend, problem); },
      output_dir, log);
  if (!run.completed || run.steps.empty())
    throw DesignRunFailed("the simulation in " + output_dir + " stopped early: " + run.failure);
  std::vector<double> heights;
  for (const NamedValue& p : setup.points) heights.push_back(p.value);
  return band_pressures(scenario->mesh, run.steps.back(), heights, setup.band_width_m);
}

}  // namespace tightfit
