#include "body/section_cutter.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace tightfit {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

}  // namespace

SectionCutter::SectionCutter(const TriangleSurface& surface, const Vec3& normal)
    : surface_(surface) {
  if (!(normal.norm() > 0)) throw std::invalid_argument("section: the plane normal is zero");
  normal_ = normal.normalized();
  const Vec3 e = std::abs(normal_.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  u_ = (e - e.dot(normal_) * normal_).normalized();
  v_ = normal_.cross(u_);
  height_.resize(surface.vertices_m.size());
  for (std::size_t i = 0; i < height_.size(); ++i) height_[i] = normal_.dot(surface.vertices_m[i]);
  if (height_.empty()) return;
  lowest_ = *std::min_element(height_.begin(), height_.end());
  highest_ = *std::max_element(height_.begin(), height_.end());
  // About 1000 buckets: a plane then looks at a thousandth of the triangles, not all of them.
  const std::size_t n_buckets = 1000;
  bucket_width_ = std::max(1e-12, (highest_ - lowest_) / n_buckets);
  buckets_.resize(n_buckets + 1);
  const auto bucket = [&](double h) {
    return std::min<std::size_t>(n_buckets,
                                 static_cast<std::size_t>((h - lowest_) / bucket_width_));
  };
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    const Triangle& tri = surface.triangles[t];
    const double lo = std::min({height_[tri[0]], height_[tri[1]], height_[tri[2]]});
    const double hi = std::max({height_[tri[0]], height_[tri[1]], height_[tri[2]]});
    for (std::size_t k = bucket(lo); k <= bucket(hi); ++k)
      buckets_[k].push_back(static_cast<int>(t));
  }
}

std::vector<SectionLoop> SectionCutter::cut(double h) const {
  std::vector<SectionLoop> loops;
  if (height_.empty() || h < lowest_ || h > highest_) return loops;
  const std::size_t k =
      std::min(buckets_.size() - 1, static_cast<std::size_t>((h - lowest_) / bucket_width_));
  // A vertex exactly on the plane counts as above it, so that every crossing edge has one end
  // strictly below and each crossed triangle has exactly two crossing edges.
  const auto above = [&](int i) { return height_[i] >= h; };
  std::unordered_map<std::uint64_t, int> point_of_edge;
  std::vector<Vec3> points;
  std::vector<std::array<int, 2>> neighbours;
  const auto point = [&](int a, int b) {
    const auto [it, fresh] = point_of_edge.emplace(edge_key(a, b), static_cast<int>(points.size()));
    if (fresh) {
      const double w = (h - height_[a]) / (height_[b] - height_[a]);
      points.push_back(surface_.vertices_m[a] +
                       w * (surface_.vertices_m[b] - surface_.vertices_m[a]));
      neighbours.push_back({-1, -1});
    }
    return it->second;
  };
  const auto link = [&](int p, int q) {
    for (const auto& [from, to] : {std::pair<int, int>{p, q}, {q, p}}) {
      auto& n = neighbours[from];
      (n[0] < 0 ? n[0] : n[1]) = to;
    }
  };
  for (const int t : buckets_[k]) {
    const Triangle& tri = surface_.triangles[t];
    int ends[2], n = 0;
    for (int e = 0; e < 3 && n < 2; ++e) {
      const int a = tri[e], b = tri[(e + 1) % 3];
      if (above(a) != above(b)) ends[n++] = point(a, b);
    }
    if (n == 2) link(ends[0], ends[1]);
  }
  std::vector<char> used(points.size(), 0);
  for (std::size_t start = 0; start < points.size(); ++start) {
    if (used[start]) continue;
    std::vector<int> chain;
    int previous = -1, current = static_cast<int>(start);
    bool closed = false;
    while (true) {
      used[current] = 1;
      chain.push_back(current);
      const auto& n = neighbours[current];
      const int next = n[0] != previous ? n[0] : n[1];
      if (next < 0) break;  // an open chain: the surface has a boundary here
      if (next == static_cast<int>(start)) {
        closed = true;
        break;
      }
      if (used[next]) break;
      previous = current;
      current = next;
    }
    if (!closed || chain.size() < 3) continue;
    SectionLoop loop;
    std::vector<Kernel::Point_2> flat;
    for (const int i : chain) {
      loop.points_m.push_back(points[i]);
      flat.emplace_back(u_.dot(points[i]), v_.dot(points[i]));
    }
    double twice_area = 0.0;
    Vec2 moment = Vec2::Zero();
    for (std::size_t i = 0; i < flat.size(); ++i) {
      const Vec2 p(flat[i].x(), flat[i].y());
      const Vec2 q(flat[(i + 1) % flat.size()].x(), flat[(i + 1) % flat.size()].y());
      loop.perimeter_m += (q - p).norm();
      const double c = p.x() * q.y() - p.y() * q.x();
      twice_area += c;
      moment += c * (p + q);
    }
    loop.area_m2 = 0.5 * std::abs(twice_area);
    const Vec2 c2 = std::abs(twice_area) > 0 ? Vec2(moment / (3.0 * twice_area))
                                             : Vec2(flat[0].x(), flat[0].y());
    loop.centroid_m = h * normal_ + c2.x() * u_ + c2.y() * v_;
    std::vector<Kernel::Point_2> hull;
    CGAL::convex_hull_2(flat.begin(), flat.end(), std::back_inserter(hull));
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const auto& p = hull[i];
      const auto& q = hull[(i + 1) % hull.size()];
      loop.hull_perimeter_m += std::hypot(q.x() - p.x(), q.y() - p.y());
      loop.hull_m.push_back(h * normal_ + p.x() * u_ + p.y() * v_);
    }
    loop.min_m = loop.max_m = loop.points_m.front();
    for (const Vec3& x : loop.points_m) {
      loop.min_m = loop.min_m.cwiseMin(x);
      loop.max_m = loop.max_m.cwiseMax(x);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

bool SectionCutter::encloses(const SectionLoop& loop, const Vec3& x) const {
  const Vec2 p(u_.dot(x), v_.dot(x));
  bool inside = false;
  const auto& q = loop.points_m;
  for (std::size_t i = 0, j = q.size() - 1; i < q.size(); j = i++) {
    const Vec2 a(u_.dot(q[i]), v_.dot(q[i]));
    const Vec2 b(u_.dot(q[j]), v_.dot(q[j]));
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
  }
  return inside;
}

double SectionCutter::distance_across(const Vec3& a, const Vec3& b) const {
  const Vec3 d = a - b;
  return (d - d.dot(normal_) * normal_).norm();
}

}  // namespace tightfit
