#include "cases/design/case_simulation.h"

#include "cases/design/band_pressure.h"
#include "cases/design/stocking_cut.h"
#include "cases/scenario.h"
#include "cases/scenario_run.h"

#include <filesystem>
#include <fstream>
#include <optional>

namespace tightfit {

std::vector<BandPressure> simulate_cut(const CaseSimulationSetup& setup,
                                       const std::vector<double>& circumferences_m,
                                       const std::string& backend, const std::string& output_dir,
                                       const std::string& start_from) {
  CaseFile file;
  file.read(setup.case_file, setup.case_overrides);
  const std::vector<CutKnot> cut = design_cut(setup.limb_girths_m, setup.points, circumferences_m);
  if (setup.garment_kind == "limb tube") {
    file.set("Garment/Limb tube/Relaxed girths=" + relaxed_girths_setting(cut));
  } else {
    file.set("Garment/Tapered tube/Girths=" + relaxed_girths_setting(cut));
    file.set("Garment/Tapered tube/Negative ease=");
  }
  file.set("Output/Directory=" + output_dir);
  if (!backend.empty()) file.set("Solver/Backend=" + backend);
  CaseParameters parameters = file.parameters();
  std::unique_ptr<Scenario> scenario;
  if (!start_from.empty() && std::filesystem::exists(start_from)) {
    file.set("Placement/Kind=from file");
    file.set("Placement/From file/File=" + start_from);
    try {
      scenario = make_scenario(file.parameters());
      parameters = scenario->parameters;
    } catch (const std::invalid_argument&) {
      scenario.reset();  // another mesh: the case's own placement
    }
  }
  if (!scenario) scenario = make_scenario(parameters);
  // The limb's axis: the direction the garment is held along, else the line it was cut along
  // (a limb tube), else the body's own.
  const std::optional<Vec3> axis = parameters.constraints.held_direction
                                       ? parameters.constraints.held_direction
                                   : scenario->garment_line ? scenario->garment_line->axis
                                                            : scenario->body->axis();
  if (!axis)
    throw std::invalid_argument(
        "the case's garment is not held along a direction and its body "
        "has no axis: the bands round the measuring points are not "
        "defined (Constraints/Held direction)");
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
  return band_pressures(scenario->mesh, run.steps.back(), heights, setup.band_width_m, *axis);
}

}  // namespace tightfit
