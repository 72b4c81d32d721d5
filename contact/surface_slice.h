// Cross-sections of a body surface by a plane: the girth a tape measure reads round a limb at a
// given height, and where the limb's axis passes (docs/stocking.md, "Girths and the leg axis").
#pragma once

#include "contact/triangle_surface.h"

namespace tightfit {

// One closed curve where the plane cuts the surface (a leg, an arm, the torso).
struct SliceLoop {
  double perimeter_m = 0.0;        // along the section itself
  double hull_perimeter_m = 0.0;   // of its convex hull: what a tape measure pulled tight reads
  double area_m2 = 0.0;            // enclosed, in the plane
  Vec3 centroid_m = Vec3::Zero();  // of the enclosed area
  double reach_m = 0.0;            // the largest distance of the section from its centroid
  int n_points = 0;
};

// The loop of the section by the plane {x : axis . x = height_m} (`axis` a direction, not
// necessarily unit: it is normalised) that encloses the point `near_m` projected onto the
// plane, or, when none does, whose centroid lies nearest to it. Throws std::invalid_argument
// naming the height when the plane misses the surface.
SliceLoop slice_surface(const TriangleSurface& surface, const Vec3& axis, double height_m,
                        const Vec3& near_m);

}  // namespace tightfit
