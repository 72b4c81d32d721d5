#include "massspring/seam_springs.h"

#include <algorithm>
#include <cmath>

namespace tightfit {

SeamSprings::SeamSprings(std::vector<std::pair<int, int>> pairs, double stiffness_N_per_m)
    : pairs_(std::move(pairs)), stiffness_N_per_m_(stiffness_N_per_m) {}

void SeamSprings::add_forces(const std::vector<Vec3>& x, std::vector<Vec3>& force_N) const {
  for (const auto& [a, b] : pairs_) {
    const Vec3 f = -stiffness_N_per_m_ * (x[a] - x[b]);
    force_N[a] += f;
    force_N[b] -= f;
  }
}

void SeamSprings::add_stiffness_bounds(std::vector<double>& stiffness_N_per_m) const {
  for (const auto& [a, b] : pairs_) {
    stiffness_N_per_m[a] += 2.0 * stiffness_N_per_m_;
    stiffness_N_per_m[b] += 2.0 * stiffness_N_per_m_;
  }
}

double SeamSprings::largest_gap_m(const std::vector<Vec3>& x) const {
  double largest_squared = 0.0;
  for (const auto& [a, b] : pairs_)
    largest_squared = std::max(largest_squared, (x[a] - x[b]).squaredNorm());
  return std::sqrt(largest_squared);
}

}  // namespace tightfit
