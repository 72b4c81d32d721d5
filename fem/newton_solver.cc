#include "fem/newton_solver.h"

#include "contact/residual_location.h"
#include "core/interruption.h"
#include "core/load_step.h"
#include "core/load_step_report.h"
#include "core/residual_history.h"
#include "core/rigid_motion_fit.h"

#include <petscmat.h>
#include <petscvec.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace tightfit {

void throw_step_failure(StopReason reason, const LoadStep& step, const std::string& what,
                        double residual_N, double tolerance_N, const std::string& details) {
  throw load_step_failure(reason, "fem backend", step, what, residual_N, tolerance_N, details);
}

namespace {

// Both rules that are on (above 0) hold: the shared one, relative to the tension scale, and
// the FE backend's own, relative to Y h.
double stop_threshold_N(const FemParameters& parameters, double stiffness_force_N,
                        double tension_scale_N) {
  double threshold_N = std::numeric_limits<double>::infinity();
  if (parameters.stop.relative_tolerance > 0.0)
    threshold_N = relative_threshold_N(parameters.stop, tension_scale_N);
  if (parameters.residual_tolerance > 0.0)
    threshold_N = std::min(threshold_N, parameters.residual_tolerance * stiffness_force_N);
  if (!std::isfinite(threshold_N))
    throw std::invalid_argument(
        "Solver/Relative tolerance and Finite elements/Residual tolerance are both 0: the FE "
        "backend needs a stop rule (set either above 0)");
  return threshold_N;
}

}  // namespace

NewtonSolver::NewtonSolver(const ReferenceMesh& pattern, const FemParameters& parameters,
                           double stiffness_scale_N_per_m, double tension_scale_N,
                           const RigidBody* body, MPI_Comm comm)
    : pattern_(pattern),
      parameters_(parameters),
      stiffness_scale_N_per_m_(stiffness_scale_N_per_m),
      tolerance_N_(stop_threshold_N(parameters, stiffness_scale_N_per_m * pattern.mean_edge_m(),
                                    tension_scale_N)),
      shared_tolerance_N_(parameters.stop.relative_tolerance > 0.0
                              ? relative_threshold_N(parameters.stop, tension_scale_N)
                              : tolerance_N_),
      body_(body),
      comm_(comm),
      linear_solver_(std::make_unique<PetscLinearSolver>(parameters.linear_solver,
                                                         parameters.max_linear_iterations, comm)) {
  const dealii::IndexSet& owned = pattern.owned_dofs();
  dof_weight_.assign(owned.n_elements(), 1.0);
  for (int node = 0; node < pattern.n_local_nodes(); ++node)
    for (const DofTriple& copy : pattern.copies(node))
      for (const GlobalDof i : copy)
        if (owned.is_element(i))
          dof_weight_[owned.index_within_set(i)] =
              pattern.mean_edge_m() / pattern.node_edge_m()[node];
}

double NewtonSolver::scaled_residual_N(const NewtonSystem& system) const {
  ResidualSize size;
  std::size_t k = 0;  // i's position among the owned DoFs (the range visits them in order)
  for (const GlobalDof i : pattern_.owned_dofs())
    size.add(std::abs(system.rhs(i)) * dof_weight_[k++]);
  // A node's residual vector lies on its free DoFs (a seam's other copies and a held
  // direction's DoF carry none): the sum over DoFs is the sum of |R_k|^2 over the nodes.
  const double sum_squared = dealii::Utilities::MPI::sum(size.sum_squared(), comm_);
  const double largest_N = parameters_.stop.norm == StopNorm::largest
                               ? dealii::Utilities::MPI::max(size.largest_N(), comm_)
                               : 0.0;
  return ResidualSize::read(parameters_.stop.norm, largest_N, sum_squared, pattern_.n_nodes());
}

