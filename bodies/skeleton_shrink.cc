#include "bodies/skeleton_shrink.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace tightfit {

namespace {
// How far along an arm from its root its turn grows to the full angle, m.
constexpr double raise_ramp_m = 0.08;
}  // namespace

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
  shares_.resize(vertices_m_.size());
  nearest_.resize(vertices_m_.size());
  raise_axis_.assign(n, Vec3::Zero());
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
    double total = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double w = blend_m > 0 ? std::max(0.0, 1.0 - (distance[k] - d_min) / blend_m)
                                   : (static_cast<int>(k) == nearest_[i] ? 1.0 : 0.0);
      if (w <= 0) continue;
      const Vec3 a = (bones_[k].end_m - bones_[k].root_m).normalized();
      const Vec3 from_root = y - bones_[k].root_m;
      shares_[i].push_back(
          {static_cast<int>(k), w, from_root - from_root.dot(a) * a, from_root.dot(a)});
      total += w;
    }
    Vec3 radial = Vec3::Zero();
    for (Share& share : shares_[i]) {
      share.weight /= total;
      radial += share.weight * share.radial_m;
    }
    reach_m_ = std::max(reach_m_, radial.norm());
  }
}

void SkeletonShrink::set_arm_raise(double radians_per_unit, const Vec3& up) {
  if (!(radians_per_unit >= 0)) throw std::invalid_argument("an arm raise must not be negative");
  raise_per_unit_ = radians_per_unit;
  raise_reach_m_ = 0.0;
  for (std::size_t k = 0; k < bones_.size(); ++k) {
    raise_axis_[k] = Vec3::Zero();
    if (bones_[k].name.rfind("arm", 0) != 0) continue;
    const Vec3 a = (bones_[k].end_m - bones_[k].root_m).normalized();
    const Vec3 axis = a.cross(up.normalized());
    if (axis.norm() > 1e-6) raise_axis_[k] = axis.normalized();
  }
  for (std::size_t i = 0; i < vertices_m_.size(); ++i)
    for (const Share& share : shares_[i])
      if (raise_axis_[share.bone].norm() > 0)
        raise_reach_m_ =
            std::max(raise_reach_m_, (vertices_m_[i] - bones_[share.bone].root_m).norm());
}

std::vector<Vec3> SkeletonShrink::positions_m(double scale) const {
  if (!(scale > 0)) throw std::invalid_argument("a body's scale must be positive");
  std::vector<Vec3> x = vertices_m_;
  if (scale == 1.0) return x;
  int torso = -1;
  for (std::size_t k = 0; k < bones_.size(); ++k)
    if (bones_[k].name == "torso") torso = static_cast<int>(k);
  const bool shorten = shorten_torso_ && torso >= 0;
  const Vec3 centre =
      shorten ? Vec3(0.5 * (bones_[torso].root_m + bones_[torso].end_m)) : Vec3::Zero();
  for (std::size_t i = 0; i < x.size(); ++i)
    for (const Share& share : shares_[i]) {
      // The displacement w_k (T_k(y) - y), T_k(y) = root + Q (y + (s - 1) r - root).
      const Vec3 shrunk_from_root =
          vertices_m_[i] - bones_[share.bone].root_m + (scale - 1.0) * share.radial_m;
      Vec3 moved = (scale - 1.0) * share.radial_m;
      if (shorten && share.bone == torso)
        moved = (scale - 1.0) * (vertices_m_[i] - centre);  // about the middle, every way
      else if (shorten)
        moved += (scale - 1.0) * (bones_[share.bone].root_m - centre);  // with its root
      if (raise_axis_[share.bone].norm() > 0) {
        const double ramp = std::clamp(share.along_m / raise_ramp_m, 0.0, 1.0);
        const Mat3 turn =
            Eigen::AngleAxisd(raise_per_unit_ * (1.0 - scale) * ramp, raise_axis_[share.bone])
                .toRotationMatrix();
        moved += (turn - Mat3::Identity()) * shrunk_from_root;
      }
      x[i] += share.weight * moved;
    }
  return x;
}

}  // namespace tightfit
