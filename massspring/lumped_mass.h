// Lumped particle masses of the mass-spring backend (the paper's Section 2.1).
#pragma once

#include "core/garment.h"

#include <vector>

namespace tightfit {

// Barycentric rest area of every welded vertex, m^2: a third of each adjacent triangle's rest
// area, so the areas sum to the garment's rest area.
std::vector<double> rest_vertex_areas_m2(const SimulationMesh& mesh);

// Particle masses, kg: areal density (kg/m^2) times the barycentric rest area, so the
// particles carry exactly the fabric's mass.
std::vector<double> lumped_masses_kg(const SimulationMesh& mesh, double areal_density_kg_per_m2);

// Mean length of the mesh's rest edges (each edge counted once), m: the length scale of the
// stop rule and of the penalty stiffness.
double mean_rest_edge_length_m(const SimulationMesh& mesh);

}  // namespace tightfit
