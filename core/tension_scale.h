// The force scale of both backends' relative stop rule ('Solver/Relative tolerance',
// core/load_step.h).
#pragma once

#include "core/garment.h"

namespace tightfit {

// The tension scale Y h^2 / L, N: Y the law's stiffness scale (N/m), h the mean rest edge (m,
// mean_rest_edge_length_m), L the square root of the rest area (m). A smooth error of strain
// amplitude e over the garment leaves about Y e h^2 / L on each vertex (the stress error's
// gradient Y e / L times the vertex area h^2), so a tolerance of e times this bounds the
// remaining strain error by about e on every mesh. Y h alone, the force of a strain e on one
// edge, lets the smooth error grow like L / h as the mesh is refined (docs/backends.md, "Reaching
// equilibrium").
double tension_scale_N(const SimulationMesh& mesh, double stiffness_scale_N_per_m);
// The same from the mesh's mean rest edge h and rest area L^2.
double tension_scale_N(double mean_rest_edge_m, double rest_area_m2,
                       double stiffness_scale_N_per_m);

}  // namespace tightfit
