#include "massspring/lumped_mass.h"

namespace tightfit {

std::vector<double> lumped_masses_kg(const SimulationMesh& mesh, double areal_density_kg_per_m2) {
  std::vector<double> masses = rest_vertex_areas_m2(mesh);
  for (double& m : masses) m *= areal_density_kg_per_m2;
  return masses;
}

}  // namespace tightfit
