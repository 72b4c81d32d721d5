#include "massspring/static_newton.h"

#include <Eigen/CholmodSupport>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace tightfit {

// CHOLMOD's supernodal LL^T; its symbolic analysis is kept while the pattern stays the same.
struct StaticNewton::Factorisation {
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt;
  Eigen::Index analysed_nonzeros = -1, analysed_size = -1;
};

StaticNewton::StaticNewton() : factorisation_(std::make_unique<Factorisation>()) {
  // A matrix that is not positive definite is expected (the pseudo time step then shrinks):
  // no warning on the console.
  cholmod_common& common = factorisation_->llt.cholmod();
  common.print = 0;
  // Fill-reducing ordering: the less fill of approximate minimum degree and METIS's nested
  // dissection, chosen once per pattern. On a garment (a surface mesh, a planar graph)
  // nested dissection bounds the flops by O(N^1.5) (George 1973) and beats minimum degree: on the
  // 8460-vertex tube 1.31e9 flops a factorisation against AMD's 2.82e9 (CHOLMOD's default
  // strategy keeps AMD there).
  common.nmethods = 2;
  common.method[0].ordering = CHOLMOD_AMD;
  common.method[1].ordering = CHOLMOD_METIS;
}
StaticNewton::~StaticNewton() = default;

namespace {

double norm2(const std::vector<Vec3>& f) {
  double sum = 0.0;
  for (const Vec3& v : f) sum += v.squaredNorm();
  return std::sqrt(sum);
}

}  // namespace

void StaticNewton::solve_increment(const std::vector<Vec3>& x, const Eigen::VectorXd& rhs,
                                   const HeldMode& held_mode, Eigen::VectorXd& dx) const {
  const Factorisation& f = *factorisation_;
  dx = f.llt.solve(rhs);
  if (!held_mode) return;
  // The held mode's constraint w^T dx = 0 with its reaction mu w (a saddle point):
  // A dx + mu w = f, so dx = A^-1 f - mu A^-1 w with mu = w^T A^-1 f / w^T A^-1 w. The
  // residual the linear step leaves, mu w, is what the forces' projection removes.
  Eigen::VectorXd w;
  held_mode(x, w);
  const Eigen::VectorXd along_w = f.llt.solve(w);
  const double w_along_w = w.dot(along_w);
  if (w_along_w > 0) dx -= (w.dot(dx) / w_along_w) * along_w;
}

StaticNewton::Result StaticNewton::solve(std::vector<Vec3>& x, const std::vector<double>& mass_kg,
                                         const Forces& forces, const Stiffness& stiffness,
                                         double tolerance_N, double initial_tau_s,
                                         int maximum_iterations, const Hooks& hooks) {
  const std::size_t n = x.size();
  // tau between these bounds: the longest makes M / tau^2 negligible against any stiffness
  // (Newton's own step), the shortest a step of explicit size.
  const double longest_tau_s = 1e8 * initial_tau_s, shortest_tau_s = 1e-8 * initial_tau_s;
  Result result;
  std::ostringstream history;
  history << "Newton (iteration: largest residual N, pseudo time step s, step length)";
  std::vector<Vec3> force(n), trial_x(n), trial_force(n);
  double largest = forces(x, force);
  double norm = norm2(force);
  double tau = initial_tau_s;
  double refused_tau = std::numeric_limits<double>::infinity();  // the last refused tau, s
  SparseMatrix K;
  Eigen::VectorXd rhs(3 * n), dx(3 * n);
  Factorisation& f = *factorisation_;
  std::vector<double> largest_by_iteration{largest};
  while (std::isfinite(largest) && largest >= tolerance_N &&
         result.iterations < maximum_iterations) {
    const int window = hooks.stall_iterations;
    if (window > 0 && result.iterations >= window &&
        !(largest < 0.9 * largest_by_iteration[result.iterations - window])) {
      result.stalled = true;
      break;
    }
    ++result.iterations;
    stiffness(x, K);
    for (std::size_t v = 0; v < n; ++v) {
      const double regularisation = mass_kg[v] / (tau * tau);
      for (int k = 0; k < 3; ++k) K.coeffRef(3 * v + k, 3 * v + k) += regularisation;
      rhs.segment<3>(3 * v) = force[v];
    }
    if (K.nonZeros() != f.analysed_nonzeros || K.rows() != f.analysed_size) {
      f.llt.analyzePattern(K);
      f.analysed_nonzeros = K.nonZeros();
      f.analysed_size = K.rows();
    }
    f.llt.factorize(K);
    bool accepted = false;
    double length = 1.0;
    if (f.llt.info() == Eigen::Success) {
      solve_increment(x, rhs, hooks.held_mode, dx);
      // Linearised again about the contact set the increment predicts, while it changes and
      // the matrix stays positive definite.
      for (int p = 0;
           p < hooks.contact_set_solves && hooks.contact_set && hooks.contact_set(dx, K, rhs);
           ++p) {
        f.llt.factorize(K);
        if (f.llt.info() != Eigen::Success) break;
        solve_increment(x, rhs, hooks.held_mode, dx);
      }
      // Backtracking on the residual's norm.
      for (int halving = 0; halving < 6 && !accepted; ++halving, length *= 0.5) {
        for (std::size_t v = 0; v < n; ++v) trial_x[v] = x[v] + length * dx.segment<3>(3 * v);
        const double trial_largest = forces(trial_x, trial_force);
        const double trial_norm = norm2(trial_force);
        if (std::isfinite(trial_largest) && trial_norm < norm) {
          accepted = true;
          x.swap(trial_x);
          force.swap(trial_force);
          largest = trial_largest;
          norm = trial_norm;
        }
      }
      if (accepted) length *= 2.0;  // undo the loop's last halving
    }
    largest_by_iteration.push_back(largest);
    history << "\n  " << result.iterations << ": " << largest << "  " << tau << "  ";
    if (accepted)
      history << length;
    else
      history << (f.llt.info() == Eigen::Success ? "0 (no descent)" : "0 (not positive definite)");
    if (accepted && length == 1.0) {
      // Towards a refused tau by halves of the way in its logarithm; that memory fades
      // (doubles) with each full step. A tau that alternates between a full step and a refusal
      // (compressed fabric held by friction on a faceted body) would factorise twice per step.
      tau = std::min({10.0 * tau, std::sqrt(tau * refused_tau), longest_tau_s});
      refused_tau *= 2.0;
    } else if (!accepted) {
      if (tau <= shortest_tau_s) break;
      if (hooks.remember_refusals) refused_tau = tau;
      tau = std::max(0.1 * tau, shortest_tau_s);
    }
  }
  result.residual_N = largest;
  result.converged = std::isfinite(largest) && largest < tolerance_N;
  result.history = history.str();
  return result;
}

}  // namespace tightfit
