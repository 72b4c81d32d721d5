// What a backend reports of a load step, as fields: the solver's iterations and residuals, its
// contact multiplier rounds, why it stopped. The log line (solver.log) is made from them by
// text(), so that tests and tools read the fields and never the text.
#pragma once

#include "core/types.h"

#include <string>
#include <vector>

namespace tightfit {

// Which size of the residual force field the stop rule reads (docs/backends.md, "Reaching
// equilibrium").
enum class StopNorm {
  // The largest residual on any vertex (the mass-spring backend: its force vector; the FE
  // backend: its largest component): every vertex balanced to within the tolerance.
  largest,
  // The root mean square over the vertices, sqrt(sum |f_i|^2 / n): the garment balanced on the
  // whole while a few vertices may still chatter against a faceted body (a limit cycle the
  // largest residual never leaves; docs/dressing.md).
  rms,
};
const char* to_string(StopNorm norm);

// Why a load step ended. solve() returns only with `converged`; every other reason comes with a
// SolverError (core/backend.h).
enum class StopReason {
  converged,             // the stop rule holds and the contact gap is closed
  not_finite,            // a residual force is not finite (the state diverged)
  ran_away,              // a vertex ran further than ten garment sizes from the step's start
  iteration_limit,       // the frames or Newton iterations allowed ran out
  stalled,               // the residual stopped falling (RK4's stall test, halvings used up)
  still_sliding,         // the garment still slid (slide damping) when the frames ran out
  gap_not_closed,        // the contact multiplier rounds ran out with a vertex too deep
  contact_lost,          // a garment that touched the body at the last step left it
  linear_solver_failed,  // a Newton system could not be solved
  seams_not_closed,      // the flat-panel start or the dressing did not close its seams
  passed_into_body,      // the dressing left a vertex deep inside the body
};
const char* to_string(StopReason reason);

// One contact multiplier round (Uzawa, contact/penalty_contact.h): a solve at fixed
// multipliers, then the update.
struct MultiplierRound {
  int iterations = 0;              // frames or Newton iterations of the solve
  std::vector<double> residual_N;  // the stop rule's residual after the solve's iterations
                                   // (every Newton iteration; RK4: the last frame's)
  double penetration_m = 0.0;      // largest penetration of a vertex in contact after it
  int n_in_contact = 0;            // vertices (nodes) in contact after it
};
// The rounds as the report writes them: "rounds (iterations: residuals N; gap m, in contact):
// [iterations: residuals; gap, in contact] | ..." (a step that failed quotes them too).
std::string text(const std::vector<MultiplierRound>& rounds);

// The mass-spring backend's flat-panel start (the paper's Section 4.3), when it ran.
struct FlatStartReport {
  int frames = 0;
  double largest_seam_gap_m = 0.0;
  double closed_below_m = 0.0;
  double wall_seconds = 0.0;
};

// The mass-spring backend's damped dynamics (RK4) of a step.
struct RelaxationReport {
  int quasi_static_frames = 0;  // frames with the velocity reset (Section 4.3)
  int slide_frames = 0;         // frames at the slide damping (0: none)
  double slide_damping_per_s = 0.0;
  int time_step_halvings = 0;  // by the stall test
  double time_step_s = 0.0;    // at the end of the step
  double damping_per_s = 0.0;
  std::string stall_history;  // the stall test's windows, when it halved the time step
};

// A Newton solve's account (the FE backend's; the mass-spring implicit integrator's
// pseudo-transient Newton fills first_pseudo_time_step_s only).
struct NewtonReport {
  std::string linear_solver;            // the solver asked for (fem: 'direct', 'cg-amg', ...)
  std::vector<int> krylov_iterations;   // per linear solve (0: direct)
  std::string linear_solver_notes;      // switches to another solver, as they happened
  bool linear_solver_switched = false;  // a solver other than the one asked for was used
  int n_shifted_solves = 0;             // tangents shifted after a failed solve or line search
  int n_set_predictions = 0;            // systems solved again on a predicted contact set
  int n_failed_line_searches = 0;       // iterations that took a step the line search refused
  double first_pseudo_time_step_s = 0.0;
};

struct StepReport {
  std::string backend;  // "mass spring", "fem"
  int step_index = 0;
  double alpha = 0.0;
  StopReason stop_reason = StopReason::converged;
  int iterations = 0;        // frames (mass-spring RK4), factorisations (its implicit
                             // integrator) or Newton iterations (FE), over every round
  double residual_N = 0.0;   // the stop rule's residual at the end
  double tolerance_N = 0.0;  // the stop rule's threshold
  // The threshold at the end's contact load (StopRule::threshold_N, core/load_step.h): the
  // tolerance tightened to Solver/Contact load tolerance times the mean contact force on a
  // vertex in contact; equal to tolerance_N where that is looser, off or out of contact.
  double load_tolerance_N = 0.0;
  StopNorm stop_norm = StopNorm::largest;
  std::vector<MultiplierRound> rounds;  // one per solve at fixed multipliers
  int multiplier_updates = 0;           // contact multiplier updates done
  double largest_penetration_m = 0.0;   // of a vertex in contact at the end
  int n_in_contact = -1;                // at the end; -1: not counted
  int n_slipping = -1;                  // vertices at friction's limit; -1: no friction
  // The net force on the garment (the sum of the residuals) when the stop rule reads it
  // (Mass spring/Net force tolerance), and its limit; limit 0: not read.
  bool net_force_read = false;
  Vec3 net_force_N = Vec3::Zero();
  double net_force_limit_N = 0.0;
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;  // this process's CPU time (on a shared machine the wall time
                             // says little)
  // The backend's own route; each present when it ran.
  bool has_flat_start = false;
  FlatStartReport flat_start;
  bool has_relaxation = false;
  RelaxationReport relaxation;
  bool has_newton = false;
  NewtonReport newton;
  // Anything else worth one clause of the log line (the FE backend's recovered traction).
  std::string note;

  // The log line, made from the fields above.
  std::string text() const;
};

}  // namespace tightfit
