// The tables `tightfit convergence` prints for a case with named regions (cases/
// convergence_run.h): each region's mean and peak pressure at every level beside the
// Richardson estimate, and each region's observed orders, estimates and GCI. One load step
// each: the last that two or more levels of the backend finished (every step is in
// convergence_regions.csv and convergence_regions_summary.csv).
#pragma once

#include "cases/convergence_run.h"
#include "io/text_table.h"

#include <vector>

namespace tightfit {

// Empty when the study read no region.
std::vector<TextTable> region_convergence_tables(const ConvergenceStudy& study);

}  // namespace tightfit
