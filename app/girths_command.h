// `tightfit girths CASE.prm --near X,Y,Z --heights ...`: the girths of the case's body at given
// heights, and the axis of the limb they belong to (bodies/surface_slice.h).
#pragma once

#include "app/command_line.h"

#include <iosfwd>

namespace tightfit {

// Returns the exit status (0; bad input throws, as every command does).
int girths_command(const CommandLine& cl, std::ostream& out);

}  // namespace tightfit
