// The sewn start: the garment already sewn into a tube, a circle round an axis (a cylinder's,
// a cone's, or one given through a mesh body's limb or waist).
#pragma once

#include "contact/cylinder.h"
#include "core/garment.h"

#include <vector>

namespace tightfit {

// Welded positions of a tube garment laid as a circle of radius `radius_m` coaxial with the
// cylinder, centred on the axis point: layout coordinate u (round the ring) becomes the angle
// 2 pi u / circumference from the cylinder's reference direction, v (along the tube) the axial
// coordinate v - height/2. The triangles' winding then makes the normals point outwards.
// Throws std::invalid_argument when the garment is not a ring.
// The same round any axis: the tube's middle at `centre_m`, angles from
// reference_direction_normal_to(axis) (contact/axis_frame.h), the tube along `axis` (any length).
std::vector<Vec3> place_tube_round_axis(const Garment& garment, const SimulationMesh& mesh,
                                        const Vec3& centre_m, const Vec3& axis, double radius_m);

std::vector<Vec3> place_tube_round_cylinder(const Garment& garment, const SimulationMesh& mesh,
                                            const Cylinder& cylinder, double radius_m);

}  // namespace tightfit
