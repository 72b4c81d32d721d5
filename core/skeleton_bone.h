// One bone of a body's skeleton: a body part's axis from its root (where it joins the torso, or
// the torso's own lowest point) to its end. A body shrinks about its bones for the dressing
// (bodies/skeleton_shrink.h); the landmarks find them (body/garment_arrangement.h).
#pragma once

#include "core/types.h"

#include <string>

namespace tightfit {

struct SkeletonBone {
  std::string name;  // torso, arm left, ...
  Vec3 root_m = Vec3::Zero();
  Vec3 end_m = Vec3::UnitZ();  // not at the root
};

}  // namespace tightfit
