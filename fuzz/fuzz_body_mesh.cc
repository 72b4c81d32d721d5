// libFuzzer target: a body mesh file (TIGHTFIT_FUZZ_EXTENSION: obj, stl or ply) read, imported
// and checked as a mesh body is (bodies/polygon_mesh_reader.cc, bodies/mesh_import.cc,
// bodies/triangle_surface.cc); a surface that passes is queried once. Any input must end in a
// body or in a BodyMeshError, never a crash, a sanitizer report, a hang or a runaway
// allocation.
#include "bodies/mesh_body.h"
#include "scratch_file.h"

#include <cstddef>
#include <cstdint>
#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = tightfit::fuzz::write_scratch_file(data, size, TIGHTFIT_FUZZ_EXTENSION);
  try {
    tightfit::MeshBodyOptions options;
    options.import.up_axis = "+z";
    const auto body = tightfit::load_mesh_body(path, options);
    body->query(tightfit::Vec3(0.1, 0.2, 0.3));
  } catch (const std::exception&) {
    // A refused file: what the program reports with exit status 2.
  }
  return 0;
}
