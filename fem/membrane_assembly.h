// The residual R(x) = dPi/dx - f_contact of the membrane on the body and its tangent dR/dx:
// the membrane's energy gradient and Hessian cell by cell (membrane_kernel.h on the pattern's
// quadrature) and the nodal augmented-Lagrangian contact (contact/nodal_contact.h) with
// Coulomb friction (contact/friction_anchors.h) at every node, assembled into the Newton system
// with its constraints.
#pragma once

#include "fem/contact_nodes.h"
#include "fem/newton_system.h"
#include "fem/reference_mesh.h"

#include <Eigen/Core>

namespace tightfit {

class MembraneAssembly {
 public:
  // `symmetric_tangent`: the contact's tangent symmetrised (contact/nodal_contact.h), for CG;
  // otherwise its exact derivative (unsymmetric on a mesh body, and with friction).
  MembraneAssembly(const ReferenceMesh& pattern, const Problem& problem, bool symmetric_tangent,
                   MPI_Comm comm);

  // system.rhs = -R(x), constrained; system.tangent = dR/dx when with_tangent. The tangent
  // of every node's contact gets `tangent_shift_N_per_m` on its diagonal (zero: nodes out of
  // contact are skipped). With gravity_on, R also loses the garment's weight (gravity_load_N).
  void assemble(const DofVector& x, const ContactNodes& contact, double tangent_shift_N_per_m,
                bool with_tangent, bool gravity_on, NewtonSystem& system) const;

  // The potential whose gradient is R(x) for frictionless contact (docs/backends.md, "Newton's
  // line search"), J, summed over every rank: the membrane's strain energy, the contact's
  // max(0, lambda_bar - kA g)^2 / (2 kA) at each node (contact/nodal_contact.h) and, with
  // gravity_on, minus the weight's work. NaN when friction is on or a contact set is predicted:
  // then R is no potential's gradient.
  double energy_J(const DofVector& x, const ContactNodes& contact, bool gravity_on) const;
  // How far R(x) is from energy_J's gradient, N: the contact force takes the body's normal n
  // where the potential's gradient takes the signed distance's, dg/dx, and on a mesh body the
  // two differ (bodies/rigid_body.h). The 2-norm over every rank of lambda (n - dg/dx) at the
  // nodes in contact, held directions removed (zero on the analytic bodies).
  double potential_defect_N(const DofVector& x, const ContactNodes& contact) const;

  // The garment's weight as consistent nodal loads, per node, N:
  //   f_k = g int N_k rho_A dA_rest,
  // rho_A the fabric's areal density over the rest area (mass is conserved, so no current
  // area enters) and g Problem::gravity_m_per_s2. Linear triangles: a third of each
  // triangle's weight at each corner (the mass-spring backend's lumped masses). Quadratic
  // triangles: nothing at the corners, a third at each edge midpoint. Throws
  // std::invalid_argument when the problem has no fabric.
  std::vector<Vec3> gravity_load_N() const;

  // The membrane's internal force (minus the energy gradient) on each welded vertex, N,
  // summed over the vertex's copies (the seam is one vertex); every rank gets all of it.
  std::vector<Vec3> internal_force_N(const DofVector& x) const;

  // Serial, for tests: R and dR/dx on the nodes (3n, node-major) at `node_positions_m`,
  // without constraints; every copy of a seam node takes its node's position.
  void linearise(const std::vector<Vec3>& node_positions_m, const ContactNodes& contact,
                 Eigen::VectorXd& residual_N, Eigen::MatrixXd& tangent_N_per_m) const;

 private:
  // Node-major energy gradient (and Hessian) of one cell, from the DoF values x.
  void cell_kernel(unsigned int cell, const DofVector& x, Eigen::VectorXd& gradient,
                   Eigen::MatrixXd* hessian) const;

  // rho_A g: the weight per unit rest area, N/m^2 (zero without a fabric).
  Vec3 weight_per_rest_area() const;

  // The contact force on owned node k (pattern.owned_nodes()[k]) at p (normal, and with friction
  // the return mapping from the anchors of the last accepted state), on the sides of the contact
  // and friction kinks the step's prediction holds (contact_set_prediction.h), and, with_tangent,
  // minus its derivative. Returns false when the node is out of contact (no force, no stiffness).
  bool node_contact(int k, const Vec3& p, const ContactNodes& contact, bool with_tangent,
                    Vec3& force_N, Mat3& stiffness_N_per_m) const;

  const ReferenceMesh& pattern_;
  const Problem& problem_;
  bool symmetric_tangent_;
  MPI_Comm comm_;
};

}  // namespace tightfit
