// `tightfit measure BODY|CASE.prm`: a body's landmarks, part axes and standard girths
// (body/body_measurements.h) on screen, as JSON and CSV, and a picture of the body with them
// (docs/measuring-bodies.md).
#pragma once

#include <iosfwd>

namespace tightfit {

// argv[1] is "measure". Returns the exit status (0); bad input throws (a UsageError for the
// command line, std::invalid_argument for a body that cannot be measured), as every command
// does.
int measure_command(int argc, const char* const* argv, std::ostream& out);

}  // namespace tightfit
