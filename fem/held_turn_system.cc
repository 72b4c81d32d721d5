#include "fem/held_turn_system.h"

#include <deal.II/base/mpi.h>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace tightfit {

HeldTurnSystem::HeldTurnSystem(const ReferenceMesh& pattern, bool symmetric)
    : pattern_(pattern),
      symmetric_(symmetric),
      turn_(pattern.constraints(), pattern.n_vertices()) {}

void HeldTurnSystem::project_residual(const DofVector& x, bool with_tangent, NewtonSystem& system) {
  if (!active()) return;
  const dealii::AffineConstraints<double>& constraints = system.constraints;
  // The centre of the nodes' rest areas, over every rank.
  double sums[4] = {0.0, 0.0, 0.0, 0.0};
  for (const int node : pattern_.owned_nodes()) {
    const double w = pattern_.node_contact_area_m2()[node];
    const Vec3 p = pattern_.node_position(x, node);
    for (int c = 0; c < 3; ++c) sums[c] += w * p[c];
    sums[3] += w;
  }
  dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(sums, 4), pattern_.comm(),
                              dealii::ArrayView<double>(sums, 4));
  if (!(sums[3] > 0.0)) return;
  const Vec3 centre = Vec3(sums[0], sums[1], sums[2]) / sums[3];

  if (border_.size() != system.rhs.size()) {
    border_.reinit(pattern_.owned_dofs(), pattern_.comm());
    field_.reinit(pattern_.owned_dofs(), pattern_.comm());
    solved_.reinit(pattern_.owned_dofs(), pattern_.comm());
  }
  border_ = 0.0;
  field_ = 0.0;
  // A free DoF takes the node's component; a constrained one hands it to the free DoFs it
  // follows, with the constraint's weights (b = C^T M t). A held direction being along the axis
  // and t normal to it, t itself satisfies the constraints: t = C (t on the free DoFs).
  std::vector<dealii::types::global_dof_index> indices;
  std::vector<double> values;
  for (const int node : pattern_.owned_nodes()) {
    const Vec3 t = turn_.axis().cross(pattern_.node_position(x, node) - centre);
    const Vec3 f = pattern_.node_contact_area_m2()[node] * t;
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
  const double lambda = -(field_ * system.rhs) / inertia_m4_;
  system.rhs.add(lambda, border_);
  if (!with_tangent || symmetric_) return;
  // The reaction lambda M t turns with the nodes: d(lambda w_i a x (x_i - c))/dx_i =
  // lambda w_i [a]x (the centre's own motion, a translation the body resists, left out). It joins
  // the tangent of R - lambda b through C: K_c -= lambda C^T W [a]x C.
  Mat3 cross;
  const Vec3& a = turn_.axis();
  cross << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  for (const int node : pattern_.owned_nodes()) {
    const DofTriple& dofs = pattern_.carrier(node);
    std::array<std::vector<std::pair<dealii::types::global_dof_index, double>>, 3> free;
    for (int c = 0; c < 3; ++c) {
      if (!constraints.is_constrained(dofs[c]))
        free[c].emplace_back(dofs[c], 1.0);
      else
        for (const auto& [j, weight] : *constraints.get_constraint_entries(dofs[c]))
          free[c].emplace_back(j, weight);
    }
    const double scale = -lambda * pattern_.node_contact_area_m2()[node];
    for (int c = 0; c < 3; ++c)
      for (int d = 0; d < 3; ++d) {
        if (cross(c, d) == 0.0) continue;
        for (const auto& [i, wi] : free[c])
          for (const auto& [j, wj] : free[d])
            system.tangent.add(i, j, scale * cross(c, d) * wi * wj);
      }
  }
  system.tangent.compress(dealii::VectorOperation::add);
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
