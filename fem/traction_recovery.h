// The contact traction of an element whose nodal contact forces do not read as a pressure
// over nodal areas (quadratic triangles: their corners carry about nothing), recovered as the
// L2 projection of the traction onto a set of surface functions phi_k:
//   M t = f,  M_kl = int phi_k phi_l dA over the current (curved) surface,
// with f_k = int phi_k t dA the loads of the traction against phi_k, which the caller derives
// from the nodal forces. Since sum_k phi_k = 1, a uniform pressure p comes back as p at every
// node, and int t dA equals the total force. No finite-element library here: the backend
// supplies the quadrature.
#pragma once

#include <vector>

namespace tightfit {

struct SurfaceQuadrature {
  // Values [q][a] of each cell's functions phi_a at the reference quadrature points.
  std::vector<std::vector<double>> shape_values;
  // Per cell, the node index of each of its functions [cell][a].
  std::vector<std::vector<int>> cell_nodes;
  // Per cell and quadrature point, the current surface area the point stands for, m^2.
  std::vector<std::vector<double>> point_area_m2;
};

// Nodal tractions t (Pa) solving M t = f for the loads f (N), one per node.
// Throws std::runtime_error when M is singular (a node no cell touches).
std::vector<double> recover_traction_Pa(int n_nodes, const SurfaceQuadrature& quadrature,
                                        const std::vector<double>& load_N);

}  // namespace tightfit
