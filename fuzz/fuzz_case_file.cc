// libFuzzer target: a case file (.prm) as `tightfit run` reads it, then checked into the
// case's parameters. Any input must end in the values or in an exception with a message,
// never a crash, a sanitizer report or a hang.
#include "cases/case_parameters.h"
#include "scratch_file.h"

#include <cstddef>
#include <cstdint>
#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = tightfit::fuzz::write_scratch_file(data, size, "prm");
  try {
    tightfit::CaseFile file;
    file.read(path, {});
    file.parameters();
  } catch (const std::exception&) {
    // A refused input: what the program reports with exit status 2.
  }
  return 0;
}
