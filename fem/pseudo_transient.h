// Pseudo-transient continuation: the first phase of a load step with friction. Each pseudo
// time step solves the backward-Euler step of the overdamped motion C dx/dt = -R(x),
//
//   (C / dt) (x - x_n) + R(x) = 0,    C / dt = sigma I,
//
// linearised once at x_n: (K(x_n) + sigma I) dx = -R(x_n), x_{n+1} = x_n + dx (the step capped
// at half an edge, as Newton's). No line search judges the step: the pseudo time step is the
// globalization, an overdamped path like the mass-spring settle's damped one, through a
// frictional state whose residual has kinks at every node (docs/performance-bodies.md, "The FE
// backend from the dressed tops"). sigma falls as the residual does (switched evolution relaxation,
// Mulder and van Leer: sigma_{n+1} = sigma_n |R_{n+1}| / |R_n|, here also divided by 1.5 at every
// step taken), so the steps become Newton's; at the stop rule the phase hands the rest of the step,
// the contact rounds, to Newton (newton_solver.h). A step that raises the residual more than
// twice is refused and sigma grows threefold.
#pragma once

#include "core/load_step.h"
#include "fem/newton_solver.h"

namespace tightfit {

struct PseudoTransientSettings {
  int max_steps = 0;           // 0: no pseudo-transient phase
  double initial_shift = 0.0;  // sigma_0 over the stiffness scale Y, dimensionless
};

// Runs the phase from x (the tangent and residual at x assembled by `assemble` first); returns
// the pseudo time steps taken (refused ones included) and appends each step's residual (the
// stop rule's size) and step length to `log`. Friction's anchors stay those of the last
// accepted load step throughout (as for every Newton iterate).
int pseudo_transient_settle(const LoadStep& step, NewtonSolver& newton,
                            const NewtonSolver::Assembler& assemble, NewtonSystem& system,
                            DofVector& x, NewtonLog& log, const PseudoTransientSettings& settings);

}  // namespace tightfit
