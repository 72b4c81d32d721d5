#include "fem/contact_rounds.h"

#include "contact/penalty_contact.h"
#include "core/load_step_report.h"
#include "fem/contact_set_prediction.h"
#include "fem/pseudo_transient.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>

namespace tightfit {

ContactRounds::ContactRounds(const ReferenceMesh& pattern, const Problem& problem,
                             const FemParameters& parameters)
    : pattern_(pattern), problem_(problem), parameters_(parameters) {
  std::vector<double> owned_area_m2, owned_edge_m;
  for (const int node : pattern.owned_nodes()) {
    owned_area_m2.push_back(pattern.node_contact_area_m2()[node]);
    owned_edge_m.push_back(pattern.node_edge_m()[node]);
  }
  nodes_.penalty_N_per_m = nodal_penalties_N_per_m(
      owned_area_m2, parameters.penalty_factor * problem.law->stiffness_scale(), owned_edge_m);
  nodes_.friction = FrictionAnchors(problem.friction_coefficient,
                                    problem.tangential_stiffness_Pa_per_m, owned_area_m2);
  nodes_.multiplier_N.assign(pattern.n_owned_nodes(), 0.0);
  nodes_.near_faces.resize(pattern.n_owned_nodes());
}

void ContactRounds::start_from(const DofVector& x) {
  history_.forget();
  friction_force_N_.assign(pattern_.n_owned_nodes(), Vec3::Zero());
  n_slipping_ = 0;
  std::vector<Vec3> nodes(pattern_.n_owned_nodes());
  for (int k = 0; k < pattern_.n_owned_nodes(); ++k)
    nodes[k] = pattern_.node_position(x, pattern_.owned_nodes()[k]);
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
    const Vec3 p = pattern_.node_position(x, pattern_.owned_nodes()[k]);
    const FrictionResponse r = nodes_.friction.response(
        k, *problem_.body, p, nodes_.query(*problem_.body, k, p),
        std::max(0.0, nodes_.multiplier_N[k]), Vec3::Zero(), nodes_.near(k));
    nodes_.friction.commit(k, r);
    friction_force_N_[k] = r.force_N;
    n_slipping_ += r.slipping;
  }
  n_slipping_ = dealii::Utilities::MPI::sum(n_slipping_, pattern_.comm());
}

void ContactRounds::secant_predictor(const LoadStep& step, DofVector& x) {
  history_.predict(step.alpha, nodes_.multiplier_N,
                   [&](double ratio, const DofVector& last, const DofVector& before) {
                     x = last;
                     x.add(ratio, last, -ratio, before);
                     x.update_ghost_values();
                   });
  // No constraints.distribute(x): the pins and held ends constrain increments, and the
  // secant of two states that satisfy them (and the seams) satisfies them already.
}

void ContactRounds::contact_predictor(DofVector& x) const {
  for (int k = 0; k < pattern_.n_owned_nodes(); ++k) {
    const int node = pattern_.owned_nodes()[k];
    const Vec3 p = pattern_.node_position(x, node);
    const SurfacePoint s = problem_.body->query(p);
    // Nodes in contact at the last step (the multiplier predicted positive) go onto the
    // surface too: a penetration or gap left by the secant would cost kA g of residual.
    if (s.signed_distance_m >= 0.0 && nodes_.multiplier_N[k] <= 0.0) continue;
    Vec3 move = s.closest_point_m - p;
    pattern_.node_constrained().remove_constrained(node, move);
    pattern_.set_node_position(x, node, p + move);
  }
  pattern_.copy_seams(x);
}

double ContactRounds::update_multipliers(const DofVector& x, int* n_active) {
  max_penetration_m_ = 0.0;
  int active = 0;
  for (int k = 0; k < pattern_.n_owned_nodes(); ++k) {
    const SurfacePoint s =
        nodes_.query(*problem_.body, k, pattern_.node_position(x, pattern_.owned_nodes()[k]));
    nodes_.multiplier_N[k] = contact_multiplier_N(nodes_.multiplier_N[k], nodes_.penalty_N_per_m[k],
                                                  s.signed_distance_m);
    if (nodes_.multiplier_N[k] > 0.0) {
      ++active;
      max_penetration_m_ = std::max(max_penetration_m_, std::abs(s.signed_distance_m));
    }
  }
  // Every rank ends the rounds alike.
  max_penetration_m_ = dealii::Utilities::MPI::max(max_penetration_m_, pattern_.comm());
  *n_active = dealii::Utilities::MPI::sum(active, pattern_.comm());
  return max_penetration_m_;
}

