#include "massspring/seam_springs.h"

#include <algorithm>
#include <cmath>

namespace tightfit {

SeamSprings::SeamSprings(std::vector<std::pair<int, int>> pairs, double stiffness_N_per_m)
    : pairs_(std::move(pairs)), stiffness_N_per_m_(stiffness_N_per_m) {}

void SeamSprings::add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& force_N) const {
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    const auto& [a, b] = pairs_[k];
    const bool sewn = !sewn_.empty() && sewn_[k];
    Vec3 f = -(sewn ? sewn_factor_ : 1.0) * stiffness_N_per_m_ * (x[a] - x[b]);
    const double pull = f.norm();
    if (pull > pull_limit_N_ && !sewn) f *= pull_limit_N_ / pull;
    force_N[a] += f;
    force_N[b] -= f;
  }
}

void SeamSprings::add_stiffness_bounds(std::vector<double>& stiffness_N_per_m) const {
  const double k = std::max(1.0, sewn_factor_) * stiffness_N_per_m_;
  for (const auto& [a, b] : pairs_) {
    stiffness_N_per_m[a] += 2.0 * k;
    stiffness_N_per_m[b] += 2.0 * k;
  }
}

int SeamSprings::sew_closed_pairs(const std::vector<Vec3>& x, double closed_m) {
  sewn_.resize(pairs_.size(), 0);
  int sewn = 0;
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    if (!sewn_[k] && (x[pairs_[k].first] - x[pairs_[k].second]).norm() < closed_m) sewn_[k] = 1;
    sewn += sewn_[k];
  }
  return sewn;
}

double SeamSprings::largest_gap_m(const std::vector<Vec3>& x) const {
  double largest_squared = 0.0;
  for (const auto& [a, b] : pairs_)
    largest_squared = std::max(largest_squared, (x[a] - x[b]).squaredNorm());
  return std::sqrt(largest_squared);
}

}  // namespace tightfit
