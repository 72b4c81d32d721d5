#include "cases/scenario.h"

#include "cases/load_steps.h"
#include "contact/penalty_contact.h"
#include "core/constrained_directions.h"
#include "core/memory_budget.h"
#include "core/thread_count.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace tightfit {

namespace {

// The ranks of the run: 1 where MPI has not been started (a test, a serial driver).
int run_ranks() {
  int started = 0;
  MPI_Initialized(&started);
  if (!started) return 1;
  int ranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  return ranks;
}

// Constraints/Held groups and Fixed groups on the garment's vertex groups. With `no_direction`,
// held groups with no direction to hold along are left out and it is set, instead of refused.
std::vector<VertexConstraint> make_constraints(const ConstraintSettings& settings,
                                               const SimulationMesh& mesh, const ScenarioBody& body,
                                               const std::optional<GarmentLine>& line,
                                               bool* no_direction = nullptr) {
  std::vector<VertexConstraint> constraints;
  try {
    if (!settings.held_groups.empty()) {
      // 'axis': the line a garment cut to the body was cut along, else the body's own axis.
      const std::optional<Vec3> direction = settings.held_direction ? settings.held_direction
                                            : line                  ? line->axis
                                                                    : body.axis();
      if (!direction && no_direction)
        *no_direction = true;
      else if (!direction)
        throw std::invalid_argument("Held direction = axis, but the body (" + body.describe() +
                                    ") has no axis and the garment is not cut along one: give a "
                                    "direction x,y,z");
      for (const std::string& group : settings.held_groups)
        if (direction) constraints.push_back(held_along(mesh, group, *direction));
    }
    for (const std::string& group : settings.fixed_groups)
      constraints.push_back(fixed_group(mesh, group));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("Constraints: ") + e.what());
  }
  return constraints;
}

// The placement must start the garment outside the body and near it: a vertex inside is pushed
// out violently by the penalty (or, deep inside, through to the far side), and a garment
// kilometres away never touches. Both are nearly always a body in the wrong units or frame.
void check_start(const Scenario& s, const std::vector<Vec3>& x) {
  const RigidBody& body = s.body->body();
  const double size_m = std::sqrt(rest_area(s.mesh));
  int deepest = -1, nearest = -1;
  double deepest_g = 0.0, nearest_g = std::numeric_limits<double>::infinity();
  for (int v = 0; v < static_cast<int>(x.size()); ++v) {
    const double g = body.query(x[v]).signed_distance_m;
    if (g < deepest_g) deepest_g = g, deepest = v;
    if (g < nearest_g) nearest_g = g, nearest = v;
  }
  const auto where = [&](int v) {
    std::ostringstream out;
    out << "vertex " << v << " at (" << x[v].x() << ", " << x[v].y() << ", " << x[v].z() << ") m";
    return out.str();
  };
  const std::string check =
      "; check the placement and the body's units and frame (Body/Mesh/Unit scale, Up axis, "
      "Translation)";
  // Round-off of a garment laid exactly on the body (a sheet at zero gap) is not a start inside.
  if (deepest >= 0 && deepest_g < -1e-9 * std::max(1.0, size_m)) {
    std::ostringstream message;
    message << "Placement/Kind = " << s.parameters.placement.kind
            << ": the garment starts inside the body (" << s.body->describe()
            << "): " << where(deepest) << " lies " << -deepest_g << " m deep" << check;
    throw std::invalid_argument(message.str());
  }
  const double far_m = 100.0 * size_m;
  if (nearest_g > far_m) {
    std::ostringstream message;
    message << "Placement/Kind = " << s.parameters.placement.kind << ": the garment starts "
            << nearest_g << " m from the body (" << s.body->describe() << "; nearest "
            << where(nearest) << "), over 100 times its own size of " << size_m
            << " m, and could never reach it" << check;
    throw std::invalid_argument(message.str());
  }
}

}  // namespace

std::unique_ptr<Scenario> make_scenario(const CaseParameters& parameters) {
  auto scenario = std::make_unique<Scenario>();
  Scenario& s = *scenario;
  s.parameters = parameters;
  // A garment cut to the body is made from it; every other one first (a cylinder body is sized
  // by its tube).
  if (parameters.garment.make.needs_body()) {
    s.body = make_case_body(parameters);
    GarmentOnBody cut = parameters.garment.make.make_on_body(parameters.garment.name,
                                                             parameters.garment.spacing, *s.body);
    s.garment = std::move(cut.garment);
    s.garment_line = cut.line;
  } else {
    s.garment = parameters.garment.make(parameters.garment.name, parameters.garment.spacing);
  }
  // Each panel was checked as it was meshed; the run holds them all.
  double n_vertices = 0;
  for (const Panel& panel : s.garment.panels) n_vertices += panel.rest_positions_m.size();
  require_memory("garment '" + s.garment.name + "': a run", n_vertices, "vertices",
                 run_bytes_per_garment_vertex);
  s.mesh = weld(s.garment);
  s.law = make_material_law(parameters.law, parameters.fabric);
  s.mean_edge_length_m = mean_rest_edge_length_m(s.mesh);
  if (!s.body) s.body = parameters.body.make(s.garment);
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
  p.friction_coefficient = parameters.friction_coefficient;
  p.tangential_stiffness_Pa_per_m =
      parameters.tangential_penalty_ratio * p.contact_stiffness_Pa_per_m;
  // A placement that puts the garment on a line of the body (a tube on a leg's line) gives the
  // line Held direction = axis holds along: the constraints are made again after it, and a
  // direction not found before it is refused only if the placement gives none either.
  const bool cut_along_line = s.garment_line.has_value();
  bool no_direction = false;
  p.constraints =
      make_constraints(parameters.constraints, s.mesh, *s.body, s.garment_line, &no_direction);
  p.gravity_m_per_s2 = -parameters.protocol.gravity_m_per_s2 * parameters.protocol.up.normalized();
  p.threads = threads_for_run(parameters.threads, run_ranks());
  s.start_positions_m = parameters.placement.place(s);
  if ((!cut_along_line && s.garment_line) || no_direction)
    p.constraints = make_constraints(parameters.constraints, s.mesh, *s.body, s.garment_line);
  check_start(s, s.start_positions_m);
  return scenario;
}

std::unique_ptr<ScenarioBody> make_case_body(const CaseParameters& parameters) {
  // A body that needs the garment (a cylinder sized by its tube) cannot carry one cut to the
  // body; it is given an empty garment and the garment's own cut then fails on it.
  if (parameters.garment.make.needs_body()) return parameters.body.make(Garment{});
  return parameters.body.make(
      parameters.garment.make(parameters.garment.name, parameters.garment.spacing));
}

Garment GarmentMaker::operator()(const std::string& name, const MeshSpacing& spacing) const {
  if (!make)
    throw std::invalid_argument("garment '" + name +
                                "' is cut to the body: it is made from the body (make_scenario)");
  return make(name, spacing);
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
