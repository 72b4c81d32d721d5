#include "fem/membrane_assembly.h"

#include "contact/penalty_contact.h"
#include "fem/contact_set_prediction.h"
#include "fem/membrane_kernel.h"

#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace tightfit {

MembraneAssembly::MembraneAssembly(const ReferenceMesh& pattern, const Problem& problem,
                                   bool symmetric_tangent, MPI_Comm comm)
    : pattern_(pattern), problem_(problem), symmetric_tangent_(symmetric_tangent), comm_(comm) {}

bool MembraneAssembly::node_contact(int k, const Vec3& p, const ContactNodes& contact,
                                    bool with_tangent, Vec3& force_N,
                                    Mat3& stiffness_N_per_m) const {
  return model_node_contact(*problem_.body, contact, k, p, with_tangent, symmetric_tangent_,
                            force_N, stiffness_N_per_m);
}

void MembraneAssembly::cell_kernel(unsigned int cell, const DofVector& x, Eigen::VectorXd& gradient,
                                   Eigen::MatrixXd* hessian) const {
  const unsigned int n_local = pattern_.n_local_dofs();
  const unsigned int n_element_nodes = pattern_.n_element_nodes();
  const dealii::ArrayView<const GlobalDof> dofs = pattern_.cell_dofs()[cell];
  gradient.setZero(n_local);
  if (hessian) hessian->setZero(n_local, n_local);
  std::vector<Vec2> grad_grain(n_element_nodes);
  for (unsigned int q = 0; q < pattern_.cell_JxW_m2()[cell].size(); ++q) {
    std::copy_n(pattern_.cell_grad_grain()[cell].begin() + q * n_element_nodes, n_element_nodes,
                grad_grain.begin());
    // F = dx/dX_grain = sum_a x_a grad_N_a^T (docs/model.md: the membrane's 3x2 gradient).
    Mat32 F = Mat32::Zero();
    for (unsigned int i = 0; i < n_local; ++i)
      F.row(pattern_.local_component()[i]) +=
          x(dofs[i]) * grad_grain[pattern_.local_node()[i]].transpose();
    add_membrane_point(*problem_.law, grad_grain, F, pattern_.cell_JxW_m2()[cell][q], gradient,
                       hessian);
  }
}

Vec3 MembraneAssembly::weight_per_rest_area() const {
  if (!problem_.fabric)
    throw std::invalid_argument("fem backend: gravity needs the fabric's areal density");
  return problem_.fabric->areal_density_kg_per_m2 * problem_.gravity_m_per_s2;
}

std::vector<Vec3> MembraneAssembly::gravity_load_N() const {
  const Vec3 weight = weight_per_rest_area();
  const std::vector<double> area = pattern_.node_rest_area_m2();
  std::vector<Vec3> load(area.size());
  for (std::size_t node = 0; node < area.size(); ++node) load[node] = area[node] * weight;
  return load;
}

