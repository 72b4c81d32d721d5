// Cross-sections of a body surface by a plane: the girth a tape measure reads round a limb at a
// given height, and where the limb's axis passes (docs/stocking.md, "Girths and the leg axis").
#pragma once

#include "bodies/triangle_surface.h"

#include <limits>
#include <vector>

namespace tightfit {

// One closed curve where the plane cuts the surface (a leg, an arm, the torso).
struct SliceLoop {
  double perimeter_m = 0.0;        // along the section itself
  double hull_perimeter_m = 0.0;   // of its convex hull: what a tape measure pulled tight reads
  double area_m2 = 0.0;            // enclosed, in the plane
  Vec3 centroid_m = Vec3::Zero();  // of the enclosed area
  double reach_m = 0.0;            // the largest distance of the section from its centroid
  int n_points = 0;
  Vec3 plane_normal = Vec3::UnitZ();  // unit, the slice's axis
  std::vector<Vec3> points_m;         // the loop's points in order (where the plane cuts edges)
  // The least distance from the centroid to a point of another loop of the same plane (the
  // other leg, an arm beside the torso); infinite when the plane cuts nothing else.
  double other_loops_distance_m = std::numeric_limits<double>::infinity();
};

// The distance from the loop's centroid to its boundary along the in-plane `direction` (unit):
// the farthest crossing of that ray with the loop (the section seen from its centroid, which a
// limb's section is star-shaped about); the reach when the ray crosses nothing.
double boundary_distance_m(const SliceLoop& loop, const Vec3& direction);

// The loop of the section by the plane {x : axis . x = height_m} (`axis` a direction, not
// necessarily unit: it is normalised) that encloses the point `near_m` projected onto the
// plane, or, when none does, whose centroid lies nearest to it. Throws std::invalid_argument
// naming the height when the plane misses the surface.
SliceLoop slice_surface(const TriangleSurface& surface, const Vec3& axis, double height_m,
                        const Vec3& near_m);

}  // namespace tightfit
