// `tightfit pattern FILE`: what a pattern file holds (panels, edge lengths, seam length
// mismatches), its mesh (quality, time), the meshed panels as VTU in the layout plane and a
// PNG of the outlines with the seams marked.
#pragma once

#include "app/command_line.h"

#include <iosfwd>

namespace tightfit {

// Returns the exit status (0; bad input throws, as every command does).
int pattern_command(const CommandLine& cl, std::ostream& out);

}  // namespace tightfit
