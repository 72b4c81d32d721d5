// Zero-rest-length springs joining the two sides of every open seam (the paper's Section
// 4.3: the flat panels "are connected by seam lines" and pulled round the cylinder by them).
#pragma once

#include "core/types.h"

#include <limits>
#include <utility>
#include <vector>

namespace tightfit {

class SeamSprings {
 public:
  // `pairs` of vertex indices; `stiffness_N_per_m` of each spring.
  SeamSprings(std::vector<std::pair<int, int>> pairs, double stiffness_N_per_m);

  // Beyond this pull (N) a spring not yet sewn pulls no harder: a constant pull along the
  // pair's line, as a drawn thread's (infinite by default: the linear spring).
  void set_pull_limit(double pull_limit_N) { pull_limit_N_ = pull_limit_N; }
  // A sewn pair's spring is this many times stiffer (1 by default; the stiffness bounds count it).
  void set_sewn_stiffness_factor(double factor) { sewn_factor_ = factor; }
  // Marks every pair closer than `closed_m` as sewn: from then on its spring is linear at any
  // gap (a seam drawn shut holds). Returns how many pairs are sewn.
  int sew_closed_pairs(const std::vector<Vec3>& positions_m, double closed_m);
  // The sewn marks, one per pair (kept when the stiffness is rescaled).
  const std::vector<char>& sewn() const { return sewn_; }
  void set_sewn(std::vector<char> sewn) { sewn_ = std::move(sewn); }

  // Adds f_a = -k (x_a - x_b) and f_b = -f_a for every pair to force_N, N; an unsewn pair's
  // pull longer than the limit is shortened to it.
  void add_forces(const std::vector<Vec3>& positions_m, std::vector<Vec3>& force_N) const;
  // Adds each spring's Gershgorin row sum, 2 k per spring a vertex belongs to, N/m.
  void add_stiffness_bounds(std::vector<double>& stiffness_N_per_m) const;
  // The largest distance between the two vertices of a pair, m (0 without pairs).
  double largest_gap_m(const std::vector<Vec3>& positions_m) const;

  std::size_t size() const { return pairs_.size(); }

 private:
  std::vector<std::pair<int, int>> pairs_;
  double stiffness_N_per_m_;
  double pull_limit_N_ = std::numeric_limits<double>::infinity();
  std::vector<char> sewn_;  // empty: none sewn
  double sewn_factor_ = 1.0;
};

}  // namespace tightfit
