#include "core/tension_scale.h"

#include <cmath>

namespace tightfit {

double tension_scale_N(const SimulationMesh& mesh, double stiffness_scale_N_per_m) {
  return tension_scale_N(mean_rest_edge_length_m(mesh), rest_area(mesh), stiffness_scale_N_per_m);
}

double tension_scale_N(double mean_rest_edge_m, double rest_area_m2,
                       double stiffness_scale_N_per_m) {
  return stiffness_scale_N_per_m * mean_rest_edge_m * mean_rest_edge_m / std::sqrt(rest_area_m2);
}

}  // namespace tightfit
