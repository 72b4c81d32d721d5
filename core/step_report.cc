#include "core/step_report.h"

#include <sstream>

namespace tightfit {

const char* to_string(StopNorm norm) {
  switch (norm) {
    case StopNorm::largest:
      return "largest";
    case StopNorm::rms:
      return "rms";
  }
  return "unknown";
}

const char* to_string(StopReason reason) {
  switch (reason) {
    case StopReason::converged:
      return "converged";
    case StopReason::not_finite:
      return "not finite";
    case StopReason::ran_away:
      return "ran away";
    case StopReason::iteration_limit:
      return "iteration limit";
    case StopReason::stalled:
      return "stalled";
    case StopReason::still_sliding:
      return "still sliding";
    case StopReason::gap_not_closed:
      return "gap not closed";
    case StopReason::contact_lost:
      return "contact lost";
    case StopReason::linear_solver_failed:
      return "linear solver failed";
    case StopReason::seams_not_closed:
      return "seams not closed";
    case StopReason::passed_into_body:
      return "passed into the body";
  }
  return "unknown";
}

namespace {

void write_rounds(std::ostream& out, const std::vector<MultiplierRound>& rounds) {
  out << "; " << text(rounds);
}

}  // namespace

std::string text(const std::vector<MultiplierRound>& rounds) {
  std::ostringstream out;
  out << "rounds (iterations: residuals N; gap m, in contact):";
  for (std::size_t r = 0; r < rounds.size(); ++r) {
    const MultiplierRound& round = rounds[r];
    out << (r ? " |" : "") << " [" << round.iterations << ":";
    std::ostringstream values;
    values.precision(2);
    values << std::scientific;
    for (double residual : round.residual_N) values << " " << residual;
    values << "; " << round.penetration_m;
    out << values.str() << ", " << round.n_in_contact << "]";
  }
  return out.str();
}

namespace {

void write_relaxation(std::ostream& out, const RelaxationReport& r) {
  out << " (" << r.quasi_static_frames << " quasi-static";
  if (r.slide_frames > 0)
    out << ", " << r.slide_frames << " slid at damping " << r.slide_damping_per_s << " 1/s";
  out << ", " << r.time_step_halvings << " time step halvings), dt " << r.time_step_s
      << " s, damping " << r.damping_per_s << " 1/s";
}

void write_newton(std::ostream& out, const NewtonReport& n) {
  if (n.first_pseudo_time_step_s > 0)
    out << ", first pseudo time step " << n.first_pseudo_time_step_s << " s";
  if (!n.linear_solver.empty()) {
    out << "; krylov (" << n.linear_solver << "):";
    for (int k : n.krylov_iterations) out << " " << k;
  }
  if (!n.linear_solver_notes.empty()) out << " [" << n.linear_solver_notes << "]";
  if (n.n_shifted_solves > 0) out << "; " << n.n_shifted_solves << " shifted tangents";
  if (n.n_failed_line_searches > 0)
    out << "; " << n.n_failed_line_searches << " steps taken after a failed line search";
  if (n.n_set_predictions > 0)
    out << "; " << n.n_set_predictions << " solves on a predicted contact set";
}

}  // namespace

std::string StepReport::text() const {
  std::ostringstream out;
  out << backend << ": load step " << step_index << " (alpha " << alpha << ") "
      << to_string(stop_reason);
  if (has_flat_start)
    out << " after a flat-panel start (seams closed to " << flat_start.largest_seam_gap_m << " m < "
        << flat_start.closed_below_m << " m in " << flat_start.frames << " frames, "
        << flat_start.wall_seconds << " s)";
  out << ": " << iterations << (has_relaxation ? " frames" : " Newton iterations");
  if (has_relaxation) write_relaxation(out, relaxation);
  if (has_newton) write_newton(out, newton);
  out << "; residual " << residual_N << " N, stop rule " << tolerance_N << " N ("
      << to_string(stop_norm) << ")";
  if (load_tolerance_N < tolerance_N) out << ", " << load_tolerance_N << " N at the contact load";
  if (net_force_read) {
    out << ", net force on the garment " << net_force_N.norm() << " N (" << net_force_N.x() << ", "
        << net_force_N.y() << ", " << net_force_N.z() << ")";
    if (net_force_limit_N > 0) out << " < " << net_force_limit_N << " N";
  }
  out << "; " << multiplier_updates << " contact multiplier updates";
  if (!rounds.empty()) write_rounds(out, rounds);
  out << "; largest penetration " << largest_penetration_m << " m";
  if (n_in_contact >= 0) out << ", " << n_in_contact << " in contact";
  if (n_slipping >= 0) out << ", " << n_slipping << " slipping";
  if (!note.empty()) out << "; " << note;
  out << "; " << wall_seconds << " s (" << cpu_seconds << " s CPU)";
  if (has_relaxation && !relaxation.stall_history.empty()) out << "; " << relaxation.stall_history;
  return out.str();
}

}  // namespace tightfit
