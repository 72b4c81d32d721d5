#include "bodies/triangle_bvh.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
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
  // Each triangle's bounding sphere (its corners' centroid, the farthest corner's distance)
  // and plane (unit normal, offset n . p), whose distances bound the triangle's from below.
  struct Bound {
    Vec3 centre_m;
    double radius_m;
    Vec3 normal;
    double offset_m;
  };
  std::vector<Bound> bounds;
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
  tree_->bounds.clear();
  tree_->bounds.reserve(triangles.size());
  for (const Triangle& t : triangles) {
    const Vec3 centre = (v[t[0]] + v[t[1]] + v[t[2]]) / 3.0;
    double radius = 0.0;
    for (int k = 0; k < 3; ++k) radius = std::max(radius, (v[t[k]] - centre).norm());
    // A degenerate triangle's normal is NaN: its bound then never skips it.
    const Vec3 normal = (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).normalized();
    tree_->bounds.push_back({centre, radius, normal, normal.dot(v[t[0]])});
  }
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

TriangleBvh::Hit TriangleBvh::closest_among(const Vec3& x, const std::vector<int>& triangles,
                                            int hint) const {
  const Kernel::Point_3 p(x.x(), x.y(), x.z());
  const auto project = Kernel().construct_projected_point_3_object();
  // The hint's distance bounds the answer's from above before the scan: a triangle whose
  // lower bound (its sphere's or its plane's distance) exceeds the nearest distance known,
  // with a margin far above round-off (a millionth, and a picometre), is farther than the
  // closest triangle and can neither be it nor change which of equally near triangles comes
  // first in the list; the others are projected as before, in the list's order, so the answer
  // is the full scan's exactly.
  const auto beyond = [](double squared) { return std::sqrt(squared) * (1.0 + 1e-6) + 1e-12; };
  double skip_beyond_m = std::numeric_limits<double>::infinity();
  if (hint >= 0)
    skip_beyond_m = beyond(CGAL::squared_distance(project(tree_->triangles[hint], p), p));
  Hit hit;
  double nearest = std::numeric_limits<double>::infinity();
  for (const int t : triangles) {
    const Tree::Bound& bound = tree_->bounds[t];
    const double below = std::max((x - bound.centre_m).norm() - bound.radius_m,
                                  std::abs(bound.normal.dot(x) - bound.offset_m));
    if (below > skip_beyond_m) continue;
    const Kernel::Point_3 q = project(tree_->triangles[t], p);
    const double squared = CGAL::squared_distance(q, p);
    if (squared < nearest) {
      nearest = squared;
      hit.triangle = t;
      hit.point_m = Vec3(q.x(), q.y(), q.z());
      skip_beyond_m = std::min(skip_beyond_m, beyond(squared));
    }
  }
  // A hint outside the list nearer than all of it: the scan without it.
  if (hit.triangle < 0 && hint >= 0) return closest_among(x, triangles, -1);
  return hit;
}

int compare_distances(const Vec3& x, const Vec3& a, const Vec3& b) {
  const auto point = [](const Vec3& v) { return Kernel::Point_3(v.x(), v.y(), v.z()); };
  return static_cast<int>(Kernel().compare_distance_3_object()(point(x), point(a), point(b)));
}

}  // namespace tightfit