double ContactRounds::load_threshold_N(const NewtonSolver& newton, const DofVector& x) const {
  // The load tightens the shared tension-scale rule, never the backend's own absolute one
  // (Finite elements/Residual tolerance): where that is below the tightest the load may ask
  // for, a tenth of the shared rule, the load has nothing to change (the default).
  const StopRule& rule = parameters_.stop;
  if (!(rule.relative_tolerance > 0) || !(rule.contact_load_tolerance > 0) ||
      StopRule::contact_load_floor * newton.shared_tolerance_N() >= newton.tolerance_N())
    return newton.tolerance_N();
  double load_N = 0.0;
  long n_in_contact = 0;
  for (int k = 0; k < pattern_.n_owned_nodes(); ++k) {
    const SurfacePoint s =
        nodes_.query(*problem_.body, k, pattern_.node_position(x, pattern_.owned_nodes()[k]));
    const double lambda_N = contact_multiplier_N(nodes_.multiplier_N[k], nodes_.penalty_N_per_m[k],
                                                 s.signed_distance_m);
    load_N += lambda_N;
    n_in_contact += lambda_N > 0.0;
  }
  return std::min(newton.tolerance_N(),
                  rule.threshold_N(newton.shared_tolerance_N(),
                                   dealii::Utilities::MPI::sum(load_N, pattern_.comm()),
                                   dealii::Utilities::MPI::sum(n_in_contact, pattern_.comm())));
}

MultiplierRound ContactRounds::settle(const LoadStep& step, NewtonSolver& newton,
                                      const NewtonSolver::Assembler& assemble, NewtonSystem& system,
                                      DofVector& x, NewtonLog& log, bool pseudo_transient) {
  const std::size_t first = log.residual_N.size();
  MultiplierRound round;
  // The rule at the start's contact load, then at the load where the solve stopped: the
  // solves go on while the residual there is above it (the load grows as the garment settles
  // onto the body; two more solves at most, each starting where the last stopped).
  newton.set_load_tolerance_N(load_threshold_N(newton, x));
  if (pseudo_transient) {
    PseudoTransientSettings settings;
    settings.max_steps = parameters_.max_pseudo_time_steps;
    settings.initial_shift = parameters_.pseudo_time_initial_shift;
    round.iterations = pseudo_transient_settle(step, newton, assemble, system, x, log, settings);
  }
  round.iterations += newton.solve(step, assemble, system, x, log);
  for (int pass = 0; pass < 2 && !log.residual_N.empty(); ++pass) {
    const double threshold_N = load_threshold_N(newton, x);
    if (!(log.residual_N.back() > threshold_N)) break;
    newton.set_load_tolerance_N(threshold_N);
    round.iterations += newton.solve(step, assemble, system, x, log);
  }
  round.residual_N.assign(log.residual_N.begin() + first, log.residual_N.end());
  return round;
}

void ContactRounds::solve(const LoadStep& step, NewtonSolver& newton,
                          const NewtonSolver::Assembler& assemble, NewtonSystem& system,
                          DofVector& x, NewtonLog& log, StepReport& report) {
  // After a fallback, the solver asked for returns once the garment presses on the body: the
  // loose garment's tangent (singular at zero tension) is what defeats CG, and the first
  // contact step, where the tension starts from zero, is left to the solver that got there.
  if (had_contact_) newton.linear_solver().restore_requested();
  secant_predictor(step, x);
  contact_predictor(x);
  newton.start_step();

  // The rounds of core/load_step.h. The reported contact force is the multiplier itself, the
  // force the state just solved is in equilibrium with once updated: no settle after the last
  // update.
  MultiplierRounds rounds;
  // With friction the load step opens with pseudo-transient steps (fem/pseudo_transient.h).
  bool pseudo_transient = nodes_.friction.active() && parameters_.max_pseudo_time_steps > 0;
  rounds.settle = [&] {
    const bool first_round = pseudo_transient;
    pseudo_transient = false;
    return settle(step, newton, assemble, system, x, log, first_round);
  };
  rounds.read_gap = [&](bool, int* count) { return update_multipliers(x, count); };
  rounds.max_updates = parameters_.max_augmented_lagrangian_iterations;
  rounds.gap_tolerance_m = parameters_.stop.gap_tolerance_m;
  rounds.settle_after_last_update = false;
  const bool closed = rounds.run(report);
  report.iterations = 0;
  for (const MultiplierRound& round : report.rounds) report.iterations += round.iterations;
  const double residual_N = log.residual_N.empty() ? 0.0 : log.residual_N.back();
  report.load_tolerance_N = load_threshold_N(newton, x);
  if (!closed)
    throw_step_failure(StopReason::gap_not_closed, step,
                       gap_not_closed_text(report, parameters_.stop.gap_tolerance_m), residual_N,
                       newton.tolerance_N());
  if (had_contact_ && report.n_in_contact == 0)
    throw_step_failure(StopReason::contact_lost, step, "contact lost", residual_N,
                       newton.tolerance_N());
  commit_friction(x);
  had_contact_ = had_contact_ || report.n_in_contact > 0;
  history_.record(step.alpha, report.n_in_contact > 0, x, nodes_.multiplier_N);
}

}  // namespace tightfit
