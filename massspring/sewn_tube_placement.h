// The default start of the cylinder cases: the sewn tube laid round the body as a circle.
#pragma once

#include "core/garment.h"

#include <vector>

namespace tightfit {

// Positions of the welded vertices of a tube whose layout runs round the ring along x
// (0 <= u < circumference_m) and along the tube along y (0 <= v <= height_m): layout point
// (u, v) goes to angle 2 pi u / circumference round the z axis at radius_m, axial coordinate
// v - height_m / 2. Counter-clockwise layout triangles then have outward normals. Seam vertices
// (u = 0 and u = circumference) land on the same point.
std::vector<Vec3> sewn_tube_positions(const SimulationMesh& mesh, double circumference_m,
                                      double height_m, double radius_m);

}  // namespace tightfit
