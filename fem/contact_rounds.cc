#include "fem/contact_rounds.h"

#include "contact/penalty_contact.h"
#include "fem/contact_set_prediction.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tightfit {

namespace {

std::string format_residuals(const std::vector<double>& values) {
  std::ostringstream out;
  out.precision(2);
  out << std::scientific;
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? " " : "") << values[i];
  return out.str();
}

}  // namespace

ContactRounds::ContactRounds(const PatternMesh& pattern, const Problem& problem,
                             const FemParameters& parameters)
    : pattern_(pattern), problem_(problem), parameters_(parameters) {
  std::vector<double> owned_area_m2, owned_edge_m;
  for (const int node : pattern.owned_nodes) {
    owned_area_m2.push_back(pattern.node_contact_area_m2[node]);
    owned_edge_m.push_back(pattern.node_edge_m[node]);
  }
  nodes_.penalty_N_per_m = nodal_penalties_N_per_m(
      owned_area_m2, parameters.penalty_factor * problem.law->stiffness_scale(), owned_edge_m);
  nodes_.friction = FrictionAnchors(problem.friction_coefficient,
                                    problem.tangential_stiffness_Pa_per_m, owned_area_m2);
  nodes_.multiplier_N.assign(pattern.n_owned_nodes(), 0.0);
  nodes_.near_faces.resize(pattern.n_owned_nodes());
}

void ContactRounds::start_from(const DofVector& x) {
  n_history_ = 0;
  friction_force_N_.assign(pattern_.n_owned_nodes(), Vec3::Zero());
  n_slipping_ = 0;
  std::vector<Vec3> nodes(pattern_.n_owned_nodes());
  for (int k = 0; k < pattern_.n_owned_nodes(); ++k)
    nodes[k] = pattern_.node_position(x, pattern_.owned_nodes[k]);
  nodes_.friction.place(*problem_.body, nodes);
}

int ContactRounds::predict_contact_set(const DofVector& x, const DofVector* increment) {
  if (!increment) {
    nodes_.predicted.clear();
    return 0;
  }
  return tightfit::predict_contact_set(pattern_, *problem_.body, x, *increment, nodes_);
}

void ContactRounds::commit_friction(const DofVector& x) {
  if (!nodes_.friction.active()) return;
  n_slipping_ = 0;
  for (int k = 0; k < pattern_.n_owned_nodes(); ++k) {
    const Vec3 p = pattern_.node_position(x, pattern_.owned_nodes[k]);
    const FrictionResponse r = nodes_.friction.response(
        k, *problem_.body, p, nodes_.query(*problem_.body, k, p),
        std::max(0.0, nodes_.multiplier_N[k]), Vec3::Zero(), nodes_.near(k));
    nodes_.friction.commit(k, r);
    friction_force_N_[k] = r.force_N;
    n_slipping_ += r.slipping;
  }
  n_slipping_ = dealii::Utilities::MPI::sum(n_slipping_, pattern_.comm);
}

void ContactRounds::secant_predictor(const LoadStep& step, DofVector& x) {
  if (n_history_ < 2) return;
  const double ratio = (step.alpha - history_alpha_[0]) / (history_alpha_[0] - history_alpha_[1]);
  // Only forward steps no longer than a few of the last: further out the secant misleads.
  if (!std::isfinite(ratio) || ratio <= 0.0 || ratio > 4.0) return;
  x = history_x_[0];
  x.add(ratio, history_x_[0], -ratio, history_x_[1]);
  x.update_ghost_values();
  std::vector<double>& multiplier = nodes_.multiplier_N;
  for (std::size_t w = 0; w < multiplier.size(); ++w)
    multiplier[w] =
        std::max(0.0, history_multiplier_N_[0][w] +
                          ratio * (history_multiplier_N_[0][w] - history_multiplier_N_[1][w]));
  // No constraints.distribute(x): the pins and held ends constrain increments, and the
  // secant of two states that satisfy them (and the seams) satisfies them already.
}

void ContactRounds::contact_predictor(DofVector& x) const {
  for (int k = 0; k < pattern_.n_owned_nodes(); ++k) {
    const int node = pattern_.owned_nodes[k];
    const Vec3 p = pattern_.node_position(x, node);
    const SurfacePoint s = problem_.body->query(p);
    // Nodes in contact at the last step (the multiplier predicted positive) go onto the
    // surface too: a penetration or gap left by the secant would cost kA g of residual.
    if (s.signed_distance_m >= 0.0 && nodes_.multiplier_N[k] <= 0.0) continue;
    Vec3 move = s.closest_point_m - p;
    pattern_.node_constrained.remove_constrained(node, move);
    pattern_.set_node_position(x, node, p + move);
  }
  pattern_.copy_seams(x);
}

