#include "cases/scenario.h"

#include "cases/load_steps.h"
#include "contact/penalty_contact.h"
#include "core/constrained_directions.h"
#include "core/memory_budget.h"

#include <stdexcept>

namespace tightfit {

namespace {

// Constraints/Held groups and Fixed groups on the garment's vertex groups.
std::vector<VertexConstraint> make_constraints(const ConstraintSettings& settings,
                                               const SimulationMesh& mesh,
                                               const ScenarioBody& body) {
  std::vector<VertexConstraint> constraints;
  try {
    if (!settings.held_groups.empty()) {
      const std::optional<Vec3> direction =
          settings.held_direction ? settings.held_direction : body.axis();
      if (!direction)
        throw std::invalid_argument("Held direction = axis, but the body (" + body.describe() +
                                    ") has no axis: give a direction x,y,z");
      for (const std::string& group : settings.held_groups)
        constraints.push_back(held_along(mesh, group, *direction));
    }
    for (const std::string& group : settings.fixed_groups)
      constraints.push_back(fixed_group(mesh, group));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("Constraints: ") + e.what());
  }
  return constraints;
}

}  // namespace

std::unique_ptr<Scenario> make_scenario(const CaseParameters& parameters) {
  auto scenario = std::make_unique<Scenario>();
  Scenario& s = *scenario;
  s.parameters = parameters;
  s.garment = parameters.garment.make(parameters.garment.name, parameters.garment.spacing);
  // Each panel was checked as it was meshed; the run holds them all.
  double n_vertices = 0;
  for (const Panel& panel : s.garment.panels) n_vertices += panel.rest_positions_m.size();
  require_memory("garment '" + s.garment.name + "': a run", n_vertices, "vertices",
                 run_bytes_per_garment_vertex);
  s.mesh = weld(s.garment);
  s.law = make_material_law(parameters.law, parameters.fabric);
  s.mean_edge_length_m = mean_rest_edge_length_m(s.mesh);
  s.body = parameters.body.make(s.garment);
  s.body->check_final_alpha(parameters.protocol.final_alpha);
  s.alphas = alpha_schedule(s.body->initial_alpha(), parameters.protocol.final_alpha,
                            parameters.protocol.alpha_increment);

  Problem& p = s.problem;
  p.mesh = &s.mesh;
  p.law = s.law.get();
  p.fabric = &s.parameters.fabric;
  p.body = &s.body->body();
  p.contact_stiffness_Pa_per_m = penalty_stiffness_Pa_per_m(
      parameters.penalty_factor, s.law->stiffness_scale(), s.mean_edge_length_m);
  p.constraints = make_constraints(parameters.constraints, s.mesh, *s.body);
  p.gravity_m_per_s2 = -parameters.protocol.gravity_m_per_s2 * parameters.protocol.up.normalized();
  return scenario;
}

std::vector<Vec3> Scenario::initial_positions() const {
  return parameters.placement.place(*this);
}

LoadStep Scenario::prepare_step(int step) {
  LoadStep load;
  load.index = step;
  load.alpha = alphas.at(step);
  load.gravity_on = step == 0 ? parameters.protocol.gravity_while_settling
                              : parameters.protocol.gravity_while_measuring;
  body->morph(step, load.alpha);
  return load;
}

}  // namespace tightfit
