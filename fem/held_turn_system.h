// The held turn (core/held_turn.h, docs/backends.md "The held turn") in Newton's system: when
// every vertex is held along one direction a, the garment's mean turn about a is held, as on the
// mass-spring backend. Each Newton increment du (the free DoFs after the constraints of
// fem_constraints.h) solves the bordered system
//
//     [ K    b ] [ du     ]   [ -R ]
//     [ b^T  0 ] [ lambda ] = [  0 ],      b = C^T M t,  t_i = a x (x_i - c),
//
// C the constraints' map from the free DoFs to the nodes' positions, M the nodes' rest areas as
// masses (the weights of the mean) and c their centre. Its second row holds the increment's
// mean turn at zero; lambda is the grip's torque over I = t^T M t. Block elimination with the
// tangent's factorization: K y = -R, K z = b, du = y - (b.y / b.z) z (one more back-solve per
// Newton solve). The turn no longer dominates the increments, and Newton converges
// quadratically on the constrained problem.
//
// The residual Newton's stop rule and line search read is R with the turn's reaction removed,
// R - M t (t.R) / I: the mass-spring backend's remove_from_forces through C^T. Its zero is an
// equilibrium up to a torque about the axis, the grip's, which vanishes at the free tube's
// equilibrium. With an unsymmetric tangent (any solver but CG) the reaction's turning with the
// nodes, -lambda M [a]x, joins K (measured on the stocking: it changes no iteration count).
// The rigid-motion pin (rigid_motion_pin.h) leaves this turn alone.
#pragma once

#include "core/held_turn.h"
#include "fem/newton_system.h"
#include "fem/reference_mesh.h"

#include <functional>

namespace tightfit {

class HeldTurnSystem {
 public:
  // `symmetric`: the tangent must stay symmetric (CG), so the reaction's own stiffness is left out.
  HeldTurnSystem(const ReferenceMesh& pattern, bool symmetric);

  bool active() const { return turn_.active(); }
  const HeldTurn& turn() const { return turn_; }
  // At positions x: the border b and the turn field t on the free DoFs (from
  // system.constraints), then system.rhs loses the turn's reaction (see above). Collective.
  void project_residual(const DofVector& x, bool with_tangent, NewtonSystem& system);
  // system.increment holds K^-1 rhs; `solve(b, z)` solves K z = b with the same tangent. Leaves
  // the bordered system's increment in system.increment. Collective.
  using Solve = std::function<void(const dealii::PETScWrappers::MPI::Vector& b,
                                   dealii::PETScWrappers::MPI::Vector& z)>;
  void constrain_increment(NewtonSystem& system, const Solve& solve);
  // The mean turn of the increment on the free DoFs, t^T M du / I (rad), for tests.
  double mean_turn(const dealii::PETScWrappers::MPI::Vector& increment) const;

 private:
  const ReferenceMesh& pattern_;
  bool symmetric_;
  HeldTurn turn_;
  dealii::PETScWrappers::MPI::Vector border_;  // b = C^T M t, m^3 (area times length)
  dealii::PETScWrappers::MPI::Vector field_;   // t on the free DoFs, m
  dealii::PETScWrappers::MPI::Vector solved_;  // K^-1 b
  double inertia_m4_ = 0.0;                    // I = t^T M t
};

}  // namespace tightfit
