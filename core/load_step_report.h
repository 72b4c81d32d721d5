// What both backends write alike of a load step, into its report (core/step_report.h) or its
// failure (SolverError, core/backend.h): which backend and step, the stop rule's threshold, the
// clocks, and the failure message's frame.
#pragma once

#include "core/backend.h"
#include "core/load_step.h"
#include "core/step_report.h"

#include <chrono>
#include <ctime>
#include <string>

namespace tightfit {

// The stop rule's threshold, N: 'Solver/Relative tolerance' times the tension scale Y h^2 / L
// (core/tension_scale.h, docs/backends.md, "Reaching equilibrium").
inline double relative_threshold_N(const StopRule& rule, double tension_scale_N) {
  return rule.relative_tolerance * tension_scale_N;
}

// Fills the report's backend name, step index, alpha, stop threshold and norm.
void write_step_header(const std::string& backend, const LoadStep& step, double tolerance_N,
                       StopNorm norm, StepReport& report);

// A load step's clocks, started at construction: the wall time and this process's CPU time
// (on a shared machine the wall time says little).
class StepClock {
 public:
  // Writes the time since construction into report.wall_seconds and report.cpu_seconds.
  void read(StepReport& report) const;

 private:
  std::chrono::steady_clock::time_point wall_start_ = std::chrono::steady_clock::now();
  std::clock_t cpu_start_ = std::clock();
};

// What a load step whose multiplier rounds (core/load_step.h) left the gap open says: "the
// contact gap did not close (largest penetration <p> m, Solver/Gap tolerance <g> m) after <n>
// contact multiplier updates; rounds ...", from the report the rounds ran into.
std::string gap_not_closed_text(const StepReport& report, double gap_tolerance_m);

// The error a backend throws when a load step fails, its message
// "<backend>, load step <index> (alpha <alpha>): <what>; residual <r> N (tolerance <t> N)"
// followed by "; <details>" when there are any; the same as fields in its failure().
SolverError load_step_failure(StopReason reason, const std::string& backend, const LoadStep& step,
                              const std::string& what, double residual_N, double tolerance_N,
                              const std::string& details = "");

}  // namespace tightfit
