// Lumped particle masses of the mass-spring backend (the paper's Section 2.1); the rest
// vertex areas and edge lengths they use are in core/garment.h.
#pragma once

#include "core/garment.h"

#include <vector>

namespace tightfit {

// Particle masses, kg: areal density (kg/m^2) times the barycentric rest area, so the
// particles carry exactly the fabric's mass.
std::vector<double> lumped_masses_kg(const SimulationMesh& mesh, double areal_density_kg_per_m2);

}  // namespace tightfit
