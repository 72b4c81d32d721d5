// Starts a cylinder case's tube on a cylinder already at alpha = r / R0, so that a test runs
// only the load steps it checks.
#pragma once

#include "cases/case_parameters.h"

#include <cstdio>

namespace tightfit::testing {

// Sets Body/Cylinder/Initial radius to alpha R0, R0 the tube's rest radius (m).
inline void start_cylinder_at(CaseFile& file, double alpha, double rest_radius_m) {
  char initial_radius[96];
  std::snprintf(initial_radius, sizeof initial_radius, "Body/Cylinder/Initial radius=%.17g",
                alpha * rest_radius_m);
  file.set(initial_radius);
}

}  // namespace tightfit::testing
