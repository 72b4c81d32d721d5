// Newton's method on the static equilibrium R(x) = 0 of one load step: the consistent tangent,
// an inexact-Newton forcing term for Krylov solves, a backtracking (Armijo) line search on the
// potential or ||R||_2, a cap on the step length and an adaptive Levenberg-Marquardt shift of the
// tangent: it grows tenfold where the line search would cut a step below an eighth (the step is
// solved again), relaxes tenfold after a whole step and vanishes at the end, where convergence
// is Newton's (docs/backends.md, "Newton's line search"). The residual is never modified, so
// the converged state is unbiased.
#pragma once

#include "bodies/rigid_body.h"
#include "core/backend.h"
#include "fem/fem_parameters.h"
#include "fem/held_turn_system.h"
#include "fem/newton_system.h"
#include "fem/petsc_linear_solver.h"
#include "fem/reference_mesh.h"

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tightfit {

// Throws SolverError naming the step (index, alpha), what failed and the residual, then
// `details` (where the residual sits, its history) when not empty.
[[noreturn]] void throw_step_failure(StopReason reason, const LoadStep& step,
                                     const std::string& what, double residual_N, double tolerance_N,
                                     const std::string& details = "");

// What a load step's Newton solves did, for its report.
struct NewtonLog {
  std::vector<double> residual_N;      // per iteration, the stop rule's size of R (see solve())
  std::vector<double> step_length;     // per iteration, the fraction of Newton's step taken
  std::vector<int> krylov_iterations;  // per linear solve (0 for the direct solver)
  std::string notes;                   // linear solver switches
  std::string globalization;           // where the potential stopped judging, and why
  int n_shifted_solves = 0;            // tangents shifted after failed line searches
  int n_set_predictions = 0;           // systems solved again on a predicted contact set
  int n_failed_line_searches = 0;      // iterations whose every shift failed the line search
};

class NewtonSolver {
 public:
  // Fills system.rhs = -R(x) (constrained), and system.tangent = dR/dx when asked.
  using Assembler = std::function<void(const DofVector& x, bool with_tangent)>;
  // The potential whose gradient is R (MembraneAssembly::energy_J), J; NaN where there is none.
  using Energy = std::function<double(const DofVector& x)>;
  // Given x and Newton's increment, sets the contact set the next assembly takes for the step's
  // model and returns how many nodes changed side (fem/contact_set_prediction.h); given a null
  // increment, returns every node to its own side at the point assembled.
  using ContactSetPredictor = std::function<int(const DofVector& x, const DofVector* increment)>;

  // Y = stiffness_scale_N_per_m, h = pattern.mean_edge_m(). The stop rule's force is 'Residual
  // tolerance' times Y h or, when 'Relative tolerance' is set, that times tension_scale_N, the
  // mass-spring backend's Y h^2 / L (core/tension_scale.h). The step is capped at half of h. On a
  // graded mesh each node's residual counts relative to its own edge h_k (pattern.node_edge_m()):
  // the stop rule reads R_k h / h_k, the force the same strain error would leave on a node of mean
  // size, its largest component or the rms of the nodes' vectors ('Stop norm'). `body` (may be
  // null) names where a failed step's residual sits.
  NewtonSolver(const ReferenceMesh& pattern, const FemParameters& parameters,
               double stiffness_scale_N_per_m, double tension_scale_N, const RigidBody* body,
               MPI_Comm comm);

  double tolerance_N() const { return tolerance_N_; }
  // The shared stop rule's force, Solver/Relative tolerance times the tension scale, N (the
  // FE backend's own rule when that is off): the residual both backends accept.
  double shared_tolerance_N() const { return shared_tolerance_N_; }
  // The stop rule at the step's contact load (StopRule::threshold_N, core/load_step.h): the
  // solves that follow stop below the tighter of it and tolerance_N(); start_step() forgets it.
  void set_load_tolerance_N(double threshold_N) { load_tolerance_N_ = threshold_N; }
  // Forgets the tangent's shift of earlier steps (call at the start of a load step).
  void start_step() {
    load_tolerance_N_ = tolerance_N_;
    shift_N_per_m_ = 0.0;
    step_cut_ = false;
    first_solve_ = true;
    potential_trusted_ = true;
    has_increment_ = false;
  }
  // The matrix's pattern changed (new constraints): the next solve analyses it afresh.
  void pattern_changed() { linear_solver_->reset(); }
  PetscLinearSolver& linear_solver() { return *linear_solver_; }
  // Used by solve() for up to 'Contact set predictions' re-solves of each step.
  void set_contact_set_predictor(ContactSetPredictor predictor) {
    predictor_ = std::move(predictor);
  }

  // The line search's first merit (see solve()); without it, ||R||_2 alone.
  // With `defect`, how far R is from the potential's gradient (MembraneAssembly::
  // potential_defect_N), N: the potential judges steps only where R is well above it.
  // The held turn (held_turn_system.h; may be null or inactive): each linear solve then gives
  // the bordered system's increment, whose mean turn about the held axis is zero. The assembler
  // projects the residual itself (HeldTurnSystem::project_residual).
  void set_held_turn(HeldTurnSystem* held_turn) { held_turn_ = held_turn; }

  void set_energy(Energy energy, Energy defect = {}) {
    energy_ = std::move(energy);
    defect_ = std::move(defect);
  }

  // Iterates from x until max |R| <= tolerance_N(); returns the iterations taken. Throws
  // SolverError (throw_step_failure) on a non-finite residual or too many iterations.
  int solve(const LoadStep& step, const Assembler& assemble, NewtonSystem& system, DofVector& x,
            NewtonLog& log);

  // The stop rule's size of rhs over every rank, N: the largest |rhs_i| h / h_k(i), or the rms
  // over the nodes (see the constructor).
  double scaled_residual_N(const NewtonSystem& system) const;
  // One linear solve of (K + shift I) increment = rhs with the tangent assembled at x (shifted
  // in place): the increment on this rank's DoFs and ghosts, constraints distributed
  // (fem/pseudo_transient.h).
  void solve_shifted(const LoadStep& step, const DofVector& x, NewtonSystem& system,
                     double shift_N_per_m, NewtonLog& log, DofVector& increment);
  double stiffness_scale_N_per_m() const { return stiffness_scale_N_per_m_; }
  double mean_edge_m() const { return pattern_.mean_edge_m(); }
  // The residual tolerance the next solve() stops at, N (the tighter of the backend's and the
  // contact load's rules).
  double solve_tolerance_N() const { return std::min(tolerance_N_, load_tolerance_N_); }

 private:
  // Where the residual at x sits (contact/residual_location.h) and the history of the step's
  // iterations, for the message of a failed step.
  std::string failure_details(const NewtonSystem& system, const DofVector& x,
                              const NewtonLog& log) const;
  // Solves tangent * increment = rhs at positions x; returns the Krylov iterations (0 for
  // direct).
  int solve_linear_system(const LoadStep& step, const DofVector& x, NewtonSystem& system,
                          NewtonLog& log);
  // rhs . increment over every rank.
  double owned_dot(const NewtonSystem& system, const DofVector& increment) const;
  // The increment on this rank's DoFs and ghosts, constraints distributed.
  void ghosted_increment(NewtonSystem& system, DofVector& increment) const;
  [[noreturn]] void fail(StopReason reason, const LoadStep& step, const std::string& what,
                         double residual_N, const std::string& details = "") const;

  const ReferenceMesh& pattern_;
  FemParameters parameters_;
  double stiffness_scale_N_per_m_;
  double tolerance_N_;
  double shared_tolerance_N_;
  double load_tolerance_N_ = tolerance_N_;
  const RigidBody* body_;
  MPI_Comm comm_;
  std::unique_ptr<PetscLinearSolver> linear_solver_;
  ContactSetPredictor predictor_;
  HeldTurnSystem* held_turn_ = nullptr;
  Energy energy_;
  Energy defect_;
  // Levenberg-Marquardt shift of the tangent from line-search failures, N/m (the residual's
  // own shift, 'Residual shift factor', is added in solve()).
  double shift_N_per_m_ = 0.0;
  // Per DoF this rank owns (in the order of pattern.owned_dofs()), h / h_k of the node it belongs
  // to (every copy of a seam node alike).
  std::vector<double> dof_weight_;
  // Whether the line search cut the last iteration's step (its next step is then solved on the
  // contact set it predicts, see solve()).
  bool step_cut_ = false;
  // No solve() yet since start_step().
  bool first_solve_ = true;
  // The potential may judge steps in this load step: false from the first iteration where
  // ||R||_2 fell to kDefectRatio times its defect (see solve()); the rest of the step is then
  // judged as 'Globalization = residual' judges it.
  bool potential_trusted_ = true;
  // Prediction rounds of a step after a cut one: 1 took the tubes on mesh bodies through in
  // 11 to 23 iterations where the contact set at x took them nowhere (docs/performance.md).
  static constexpr int kPredictionRoundsAfterCut = 1;
  // Prediction rounds of every step while the potential judges (see solve()): the stocking's
  // set reached its fixed point within 5.
  static constexpr int kPredictionRoundsWhileTravelling = 5;
  // The potential's relative round-off, over its sum of cells and nodes (see solve()).
  static constexpr double kPotentialRoundOff = 1e-12;
  // ||R||_2 over the potential's defect (see solve()) above which the potential judges steps.
  static constexpr double kDefectRatio = 10.0;
  // Iterations in a row that lower the residual by less than a tenth before the potential stops
  // judging for the rest of a solve (see solve()).
  static constexpr int kStalledIterations = 5;
  // The line search's halvings before a refused step grows the shift instead (see solve()): a
  // step is cut to an eighth at most while the shift may grow. Cut further, the stocking's and
  // the tops' steps crept (1/512 of Newton's for hundreds of iterations).
  static constexpr int kHalvingsBeforeShift = 3;
  // How often the shift grows tenfold within one iteration: from 1e-2 of the stiffness scale to
  // 1e5 of it (kLargestShift caps it).
  static constexpr int kMaxEscalations = 8;
  // The largest shift, over the stiffness scale: beyond it the step is a steepest descent
  // already, too short to matter.
  static constexpr double kLargestShift = 1e6;
  // The shift grown tenfold, from 1e-2 of the stiffness scale, capped by kLargestShift.
  double grown_shift_N_per_m() const {
    return std::min(shift_N_per_m_ > 0.0 ? 10.0 * shift_N_per_m_ : 1e-2 * stiffness_scale_N_per_m_,
                    kLargestShift * stiffness_scale_N_per_m_);
  }
  // Newton's increment of the last iteration (ghosted), for the message of a failed step.
  DofVector last_increment_;
  bool has_increment_ = false;  // last_increment_ is of this load step
  // Relative tolerance of the next Krylov solve (inexact Newton, see solve()).
  double krylov_tolerance_ = 1e-10;
};

}  // namespace tightfit
