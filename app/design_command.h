// `tightfit design DESIGN.prm [--set ...] [--output DIR]`: designs a tubular garment so that it
// gives the pressure profile asked for on its limb (docs/design.md): Laplace's first guess,
// then simulations corrected band by band until every band is within the tolerance; writes the
// iterations' tables, the final comparison with Laplace's law and the cut (CSV, SVG, DXF).
#pragma once

#include "app/command_line.h"

#include <iosfwd>

namespace tightfit {

// Returns 0 when every band met its target, 1 when the iterations ran out or a simulation
// failed (what was found is written); bad input throws, as every command does.
int design_command(const CommandLine& cl, std::ostream& out);

}  // namespace tightfit
