// The finite-element membrane backend: the garment's pattern is the reference
// domain, the unknown is the 3D position field, seams are constraints, contact is
// augmented-Lagrangian through contact/, and each load step is solved by Newton's method.
// deal.II stays behind the pointer to the implementation: this header is light.
//
// Element degree 2 (quadratic triangles) has a node at every edge midpoint besides the
// vertices: seams identify midpoints pairwise as they identify vertices, held ends hold the
// midpoints of the end rows' edges, and contact acts at every node. What the shared extractor
// reads then differs from degree 1. There, SurfaceState::internal_force_N is the membrane's
// own nodal force. For degree 2 it is not: the nodal forces of quadratic triangles are
// consistent loads (about zero at the corners under a uniform pressure), so the contact
// traction t is recovered on the curved surface by solving the surface mass-matrix system
// M t = f for the nodal contact forces f (traction_recovery.h), and each welded vertex gets
//   internal_force_N = -(t A_v) n_v,
// A_v its flat barycentric area and n_v the extractor's vertex normal: the extractor's
// pressure at the vertex is t, its mean is exact under a uniform pressure, and
// contact_traction_Pa() equals it. StepReport::text() says so.
#pragma once

#include "core/backend.h"
#include "fem/fem_parameters.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace tightfit {

class FemBackend final : public Backend {
 public:
  // Builds the mesh, the degrees of freedom and the seam constraints, distributed over
  // MPI_COMM_WORLD (MPI and PETSc are started here when the program has not done so). The
  // problem's mesh and constraints are read on rank 0 (Problem::mesh), which sends each rank its
  // part of the mesh (fem/mesh_part.h).
  FemBackend(const Problem& problem, const FemParameters& parameters);
  ~FemBackend() override;

  std::string name() const override { return "fem"; }
  void set_positions(const std::vector<Vec3>& positions_m) override;
  // Throws SolverError naming the step (index, alpha) and the residual when it fails.
  StepReport solve(const LoadStep& step) override;
  // Every vertex's, on every rank; collective: each rank keeps its own vertices' output only.
  SurfaceState state() const override;
  // contact_traction_Pa() as "contact_traction_Pa", beside the extractor's pressure_Pa
  // (collective).
  std::vector<std::pair<std::string, std::vector<double>>> extra_point_data() const override;

  // Contact traction at each welded vertex, Pa (zero off contact), written beside the
  // extractor's pressure. Degree 1: the contact multiplier over the vertex's current
  // barycentric area. Degree 2: the traction recovered on the curved surface. Collective.
  std::vector<double> contact_traction_Pa() const;
  // The contact multipliers of every node (vertices, then with degree 2 the edge midpoints)
  // after the last step, N: the solver's own nodal contact forces, before any traction is
  // recovered from them. Collective (each rank keeps its own nodes').
  std::vector<double> nodal_contact_force_N() const;
  // Largest penetration of a vertex in contact after the last step, m.
  double max_penetration_m() const;
  // Residual-force history (largest component, N) of every Newton iteration of the last step.
  const std::vector<double>& last_residual_history_N() const;

  // For tests, serial only: the residual R = dPi/dx - f_contact (N) on the nodes and its
  // derivative dR/dx (N/m, 3n x 3n, node-major) at `node_positions_m`, with the current
  // contact multipliers and without pins or held ends. The nodes are the welded vertices, then
  // with degree 2 the midpoints of the welded edges (node_positions gives them); every copy of
  // a seam node takes its node's position.
  void linearise(const std::vector<Vec3>& node_positions_m, Eigen::VectorXd& residual_N,
                 Eigen::MatrixXd& tangent_N_per_m) const;
  // For tests, serial only, at `node_positions_m` (as for linearise) with the current contact
  // multipliers: the potential whose gradient is R for frictionless contact (J), and how far R
  // is from that gradient (N) (fem/membrane_assembly.h).
  double energy_J(const std::vector<Vec3>& node_positions_m, bool gravity_on) const;
  double potential_defect_N(const std::vector<Vec3>& node_positions_m) const;
  // The nodes' positions for the welded vertices at `vertex_positions_m`: those, then (degree
  // 2) each edge's midpoint on its chord.
  std::vector<Vec3> node_positions(const std::vector<Vec3>& vertex_positions_m) const;
  // The garment's weight as consistent nodal loads on the nodes (as for node_positions), N:
  // applied in the load steps with LoadStep::gravity_on (membrane_assembly.h).
  std::vector<Vec3> gravity_load_N() const;
  // The membrane's internal force (minus the energy gradient) on each welded vertex, N. With
  // degree 2 the edge midpoints sit on the chords between the given vertices, and their own
  // forces are left out.
  std::vector<Vec3> internal_force_N(const std::vector<Vec3>& positions_m) const;

 private:
  class Implementation;
  std::unique_ptr<Implementation> impl_;
};

}  // namespace tightfit
