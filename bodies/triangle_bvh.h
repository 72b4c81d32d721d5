// A bounding-volume hierarchy over a triangle mesh that finds the closest point of the surface
// to a query point: CGAL's AABB tree, whose headers stay in triangle_bvh.cc.
#pragma once

#include "core/types.h"

#include <memory>
#include <vector>

namespace tightfit {

class TriangleBvh {
 public:
  TriangleBvh();
  ~TriangleBvh();
  TriangleBvh(TriangleBvh&&) noexcept;
  TriangleBvh& operator=(TriangleBvh&&) noexcept;

  // Builds the tree afresh (also after the vertices moved: CGAL's tree has no refit; the cost
  // is in docs/performance.md).
  void build(const std::vector<Vec3>& vertices_m, const std::vector<Triangle>& triangles);

  struct Hit {
    int triangle = -1;
    Vec3 point_m = Vec3::Zero();  // the closest point of that triangle
  };
  Hit closest(const Vec3& x_m) const;
  // The triangles whose closest point to x lies within `radius_m` of it, into `out` (cleared).
  void within(const Vec3& x_m, double radius_m, std::vector<int>& out) const;
  // The closest point among `triangles` alone (not empty): the same projection as closest(),
  // so that a list holding closest()'s triangle gives its answer. `hint` (a triangle of the
  // list, or -1), likely the closest (the last answer's), lets the scan skip the triangles
  // bounded away from x beyond it; the answer is the same with any hint.
  Hit closest_among(const Vec3& x_m, const std::vector<int>& triangles, int hint = -1) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

// -1, 0 or 1 as `a` lies nearer to x than `b`, as near, or farther, decided exactly (CGAL's
// predicate, by which the tree's own search keeps the nearer of two points): nearest points
// found by searches over parts of a mesh then compare as they would in one search.
int compare_distances(const Vec3& x_m, const Vec3& a_m, const Vec3& b_m);

}  // namespace tightfit
