// The headers nearly every translation unit includes, compiled once per target and reused by
// each of its files (CMake's target_precompile_headers; TIGHTFIT_PRECOMPILED_HEADERS in the
// top-level CMakeLists.txt). Parsing Eigen and the standard library is about two thirds of a
// typical file's compile time (docs/performance.md, "Building"). Only headers that change
// nothing but compile time belong here: every file still includes what it uses.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
