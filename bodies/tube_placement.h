// The sewn start: the garment already sewn into a tube, a circle round an axis (a cylinder's,
// a cone's, or one given through a mesh body's limb or waist).
#pragma once

#include "bodies/cylinder.h"
#include "bodies/triangle_surface.h"
#include "core/garment.h"

#include <vector>

namespace tightfit {

// Welded positions of a tube garment laid as a circle of radius `radius_m` coaxial with the
// cylinder, centred on the axis point: a vertex's share of its row's girth (core/tube_garment.h,
// ring_coordinates; for a rectangle tube its layout x over the circumference) becomes the angle
// 2 pi share from the cylinder's reference direction, v (along the tube) the axial coordinate
// v - height/2. The triangles' winding then makes the normals point outwards.
// Throws std::invalid_argument when the garment is not a ring.
// The same round any axis: the tube's middle at `centre_m`, angles from
// reference_direction_normal_to(axis) (bodies/axis_frame.h), the tube along `axis` (any length).
// With `stretch` > 0 each ring lies at that many times its own rest radius (its girth over
// 2 pi) instead of at `radius_m`: a tapered tube stretched evenly.
std::vector<Vec3> place_tube_round_axis(const Garment& garment, const SimulationMesh& mesh,
                                        const Vec3& centre_m, const Vec3& axis, double radius_m,
                                        double stretch = 0.0);

// The same round a limb of the body `surface`: each ring centred on the centroid of the body's
// section in its plane (normal to `axis`, the loop round the axis; bodies/surface_slice.h) and
// `clearance_m` outside that section's farthest point, so a tube follows a bent leg or arm.
// Where that circle would come nearer than `clearance_m` to another loop of the plane (the
// other thigh near the crotch), the ring is the section offset by `clearance_m` along each
// ray from its centroid instead.
// Throws std::invalid_argument naming the ring's height when its plane misses the body.
std::vector<Vec3> place_tube_round_limb(const Garment& garment, const SimulationMesh& mesh,
                                        const Vec3& centre_m, const Vec3& axis,
                                        const TriangleSurface& surface, double clearance_m);

std::vector<Vec3> place_tube_round_cylinder(const Garment& garment, const SimulationMesh& mesh,
                                            const Cylinder& cylinder, double radius_m);

}  // namespace tightfit
