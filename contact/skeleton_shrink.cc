#include "contact/skeleton_shrink.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace tightfit {

double distance_to_segment_m(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double t = std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (x - (a + t * d)).norm();
}

SkeletonShrink::SkeletonShrink(std::vector<Vec3> vertices_m, std::vector<SkeletonBone> bones,
                               double blend_m)
    : vertices_m_(std::move(vertices_m)), bones_(std::move(bones)) {
  if (bones_.empty()) throw std::invalid_argument("a skeleton shrink needs at least one bone");
  for (const SkeletonBone& bone : bones_)
    if (!((bone.end_m - bone.root_m).norm() > 0))
      throw std::invalid_argument("skeleton bone '" + bone.name + "' has zero length");
  if (!(blend_m >= 0)) throw std::invalid_argument("a skeleton's blend width must not be negative");
  const std::size_t n = bones_.size();
  radial_m_.resize(vertices_m_.size());
  nearest_.resize(vertices_m_.size());
  std::vector<double> distance(n);
  for (std::size_t i = 0; i < vertices_m_.size(); ++i) {
    const Vec3& y = vertices_m_[i];
    double d_min = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < n; ++k) {
      distance[k] = distance_to_segment_m(y, bones_[k].root_m, bones_[k].end_m);
      if (distance[k] < d_min) {
        d_min = distance[k];
        nearest_[i] = static_cast<int>(k);
      }
    }
    Vec3 radial = Vec3::Zero();
    double total = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double w = blend_m > 0 ? std::max(0.0, 1.0 - (distance[k] - d_min) / blend_m)
                                   : (static_cast<int>(k) == nearest_[i] ? 1.0 : 0.0);
      if (w <= 0) continue;
      const Vec3 a = (bones_[k].end_m - bones_[k].root_m).normalized();
      const Vec3 from_root = y - bones_[k].root_m;
      radial += w * (from_root - from_root.dot(a) * a);
      total += w;
    }
    radial_m_[i] = radial / total;
    reach_m_ = std::max(reach_m_, radial_m_[i].norm());
  }
}

std::vector<Vec3> SkeletonShrink::positions_m(double scale) const {
  if (!(scale > 0)) throw std::invalid_argument("a body's scale must be positive");
  std::vector<Vec3> x(vertices_m_.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = vertices_m_[i] + (scale - 1.0) * radial_m_[i];
  return x;
}

}  // namespace tightfit
