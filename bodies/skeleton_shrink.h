// A body mesh shrunk about its skeleton (docs/arrangement.md "The body shrunk about its
// skeleton"): each vertex moves towards the axis of the body part it belongs to (the torso's,
// an arm's, a leg's), its distance from that axis times the scale, its position along the axis
// kept, so that the limbs thin about their own axes and open room between them and the torso.
// A vertex belongs to the bone whose segment is nearest; within `blend_m` of a tie (the
// shoulders, the armpits, the crotch) the directions of the bones within reach are blended with
// weights falling linearly from the nearest (w_k = max(0, 1 - (d_k - d_min) / blend), summed to
// one), so the shrunk mesh stays continuous where parts join:
//   y' = y + (s - 1) sum_k w_k (y - foot_k(y)),
// foot_k the foot of the perpendicular from y onto bone k's line. Scale 1 is the identity.
// With an arm raise r (radians per unit of 1 - s), an arm's bone also turns its share of the
// vertex about the bone's root by the angle r (1 - s), away from the torso's axis `up`
// (abduction, towards a T-pose), so that the arms leave the torso's sides at the start:
//   y' = sum_k w_k (root_k + Q_k (y + (s - 1)(y - foot_k(y)) - root_k)),
// Q_k that rotation (the identity for every other bone). The turn grows from nothing at the
// shoulder (the bone's root) to its full angle 8 cm along the arm, so the shoulder blade and
// the chest, nearer the arm's root than the torso's axis, do not swing with it.
#pragma once

#include "core/skeleton_bone.h"
#include "core/types.h"

#include <vector>

namespace tightfit {

class SkeletonShrink {
 public:
  // Throws std::invalid_argument for no bones, a bone of zero length or a blend below zero.
  SkeletonShrink(std::vector<Vec3> vertices_m, std::vector<SkeletonBone> bones,
                 double blend_m = 0.03);

  // Turns the arms (bones named "arm ...") by `radians_per_unit` (1 - s) away from `up` (the
  // torso's direction) as the body shrinks to s; 0 (the default) keeps them. Throws
  // std::invalid_argument for a negative rate.
  void set_arm_raise(double radians_per_unit, const Vec3& up = Vec3::UnitZ());

  // With `on`, the torso shrinks about its bone's middle along its axis too (the neck and
  // shoulders lower, the crotch rises by (1 - s) half the torso's length) and each limb moves
  // with its root: a limb's share of a vertex is moved as the torso moves the limb's root, then
  // shrunk (and turned) about that root, so that shoulder seams find room over the shoulders.
  // Off by default.
  void set_torso_shortening(bool on) { shorten_torso_ = on; }

  // The vertices shrunk to `scale` (> 0; 1 gives them back unchanged).
  std::vector<Vec3> positions_m(double scale) const;
  // The bone each vertex belongs to most (its largest weight), by index into bones().
  const std::vector<int>& nearest_bone() const { return nearest_; }
  const std::vector<SkeletonBone>& bones() const { return bones_; }
  // The largest distance of a vertex from its blended axis: how far a vertex moves per unit of
  // scale, m.
  double reach_m() const { return reach_m_ + raise_per_unit_ * raise_reach_m_; }

 private:
  std::vector<Vec3> vertices_m_;
  std::vector<SkeletonBone> bones_;
  // Each vertex's bones within the blend: bone, weight and y - foot_k(y).
  struct Share {
    int bone;
    double weight;
    Vec3 radial_m;
    double along_m;  // (y - root_k) . a_k: how far past the bone's root
  };
  std::vector<std::vector<Share>> shares_;
  std::vector<int> nearest_;
  std::vector<Vec3> raise_axis_;  // per bone: the unit axis an arm turns about (zero: none)
  double raise_per_unit_ = 0.0;
  bool shorten_torso_ = false;
  double reach_m_ = 0.0;        // of the shrink alone
  double raise_reach_m_ = 0.0;  // the farthest an arm's vertex lies from its bone's root
};

// The distance from x to the segment from a to b, m.
double distance_to_segment_m(const Vec3& x, const Vec3& a, const Vec3& b);

}  // namespace tightfit
