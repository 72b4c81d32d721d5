// Parameters of the finite-element membrane backend: the "Finite elements" subsection.
#pragma once

#include "core/load_step.h"

#include <string>

namespace dealii {
class ParameterHandler;
}

namespace tightfit {

enum class LinearSolverKind {
  direct,     // PETSc's MUMPS sparse LU: small problems, exact solves
  cg_amg,     // conjugate gradients with BoomerAMG: large problems (the tangent is symmetric)
  gmres_amg,  // GMRES with BoomerAMG: when the tangent is not positive definite
  // The same Krylov methods with PETSc's smoothed-aggregation multigrid (GAMG), the nodes'
  // three displacements one block and the six rigid motions of the current positions its
  // near null space (petsc_linear_solver.h).
  cg_gamg,
  gmres_gamg,
};

// Conjugate gradients (a symmetric tangent needed), and PETSc's GAMG as preconditioner.
bool uses_cg(LinearSolverKind kind);
bool uses_gamg(LinearSolverKind kind);

// What the iterative solvers trade between memory and time (petsc_linear_solver.h).
enum class IterativeSolverMemory {
  fast,  // PETSc's defaults: GAMG's Galerkin products through A P, GMRES restarted after 100
  lean,  // P^T A P all at once (A P never stored), GMRES restarted after 30
};

// How the membrane treats slack (docs/model.md, "Slack: the tension field").
enum class SlackTreatment {
  none,           // the law as given: compression is as stiff as tension
  tension_field,  // the law relaxed: no stress across wrinkles, none where slack every way
};

struct FemParameters {
  // Polynomial degree of the position field on triangles, 1 or 2. Degree 1 makes the assembled
  // internal force that of the mass-spring backend's triangle element; degree 2 (quadratic
  // triangles) hands the extractor a recovered traction (fem_backend.h).
  int element_degree = 1;
  LinearSolverKind linear_solver = LinearSolverKind::direct;
  IterativeSolverMemory iterative_solver_memory = IterativeSolverMemory::fast;
  // Krylov stopping rule: residual relative to the right-hand side; the floor of the inexact
  // Newton forcing term (newton_solver.cc).
  double linear_tolerance = 1e-10;
  int max_linear_iterations = 1000;
  // The FE backend's own stop rule (0: off): the residual force on a free degree of freedom
  // (stop.norm) below residual_tolerance * Y * h_k (Y the law's stiffness scale, N/m; h_k the
  // rest edge length of the degree of freedom's node, m: fem/contact_nodes.h). A case file's
  // auto: off on a rough mesh body, where the shared rms rule alone is met.
  double residual_tolerance = 1e-10;
  // The shared stop rule and gap tolerance (the case file's Solver entries, core/load_step.h):
  // the residual (stop.norm: its largest component, or the root mean square of the nodes'
  // residual vectors, both weighted by h / h_k, newton_solver.h) below stop.relative_tolerance
  // times Y h^2 / L, the tension scale (0: off). Newton stops when both rules that are on hold.
  // Here, for programs that build the backend themselves, the shared rule off and a gap of
  // 1e-9 m; a case file's defaults are the Solver subsection's (1e-4 and 1e-8 m).
  StopRule stop{0.0, StopNorm::largest, 1e-9};
  // Per contact round. The tops' first round from the mass-spring state takes 37 to 43: the slip
  // of fabric held by friction at its limit has no stiffness along the slip, and the shifted
  // steps carry it a few per cent of the residual an iteration (docs/performance-bodies.md,
  // "Newton on the tops"); the stocking's and the tubes' rounds take 32 or fewer.
  int max_newton_iterations = 60;
  bool line_search = true;
  // Globalization = potential: the potential judges the first Newton solve of a load step, and a
  // cut step is followed by a contact-set prediction (docs/backends.md, "Newton's line search");
  // false (residual): the residual's norm alone decides.
  bool potential_globalization = true;
  int max_line_search_halvings = 10;
  // Newton steps re-solved with the contact set the step predicts, at most this many times per
  // step (fem/contact_set_prediction.h); 0: each step on the contact set at x (but for the
  // globalization's own predictions, newton_solver.h); kAutoPredictions: 1 with friction, 0
  // without (the backend resolves it, fem_backend.cc).
  static constexpr int kAutoPredictions = -1;
  int max_contact_set_predictions = kAutoPredictions;
  // Penalty k_k = beta * Y / h_k^2 (Pa/m) of the augmented-Lagrangian contact at node k.
  double penalty_factor = 100.0;
  int max_augmented_lagrangian_iterations = 20;
  // Added to the tangent's diagonal (N/m) to remove rigid motions of bodies that do not
  // pin them; changes the path, never the converged state (the residual is untouched).
  double tangent_shift_N_per_m = 0.0;
  // Levenberg-Marquardt shift mu = theta |R|_max / h (N/m) of each Newton system; theta here,
  // dimensionless. Zero turns it off.
  double residual_shift_factor = 1.0;
  // Pseudo-transient continuation before Newton's rounds, with friction (fem/pseudo_transient.h):
  // at most this many pseudo time steps (0: none, the default: the coarse top took 1222 where
  // the mass-spring settle is three times cheaper, docs/performance-bodies.md), the first
  // shifted by pseudo_time_initial_shift times the stiffness scale.
  int max_pseudo_time_steps = 0;
  double pseudo_time_initial_shift = 0.1;
  SlackTreatment slack_treatment = SlackTreatment::none;
  // Under the tension field, the fraction of the law's own stiffness kept where the fabric is
  // wrinkled or slack (dimensionless): it keeps one equilibrium where nothing pulls across.
  double compression_stiffness_fraction = 1e-2;

  static void declare_parameters(dealii::ParameterHandler& prm);
  // Reads the subsection (not `stop`: the caller sets it from the Solver one); the entries at
  // auto take their values for a rough mesh body (StopRule::rough_mesh_body) when
  // `rough_mesh_body`. Throws std::invalid_argument naming the entry on a bad value.
  void parse_parameters(dealii::ParameterHandler& prm, bool rough_mesh_body = false);
};

const char* to_string(LinearSolverKind kind);
const char* to_string(SlackTreatment treatment);
const char* to_string(IterativeSolverMemory memory);

}  // namespace tightfit
