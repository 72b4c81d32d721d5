// `tightfit compare`: one case on both backends, on the same mesh.
#pragma once

#include "app/command_line.h"

#include <iosfwd>

namespace tightfit {

// Returns 0 when both runs finished, 1 when a solver stopped one. Throws for bad input.
int compare_command(const CommandLine& command_line, std::ostream& out);

}  // namespace tightfit
