// A mesh body that changes between load steps: a blend between two shapes with one
// connectivity (MakeHuman's default female and male share theirs), then a scale about a point
// or an axis (a body that grows, as the paper's cylinder does). docs/bodies.md "Morphing".
#pragma once

#include "bodies/changing_mesh_body.h"

#include <memory>
#include <string>
#include <vector>

namespace tightfit {

struct BodyScaling {
  enum class About { point, axis };
  About about = About::axis;
  Vec3 centre_m = Vec3::Zero();  // the fixed point, or a point on the fixed axis
  Vec3 axis = Vec3::UnitZ();     // (about an axis) distances from it scale, lengths along it do not
};

class MorphingMeshBody final : public ChangingMeshBody<RigidBody> {
 public:
  // `target_vertices_m` (empty: no blend) must be as many as the base's vertices.
  MorphingMeshBody(TriangleSurface base, std::vector<Vec3> target_vertices_m,
                   const MeshBodyOptions& options, const BodyScaling& scaling = {},
                   const std::string& what = "body mesh");

  std::string name() const override { return "morphing mesh"; }

  // The shape (1 - t) base + t target, scaled by `scale` (> 0) as BodyScaling says; the BVH
  // is rebuilt. Throws std::invalid_argument for t outside [0, 1] (or t != 0 without a
  // target) or a scale that is not positive.
  void set_morph(double t, double scale = 1.0);
  double blend() const { return t_; }
  double scale() const { return scale_; }

 private:
  std::vector<Vec3> base_, target_;
  BodyScaling scaling_;
  double t_ = 0.0, scale_ = 1.0;
};

// Reads, imports and checks both files (the same import options for both) and checks that
// they share their connectivity; `target_path` empty: a body that only scales.
std::unique_ptr<MorphingMeshBody> load_morphing_mesh_body(const std::string& base_path,
                                                          const std::string& target_path,
                                                          const MeshBodyOptions& options,
                                                          const BodyScaling& scaling = {});

}  // namespace tightfit
