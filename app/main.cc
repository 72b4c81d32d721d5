// tightfit: the one executable. Bad input exits with status 2 and a message that says what
// and where; a solver that fails exits with 1 and keeps what was written.
#include "app/command_line.h"
#include "app/compare_command.h"
#include "app/convergence_command.h"
#include "app/design_command.h"
#include "app/girths_command.h"
#include "app/measure_command.h"
#include "app/mpi_session.h"
#include "app/pattern_command.h"
#include "app/run_command.h"
#include "cases/case_parameters.h"
#include "core/interruption.h"

#include <iostream>
#include <sstream>

int main(int argc, char** argv) {
  using namespace tightfit;
  MpiSession mpi(argc, argv);
  // Every rank computes; the first one alone prints (and writes all files but the pieces of
  // parallel garment output).
  std::ostringstream discarded;
  std::ostream& out = mpi.is_first_rank() ? std::cout : discarded;
  try {
    // measure reads its own options (app/measure_command.h).
    if (argc > 1 && std::string(argv[1]) == "measure") return measure_command(argc, argv, out);
    CommandLine cl = parse_command_line(argc, argv);
    cl.rank = mpi.rank();
    cl.n_ranks = mpi.n_ranks();
    if (mpi.n_ranks() > 1)
      cl.end_every_rank = [&mpi](const std::string& what) {
        std::cerr << "tightfit (rank " << mpi.rank() << " of " << mpi.n_ranks()
                  << "): error: " << what << std::endl;
        mpi.abort_all_ranks(2);
      };
    if (cl.command == "help") {
      out << usage_text();
      return 0;
    }
    if (cl.command == "version") {
      out << "tightfit 0.1.0\n";
      return 0;
    }
    if (cl.command == "print-parameters") {
      const auto format = cl.parameters_format == "prm"    ? CaseFile::ParameterFormat::prm
                          : cl.parameters_format == "json" ? CaseFile::ParameterFormat::json
                                                           : CaseFile::ParameterFormat::text;
      CaseFile().print(out, format);
      return 0;
    }
    // From here on Ctrl-C and SIGTERM end the run at the next iteration, keeping every finished
    // load step, with status 128 + the signal's number.
    install_interruption_handlers();
    int status = 2;
    if (cl.command == "run") status = run_command(cl, out);
    if (cl.command == "compare") status = compare_command(cl, out);
    if (cl.command == "convergence") status = convergence_command(cl, out);
    if (cl.command == "design") status = design_command(cl, out);
    if (interruption_signal() != 0) return 128 + interruption_signal();
    if (cl.command == "run" || cl.command == "compare" || cl.command == "convergence" ||
        cl.command == "design")
      return status;
    if (cl.command == "pattern") return pattern_command(cl, out);
    if (cl.command == "girths") return girths_command(cl, out);
    std::cerr << "tightfit: '" << cl.command << "' is not available yet\n";
    return 2;
  } catch (const UsageError& e) {
    std::cerr << "tightfit: " << e.what() << "\n\n" << usage_text();
    return 2;
  } catch (const std::exception& e) {
    // Under MPI an error may reach one rank only (its piece of the output cannot be written):
    // it names itself and takes the others down with it instead of leaving them to hang.
    if (mpi.n_ranks() > 1) {
      std::cerr << "tightfit (rank " << mpi.rank() << " of " << mpi.n_ranks()
                << "): error: " << e.what() << std::endl;
      mpi.abort_all_ranks(2);
    }
    std::cerr << "tightfit: error: " << e.what() << "\n";
    return 2;
  }
}
