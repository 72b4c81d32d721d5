// Post-processing of a converged step: the SurfaceState the shared pressure extractor reads
// and the backend's own contact traction per welded vertex.
//
// Degree 1: the membrane's nodal forces and the contact multipliers over the vertices' current
// barycentric areas. Degree 2: quadratic triangles carry consistent loads (about nothing at
// the corners under a uniform pressure), so the traction is recovered on the curved surface
// (traction_recovery.h) and handed to the extractor as forces it turns back into that traction
// (see fem_backend.h).
#pragma once

#include "core/surface_state.h"
#include "fem/membrane_assembly.h"
#include "fem/reference_mesh.h"

#include <vector>

namespace tightfit {

struct FemSurfaceOutput {
  SurfaceState state;
  std::vector<double> contact_traction_Pa;  // per welded vertex, zero off contact
};

// `gravity_load_N`: per node, the weight the garment carries in this step (empty without
// gravity); degree 2 needs it to tell the garment's own force from the contact force.
// `friction_force_N`: per node, the tangential contact force (empty or zero without friction):
// it joins the contact force, where the extractor reads it as friction traction (degree 2: the
// traction recovered from the nodal forces, as for the normal one).
// `x` is this rank's part of the positions, `multiplier_N` and `friction_force_N` every node's
// (ReferenceMesh::gather_nodes): every rank builds the whole output.
FemSurfaceOutput surface_output(const ReferenceMesh& pattern, const MembraneAssembly& assembly,
                                const RigidBody& body, const DofVector& x,
                                const std::vector<double>& multiplier_N,
                                const std::vector<Vec3>& gravity_load_N,
                                const std::vector<Vec3>& friction_force_N);

// The output as a rank keeps it between steps: the values of its owned nodes only (in the order
// of ReferenceMesh::owned_nodes; an edge midpoint's are zero), so that no rank holds every
// vertex's state while the next step is solved. state() and contact_traction_Pa() give every
// vertex's again, on every rank (collective; empty before the first step), exactly: each
// vertex's values come from the one rank that owns it.
class OwnedSurfaceOutput {
 public:
  OwnedSurfaceOutput() = default;
  OwnedSurfaceOutput(const ReferenceMesh& pattern, const FemSurfaceOutput& whole);
  SurfaceState state(const ReferenceMesh& pattern) const;
  std::vector<double> contact_traction_Pa(const ReferenceMesh& pattern) const;

 private:
  bool has_step_ = false;
  std::vector<Vec3> positions_m_, internal_force_N_, contact_force_N_;
  std::vector<double> gap_m_, in_contact_, contact_traction_Pa_;  // in contact: 1 or 0
};

}  // namespace tightfit
