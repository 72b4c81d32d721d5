// A body mesh shrunk about its skeleton (skeleton_shrink.h) for the dressing
// (massspring/dressing.h): its own faceted mesh body whose vertices follow the scale. The mesh
// is moved, its normals and tree rebuilt, only when the scale asked for has moved by `step`
// from the one the surface has (or reaches 1), so a dressing's thousands of frames cost a few
// dozen rebuilds; scale() is the surface's.
#pragma once

#include "bodies/changing_mesh_body.h"
#include "bodies/shrinking_body.h"
#include "bodies/skeleton_shrink.h"

namespace tightfit {

class SkeletonShrunkBody final : public ChangingMeshBody<ShrinkingBody> {
 public:
  // `surface` is the whole body's mesh (closed); throws as SkeletonShrink and MeshBody do.
  // `arm_raise_per_unit`: SkeletonShrink::set_arm_raise's rate (radians per unit of 1 - s),
  // the torso's direction `up`.
  SkeletonShrunkBody(TriangleSurface surface, std::vector<SkeletonBone> bones,
                     double blend_m = 0.03, double step = 0.005, double arm_raise_per_unit = 0.0,
                     const Vec3& up = Vec3::UnitZ(), bool shorten_torso = false);

  void set_scale(double scale) override;
  double scale() const override { return scale_; }
  double reach_m() const override { return shrink_.reach_m(); }
  const SkeletonShrink& shrink() const { return shrink_; }

  std::string name() const override { return "mesh (shrunk about its skeleton)"; }

 private:
  SkeletonShrink shrink_;
  double step_;
  double scale_ = 1.0;
};

}  // namespace tightfit
