// The tightfit command line: which command, which case files, which overrides.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace tightfit {

struct CommandLine {
  std::string command;  // run, compare, convergence, design, pattern, girths, print-parameters,
                        // help, version
  std::vector<std::string> case_files;
  std::string output_dir;              // empty: the case's Output/Directory
  std::vector<std::string> overrides;  // "Path/To/Entry=value"
  int levels = 3;                      // convergence: number of meshes
  // convergence: the edge lengths' ratio from one level to the next, the regions to study
  // (empty: every region of the case) and the backends to run (empty: every backend).
  double refinement_ratio = 2.0;
  std::vector<std::string> convergence_regions, convergence_backends;
  std::string parameters_format = "text";  // print-parameters: text, prm or json
  // pattern: target mesh edge length (m), seams and fold edges besides the file's.
  double pattern_edge_length_m = 0.01;
  std::string pattern_seams, pattern_folds;
  // pattern: the size of a graded file and the unit of a file that names none (DXF).
  std::string pattern_size, pattern_units;
  // girths: the point the limb's loop must enclose, the slice heights and their direction.
  std::vector<double> girths_near, girths_heights, girths_axis = {0.0, 0.0, 1.0};
  int rank = 0;  // this process among the MPI ranks
  int n_ranks = 1;
  // Reports an error of this rank alone and ends every rank (OutputSettings::end_every_rank).
  std::function<void(const std::string&)> end_every_rank;
};

// Thrown for a malformed command line; the message says what is wrong.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

CommandLine parse_command_line(int argc, const char* const* argv);
std::string usage_text();

}  // namespace tightfit
