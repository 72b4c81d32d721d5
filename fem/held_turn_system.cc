#include "fem/held_turn_system.h"

#include <deal.II/base/mpi.h>

#include <cmath>

namespace tightfit {

HeldTurnSystem::HeldTurnSystem(const PatternMesh& pattern)
    : pattern_(pattern), turn_(pattern.constraints, pattern.n_vertices()) {}

void HeldTurnSystem::project_residual(const DofVector& x, NewtonSystem& system) {
  if (!active()) return;
  const dealii::AffineConstraints<double>& constraints = system.constraints;
  // The centre of the nodes' rest areas, over every rank.
  double sums[4] = {0.0, 0.0, 0.0, 0.0};
  for (const int node : pattern_.owned_nodes) {
    const double w = pattern_.node_contact_area_m2[node];
    const Vec3 p = pattern_.node_position(x, node);
    for (int c = 0; c < 3; ++c) sums[c] += w * p[c];
    sums[3] += w;
  }
  dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sums, 4), pattern_.comm,
                              dealii::ArrayView<double>(sums, 4));
  if (!(sums[3] > 0.0)) return;
  const Vec3 centre = Vec3(sums[0], sums[1], sums[2]) / sums[3];

  if (border_.size() != system.rhs.size()) {
    border_.reinit(pattern_.owned_dofs, pattern_.comm);
    field_.reinit(pattern_.owned_dofs, pattern_.comm);
    solved_.reinit(pattern_.owned_dofs, pattern_.comm);
  }
  border_ = 0.0;
  field_ = 0.0;
  // A free DoF takes the node's component; a constrained one hands it to the free DoFs it
  // follows, with the constraint's weights (b = C^T M t). A held direction being along the axis
  // and t normal to it, t itself satisfies the constraints: t = C (t on the free DoFs).
  std::vector<dealii::types::global_dof_index> indices;
  std::vector<double> values;
  for (const int node : pattern_.owned_nodes) {
    const Vec3 t = turn_.axis().cross(pattern_.node_position(x, node) - centre);
    const Vec3 f = pattern_.node_contact_area_m2[node] * t;
    const DofTriple& dofs = pattern_.carrier(node);
    for (int c = 0; c < 3; ++c) {
      if (!constraints.is_constrained(dofs[c])) {
        indices.push_back(dofs[c]);
        values.push_back(f[c]);
        field_(dofs[c]) = t[c];
        continue;
      }
      for (const auto& [j, weight] : *constraints.get_constraint_entries(dofs[c])) {
        indices.push_back(j);
        values.push_back(weight * f[c]);
      }
    }
  }
  border_.add(indices, values);
  border_.compress(dealii::VectorOperation::add);
  field_.compress(dealii::VectorOperation::insert);
  inertia_m4_ = field_ * border_;
  if (!(inertia_m4_ > 0.0)) return;
  // rhs = -R loses M t (t.(-R)) / I: afterwards t.rhs = 0 (t . C^T R = (C t) . R = t . R).
  system.rhs.add(-(field_ * system.rhs) / inertia_m4_, border_);
}

void HeldTurnSystem::constrain_increment(NewtonSystem& system, const Solve& solve) {
  if (!active() || !(inertia_m4_ > 0.0)) return;
  solve(border_, solved_);
  const double denominator = border_ * solved_;
  if (!(std::abs(denominator) > 0.0)) return;
  system.increment.add(-(border_ * system.increment) / denominator, solved_);
}

double HeldTurnSystem::mean_turn(const dealii::PETScWrappers::MPI::Vector& increment) const {
  return inertia_m4_ > 0.0 ? (border_ * increment) / inertia_m4_ : 0.0;
}

}  // namespace tightfit
