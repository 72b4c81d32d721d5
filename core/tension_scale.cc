#include "core/tension_scale.h"

#include <cmath>

namespace tightfit {

double tension_scale_N(const SimulationMesh& mesh, double stiffness_scale_N_per_m) {
  const double edge_m = mean_rest_edge_length_m(mesh);
  return stiffness_scale_N_per_m * edge_m * edge_m / std::sqrt(rest_area(mesh));
}

}  // namespace tightfit
