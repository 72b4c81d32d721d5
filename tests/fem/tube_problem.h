// The paper's cylinder study as the FE tests need it: a tube garment placed round a rigid
// cylinder (axis z through the origin), with the closed forms of cases/cylinder_theory.h.
#pragma once

#include "bodies/cylinder.h"
#include "bodies/tube_placement.h"
#include "cases/cylinder_theory.h"
#include "contact/pressure_extractor.h"
#include "core/backend.h"
#include "core/constrained_directions.h"
#include "core/material.h"
#include "core/tube_garment.h"

#include <mpi.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tightfit::testing {

// Builds the garment and its mesh on the first rank of MPI_COMM_WORLD only (TubeCase's
// constructor tag).
struct MeshOnFirstRank {};

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
    set_up(law_name, ends, ring_circumference_m(garment) / (2.0 * M_PI));
  }

  // The "4 5T" garment as above, with the garment and its mesh on the first rank only: the
  // other ranks hold neither (nor the held ends' constraints: the FE backend reads the first
  // rank's), their problem.mesh is null, and placed() hands every rank the first rank's
  // positions (collective). pressure() reads the mesh: the first rank's only.
  TubeCase(const std::string& law_name, EndCondition ends, MeshSpacing spacing, MeshOnFirstRank)
      : mesh_on_first_rank_(true) {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    double radius_m = 0.0;
    if (rank_ == 0) {
      garment = make_tube_garment("4 5T", 0.1878, 0.24, 2, spacing);
      mesh = weld(garment);
      radius_m = ring_circumference_m(garment) / (2.0 * M_PI);
      n_vertices_ = mesh.n_vertices;
    }
    MPI_Bcast(&radius_m, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    MPI_Bcast(&n_vertices_, 1, MPI_INT, 0, MPI_COMM_WORLD);
    set_up(law_name, ends, radius_m);
  }

  // The welded vertices, on every rank.
  int n_vertices() const { return mesh_on_first_rank_ ? n_vertices_ : mesh.n_vertices; }

  // The tube as a circle of radius `radius_m`: layout (u, v) goes to angle 2 pi u / L and
  // axial coordinate v - H/2; the triangles' winding then gives outward normals.
  std::vector<Vec3> placed(double radius_m) const {
    if (!mesh_on_first_rank_) return place_tube_round_cylinder(garment, mesh, *cylinder, radius_m);
    std::vector<Vec3> positions_m(n_vertices_, Vec3::Zero());
    if (rank_ == 0) positions_m = place_tube_round_cylinder(garment, mesh, *cylinder, radius_m);
    MPI_Bcast(positions_m.data()->data(), 3 * n_vertices_, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    return positions_m;
  }

  // Sets the cylinder to alpha R0.
  void grow_to(double alpha) { cylinder->set_radius(alpha * rest_radius_m); }

  PressureSummary pressure(const SurfaceState& state) const {
    return summarize(
        extract_pressure(mesh.triangles, state, VertexAreaDefinition::barycentric, cylinder.get()));
  }

 private:
  bool mesh_on_first_rank_ = false;
  int rank_ = 0;
  int n_vertices_ = 0;  // with the mesh on the first rank only

  // The law, the cylinder of radius `radius_m` and the problem (the mesh and the held ends
  // where this rank has the mesh).
  void set_up(const std::string& law_name, EndCondition ends, double radius_m) {
    law = make_material_law(law_name, fabric);
    rest_radius_m = radius_m;
    cylinder = std::make_unique<Cylinder>(Vec3::Zero(), Vec3::UnitZ(), rest_radius_m);
    const bool has_mesh = !mesh_on_first_rank_ || rank_ == 0;
    problem.mesh = has_mesh ? &mesh : nullptr;
    problem.law = law.get();
    problem.fabric = &fabric;
    problem.body = cylinder.get();
    if (has_mesh && ends == EndCondition::held_ends)
      for (const char* edge : {"bottom", "top"})
        problem.constraints.push_back(held_along(mesh, edge, Vec3::UnitZ()));
  }
};

}  // namespace tightfit::testing
