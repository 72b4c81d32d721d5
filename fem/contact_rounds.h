// The augmented-Lagrangian contact loop of a load step: Newton's method at fixed multipliers,
// then Uzawa's update (each node's multiplier becomes the contact force just found,
// contact/nodal_contact.h), repeated until no node in contact is deeper than the gap
// tolerance. With friction the rounds solve one quasi-static increment: every residual takes
// the return mapping from the anchors of the last accepted state, and the converged step
// commits the new anchors (contact/friction_anchors.h). Before the rounds, two predictors
// choose the start (they change the path, never
// the equilibrium): a secant in alpha through the last two converged steps in contact, and
// the nodes inside the body moved onto its surface.
#pragma once

#include "core/load_step.h"
#include "fem/contact_nodes.h"
#include "fem/newton_solver.h"
#include "fem/reference_mesh.h"

#include <string>
#include <vector>

namespace tightfit {

class ContactRounds {
 public:
  // Penalty k_k = beta Y / h_k^2 (Pa/m) at node k, h_k its own edge length (contact_nodes.h);
  // multipliers start at 0.
  ContactRounds(const ReferenceMesh& pattern, const Problem& problem,
                const FemParameters& parameters);

  // The contact state of this rank's nodes (ReferenceMesh::owned_nodes).
  const ContactNodes& nodes() const { return nodes_; }
  // Largest penetration of a node in contact after the last round, over every rank, m.
  double max_penetration_m() const { return max_penetration_m_; }
  // The positions were set from outside: the secant has nothing to extrapolate from, and the
  // friction anchors start at the nodes' closest points (where they stick when they touch).
  void start_from(const DofVector& x);
  // With friction: the tangential force on each of this rank's nodes at the last accepted state
  // (zero off contact), N, and how many nodes of every rank slipped there.
  const std::vector<Vec3>& friction_force_N() const { return friction_force_N_; }
  int n_slipping() const { return n_slipping_; }
  // NewtonSolver::ContactSetPredictor on these nodes (contact_set_prediction.h).
  int predict_contact_set(const DofVector& x, const DofVector* increment);

  // Predicts the start from x, runs the rounds (core/load_step.h: Newton on `assemble` at
  // fixed multipliers, then the update) into `report` (rounds, iterations, gap, nodes in
  // contact), and records the converged step for the next secant. Throws SolverError when the
  // gap does not close in 'Maximum augmented Lagrangian iterations' updates or contact is lost.
  void solve(const LoadStep& step, NewtonSolver& newton, const NewtonSolver::Assembler& assemble,
             NewtonSystem& system, DofVector& x, NewtonLog& log, StepReport& report);

 private:
  // Secant extrapolation in alpha of the positions and multipliers of the last two converged
  // steps in contact (a continuation predictor: it changes the start, not the equilibrium).
  void secant_predictor(const LoadStep& step, DofVector& x);
  // Nodes the body has grown into, and those predicted in contact, start from their closest
  // point on its surface, keeping constrained nodes on their planes (each rank its own nodes,
  // then the seams' copies follow).
  void contact_predictor(DofVector& x) const;
  // Uzawa's update at this rank's nodes; returns the largest penetration of a node in contact
  // over every rank, m, and counts those nodes into `n_active` (every rank's).
  double update_multipliers(const DofVector& x, int* n_active);
  // The stop rule's threshold at x's contact load (StopRule::threshold_N, core/load_step.h):
  // the shared rule tightened by the normal forces max(0, lambda - k g) of every rank's nodes
  // in contact, and the backend's own rule, whichever is the tighter, N.
  double load_threshold_N(const NewtonSolver& newton, const DofVector& x) const;
  // Newton at fixed multipliers to the stop rule at the contact load where it stops.
  // With `pseudo_transient`, the pseudo-transient steps first (fem/pseudo_transient.h).
  MultiplierRound settle(const LoadStep& step, NewtonSolver& newton,
                         const NewtonSolver::Assembler& assemble, NewtonSystem& system,
                         DofVector& x, NewtonLog& log, bool pseudo_transient);
  // Keeps each node's anchor of the accepted state x (after update_multipliers, whose
  // multipliers are the normal forces x was in equilibrium with) and its friction force.
  void commit_friction(const DofVector& x);

  const ReferenceMesh& pattern_;
  const Problem& problem_;
  FemParameters parameters_;
  ContactNodes nodes_;
  double max_penetration_m_ = 0.0;
  bool had_contact_ = false;
  // The last two converged steps in contact (DoF positions, this rank's multipliers), in the
  // secant's predictor (core/load_step.h).
  AlphaHistory<DofVector> history_;
  std::vector<Vec3> friction_force_N_;
  int n_slipping_ = 0;
};

}  // namespace tightfit