std::string NewtonSolver::failure_details(const NewtonSystem& system, const DofVector& x_owned,
                                          const NewtonLog& log) const {
  DofVector rhs = pattern_.dof_vector();
  for (const auto i : pattern_.owned_dofs()) rhs(i) = system.rhs(i);
  rhs.update_ghost_values();
  // rhs = -R: the residual force on each owned node, summed over its copies; then every node's.
  std::vector<Vec3> owned_positions, owned_residual;
  for (const int node : pattern_.owned_nodes()) {
    owned_positions.push_back(pattern_.node_position(x_owned, node));
    owned_residual.push_back(pattern_.node_position(rhs, node));
    const ListView<DofTriple> copies = pattern_.copies(node);
    for (std::size_t k = 1; k < copies.size(); ++k)
      for (int c = 0; c < 3; ++c) owned_residual.back()[c] += rhs(copies[k][c]);
  }
  const std::vector<Vec3> positions = pattern_.gather_nodes(owned_positions);
  const std::vector<Vec3> residual = pattern_.gather_nodes(owned_residual);
  // Windows of 20 iterations, marked 'stalled' where the residual fell by less than a tenth
  // over one (the mark only informs: the iteration limit ends the step).
  ResidualHistory history(20, 0.9, "Newton iterations", "step length taken there");
  for (std::size_t k = 0; k < log.residual_N.size(); ++k)
    history.record(static_cast<int>(k), log.residual_N[k],
                   k < log.step_length.size() ? log.step_length[k] : 0.0);
  std::string rigid;
  if (has_increment_) {
    // How much of the last increment moved the garment as a whole: most of it where the step
    // crept along a motion the body barely resists (docs/backends.md, "Newton's line search").
    std::vector<Vec3> owned_increment;
    for (const int node : pattern_.owned_nodes())
      owned_increment.push_back(pattern_.node_position(last_increment_, node));
    const std::vector<Vec3> increment = pattern_.gather_nodes(owned_increment);
    if (!positions.empty())
      rigid = "; the last Newton increment is " + text(fit_rigid_motion(positions, increment));
  }
  return text(locate_residual(positions, residual, body_)) + " (node numbers: welded vertices, " +
         "then edge midpoints); " + history.text() + rigid;
}

void NewtonSolver::fail(StopReason reason, const LoadStep& step, const std::string& what,
                        double residual_N, const std::string& details) const {
  throw_step_failure(reason, step, what, residual_N, tolerance_N(), details);
}

int NewtonSolver::solve_linear_system(const LoadStep& step, const DofVector& x,
                                      NewtonSystem& system, NewtonLog& log) {
  try {
    // GAMG's rigid motions: a DoF's coordinate is its own position value, since the DoFs are
    // the nodes' positions, numbered in a node's x, y, z rows (ReferenceMesh::dofs_in_node_blocks).
    dealii::PETScWrappers::MPI::Vector coordinates;
    if (linear_solver_->needs_node_coordinates() && pattern_.dofs_in_node_blocks()) {
      coordinates.reinit(pattern_.owned_dofs(), comm_);
      for (const GlobalDof i : pattern_.owned_dofs()) coordinates(i) = x(i);
      coordinates.compress(dealii::VectorOperation::insert);
    }
    const LinearSolveResult result = linear_solver_->solve(
        system.tangent.petsc_matrix(), system.rhs, system.increment, krylov_tolerance_,
        coordinates.size() > 0 ? static_cast<Vec>(coordinates) : nullptr);
    log.notes += result.note;
    int iterations = result.used == LinearSolverKind::direct ? 0 : result.iterations;
    // The held turn's border: one more solve with the same tangent (its factorization kept).
    if (held_turn_ && held_turn_->active())
      held_turn_->constrain_increment(system, [&](const dealii::PETScWrappers::MPI::Vector& b,
                                                  dealii::PETScWrappers::MPI::Vector& z) {
        const LinearSolveResult border =
            linear_solver_->solve(system.tangent.petsc_matrix(), b, z, krylov_tolerance_,
                                  coordinates.size() > 0 ? static_cast<Vec>(coordinates) : nullptr);
        log.notes += border.note;
        if (border.used != LinearSolverKind::direct) iterations += border.iterations;
      });
    return iterations;
  } catch (const std::exception& e) {
    fail(StopReason::linear_solver_failed, step,
         std::string("linear solver '") + to_string(parameters_.linear_solver) +
             "' failed: " + e.what(),
         system.rhs.linfty_norm(), failure_details(system, x, log));
  }
}

void NewtonSolver::solve_shifted(const LoadStep& step, const DofVector& x, NewtonSystem& system,
                                 double shift_N_per_m, NewtonLog& log, DofVector& increment) {
  krylov_tolerance_ = parameters_.linear_tolerance;
  if (shift_N_per_m > 0.0) MatShift(system.tangent.petsc_matrix(), shift_N_per_m);
  log.krylov_iterations.push_back(solve_linear_system(step, x, system, log));
  ghosted_increment(system, increment);
  last_increment_ = increment;
  has_increment_ = true;
}

