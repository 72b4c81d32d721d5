// Running a VTK reader with its reports collected instead of printed, so that a bad file gives
// one clear message naming it rather than VTK's lines on the terminal.
#pragma once

#include <string>

class vtkAlgorithm;

namespace tightfit {

// reader.Update() with VTK's error and warning reports caught. Returns what went wrong in the
// reader's own words (the first line of each report, without VTK's "ERROR: In file, line n"
// and "vtkClass (address): " prefixes, joined by "; "), else its pipeline's, else "error code
// N" for a reader that failed silently; empty when the read succeeded.
std::string update_reader_quietly(vtkAlgorithm& reader);

}  // namespace tightfit
