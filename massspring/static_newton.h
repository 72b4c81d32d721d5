// The implicit route to the mass-spring backend's stable state (Mass spring/Integrator =
// implicit): a regularised Newton iteration on the static equilibrium f(x) = 0 with the same
// forces as RK4 (membrane, bending, contact, gravity, held components removed) and their
// stiffness K = -df/dx, each increment from the sparse Cholesky factorisation (CHOLMOD) of
//
//     (K + M / tau^2) dx = f(x),
//
// M the lumped masses: one step of implicit Euler with the velocity reset (pseudo-transient
// continuation, Kelley and Keyes, SIAM J. Numer. Anal. 35, 1998). A short pseudo-time tau
// makes the matrix positive definite where K is not (a slack garment, the rigid slide and
// turn of a frictionless tube on a cylinder, compressed wrinkles) and the step a damped one;
// tau grows tenfold after every full step, so the iteration becomes Newton's and converges
// quadratically near the equilibrium. A step that does not lower the residual's norm is
// halved (backtracking), and when halving does not help, or the factorisation finds the matrix
// not positive definite, tau shrinks tenfold (Hooks::remember_refusals: how it grows back). The
// stop rule is RK4's: the largest residual force on a vertex below the tolerance; so both reach the
// same equilibrium to it.
#pragma once

#include "core/types.h"
#include "massspring/sparse_blocks.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tightfit {

class StaticNewton {
 public:
  // Fills `force` (N) for positions `x`; returns the largest magnitude over the vertices (NaN
  // when a force is not finite).
  using Forces = std::function<double(const std::vector<Vec3>& x, std::vector<Vec3>& force)>;
  // Sets `K` to the stiffness -df/dx (N/m, symmetric, 3n x 3n) at `x`.
  using Stiffness = std::function<void(const std::vector<Vec3>& x, SparseMatrix& K)>;
  // Sets `w` (3n) to a mode the increments must not move along, w^T dx = 0, whose reaction the
  // residual already has removed (f^T u = 0 for the u with w^T u != 0 that the forces project
  // out): the held turn's mass-weighted turn m_i a x (x_i - c) (core/held_turn.h).
  using HeldMode = std::function<void(const std::vector<Vec3>& x, Eigen::VectorXd& w)>;
  // Contact set prediction: given the increment `dx` just solved for, changes the system
  // (A dx = rhs, A the regularised matrix) at the vertices whose contact the increment opens
  // or closes, to the linearisation about the set the increment predicts; returns false when
  // the set it predicts is the one the system already has (a primal-dual active set step,
  // Hintermueller, Ito and Kunisch, SIAM J. Optim. 13, 2003).
  using ContactSet =
      std::function<bool(const Eigen::VectorXd& dx, SparseMatrix& A, Eigen::VectorXd& rhs)>;
  struct Hooks {
    HeldMode held_mode;          // empty: no held mode
    ContactSet contact_set;      // empty: the set at x
    int contact_set_solves = 3;  // at most this many solves more per iteration
    // Above 0: stop (not converged) once the largest residual has not fallen below 0.9 times
    // its value this many iterations before: a stall, for the caller to finish another way.
    int stall_iterations = 0;
    // After a refused step, grow tau back only halfway (in its logarithm) towards the refused
    // value, a memory that fades twofold with each full step; without it tau grows tenfold
    // after every full step. For the projected tangent on a friction-held garment, where a
    // tau alternating between a full step and a refusal factorised twice per step.
    bool remember_refusals = false;
  };

  struct Result {
    bool converged = false;
    int iterations = 0;       // factorisations
    double residual_N = 0.0;  // the largest residual force at the end
    bool stalled = false;     // stopped by Hooks::stall_iterations
    std::string history;      // one line per iteration
  };

  StaticNewton();
  ~StaticNewton();

  // Iterates from `x` (updated in place) until the largest residual force is below
  // tolerance_N, or `maximum_iterations` factorisations. `initial_tau_s` is the first pseudo
  // time step (s), e.g. the inverse of the garment's critical damping.
  Result solve(std::vector<Vec3>& x, const std::vector<double>& mass_kg, const Forces& forces,
               const Stiffness& stiffness, double tolerance_N, double initial_tau_s,
               int maximum_iterations, const Hooks& hooks);

 private:
  // dx = A^-1 rhs from the factorisation, kept normal to the held mode's w when there is one.
  void solve_increment(const std::vector<Vec3>& x, const Eigen::VectorXd& rhs,
                       const HeldMode& held_mode, Eigen::VectorXd& dx) const;

  struct Factorisation;
  std::unique_ptr<Factorisation> factorisation_;
};

}  // namespace tightfit
