// `tightfit run`: each case on the backend its file names, with progress and a summary.
#pragma once

#include "app/command_line.h"
#include "cases/case_parameters.h"

#include <iosfwd>

namespace tightfit {

// Returns the process exit status: 0 when every case finished, 1 when a solver stopped one.
// Throws for bad input (std::invalid_argument, std::runtime_error): nothing ran then.
int run_command(const CommandLine& command_line, std::ostream& out);

// Where a case's results go: --output (DIR/<case file stem> with several cases), else the
// case's Output/Directory.
std::string output_directory_for(const CommandLine& command_line, const std::string& case_file,
                                 const std::string& from_case);

// This process among the MPI ranks of the run, and how an error of its own ends them all
// (OutputSettings::rank, n_ranks, end_every_rank): every command that runs a case sets them.
void share_output_by_rank(const CommandLine& command_line, OutputSettings& output);

}  // namespace tightfit
