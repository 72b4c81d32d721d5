// The one exception a body mesh's reader, importer and checks throw: bad input, which the
// application reports with exit status 2 (app/main.cc catches it as a std::exception).
#pragma once

#include <stdexcept>
#include <string>

namespace tightfit {

class BodyMeshError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace tightfit
