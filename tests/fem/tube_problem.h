// The paper's cylinder study as the FE tests need it: a tube garment placed round a rigid
// cylinder (axis z through the origin), with the closed forms of cases/cylinder_theory.h.
#pragma once

#include "cases/cylinder_theory.h"
#include "contact/cylinder.h"
#include "contact/pressure_extractor.h"
#include "contact/tube_placement.h"
#include "core/backend.h"
#include "core/constrained_directions.h"
#include "core/material.h"
#include "core/tube_garment.h"

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tightfit::testing {

struct TubeCase {
  FabricParameters fabric;
  Garment garment;
  SimulationMesh mesh;
  std::unique_ptr<MaterialLaw> law;
  std::unique_ptr<Cylinder> cylinder;
  Problem problem;
  double rest_radius_m = 0.0;
  double height_m = 0.24;

  // The "4 5T" garment (two panels 18.78 cm x 24 cm) at the given mesh spacing.
  TubeCase(const std::string& law_name, EndCondition ends, MeshSpacing spacing = MeshSpacing{})
      : TubeCase(law_name, ends, make_tube_garment("4 5T", 0.1878, 0.24, 2, spacing)) {}

  // Any tube sewn into a ring (ring_circumference_m), 0.24 m high.
  TubeCase(const std::string& law_name, EndCondition ends, Garment tube_garment)
      : garment(std::move(tube_garment)), mesh(weld(garment)) {
    law = make_material_law(law_name, fabric);
    rest_radius_m = ring_circumference_m(garment) / (2.0 * M_PI);
    cylinder = std::make_unique<Cylinder>(Vec3::Zero(), Vec3::UnitZ(), rest_radius_m);
    problem.mesh = &mesh;
    problem.law = law.get();
    problem.fabric = &fabric;
    problem.body = cylinder.get();
    if (ends == EndCondition::held_ends)
      for (const char* edge : {"bottom", "top"})
        problem.constraints.push_back(held_along(mesh, edge, Vec3::UnitZ()));
  }

  // The tube as a circle of radius `radius_m`: layout (u, v) goes to angle 2 pi u / L and
  // axial coordinate v - H/2; the triangles' winding then gives outward normals.
  std::vector<Vec3> placed(double radius_m) const {
    return place_tube_round_cylinder(garment, mesh, *cylinder, radius_m);
  }

  // Sets the cylinder to alpha R0.
  void grow_to(double alpha) { cylinder->set_radius(alpha * rest_radius_m); }

  PressureSummary pressure(const SurfaceState& state) const {
    return summarize(
        extract_pressure(mesh.triangles, state, VertexAreaDefinition::barycentric, cylinder.get()));
  }
};

}  // namespace tightfit::testing
