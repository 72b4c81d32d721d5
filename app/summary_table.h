// The table `tightfit run` ends with: pressure against alpha beside the closed forms.
#pragma once

#include "cases/cylinder_run.h"
#include "cases/cylinder_setup.h"
#include "io/text_table.h"

namespace tightfit {

TextTable pressure_summary_table(const CylinderSetup& setup, const RunResult& result);

// The case in a few lines: garment, mesh, law, body, backend.
void print_case_header(std::ostream& out, const std::string& case_file, const CylinderSetup& setup);

}  // namespace tightfit
