// The constraints on the Newton increments: every copy of a seam node follows the copy that
// carries it, constrained nodes (held groups, fixed groups) keep their coordinates along their
// directions, and vertices are pinned against the body's free rigid motions
// (rigid_motion_pin.h). They fix the tangent's sparsity pattern, so the system is rebuilt
// with them.
#pragma once

#include "fem/newton_system.h"
#include "fem/reference_mesh.h"

namespace tightfit {

// Rebuilds system.constraints for the garment with its welded vertices at `positions_m` (the
// pin is chosen there), then the tangent's pattern and the vectors on the rank's own DoFs.
void build_constraints_and_system(const ReferenceMesh& pattern, const Problem& problem,
                                  const std::vector<Vec3>& positions_m, MPI_Comm comm,
                                  NewtonSystem& system);

}  // namespace tightfit
