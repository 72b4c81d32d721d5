// A scenario built from a case's parameters (docs/scenarios.md): the garment and its mesh, the
// material law, the body, the constraints and the schedule of load steps, with the Problem
// both backends solve. Everything particular to one kind of case (a tube on a cylinder, a
// sheet on a plane) lives in the parts the case file chose (cases/parts/).
#pragma once

#include "cases/case_parameters.h"
#include "core/backend.h"
#include "core/garment.h"

#include <memory>
#include <optional>
#include <vector>

namespace tightfit {

struct Scenario {
  Scenario() = default;
  // `problem` points into the members below: a scenario is neither copied nor moved (made on
  // the heap by make_scenario and kept there).
  Scenario(const Scenario&) = delete;
  Scenario& operator=(const Scenario&) = delete;

  CaseParameters parameters;
  Garment garment;
  SimulationMesh mesh;
  std::unique_ptr<MaterialLaw> law;
  std::unique_ptr<ScenarioBody> body;
  Problem problem;  // points into the members above
  // The line a garment cut to the body was cut along (GarmentMaker::make_on_body), if it was.
  std::optional<GarmentLine> garment_line;
  double mean_edge_length_m = 0.0;
  // Every load step's body morph parameter, the first the settling one.
  std::vector<double> alphas;

  // The placement's start positions of the garment, m, found once when the scenario is made
  // (a dressing solves for them).
  std::vector<Vec3> start_positions_m;
  const std::vector<Vec3>& initial_positions() const { return start_positions_m; }
  // Shapes the body for load step `step` and returns that step's description.
  LoadStep prepare_step(int step);
};

// Throws std::invalid_argument with a message naming the parameter at fault (a garment that
// can never press on the body, an unknown vertex group, a bad value, a placement that starts
// the garment inside the body or over a hundred garment sizes away from it).
std::unique_ptr<Scenario> make_scenario(const CaseParameters& parameters);

// The case's body alone, as make_scenario makes it (for commands that look at the body only).
std::unique_ptr<ScenarioBody> make_case_body(const CaseParameters& parameters);

}  // namespace tightfit