void MembraneAssembly::assemble(const DofVector& x, const ContactNodes& contact,
                                double tangent_shift_N_per_m, bool with_tangent, bool gravity_on,
                                NewtonSystem& system) const {
  const unsigned int n_local = pattern_.n_local_dofs();
  const Vec3 weight = gravity_on ? weight_per_rest_area() : Vec3::Zero();
  if (with_tangent) system.tangent = 0;
  system.rhs = 0;
  dealii::FullMatrix<double> cell_matrix(n_local, n_local);
  dealii::Vector<double> cell_rhs(n_local);
  Eigen::VectorXd gradient;
  Eigen::MatrixXd hessian;
  std::vector<GlobalDof> dofs;
  for (int cell = 0; cell < pattern_.n_cells(); ++cell) {
    cell_kernel(cell, x, gradient, with_tangent ? &hessian : nullptr);
    pattern_.get_cell_dofs(cell, dofs);
    for (unsigned int i = 0; i < n_local; ++i) {
      const int a = pattern_.node_major(i);
      // The weight is constant: a load on the right-hand side, nothing in the tangent.
      cell_rhs[i] =
          -gradient[a] + pattern_.cell_node_rest_area_m2()[cell][pattern_.local_node()[i]] *
                             weight[pattern_.local_component()[i]];
      if (with_tangent)
        for (unsigned int j = 0; j < n_local; ++j)
          cell_matrix(i, j) = hessian(a, pattern_.node_major(j));
    }
    if (with_tangent)
      system.constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs, system.tangent,
                                                    system.rhs);
    else
      system.constraints.distribute_local_to_global(cell_rhs, dofs, system.rhs);
  }

  // Contact at the nodes (vertices, and midpoints for degree 2: without them the quadratic
  // edges would sink into the body as straight chords), each on the rank that owns its DoFs.
  dealii::FullMatrix<double> vertex_matrix(3, 3);
  dealii::Vector<double> vertex_rhs(3);
  std::vector<GlobalDof> vertex_dof_list(3);
  for (int k = 0; k < pattern_.n_owned_nodes(); ++k) {
    const int node = pattern_.owned_nodes()[k];
    const DofTriple& d = pattern_.carrier(node);
    Vec3 force_N;
    Mat3 stiffness_N_per_m;
    const bool touching = node_contact(k, pattern_.node_position(x, node), contact, with_tangent,
                                       force_N, stiffness_N_per_m);
    if (!touching && tangent_shift_N_per_m <= 0.0) continue;
    for (int i = 0; i < 3; ++i) {
      vertex_dof_list[i] = d[i];
      vertex_rhs[i] = force_N[i];
      for (int j = 0; j < 3; ++j)
        vertex_matrix(i, j) = stiffness_N_per_m(i, j) + (i == j ? tangent_shift_N_per_m : 0.0);
    }
    if (with_tangent)
      system.constraints.distribute_local_to_global(vertex_matrix, vertex_rhs, vertex_dof_list,
                                                    system.tangent, system.rhs);
    else
      system.constraints.distribute_local_to_global(vertex_rhs, vertex_dof_list, system.rhs);
  }
  if (with_tangent) system.tangent.compress(dealii::VectorOperation::add);
  system.rhs.compress(dealii::VectorOperation::add);
}

double MembraneAssembly::energy_J(const DofVector& x, const ContactNodes& contact,
                                  bool gravity_on) const {
  const bool predicted =
      std::any_of(contact.predicted.begin(), contact.predicted.end(),
                  [](const PredictedSide& side) { return !side.same_branches(PredictedSide()); });
  if (contact.friction.active() || predicted) return std::numeric_limits<double>::quiet_NaN();
  const Vec3 weight = gravity_on ? weight_per_rest_area() : Vec3::Zero();
  const unsigned int n_element_nodes = pattern_.n_element_nodes();
  double energy = 0.0;
  std::vector<Vec2> grad_grain(n_element_nodes);
  for (int cell = 0; cell < pattern_.n_cells(); ++cell) {
    const dealii::ArrayView<const GlobalDof> dofs = pattern_.cell_dofs()[cell];
    for (unsigned int q = 0; q < pattern_.cell_JxW_m2()[cell].size(); ++q) {
      std::copy_n(pattern_.cell_grad_grain()[cell].begin() + q * n_element_nodes, n_element_nodes,
                  grad_grain.begin());
      Mat32 F = Mat32::Zero();
      for (unsigned int i = 0; i < dofs.size(); ++i)
        F.row(pattern_.local_component()[i]) +=
            x(dofs[i]) * grad_grain[pattern_.local_node()[i]].transpose();
      energy += pattern_.cell_JxW_m2()[cell][q] * problem_.law->energy(F.transpose() * F);
    }
    // The weight's work, as the right-hand side's load (assemble()).
    for (unsigned int i = 0; i < dofs.size(); ++i)
      energy -= pattern_.cell_node_rest_area_m2()[cell][pattern_.local_node()[i]] *
                weight[pattern_.local_component()[i]] * x(dofs[i]);
  }
  for (int k = 0; k < pattern_.n_owned_nodes(); ++k) {
    const Vec3 p = pattern_.node_position(x, pattern_.owned_nodes()[k]);
    const double kA = contact.penalty_N_per_m[k];
    const double lambda = contact_multiplier_N(
        contact.multiplier_N[k], kA, contact.query(*problem_.body, k, p).signed_distance_m);
    energy += lambda * lambda / (2.0 * kA);
  }
  return dealii::Utilities::MPI::sum(energy, comm_);
}

