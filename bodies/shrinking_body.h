// A body the dressing (massspring/dressing.h) starts shrunk inside the open garment and grows
// back to its own shape: about a point or an axis (scaled_body.h), or about its skeleton
// (skeleton_shrunk_body.h). docs/arrangement.md "The body shrunk about its skeleton".
#pragma once

#include "bodies/rigid_body.h"

namespace tightfit {

class ShrinkingBody : public RigidBody {
 public:
  // Throws std::invalid_argument unless the scale is positive.
  virtual void set_scale(double scale) = 0;
  // The scale the surface has now (a body that changes in steps may lag the one asked for).
  virtual double scale() const = 0;
  // The farthest any surface point moves per unit change of the scale, m: what the contact's
  // cached faces are told the body moved by.
  virtual double reach_m() const = 0;
};

}  // namespace tightfit
