#include "bodies/triangle_bvh.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <iterator>
#include <limits>

namespace tightfit {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalTriangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, CgalTriangles::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

struct TriangleBvh::Tree {
  CgalTriangles triangles;  // the primitives point into this
  AabbTree tree;
};

TriangleBvh::TriangleBvh() = default;
TriangleBvh::~TriangleBvh() = default;
TriangleBvh::TriangleBvh(TriangleBvh&&) noexcept = default;
TriangleBvh& TriangleBvh::operator=(TriangleBvh&&) noexcept = default;

void TriangleBvh::build(const std::vector<Vec3>& v, const std::vector<Triangle>& triangles) {
  auto point = [&](int i) { return Kernel::Point_3(v[i].x(), v[i].y(), v[i].z()); };
  tree_ = std::make_unique<Tree>();
  tree_->triangles.reserve(triangles.size());
  for (const Triangle& t : triangles)
    tree_->triangles.emplace_back(point(t[0]), point(t[1]), point(t[2]));
  tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
  tree_->tree.build();
  // A kd-tree of the vertices gives each query a near first guess (CGAL's recommendation for
  // many distance queries); building it now keeps later queries free of lazy construction.
  tree_->tree.accelerate_distance_queries();
}

TriangleBvh::Hit TriangleBvh::closest(const Vec3& x) const {
  const auto found = tree_->tree.closest_point_and_primitive(Kernel::Point_3(x.x(), x.y(), x.z()));
  Hit hit;
  hit.triangle = static_cast<int>(found.second - tree_->triangles.cbegin());
  hit.point_m = Vec3(found.first.x(), found.first.y(), found.first.z());
  return hit;
}

void TriangleBvh::within(const Vec3& x, double radius_m, std::vector<int>& out) const {
  out.clear();
  // The box round the ball first (the tree's boxes), then each triangle's own distance.
  const CGAL::Bbox_3 box(x.x() - radius_m, x.y() - radius_m, x.z() - radius_m, x.x() + radius_m,
                         x.y() + radius_m, x.z() + radius_m);
  std::vector<AabbTree::Primitive_id> found;
  tree_->tree.all_intersected_primitives(box, std::back_inserter(found));
  const Kernel::Point_3 p(x.x(), x.y(), x.z());
  const auto project = Kernel().construct_projected_point_3_object();
  for (const auto& id : found)
    if (CGAL::squared_distance(project(*id, p), p) <= radius_m * radius_m)
      out.push_back(static_cast<int>(id - tree_->triangles.cbegin()));
}

TriangleBvh::Hit TriangleBvh::closest_among(const Vec3& x,
                                            const std::vector<int>& triangles) const {
  const Kernel::Point_3 p(x.x(), x.y(), x.z());
  const auto project = Kernel().construct_projected_point_3_object();
  Hit hit;
  double nearest = std::numeric_limits<double>::infinity();
  for (const int t : triangles) {
    const Kernel::Point_3 q = project(tree_->triangles[t], p);
    const double squared = CGAL::squared_distance(q, p);
    if (squared < nearest) {
      nearest = squared;
      hit.triangle = t;
      hit.point_m = Vec3(q.x(), q.y(), q.z());
    }
  }
  return hit;
}

int compare_distances(const Vec3& x, const Vec3& a, const Vec3& b) {
  const auto point = [](const Vec3& v) { return Kernel::Point_3(v.x(), v.y(), v.z()); };
  return static_cast<int>(Kernel().compare_distance_3_object()(point(x), point(a), point(b)));
}

}  // namespace tightfit
