// The one exception a body mesh's reader, importer and checks throw: bad input, which the
// application reports with exit status 2 (app/main.cc catches it as a std::exception).
#pragma once

#include "core/memory_budget.h"

#include <stdexcept>
#include <string>

namespace tightfit {

class BodyMeshError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// "body mesh 'PATH', line N: MESSAGE", for a fault a file's checks find on one line.
inline BodyMeshError body_mesh_line_error(const std::string& path, int line,
                                          const std::string& message) {
  return BodyMeshError("body mesh '" + path + "', line " + std::to_string(line) + ": " + message);
}

// require_memory's refusal of the faces a file announces, as the readers' own error type.
inline void require_body_memory(const std::string& path, double faces, const std::string& items) {
  try {
    require_memory("body mesh '" + path + "'", faces, items, bytes_per_body_face);
  } catch (const std::invalid_argument& e) {
    throw BodyMeshError(e.what());
  }
}

}  // namespace tightfit
