// tightfit: the one executable. Bad input exits with status 2 and a message that says what
// and where; a solver that fails exits with 1 and keeps what was written.
#include "app/command_line.h"
#include "app/compare_command.h"
#include "app/convergence_command.h"
#include "app/run_command.h"
#include "cases/case_parameters.h"

#include <iostream>

int main(int argc, char** argv) {
  using namespace tightfit;
  try {
    const CommandLine cl = parse_command_line(argc, argv);
    if (cl.command == "help") {
      std::cout << usage_text();
      return 0;
    }
    if (cl.command == "version") {
      std::cout << "tightfit 0.1.0\n";
      return 0;
    }
    if (cl.command == "print-parameters") {
      CaseFile().print(std::cout, cl.parameters_as_prm);
      return 0;
    }
    if (cl.command == "run") return run_command(cl, std::cout);
    if (cl.command == "compare") return compare_command(cl, std::cout);
    if (cl.command == "convergence") return convergence_command(cl, std::cout);
    std::cerr << "tightfit: '" << cl.command << "' is not available yet\n";
    return 2;
  } catch (const UsageError& e) {
    std::cerr << "tightfit: " << e.what() << "\n\n" << usage_text();
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "tightfit: error: " << e.what() << "\n";
    return 2;
  }
}
