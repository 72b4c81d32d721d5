// The residual R(x) = dPi/dx - f_contact of the membrane on the body and its tangent dR/dx:
// the membrane's energy gradient and Hessian cell by cell (membrane_kernel.h on the pattern's
// quadrature) and the nodal augmented-Lagrangian contact (contact/nodal_contact.h) at every
// node, assembled into the Newton system with its constraints.
#pragma once

#include "fem/contact_nodes.h"
#include "fem/newton_system.h"
#include "fem/pattern_mesh.h"

#include <Eigen/Core>

namespace tightfit {

class MembraneAssembly {
 public:
  MembraneAssembly(const PatternMesh& pattern, const Problem& problem, MPI_Comm comm);

  // system.rhs = -R(x), constrained; system.tangent = dR/dx when with_tangent. The tangent
  // of every node's contact gets `tangent_shift_N_per_m` on its diagonal (zero: nodes out of
  // contact are skipped).
  void assemble(const dealii::Vector<double>& x, const ContactNodes& contact,
                double tangent_shift_N_per_m, bool with_tangent, NewtonSystem& system) const;

  // The membrane's internal force (minus the energy gradient) on each welded vertex, N,
  // summed over the vertex's copies (the seam is one vertex); every rank gets all of it.
  std::vector<Vec3> internal_force_N(const dealii::Vector<double>& x) const;

  // Serial, for tests: R and dR/dx on the nodes (3n, node-major) at `node_positions_m`,
  // without constraints; every copy of a seam node takes its node's position.
  void linearise(const std::vector<Vec3>& node_positions_m, const ContactNodes& contact,
                 Eigen::VectorXd& residual_N, Eigen::MatrixXd& tangent_N_per_m) const;

 private:
  // Node-major energy gradient (and Hessian) of one cell, from the DoF values x.
  void cell_kernel(unsigned int cell, const dealii::Vector<double>& x, Eigen::VectorXd& gradient,
                   Eigen::MatrixXd* hessian) const;

  const PatternMesh& pattern_;
  const Problem& problem_;
  MPI_Comm comm_;
};

}  // namespace tightfit
