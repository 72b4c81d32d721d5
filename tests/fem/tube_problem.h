// The paper's cylinder study as the FE tests need it: a tube garment placed round a rigid
// cylinder (axis z through the origin), with the closed forms of cylinder-theory.md.
#pragma once

#include "contact/cylinder.h"
#include "contact/pressure_extractor.h"
#include "core/backend.h"
#include "core/material.h"
#include "core/tube_garment.h"

#include <cmath>
#include <memory>
#include <string>
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
      : garment(make_tube_garment("4 5T", 0.1878, 0.24, 2, spacing)), mesh(weld(garment)) {
    law = make_material_law(law_name, fabric);
    rest_radius_m = garment.ring_circumference_m / (2.0 * M_PI);
    cylinder = std::make_unique<Cylinder>(Vec3::Zero(), Vec3::UnitZ(), rest_radius_m);
    problem.mesh = &mesh;
    problem.law = law.get();
    problem.fabric = &fabric;
    problem.body = cylinder.get();
    problem.end_condition = ends;
    if (ends == EndCondition::held_ends) {
      for (const char* edge : {"bottom", "top"})
        for (int v : mesh.vertex_groups.at(edge)) problem.held_vertices.push_back(v);
      problem.held_direction = Vec3::UnitZ();
    }
  }

  // The tube as a circle of radius `radius_m`: layout (u, v) goes to angle 2 pi u / L and
  // axial coordinate v - H/2; the triangles' winding then gives outward normals.
  std::vector<Vec3> placed(double radius_m) const {
    std::vector<Vec3> x(mesh.n_vertices);
    const double L = garment.ring_circumference_m;
    for (int u = 0; u < mesh.n_unwelded_vertices(); ++u) {
      const Vec2& p = mesh.layout_positions_m[u];
      const double angle = 2.0 * M_PI * p.x() / L;
      x[mesh.welded_index[u]] =
          Vec3(radius_m * std::cos(angle), radius_m * std::sin(angle), p.y() - 0.5 * height_m);
    }
    return x;
  }

  // Sets the cylinder to alpha R0.
  void grow_to(double alpha) { cylinder->set_radius(alpha * rest_radius_m); }

  PressureSummary pressure(const SurfaceState& state) const {
    return summarize(
        extract_pressure(mesh.triangles, state, VertexAreaDefinition::barycentric, cylinder.get()));
  }
};

// cylinder-theory.md, "Results": pressure on a cylinder of radius alpha R0, Pa.
inline double closed_form_pressure_Pa(const std::string& law, EndCondition ends, double a,
                                      const FabricParameters& f, double R0) {
  const double Y1 = f.stiffness_weft_N_per_m;
  const double nu12 = f.poisson_weft_warp, nu21 = f.poisson_warp_weft();
  const double Gt0 = f.neo_hookean_shear_modulus_Pa * f.thickness_m;
  const bool free_ends = ends == EndCondition::free_ends;
  if (law == "linear biot")
    return free_ends ? Y1 * (1 - 1 / a) / (R0 * (1 - nu12 * (a - 1)))
                     : Y1 * (1 - 1 / a) / (R0 * (1 - nu12 * nu21));
  if (law == "st venant kirchhoff")
    return free_ends ? Y1 * (a * a - 1) / (2 * R0 * std::sqrt(1 - nu12 * (a * a - 1)))
                     : Y1 * (a * a - 1) / (2 * R0 * (1 - nu12 * nu21));
  // Incompressible neo-Hookean.
  return free_ends ? Gt0 * (std::sqrt(a) - std::pow(a, -2.5)) / R0
                   : Gt0 * (1 - std::pow(a, -4)) / R0;
}

}  // namespace tightfit::testing
