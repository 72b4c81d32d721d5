// The augmented-Lagrangian contact's state at the FE nodes (welded vertices, then with degree 2
// the welded edges' midpoints): each node's penalty stiffness and multiplier estimate, the
// arguments of contact/nodal_contact.h.
#pragma once

#include "core/garment.h"

#include <array>
#include <map>
#include <vector>

namespace tightfit {

struct ContactNodes {
  std::vector<double> penalty_N_per_m;  // k w_k per node (w_k its positive nodal rest area)
  std::vector<double> multiplier_N;     // augmented-Lagrangian estimate per node, N
};

// The penalty k w_k of each node, k in Pa/m and w_k a positive rest area per node. Linear
// triangles (degree 1): the barycentric third of each triangle (their lumped mass). Quadratic
// triangles: their lumped (row-sum) mass gives the corners zero area, which would leave them
// without contact, so each triangle is split at its edge midpoints into four linear triangles
// of area A/4 whose lumped masses give A/12 to each corner and A/4 to each midpoint
// (3 x A/12 + 3 x A/4 = A). `edge_index` maps a sorted welded vertex pair to its edge's
// midpoint node minus n_vertices. These weights only set the penalty, which the
// augmented-Lagrangian updates remove from the converged state.
std::vector<double> nodal_penalties_N_per_m(const SimulationMesh& mesh,
                                            const std::map<std::array<int, 2>, int>& edge_index,
                                            int element_degree, double k_Pa_per_m);

}  // namespace tightfit