int ContactRounds::update_multipliers(const DofVector& x) {
  max_penetration_m_ = 0.0;
  int n_active = 0;
  for (int k = 0; k < pattern_.n_owned_nodes(); ++k) {
    const SurfacePoint s =
        nodes_.query(*problem_.body, k, pattern_.node_position(x, pattern_.owned_nodes[k]));
    nodes_.multiplier_N[k] = contact_multiplier_N(nodes_.multiplier_N[k], nodes_.penalty_N_per_m[k],
                                                  s.signed_distance_m);
    if (nodes_.multiplier_N[k] > 0.0) {
      ++n_active;
      max_penetration_m_ = std::max(max_penetration_m_, std::abs(s.signed_distance_m));
    }
  }
  // Every rank ends the rounds alike.
  max_penetration_m_ = dealii::Utilities::MPI::max(max_penetration_m_, pattern_.comm);
  return dealii::Utilities::MPI::sum(n_active, pattern_.comm);
}

ContactRoundsResult ContactRounds::solve(const LoadStep& step, NewtonSolver& newton,
                                         const NewtonSolver::Assembler& assemble,
                                         NewtonSystem& system, DofVector& x, NewtonLog& log) {
  // After a fallback, the solver asked for returns once the garment presses on the body: the
  // loose garment's tangent (singular at zero tension) is what defeats CG, and the first
  // contact step, where the tension starts from zero, is left to the solver that got there.
  if (had_contact_) newton.linear_solver().restore_requested();
  secant_predictor(step, x);
  contact_predictor(x);
  newton.start_step();

  ContactRoundsResult result;
  bool gap_closed = false;
  // One line per round for the message of a step whose gap does not close.
  std::string history =
      "rounds (round, Newton iterations, first / last residual N, largest penetration m after "
      "the update, nodes in contact):";
  for (int round = 0; round < parameters_.max_augmented_lagrangian_iterations; ++round) {
    const std::size_t first = log.residual_N.size();
    const int iterations = newton.solve(step, assemble, system, x, log);
    result.newton_iterations += iterations;
    result.n_active = update_multipliers(x);
    std::ostringstream gap;
    gap.precision(2);
    gap << std::scientific << "; gap " << max_penetration_m_ << " m, " << result.n_active
        << " in contact";
    result.rounds.push_back(format_residuals(std::vector<double>(log.residual_N.begin() + first,
                                                                 log.residual_N.end())) +
                            gap.str());
    std::ostringstream summary;
    summary.precision(2);
    summary << std::scientific << "\n  " << round << "  " << iterations << "  "
            << log.residual_N[first] << " / " << log.residual_N.back() << "  " << max_penetration_m_
            << "  " << result.n_active;
    history += summary.str();
    if (max_penetration_m_ <= parameters_.gap_tolerance_m) {
      gap_closed = true;
      break;
    }
  }
  const double residual_N = log.residual_N.empty() ? 0.0 : log.residual_N.back();
  if (!gap_closed) {
    std::ostringstream what;
    what << "the contact gap did not close (largest penetration " << max_penetration_m_
         << " m, tolerance " << parameters_.gap_tolerance_m << " m) after "
         << parameters_.max_augmented_lagrangian_iterations << " augmented-Lagrangian updates";
    throw_step_failure(step, what.str(), residual_N, newton.tolerance_N(), history);
  }
  if (had_contact_ && result.n_active == 0)
    throw_step_failure(step, "contact lost", residual_N, newton.tolerance_N());
  commit_friction(x);
  had_contact_ = had_contact_ || result.n_active > 0;
  if (result.n_active == 0) {
    n_history_ = 0;
  } else {
    history_alpha_[1] = history_alpha_[0];
    history_x_[1].swap(history_x_[0]);
    history_multiplier_N_[1].swap(history_multiplier_N_[0]);
    history_alpha_[0] = step.alpha;
    history_x_[0] = x;
    history_multiplier_N_[0] = nodes_.multiplier_N;
    n_history_ = std::min(n_history_ + 1, 2);
  }
  return result;
}

}  // namespace tightfit
