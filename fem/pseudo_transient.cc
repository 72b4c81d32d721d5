#include "fem/pseudo_transient.h"

#include <algorithm>
#include <cmath>

namespace tightfit {

namespace {

// Hands over to Newton below this many times the stop rule. At 10 the coarse top handed over
// in its slide (2.5e-3 N against 2.5e-4 N) and Newton stalled there as from the dressed state.
constexpr double kHandOver = 1.0;
// A step that raises the residual more than this is refused and sigma grows threefold (the
// pseudo path may climb a little: the residual is not the overdamped motion's energy).
constexpr double kLargestGrowth = 2.0;
constexpr double kRefusedGrowth = 3.0;
// The pseudo time step's growth at every step taken: SER alone left sigma where it started while
// the coarse top slid at a level residual.
constexpr double kGrowth = 1.5;
// sigma stays between these multiples of the stiffness scale.
constexpr double kSmallestShift = 1e-8;
constexpr double kLargestShift = 1e6;

}  // namespace

int pseudo_transient_settle(const LoadStep& step, NewtonSolver& newton,
                            const NewtonSolver::Assembler& assemble, NewtonSystem& system,
                            DofVector& x, NewtonLog& log, const PseudoTransientSettings& settings) {
  if (settings.max_steps <= 0) return 0;
  const double Y = newton.stiffness_scale_N_per_m();
  const double mean_edge_m = newton.mean_edge_m();
  double sigma = settings.initial_shift * Y;
  assemble(x, true);
  double residual_N = newton.scaled_residual_N(system);
  DofVector increment, trial;
  int n = 0;
  for (; n < settings.max_steps; ++n) {
    if (!std::isfinite(residual_N) || residual_N <= kHandOver * newton.solve_tolerance_N()) break;
    log.residual_N.push_back(residual_N);
    newton.solve_shifted(step, x, system, sigma, log, increment);
    const double length = std::min(1.0, 0.5 * mean_edge_m / increment.linfty_norm());
    trial = x;
    trial.add(length, increment);
    assemble(trial, true);
    const double trial_N = newton.scaled_residual_N(system);
    if (!std::isfinite(trial_N) || trial_N > kLargestGrowth * residual_N) {
      log.step_length.push_back(0.0);
      ++log.n_shifted_solves;
      sigma = std::min(kRefusedGrowth * std::max(sigma, kSmallestShift * Y), kLargestShift * Y);
      assemble(x, true);
      continue;
    }
    log.step_length.push_back(length);
    x = trial;
    // Switched evolution relaxation: the pseudo time step grows as the residual falls, and
    // by kGrowth at every step taken (a slide whose residual stays level still speeds up).
    sigma = std::clamp(sigma * std::min(1.0, trial_N / residual_N) / kGrowth, kSmallestShift * Y,
                       kLargestShift * Y);
    residual_N = trial_N;
  }
  return n;
}

}  // namespace tightfit
