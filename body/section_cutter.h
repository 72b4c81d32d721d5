// Every closed curve where a family of parallel planes cuts a body surface: the sections a
// tailor's tape goes round (docs/measuring-bodies.md). Unlike bodies/surface_slice.h,
// which returns the one loop round a given point, a cutter returns all loops of a plane, so that
// the parts of a body (legs, arms, torso) can be told apart and followed from plane to plane.
#pragma once

#include "bodies/triangle_surface.h"

#include <vector>

namespace tightfit {

struct SectionLoop {
  std::vector<Vec3> points_m;  // in order round the loop, on the plane
  double perimeter_m = 0.0;    // along the section itself
  // Of the section's convex hull: what a tape pulled tight round it reads (ISO 8559-1 measures
  // girths so, bridging hollows such as the one between the breasts).
  double hull_perimeter_m = 0.0;
  std::vector<Vec3> hull_m;  // the hull's corners in order, on the plane
  double area_m2 = 0.0;      // enclosed, in the plane
  Vec3 centroid_m = Vec3::Zero();
  Vec3 min_m = Vec3::Zero(), max_m = Vec3::Zero();  // bounding box
};

class SectionCutter {
 public:
  // The planes {x : normal . x = h}; `normal` need not be unit length (it is normalised).
  // Throws std::invalid_argument for a zero normal.
  SectionCutter(const TriangleSurface& surface, const Vec3& normal);

  const Vec3& normal() const { return normal_; }
  double lowest() const { return lowest_; }  // the smallest normal . x over the vertices
  double highest() const { return highest_; }

  // The closed loops of the plane at height h (none when the plane misses the surface).
  std::vector<SectionLoop> cut(double height_m) const;

  // Whether `x`, projected onto the loop's plane, lies inside the loop (even-odd rule).
  bool encloses(const SectionLoop& loop, const Vec3& x_m) const;
  // The distance between two points across the normal (in the plane).
  double distance_across(const Vec3& a_m, const Vec3& b_m) const;

 private:
  const TriangleSurface& surface_;
  Vec3 normal_, u_, v_;         // the normal and two directions in the planes
  std::vector<double> height_;  // of each vertex along the normal
  double lowest_ = 0.0, highest_ = 0.0, bucket_width_ = 1.0;
  // The triangles whose height range meets each bucket [lowest + k w, lowest + (k + 1) w).
  std::vector<std::vector<int>> buckets_;
};

}  // namespace tightfit
