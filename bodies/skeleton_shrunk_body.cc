#include "bodies/skeleton_shrunk_body.h"

#include <cmath>
#include <stdexcept>

namespace tightfit {

SkeletonShrunkBody::SkeletonShrunkBody(TriangleSurface surface, std::vector<SkeletonBone> bones,
                                       double blend_m, double step, double arm_raise_per_unit,
                                       const Vec3& up, bool shorten_torso)
    : ChangingMeshBody(std::move(surface), MeshBodyOptions{},
                       "body mesh shrunk about its skeleton"),
      shrink_(mesh_.surface().vertices_m, std::move(bones), blend_m),
      step_(step) {
  if (!(step > 0)) throw std::invalid_argument("a skeleton shrink's scale step must be positive");
  shrink_.set_arm_raise(arm_raise_per_unit, up);
  shrink_.set_torso_shortening(shorten_torso);
}

void SkeletonShrunkBody::set_scale(double scale) {
  if (!(scale > 0)) throw std::invalid_argument("a body's scale must be positive");
  if (scale == scale_ || (std::abs(scale - scale_) < step_ && scale != 1.0)) return;
  mesh_.set_vertex_positions(shrink_.positions_m(scale));
  scale_ = scale;
}

}  // namespace tightfit
