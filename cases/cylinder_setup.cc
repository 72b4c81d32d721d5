#include "cases/cylinder_setup.h"

#include "cases/load_steps.h"
#include "contact/penalty_contact.h"
#include "contact/tube_placement.h"
#include "core/tube_garment.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tightfit {

std::unique_ptr<CylinderSetup> make_cylinder_setup(const CaseParameters& parameters) {
  auto setup = std::make_unique<CylinderSetup>();
  CylinderSetup& s = *setup;
  s.parameters = parameters;
  const GarmentSettings& g = parameters.garment;
  s.garment = make_tube_garment(g.name, g.panel_width_m, g.panel_height_m, g.n_panels, g.spacing);
  s.mesh = weld(s.garment);
  s.law = make_material_law(parameters.law, parameters.fabric);
  s.rest_radius_m = s.garment.ring_circumference_m / (2.0 * M_PI);
  s.mean_edge_length_m = mean_rest_edge_length_m(s.mesh);
  s.body = std::make_unique<Cylinder>(parameters.body.axis_point_m, parameters.body.axis,
                                      parameters.body.initial_radius_m,
                                      parameters.body.display_height_m);

  const double initial_alpha = parameters.body.initial_radius_m / s.rest_radius_m;
  if (parameters.protocol.final_alpha <= 1.0) {
    std::ostringstream message;
    message << "Protocol/Final alpha = " << parameters.protocol.final_alpha
            << ": the garment (rest radius R0 = " << s.rest_radius_m * 100
            << " cm) never presses on the cylinder; pressure needs alpha = r/R0 > 1";
    throw std::invalid_argument(message.str());
  }
  s.alphas = alpha_schedule(initial_alpha, parameters.protocol.final_alpha,
                            parameters.protocol.alpha_increment);

  Problem& p = s.problem;
  p.mesh = &s.mesh;
  p.law = s.law.get();
  p.fabric = &s.parameters.fabric;
  p.body = s.body.get();
  p.contact_stiffness_Pa_per_m = penalty_stiffness_Pa_per_m(
      parameters.penalty_factor, s.law->stiffness_scale(), s.mean_edge_length_m);
  p.end_condition = parameters.protocol.end_condition;
  if (p.end_condition == EndCondition::held_ends) {
    for (const char* group : {"bottom", "top"})
      for (int v : s.mesh.vertex_groups.at(group)) p.held_vertices.push_back(v);
    p.held_direction = s.body->axis();
  }
  p.gravity_m_per_s2 = -parameters.protocol.gravity_m_per_s2 * parameters.protocol.up.normalized();
  return setup;
}

std::vector<Vec3> CylinderSetup::initial_positions() const {
  // Start stress-free at R0 when the tube is loose, else 0.5% outside the body.
  const double radius = std::max(rest_radius_m, 1.005 * body->radius_m());
  return place_tube_round_cylinder(garment, mesh, *body, radius);
}

LoadStep CylinderSetup::prepare_step(int step) {
  LoadStep load;
  load.index = step;
  load.alpha = alphas.at(step);
  load.gravity_on = step == 0 ? parameters.protocol.gravity_while_settling
                              : parameters.protocol.gravity_while_measuring;
  body->set_radius(step == 0 ? parameters.body.initial_radius_m : radius_at(load.alpha));
  return load;
}

}  // namespace tightfit
