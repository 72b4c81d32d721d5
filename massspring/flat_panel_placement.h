// The paper's initial configuration (Section 4.3, Figure 5, left): the panels unsewn and flat,
// on opposite sides of the cylinder at a small equal distance, facing its axis.
#pragma once

#include "bodies/cylinder.h"
#include "core/garment.h"

#include <vector>

namespace tightfit {

// Positions of the panel ("unwelded") vertices of `mesh`, m. With C the sum of the panels'
// layout widths (the tube's circumference), panel p, its layout centre at u_p, lies flat in
// the plane at `distance_m` from the axis whose outward normal n_p points at the angle
// 2 pi u_p / C from the cylinder's reference direction (for the paper's two panels: opposite
// sides). Layout u (round the tube) runs along axis x n_p and v (along the tube) along the
// axis, centred on the axis point as in place_tube_round_cylinder: the panels face the axis
// with outward normals, each panel sits where the sewn tube would put it, and the two sides
// of every seam face each other across the cylinder. Throws std::invalid_argument for fewer
// than two panels (one panel cannot lie on both sides).
std::vector<Vec3> place_panels_flat(const SimulationMesh& mesh, const Cylinder& cylinder,
                                    double distance_m);

}  // namespace tightfit