double MembraneAssembly::potential_defect_N(const DofVector& x, const ContactNodes& contact) const {
  double sum_squared = 0.0;
  for (int k = 0; k < pattern_.n_owned_nodes(); ++k) {
    const int node = pattern_.owned_nodes()[k];
    const SurfacePoint s = contact.query(*problem_.body, k, pattern_.node_position(x, node));
    const double lambda = contact_multiplier_N(contact.multiplier_N[k], contact.penalty_N_per_m[k],
                                               s.signed_distance_m);
    if (lambda <= 0.0) continue;
    Vec3 defect = lambda * (s.outward_normal - s.gap_gradient);
    pattern_.node_constrained().remove_constrained(node, defect);
    sum_squared += defect.squaredNorm();
  }
  return std::sqrt(dealii::Utilities::MPI::sum(sum_squared, comm_));
}

std::vector<Vec3> MembraneAssembly::internal_force_N(const DofVector& x) const {
  // The energy gradient on this rank's DoFs and ghosts, each cell's on the rank that owns it.
  DofVector gradient_dofs = pattern_.dof_vector();
  Eigen::VectorXd gradient;
  for (int cell = 0; cell < pattern_.n_cells(); ++cell) {
    cell_kernel(cell, x, gradient, nullptr);
    for (unsigned int i = 0; i < pattern_.cell_dofs()[cell].size(); ++i)
      gradient_dofs(pattern_.cell_dofs()[cell][i]) += gradient[pattern_.node_major(i)];
  }
  gradient_dofs.compress(dealii::VectorOperation::add);
  gradient_dofs.update_ghost_values();
  // Each owned vertex's force, summed over its copies (the first carries it), then gathered.
  std::vector<Vec3> owned_force(pattern_.n_owned_nodes(), Vec3::Zero());
  for (int k = 0; k < pattern_.n_owned_nodes(); ++k)
    for (const DofTriple& d : pattern_.copies(pattern_.owned_nodes()[k]))
      owned_force[k] -= Vec3(gradient_dofs(d[0]), gradient_dofs(d[1]), gradient_dofs(d[2]));
  std::vector<Vec3> force = pattern_.gather_nodes(owned_force);
  force.resize(pattern_.n_vertices());  // the vertices come first
  return force;
}

void MembraneAssembly::linearise(const std::vector<Vec3>& node_positions_m,
                                 const ContactNodes& contact, Eigen::VectorXd& residual_N,
                                 Eigen::MatrixXd& tangent_N_per_m) const {
  const int n = pattern_.n_nodes();
  if (static_cast<int>(node_positions_m.size()) != n)
    throw std::invalid_argument("fem backend: linearise() needs one position per node");
  if (pattern_.n_owned_nodes() != n)
    throw std::logic_error("fem backend: linearise() runs on one MPI rank only");
  DofVector x = pattern_.dof_vector();
  // DoF -> row 3 node + c of the node it carries (every copy of a node shares its rows).
  std::vector<int> dof_row(pattern_.n_dofs(), -1);
  for (int node = 0; node < n; ++node) {
    pattern_.set_node_position(x, node, node_positions_m[node]);
    for (const DofTriple& d : pattern_.copies(node))
      for (int c = 0; c < 3; ++c) dof_row[d[c]] = 3 * node + c;
  }
  residual_N.setZero(3 * n);
  tangent_N_per_m.setZero(3 * n, 3 * n);
  Eigen::VectorXd gradient;
  Eigen::MatrixXd hessian;
  const unsigned int n_local = pattern_.n_local_dofs();
  std::vector<int> row(n_local);
  for (int cell = 0; cell < pattern_.n_cells(); ++cell) {
    cell_kernel(cell, x, gradient, &hessian);
    for (unsigned int i = 0; i < n_local; ++i) row[i] = dof_row[pattern_.cell_dofs()[cell][i]];
    for (unsigned int i = 0; i < n_local; ++i) {
      const int a = pattern_.node_major(i);
      residual_N[row[i]] += gradient[a];
      for (unsigned int j = 0; j < n_local; ++j)
        tangent_N_per_m(row[i], row[j]) += hessian(a, pattern_.node_major(j));
    }
  }
  // Serial: the owned nodes are every node, k the node's own number.
  for (int node = 0; node < n; ++node) {
    Vec3 force_N;
    Mat3 stiffness_N_per_m;
    if (!node_contact(node, node_positions_m[node], contact, true, force_N, stiffness_N_per_m))
      continue;
    residual_N.segment<3>(3 * node) -= force_N;
    tangent_N_per_m.block<3, 3>(3 * node, 3 * node) += stiffness_N_per_m;
  }
}

}  // namespace tightfit
