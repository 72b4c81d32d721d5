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

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace tightfit
