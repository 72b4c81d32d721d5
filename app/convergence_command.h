// `tightfit convergence`: one case at successively halved edge lengths on every backend.
#pragma once

#include "app/command_line.h"

#include <iosfwd>

namespace tightfit {

// Writes convergence.csv and convergence_summary.csv (columns documented in
// cases/convergence_run.h) into --output DIR or <Output/Directory>_convergence, and prints the
// summary. Returns 0 when every backend finished every level, 1 when a solver stopped one
// (what was written stays). Throws for bad input.
int convergence_command(const CommandLine& command_line, std::ostream& out);

}  // namespace tightfit
