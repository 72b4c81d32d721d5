// libFuzzer target: `--set "Path/To/Entry=value"` assignments, one per line of the input,
// applied over the defaults and checked into the case's parameters.
#include "cases/case_parameters.h"

#include <cstddef>
#include <cstdint>
#include <exception>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  try {
    tightfit::CaseFile file;
    for (std::string line; std::getline(lines, line);) file.set(line);
    file.parameters();
  } catch (const std::exception&) {
    // A refused assignment: what the program reports with exit status 2.
  }
  return 0;
}
