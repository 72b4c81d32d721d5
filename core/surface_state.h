// What a backend hands to the shared measurement code: the garment's current surface.
#pragma once

#include "core/types.h"

#include <vector>

namespace tightfit {

// One entry per welded vertex of the SimulationMesh the backend solved.
struct SurfaceState {
  std::vector<Vec3> positions_m;
  // Force the garment itself (membrane and bending) exerts on each vertex, N. At equilibrium
  // it balances the contact force; the pressure extractor reads pressure from it, as the
  // paper's simulator did (Section 2.2).
  std::vector<Vec3> internal_force_N;
  // Force the body exerts on each vertex, N.
  std::vector<Vec3> contact_force_N;
  // 1 where the vertex touches the body.
  std::vector<char> in_contact;
  // Signed distance to the body surface, m (negative inside).
  std::vector<double> gap_m;

  std::size_t size() const { return positions_m.size(); }
};

}  // namespace tightfit
