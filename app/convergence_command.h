// `tightfit convergence`: one case at edge lengths divided by a constant ratio (--ratio, 2 by
// default) level by level, on every backend or those of --backends; with named regions, each
// region's mean and peak pressure too (--regions chooses which).
#pragma once

#include "app/command_line.h"

#include <iosfwd>

namespace tightfit {

// Writes convergence.csv and convergence_summary.csv, and for a case with regions
// convergence_regions.csv and convergence_regions_summary.csv (columns documented in
// cases/convergence_run.h), into --output DIR or <Output/Directory>_convergence, and prints the
// summary. Returns 0 when every backend finished every level, 1 when a solver stopped one
// (what was written stays). Throws for bad input (an unknown backend or region among them).
int convergence_command(const CommandLine& command_line, std::ostream& out);

}  // namespace tightfit
