// Mesh convergence of the pressure by named region (docs/validation.md, "Mesh convergence on a
// body"): each region's mean and peak pressure (cases/region_pressure.h) on meshes refined by a
// nearly constant ratio, with the observed order, Richardson's estimate and Roache's GCI of each
// (cases/convergence_analysis.h). Plain arithmetic: no mesh, no scenario.
#pragma once

#include "cases/convergence_analysis.h"

#include <limits>
#include <string>
#include <vector>

namespace tightfit {

// One region's pressure on one level, Pa; NaN where the garment does not touch it.
struct RegionLevelPressure {
  double mean_Pa = std::numeric_limits<double>::quiet_NaN();
  double peak_Pa = std::numeric_limits<double>::quiet_NaN();
};

// What the levels say about one region.
struct RegionConvergence {
  std::string region;
  int n_levels = 0;
  double edge_fine_m = 0.0;  // mean edge of the finest level, m
  double ratio = 2.0;        // measured refinement ratio (measured_refinement_ratio)
  double mean_fine_Pa = 0.0;
  double peak_fine_Pa = 0.0;
  ConvergenceEstimate mean;  // of the mean pressure over the region's contact area
  ConvergenceEstimate peak;  // of the peak vertex pressure in the region
};

// The refinement ratio an estimate from these levels uses: the geometric mean of the ratios of
// mean edge lengths over the finest three (or two) levels, coarse to fine. Whole numbers of
// divisions make a level's edge shrink by the nominal ratio only nearly. Throws
// std::invalid_argument with fewer than two levels.
double measured_refinement_ratio(const std::vector<double>& edges_m);

// One row per region of `names`, from `pressures[level][region]` and `edges_m[level]`, levels
// coarse to fine (at least two; throws std::invalid_argument otherwise, or when a level does not
// hold one value per region). With two levels the order is `assumed_order` (safety factor 3).
std::vector<RegionConvergence> estimate_region_convergence(
    const std::vector<std::string>& names, const std::vector<double>& edges_m,
    const std::vector<std::vector<RegionLevelPressure>>& pressures, double assumed_order);

}  // namespace tightfit
