#include "app/run_command.h"

#include "app/summary_table.h"
#include "cases/case_parameters.h"
#include "cases/scenario.h"
#include "cases/scenario_run.h"

#include <filesystem>
#include <iostream>
#include <ostream>

namespace tightfit {

std::string output_directory_for(const CommandLine& cl, const std::string& case_file,
                                 const std::string& from_case) {
  if (cl.output_dir.empty()) return from_case;
  if (cl.case_files.size() == 1) return cl.output_dir;
  return (std::filesystem::path(cl.output_dir) / std::filesystem::path(case_file).stem()).string();
}

void share_output_by_rank(const CommandLine& cl, OutputSettings& output) {
  output.rank = cl.rank;
  output.n_ranks = cl.n_ranks;
  output.end_every_rank = cl.end_every_rank;
}

int run_command(const CommandLine& cl, std::ostream& out) {
  // Read and check every case before running any, so a typo in the second file does not
  // surface after the first has run for minutes.
  std::vector<std::unique_ptr<CaseFile>> files;
  std::vector<std::unique_ptr<Scenario>> setups;
  for (const std::string& path : cl.case_files) {
    files.push_back(std::make_unique<CaseFile>());
    files.back()->read(path, cl.overrides);
    CaseParameters parameters = files.back()->parameters();
    share_output_by_rank(cl, parameters.output);
    // Where the run writes, known before the scenario is made: a dressing that fails writes
    // the state it stopped in there.
    parameters.output.directory = output_directory_for(cl, path, parameters.output.directory);
    try {
      setups.push_back(make_scenario(parameters));
    } catch (const SolverError& e) {
      // A start that must be solved for (Placement/Kind = dressing) and failed: a failed solve.
      std::cerr << "tightfit: error: " << path << ": " << e.what() << "\n";
      return 1;
    }
  }

  int status = 0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    Scenario& setup = *setups[i];
    const CaseFile& file = *files[i];
    const std::string dir =
        output_directory_for(cl, cl.case_files[i], setup.parameters.output.directory);
    print_case_header(out, cl.case_files[i], setup);
    const RunResult result = run_scenario(
        setup,
        [&](const Problem& problem) {
          return file.create_backend(setup.parameters.backend, problem);
        },
        dir, out);
    out << "\n" << pressure_summary_table(setup, result);
    for (const TextTable& table : result.tables) out << "\n" << table;
    out << "  results in " << dir << "/ (pressure.csv, solver.log";
    for (const std::string& f : result.files) out << ", " << f;
    out << (setup.parameters.output.write_vtu ? ", garment.pvd, body.pvd" : "") << ")\n";
    if (!result.completed) {
      out << "  the run stopped early: " << result.failure << "\n";
      status = 1;
    }
    out << "\n";
    if (result.interrupted_by != 0) break;  // main returns 128 + the signal
  }
  return status;
}

}  // namespace tightfit
