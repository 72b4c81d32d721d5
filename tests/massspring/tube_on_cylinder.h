// The paper's cylinder study (Sections 4-5) as a test fixture: a sewn tube on a rigid
// cylinder along z, linear Biot with zero Poisson ratio, free ends, no gravity.
#pragma once

#include "bodies/cylinder.h"
#include "bodies/tube_placement.h"
#include "contact/penalty_contact.h"
#include "core/tube_garment.h"
#include "massspring/lumped_mass.h"
#include "massspring/massspring_backend.h"

#include <cmath>
#include <memory>

namespace tightfit::test {

struct TubeOnCylinder {
  static constexpr double height_m = 0.24;
  double circumference_m;
  Garment garment;
  SimulationMesh mesh;
  FabricParameters fabric;
  std::unique_ptr<MaterialLaw> law;
  Cylinder cylinder;
  Problem problem;

  TubeOnCylinder(double panel_width_m, const MeshSpacing& spacing, double poisson = 0.0)
      : circumference_m(2 * panel_width_m),
        garment(make_tube_garment("tube", panel_width_m, height_m, 2, spacing)),
        mesh(weld(garment)),
        cylinder(Vec3::Zero(), Vec3::UnitZ(), rest_radius_m()) {
    fabric.poisson_weft_warp = poisson;
    law = make_material_law("linear biot", fabric);
    problem.mesh = &mesh;
    problem.law = law.get();
    problem.fabric = &fabric;
    problem.body = &cylinder;
    // Penalty factor 50 (penalty_contact.h): penetration ~ strain / 50 edge lengths.
    problem.contact_stiffness_Pa_per_m =
        penalty_stiffness_Pa_per_m(50.0, law->stiffness_scale(), mean_rest_edge_length_m(mesh));
  }
  double rest_radius_m() const { return circumference_m / (2 * M_PI); }
  // The sewn tube as a circle round the cylinder of radius max(R0, r).
  std::vector<Vec3> start_positions() const {
    return place_tube_round_cylinder(garment, mesh, cylinder,
                                     std::max(rest_radius_m(), cylinder.radius_m()));
  }
  // The paper's Eq. 7: p = Et (1 - 1/alpha) / R0, hoop = weft.
  double eq7_pressure_Pa(double alpha) const {
    return fabric.stiffness_weft_N_per_m * (1 - 1 / alpha) / rest_radius_m();
  }
};

}  // namespace tightfit::test
