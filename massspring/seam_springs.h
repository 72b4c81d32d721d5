// Zero-rest-length springs joining the two sides of every open seam (the paper's Section
// 4.3: the flat panels "are connected by seam lines" and pulled round the cylinder by them).
#pragma once

#include "core/types.h"

#include <utility>
#include <vector>

namespace tightfit {

class SeamSprings {
 public:
  // `pairs` of vertex indices; `stiffness_N_per_m` of each spring.
  SeamSprings(std::vector<std::pair<int, int>> pairs, double stiffness_N_per_m);

  // Adds f_a = -k (x_a - x_b) and f_b = -f_a for every pair to force_N, N.
  void add_forces(const std::vector<Vec3>& positions_m, std::vector<Vec3>& force_N) const;
  // Adds each spring's Gershgorin row sum, 2 k per spring a vertex belongs to, N/m.
  void add_stiffness_bounds(std::vector<double>& stiffness_N_per_m) const;
  // The largest distance between the two vertices of a pair, m (0 without pairs).
  double largest_gap_m(const std::vector<Vec3>& positions_m) const;

  std::size_t size() const { return pairs_.size(); }

 private:
  std::vector<std::pair<int, int>> pairs_;
  double stiffness_N_per_m_;
};

}  // namespace tightfit
