#include "bodies/surface_slice.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace tightfit {

namespace {

using EdgeKey = std::pair<int, int>;

EdgeKey key(int a, int b) {
  return a < b ? EdgeKey(a, b) : EdgeKey(b, a);
}

double cross2(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Perimeter of the convex hull of `points` (Andrew's monotone chain).
double hull_perimeter_m(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (points.size() < 3) return 0.0;
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {  // lower hull
    while (k >= 2 && cross2(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // upper hull
    while (k >= lower && cross2(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i];
  }
  double perimeter = 0.0;
  for (std::size_t i = 1; i < k; ++i) perimeter += (hull[i] - hull[i - 1]).norm();
  return perimeter;
}

// Whether `p` lies inside the closed polygon `loop` (even-odd rule).
bool encloses(const std::vector<Vec2>& loop, const Vec2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const Vec2& a = loop[i];
    const Vec2& b = loop[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
  }
  return inside;
}

}  // namespace

SliceLoop slice_surface(const TriangleSurface& surface, const Vec3& axis, double height_m,
                        const Vec3& near_m) {
  if (!(axis.norm() > 0)) throw std::invalid_argument("slice: the axis must not be zero");
  const Vec3 a = axis.normalized();
  const Vec3 e1 = (std::abs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY());
  const Vec3 u = (e1 - e1.dot(a) * a).normalized();
  const Vec3 v = a.cross(u);
  // Signed height of each vertex above the plane; a vertex exactly on it counts as above, so
  // every crossing edge has one end strictly below.
  std::vector<double> s(surface.vertices_m.size());
  for (std::size_t i = 0; i < s.size(); ++i) s[i] = a.dot(surface.vertices_m[i]) - height_m;
  const auto above = [&](int i) { return s[i] >= 0.0; };
  // Each triangle the plane crosses gives a segment between two crossing edges; every crossing
  // edge of a closed surface belongs to two such triangles, so the segments chain into loops.
  std::map<EdgeKey, std::vector<EdgeKey>> links;
  std::map<EdgeKey, Vec3> point;
  for (const Triangle& t : surface.triangles) {
    std::vector<EdgeKey> crossing;
    for (int k = 0; k < 3; ++k) {
      const int i = t[k], j = t[(k + 1) % 3];
      if (above(i) == above(j)) continue;
      const EdgeKey e = key(i, j);
      const double w = s[e.first] / (s[e.first] - s[e.second]);
      point[e] = surface.vertices_m[e.first] +
                 w * (surface.vertices_m[e.second] - surface.vertices_m[e.first]);
      crossing.push_back(e);
    }
    if (crossing.size() != 2) continue;
    links[crossing[0]].push_back(crossing[1]);
    links[crossing[1]].push_back(crossing[0]);
  }
  if (links.empty())
    throw std::invalid_argument("slice: the plane at height " + std::to_string(height_m) +
                                " m misses the body");
  const auto in_plane = [&](const Vec3& x) { return Vec2(u.dot(x), v.dot(x)); };
  const Vec2 target = in_plane(near_m);
  SliceLoop best;
  bool best_encloses = false;
  double best_distance = 0.0;
  std::vector<std::vector<Vec3>> loops;
  std::size_t best_index = 0;
  std::map<EdgeKey, bool> used;
  for (const auto& [start, ignored] : links) {
    if (used[start]) continue;
    std::vector<Vec3> loop;
    EdgeKey previous = start, current = start;
    while (!used[current]) {
      used[current] = true;
      loop.push_back(point[current]);
      const std::vector<EdgeKey>& next = links[current];
      const EdgeKey* step = nullptr;
      for (const EdgeKey& n : next)
        if (n != previous && !used[n]) step = &n;
      if (!step) break;
      previous = current;
      current = *step;
    }
    if (loop.size() < 3) continue;
    loops.push_back(loop);
    SliceLoop l;
    l.n_points = static_cast<int>(loop.size());
    std::vector<Vec2> flat;
    for (const Vec3& x : loop) flat.push_back(in_plane(x));
    double twice_area = 0.0;
    Vec2 moment = Vec2::Zero();
    for (std::size_t i = 0; i < flat.size(); ++i) {
      const Vec2& p = flat[i];
      const Vec2& q = flat[(i + 1) % flat.size()];
      l.perimeter_m += (q - p).norm();
      const double c = cross2(p, q);
      twice_area += c;
      moment += c * (p + q);
    }
    l.area_m2 = 0.5 * std::abs(twice_area);
    const Vec2 centre = std::abs(twice_area) > 0 ? Vec2(moment / (3.0 * twice_area)) : flat[0];
    l.centroid_m = height_m * a + centre.x() * u + centre.y() * v;
    l.hull_perimeter_m = hull_perimeter_m(flat);
    for (const Vec2& p : flat) l.reach_m = std::max(l.reach_m, (p - centre).norm());
    const bool inside = encloses(flat, target);
    const double distance = (centre - target).norm();
    // A loop round the point wins; among equals the nearest centroid (an enclosing loop inside
    // another, a hole, does not occur on a limb).
    if (best.n_points == 0 || (inside && !best_encloses) ||
        (inside == best_encloses && distance < best_distance)) {
      best = l;
      best_encloses = inside;
      best_distance = distance;
      best_index = loops.size() - 1;
    }
  }
  if (best.n_points == 0)
    throw std::invalid_argument("slice: the plane at height " + std::to_string(height_m) +
                                " m cuts no closed loop");
  best.plane_normal = a;
  best.points_m = loops[best_index];
  for (std::size_t k = 0; k < loops.size(); ++k)
    if (k != best_index)
      for (const Vec3& x : loops[k])
        best.other_loops_distance_m =
            std::min(best.other_loops_distance_m, (x - best.centroid_m).norm());
  return best;
}

double boundary_distance_m(const SliceLoop& loop, const Vec3& direction) {
  // A segment p q (relative to the centroid c) crosses the ray's line where its component along
  // e = normal x d changes sign; the crossing's component along d is its distance on the ray.
  const std::vector<Vec3>& points = loop.points_m;
  const Vec3 e = loop.plane_normal.cross(direction);
  double farthest = -1.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 p = points[i] - loop.centroid_m;
    const Vec3 q = points[(i + 1) % points.size()] - loop.centroid_m;
    const double pe = p.dot(e), qe = q.dot(e);
    if ((pe > 0) == (qe > 0)) continue;  // both on one side of the ray's line
    const double t = (p + pe / (pe - qe) * (q - p)).dot(direction);
    farthest = std::max(farthest, t);
  }
  return farthest > 0 ? farthest : loop.reach_m;
}

}  // namespace tightfit
