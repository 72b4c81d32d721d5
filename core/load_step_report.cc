#include "core/load_step_report.h"

#include <sstream>

namespace tightfit {

void write_step_header(const std::string& backend, const LoadStep& step, double tolerance_N,
                       StopNorm norm, StepReport& report) {
  report.backend = backend;
  report.step_index = step.index;
  report.alpha = step.alpha;
  report.tolerance_N = tolerance_N;
  report.load_tolerance_N = tolerance_N;  // until a backend reads the contact load
  report.stop_norm = norm;
}

void StepClock::read(StepReport& report) const {
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
  report.cpu_seconds = double(std::clock() - cpu_start_) / CLOCKS_PER_SEC;
}

std::string gap_not_closed_text(const StepReport& report, double gap_tolerance_m) {
  std::ostringstream out;
  out << "the contact gap did not close (largest penetration " << report.largest_penetration_m
      << " m, Solver/Gap tolerance " << gap_tolerance_m << " m) after " << report.multiplier_updates
      << " contact multiplier updates; " << text(report.rounds);
  return out.str();
}

SolverError load_step_failure(StopReason reason, const std::string& backend, const LoadStep& step,
                              const std::string& what, double residual_N, double tolerance_N,
                              const std::string& details) {
  std::ostringstream out;
  out << backend << ", load step " << step.index << " (alpha " << step.alpha << "): " << what
      << "; residual " << residual_N << " N (tolerance " << tolerance_N << " N)";
  if (!details.empty()) out << "; " << details;
  return SolverError(reason, out.str(),
                     StepFailure{backend, step.index, step.alpha, residual_N, tolerance_N});
}

}  // namespace tightfit
