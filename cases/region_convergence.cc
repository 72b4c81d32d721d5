#include "cases/region_convergence.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace tightfit {

double measured_refinement_ratio(const std::vector<double>& edges_m) {
  const std::size_t n = edges_m.size();
  if (n < 2) throw std::invalid_argument("a refinement ratio needs at least two levels");
  const std::size_t used = std::min<std::size_t>(n, 3);
  return std::pow(edges_m[n - used] / edges_m[n - 1], 1.0 / static_cast<double>(used - 1));
}

std::vector<RegionConvergence> estimate_region_convergence(
    const std::vector<std::string>& names, const std::vector<double>& edges_m,
    const std::vector<std::vector<RegionLevelPressure>>& pressures, double assumed_order) {
  if (pressures.size() != edges_m.size())
    throw std::invalid_argument("region convergence: one edge length per level is needed");
  for (const std::vector<RegionLevelPressure>& level : pressures)
    if (level.size() != names.size())
      throw std::invalid_argument("region convergence: every level needs one value per region");
  const double ratio = measured_refinement_ratio(edges_m);
  std::vector<RegionConvergence> rows;
  for (std::size_t k = 0; k < names.size(); ++k) {
    std::vector<double> means, peaks;
    for (const std::vector<RegionLevelPressure>& level : pressures) {
      means.push_back(level[k].mean_Pa);
      peaks.push_back(level[k].peak_Pa);
    }
    RegionConvergence r;
    r.region = names[k];
    r.n_levels = static_cast<int>(pressures.size());
    r.edge_fine_m = edges_m.back();
    r.ratio = ratio;
    r.mean_fine_Pa = means.back();
    r.peak_fine_Pa = peaks.back();
    // A region without contact on some level reads NaN there; the estimates then read NaN too.
    r.mean = estimate_convergence(means, ratio, assumed_order, std::nullopt);
    r.peak = estimate_convergence(peaks, ratio, assumed_order, std::nullopt);
    rows.push_back(r);
  }
  return rows;
}

}  // namespace tightfit
