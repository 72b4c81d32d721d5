// libFuzzer target: a pattern file (TIGHTFIT_FUZZ_EXTENSION: svg, json or dxf) read as
// `tightfit pattern` reads it (pattern/svg_reader.cc, garmentcode_reader.cc, dxf_reader.cc),
// checked, cut, and, when it passes, meshed at a coarse edge length and sewn
// (pattern_fuzz_steps.h). Any input must end in a garment or in an exception with a message,
// never a crash, a sanitizer report, a hang or a runaway allocation.
#include "pattern_fuzz_steps.h"
#include "scratch_file.h"

#include <cstddef>
#include <cstdint>
#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = tightfit::fuzz::write_scratch_file(data, size, TIGHTFIT_FUZZ_EXTENSION);
  try {
    tightfit::pattern::fuzz::read_check_mesh_and_sew(path);
  } catch (const std::exception&) {
    // A refused pattern: what the program reports with exit status 2.
  }
  return 0;
}
