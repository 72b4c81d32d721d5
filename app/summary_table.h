// The table `tightfit run` ends with: pressure against the body's morph parameter beside the
// scenario's closed form and its measurements' columns.
#pragma once

#include "cases/scenario.h"
#include "cases/scenario_run.h"
#include "io/text_table.h"

namespace tightfit {

TextTable pressure_summary_table(const Scenario& scenario, const RunResult& result);

// The case in a few lines: garment, mesh, law, body, constraints, backend.
void print_case_header(std::ostream& out, const std::string& case_file, const Scenario& scenario);

}  // namespace tightfit