double NewtonSolver::owned_dot(const NewtonSystem& system, const DofVector& increment) const {
  double sum = 0.0;
  for (const GlobalDof i : pattern_.owned_dofs()) sum += system.rhs(i) * increment(i);
  return dealii::Utilities::MPI::sum(sum, comm_);
}

void NewtonSolver::ghosted_increment(NewtonSystem& system, DofVector& increment) const {
  // The seam copies and constrained directions of this rank's DoFs take their values from the
  // DoFs they follow (other ranks' among them fetched by deal.II); the solver zeroes the vector
  // before its next solve, so it may be changed here.
  system.constraints.distribute(system.increment);
  if (increment.get_partitioner() != pattern_.partitioner())
    increment.reinit(pattern_.partitioner());
  // Both hold this rank's DoFs, one contiguous range, in ascending order.
  const PetscScalar* values = nullptr;
  VecGetArrayRead(system.increment, &values);
  for (unsigned int i = 0; i < increment.locally_owned_size(); ++i)
    increment.local_element(i) = values[i];
  VecRestoreArrayRead(system.increment, &values);
  increment.update_ghost_values();
}

// The trial point of a full step is assembled with its tangent: when the step is accepted (the
// usual case near the solution) that assembly is the next iteration's, so a Newton iteration
// costs one assembly and one solve.
int NewtonSolver::solve(const LoadStep& step, const Assembler& assemble, NewtonSystem& system,
                        DofVector& x, NewtonLog& log) {
  const double tolerance = std::min(tolerance_N(), load_tolerance_N_);
  const double mean_edge_m = pattern_.mean_edge_m();
  std::vector<double>& history_N = log.residual_N;
  assemble(x, true);
  int slow_iterations = 0;
  // The potential judges the first solve of a load step, where the garment travels onto the
  // body; the later rounds start next to the solution, where on a mesh body its minimum is not
  // R = 0 (see kDefectRatio).
  // With friction there is none (its energy is NaN): ||R|| judges from the start, and the
  // switch below never sends the solve back to its start (two iterations lost on the tops).
  const bool potential_on = parameters_.line_search && parameters_.potential_globalization &&
                            energy_ && std::isfinite(energy_(x));
  bool potential_judges = potential_on && first_solve_ && potential_trusted_;
  first_solve_ = false;
  // Where the load step's first solve starts: it starts again from here, judged by ||R||_2,
  // should the potential turn out unable to finish the step (below).
  const DofVector x_start = potential_judges ? x : DofVector();
  for (int iteration = 0;; ++iteration) {
    const double residual_N = scaled_residual_N(system);
    history_N.push_back(residual_N);
    if (!std::isfinite(residual_N))
      fail(StopReason::not_finite, step, "the residual is not finite", residual_N);
    if (residual_N <= tolerance) return iteration;
    // Collective, so that every rank stops at the same iteration whichever got the signal.
    throw_if_interrupted(dealii::Utilities::MPI::max(interruption_signal(), comm_),
                         "during load step " + std::to_string(step.index) + " (alpha " +
                             std::to_string(step.alpha) + ") at Newton iteration " +
                             std::to_string(iteration));
    // Inexact Newton (Eisenstat and Walker's second forcing term): solve each system only as
    // far as the residual's own decrease warrants, eta = 0.9 (|R_k| / |R_k-1|)^2 within
    // [linear tolerance, 1e-2]; convergence stays superlinear. Where the residual fell by less
    // than half (a near-singular tangent), loose solves only stall it: solve to the linear
    // tolerance.
    const double previous_N = iteration > 0 ? history_N[history_N.size() - 2] : 0.0;
    const double ratio = iteration > 0 ? residual_N / previous_N : 0.1;
    krylov_tolerance_ = ratio < 0.5
                            ? std::clamp(0.9 * ratio * ratio, parameters_.linear_tolerance, 1e-2)
                            : parameters_.linear_tolerance;
    // The potential's stall: kStalledIterations in a row that lowered the residual by less than
    // a tenth hand the rest of this solve to ||R|| alone (its minimum on a mesh body is not
    // R = 0, see kDefectRatio, and its steps may keep shrinking there).
    slow_iterations = iteration > 0 && ratio > 0.9 ? slow_iterations + 1 : 0;
    if (slow_iterations >= kStalledIterations) potential_judges = false;
    if (iteration >= parameters_.max_newton_iterations)
      fail(StopReason::iteration_limit, step,
           "Newton's method did not converge in " + std::to_string(iteration) + " iterations",
           residual_N, failure_details(system, x, log));
    const double norm_0 = system.rhs.l2_norm();
    // The potential's defect against ||R||_2, measured every iteration while the potential is
    // trusted (docs/backends.md, "Newton's line search"). The potential's minimum lies within
    // about its defect of R = 0 (on a mesh body the contact force's normal is not the gap's
    // gradient: potential_defect_N), so once ||R||_2 is down to kDefectRatio times the defect
    // the potential no longer judges strictly. Where that defect is also above the shared stop
    // rule (the strain error both backends accept; the tubes on smooth mesh cylinders stay
    // below it and converge quadratically under the potential), the potential's minimum may
    // not meet the rule at all, and its steps (taken where ||R||
    // refused them) led the stocking's tube towards that minimum, away from R = 0, for
    // minutes: ||R||_2 alone judges the rest of the load step, as 'Globalization = residual'
    // does, and a first solve starts again from where it started (its potential-led path
    // ended where ||R|| alone crept for hundreds of iterations, the tube turning round the
    // leg). With the turn held (held_turn_system.h) there is no such creep, and the potential
    // stays trusted (below). On the analytic bodies the defect is zero and the potential stays
    // trusted.
    if (potential_on && potential_trusted_) {
      const double defect_N = defect_ ? defect_(x) : 0.0;
      if (norm_0 <= kDefectRatio * defect_N) {
        potential_judges = false;
        // With the turn held the potential stays trusted: on the smooth contact surface its
        // defect is of order the gap (MeshBody's normal n against grad g, phi H n / m^2), which
        // the rounds close, and ||R|| alone crept there (the coarse stocking's first round:
        // steps of 1/512 for hundreds of iterations; trusted, 31 iterations).
        const bool turn_held = held_turn_ && held_turn_->active();
        if (defect_N > shared_tolerance_N_ && !turn_held) {
          potential_trusted_ = false;
          std::ostringstream note;
          note.precision(3);
          note << "the potential's defect " << defect_N << " N against ||R||_2 " << norm_0
               << " N at iteration " << iteration << ": ||R|| alone judges";
          if (x_start.size() > 0 && iteration > 0) {
            note << ", from the step's start";
            x = x_start;
            shift_N_per_m_ = 0.0;
            step_cut_ = false;
            slow_iterations = 0;
            assemble(x, true);
            log.globalization += note.str();
            log.step_length.push_back(0.0);
            continue;
          }
          log.globalization += note.str();
        }
      }
    }
    if (!potential_trusted_) potential_judges = false;
    // The potential at x, read once per iteration while it judges (the line search below).
    const double energy_0_J =
        potential_judges ? energy_(x) : std::numeric_limits<double>::quiet_NaN();
    // The potential at x where it only takes the steps ||R|| refuses, read when first needed.
    double energy_x_J = std::numeric_limits<double>::quiet_NaN();
    bool energy_x_read = false;
    // A zero-stress or compressed membrane (a tube that just touches the body) has a singular
    // or indefinite tangent, along which Newton's step may be huge or useless. When the line
    // search fails, the tangent is shifted by mu I (Levenberg-Marquardt), mu growing tenfold
    // until the line search succeeds and shrinking tenfold after each success. The residual is
    // untouched, so the converged state is not biased.
    DofVector trial(x), increment;
    bool tangent_current = false;
    double step_taken = 0.0, full_step = 0.0;
    // A step on the predicted contact set whose line search fails is tried again on the set at
    // x, with the same shift, before the shift grows: the prediction is the linearised step's,
    // and a step that ends far from it (a facet crossed, a turned normal) may not descend.
    // Predictions are made every iteration when 'Contact set predictions' asks, and otherwise
    // only after an iteration whose full step the line search cut: there the contact set at x
    // was the wrong one to linearise on (nodes the step drives into the body meet no penalty in
    // it), and re-solving on the set the step reaches is what lets the next step be taken
    // whole (docs/backends.md, "Newton's line search").
    int prediction_rounds =
        step_cut_ && parameters_.potential_globalization && potential_trusted_
            ? std::max(parameters_.max_contact_set_predictions, kPredictionRoundsAfterCut)
            : parameters_.max_contact_set_predictions;
    // While the potential judges (the travel onto the body), every step is solved on the
    // contact set it reaches, up to kPredictionRoundsWhileTravelling times: a step linearised on
    // the set at x drove the nodes about to touch into the penalty, the line search cut it to an
    // eighth, and the step after it on the predicted set overshot (the stocking's first round
    // went 45 iterations so; with the set followed to its fixed point, 20).
    // Not with friction, which has no potential (its energy is NaN).
    if (std::isfinite(energy_0_J) && parameters_.potential_globalization)
      prediction_rounds = std::max(prediction_rounds, kPredictionRoundsWhileTravelling);
    bool predict = predictor_ && prediction_rounds > 0, predicted = false, reassemble = false;
    // How often the shift has grown in this iteration (after a failed solve or line search).
    int escalations = 0;
    bool accepted = false;
    for (;;) {
      // Yamashita and Fukushima's mu ~ |R|: it damps the step where the residual is large and
      // vanishes with it, so that convergence stays quadratic, even when the tangent is
      // singular at the solution (a tube touching the body at zero tension).
      const double shift_N_per_m =
          std::max(shift_N_per_m_, parameters_.residual_shift_factor * residual_N / mean_edge_m);
      try {
        // Before any escalation the tangent and residual at x are assembled already; later,
        // the tangent is assembled afresh. Either way it is shifted in place (same pattern: the
        // factorization's analysis is kept).
        if (escalations > 0 || reassemble) assemble(x, true);
        if (escalations > 0 || reassemble || shift_N_per_m > 0.0)
          MatShift(system.tangent.petsc_matrix(), shift_N_per_m);
        log.krylov_iterations.push_back(solve_linear_system(step, x, system, log));
        ghosted_increment(system, increment);
        // The step solved again on the contact set it reaches (contact_set_prediction.h), until
        // the set it was solved with is the one it predicts. The model's residual at x is not
        // R(x): the assembly at x is redone, on every node's own side, before it is read again.
        predicted = false;
        if (predict) {
          for (int round = 0; round < prediction_rounds && predictor_(x, &increment) > 0; ++round) {
            assemble(x, true);
            if (shift_N_per_m > 0.0) MatShift(system.tangent.petsc_matrix(), shift_N_per_m);
            log.krylov_iterations.push_back(solve_linear_system(step, x, system, log));
            ghosted_increment(system, increment);
            ++log.n_set_predictions;
            predicted = true;
          }
          predictor_(x, nullptr);
        }
      } catch (const SolverError&) {
        if (predictor_) predictor_(x, nullptr);
        // A singular tangent the residual's shift is too small to lift (a loose, stress-free
        // garment whose midpoint nodes have no stiffness across it): shift as after a failed
        // line search.
        if (escalations >= kMaxEscalations) throw;
        linear_solver_->reset();  // a failed factorization is not reused
        shift_N_per_m_ = grown_shift_N_per_m();
        ++log.n_shifted_solves;
        ++escalations;
        continue;
      }
      // A step longer than half an edge leaves the region where the linearisation holds (and
      // may carry the garment, which has no bending stiffness, into a folded state): shorten
      // it.
      step_taken = full_step = std::min(1.0, 0.5 * mean_edge_m / increment.linfty_norm());
      double& s = step_taken;  // halved by the line search
      accepted = !parameters_.line_search;
      // The potential's slope along the increment, dPi/ds = R . increment = -rhs . increment
      // (rhs is zero on constrained rows), read before the trial assemblies overwrite rhs.
      // The potential judges only where R is its gradient to within a tenth (kDefectRatio):
      // closer to the solution on a mesh body, where the contact force's normal is not the
      // distance's gradient, its minimum is not R = 0 and ||R|| alone decides.
      // Elsewhere (the later rounds, a stalled potential) ||R|| decides, and the potential
      // only takes a step ||R|| refused, while it is trusted.
      const bool strict = std::isfinite(energy_0_J);
      const bool lenient = !strict && potential_on && potential_trusted_;
      const double slope_J = strict || lenient ? -owned_dot(system, increment)
                                               : std::numeric_limits<double>::quiet_NaN();
      // The potential's round-off: a sum of many terms of one sign, each exact to a few ulps.
      const double noise_J = kPotentialRoundOff * std::abs(energy_0_J);
      // A step uphill in the potential (the tangent indefinite along it: a tube turning round a
      // body that is not quite of revolution) leads to a saddle; no halving makes it descend, so
      // the tangent's shift grows at once (docs/backends.md, "Newton's line search").
      const bool uphill = strict && slope_J > noise_J;
      if (uphill) {
        trial = x;
        step_taken = 0.0;
        tangent_current = false;
      }
      for (int halving = 0; parameters_.line_search && !uphill; ++halving) {
        trial = x;
        trial.add(s, increment);
        // Armijo's sufficient decrease (1e-4 s) of the potential Pi along a descent direction,
        // or of ||R||_2 where Pi does not rise beyond its round-off (docs/backends.md, "Newton's
        // line search"). Pi admits the steps that cross a valley of ||R|| (a slack tube
        // settling, a tube on an elliptic section: ||R|| alone stalled there), and refuses those
        // that lower ||R|| while climbing Pi towards a saddle (the stocking's tube turning round
        // the leg). ||R|| alone decides where Pi has none (friction) and near the solution,
        // where Pi's change falls below its round-off.
        tangent_current = halving == 0;
        assemble(trial, tangent_current);
        const double norm = system.rhs.l2_norm();
        const bool residual_decreases = std::isfinite(norm) && norm <= (1.0 - 1e-4 * s) * norm_0;
        if (strict && std::isfinite(norm)) {
          const double energy_J = energy_(trial);
          accepted = (slope_J < 0.0 && energy_J <= energy_0_J + 1e-4 * s * slope_J) ||
                     (residual_decreases && energy_J <= energy_0_J + noise_J);
        } else {
          accepted = residual_decreases;
          if (!accepted && lenient && slope_J < 0.0 && std::isfinite(norm)) {
            if (!energy_x_read) energy_x_J = energy_(x), energy_x_read = true;
            accepted = energy_(trial) <= energy_x_J + 1e-4 * s * slope_J;
          }
        }
        // While the shift may still grow, a step is cut to an eighth at most
        // (kHalvingsBeforeShift): shorter, it would follow a soft mode of the tangent far past
        // where its linearisation holds, and the shift grows instead (below). Once every shift is
        // spent, the halvings the case allows.
        const int halvings =
            escalations < kMaxEscalations
                ? std::min(kHalvingsBeforeShift, parameters_.max_line_search_halvings)
                : parameters_.max_line_search_halvings;
        if (accepted || halving >= halvings) break;
        s *= 0.5;
      }
      if (!parameters_.line_search) {
        trial = x;
        trial.add(s, increment);
        tangent_current = false;
      }
      if (accepted) {
        // Levenberg-Marquardt's trust region, adapted: a step taken whole relaxes the shift
        // tenfold (it vanishes after a few, and the step's end is Newton's, quadratic); a step the
        // line search cut keeps it, the shift that made it descend (the loose fabric off the
        // tops needs about 10 N/m throughout, and relaxing it after every cut step had the next
        // one refused: 53 iterations against 43).
        if (step_taken >= full_step)
          shift_N_per_m_ =
              shift_N_per_m_ > 1e-8 * stiffness_scale_N_per_m_ ? 0.1 * shift_N_per_m_ : 0;
        break;
      }
      // A step on the predicted set that did not descend: solved again on the set at x, with
      // the same shift (not an escalation).
      if (predicted) {
        predict = false;
        reassemble = true;
        continue;
      }
      if (escalations >= kMaxEscalations) break;
      shift_N_per_m_ = grown_shift_N_per_m();
      ++log.n_shifted_solves;
      ++escalations;
    }
    // Every shift refused, to 1e5 times the stiffness scale, where the step is a short one down
    // the merit's slope: x is where the merit has a minimum that is not R = 0, and no step is
    // taken (docs/backends.md, "Newton's line search").
    if (!accepted) {
      ++log.n_failed_line_searches;
      std::ostringstream what;
      what.precision(3);
      what << "the line search refused Newton's step at every shift of the tangent, up to "
           << shift_N_per_m_ << " N/m";
      fail(StopReason::stalled, step, what.str(), residual_N, failure_details(system, x, log));
    }
    step_cut_ = parameters_.line_search && step_taken < full_step;
    last_increment_ = increment;
    has_increment_ = true;
    x = trial;
    log.step_length.push_back(step_taken);
    if (!tangent_current) assemble(x, true);
  }
}

}  // namespace tightfit
