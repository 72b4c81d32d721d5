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
// not positive definite, tau shrinks tenfold. The stop rule is RK4's: the largest residual
// force on a vertex below the tolerance; so both reach the same equilibrium to it.
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

  struct Result {
    bool converged = false;
    int iterations = 0;       // factorisations
    double residual_N = 0.0;  // the largest residual force at the end
    std::string history;      // one line per iteration
  };

  StaticNewton();
  ~StaticNewton();

  // Iterates from `x` (updated in place) until the largest residual force is below
  // tolerance_N, or `maximum_iterations` factorisations. `initial_tau_s` is the first pseudo
  // time step (s), e.g. the inverse of the garment's critical damping.
  Result solve(std::vector<Vec3>& x, const std::vector<double>& mass_kg, const Forces& forces,
               const Stiffness& stiffness, double tolerance_N, double initial_tau_s,
               int maximum_iterations);

 private:
  struct Factorisation;
  std::unique_ptr<Factorisation> factorisation_;
};

}  // namespace tightfit
