// Where a failed dressing leaves the state it stopped in: two VTU files in the run's output
// directory, for ParaView (docs/arrangement.md "The jumpsuit and a failed dressing").
#pragma once

#include "cases/case_parameters.h"
#include "core/dressing_stage.h"

#include <string>

namespace tightfit {

// Writes `state` as dressing_failed.vtu (the panels, unsewn: point data "seam gap", "seam
// partner" and "distance to body", field data frame and body scale) and dressing_failed_body.vtu
// (the body at the scale it had then) into `directory`. Returns the clause the dressing's error
// message ends in: where the files are, or why they could not be written.
std::string write_failed_dressing(const std::string& directory, const DressingSnapshot& state);

// Sets settings.on_failure to write the failed state into output.directory, when the run writes
// files at all (output.write_files) and only on MPI rank 0.
void write_failed_dressing_to(const OutputSettings& output, DressingSettings& settings);

}  // namespace tightfit
