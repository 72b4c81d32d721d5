// Points that a penalty contact left inside a rigid body, put back onto its surface.
//
// The penalty law lets a vertex in contact sit p / k inside the body (contact/penalty_contact.h),
// and a settled state with multiplier updates still up to the gap tolerance. A state handed on
// as the start of another stage (a dressed garment, a state read from a file) must begin
// outside the body, so such vertices go back onto the surface; a vertex much deeper than the
// penalty's own depth means the garment passed through the body, which the caller refuses.
#pragma once

#include "bodies/rigid_body.h"

#include <vector>

namespace tightfit {

struct SurfaceReturn {
  int points_moved = 0;
  double deepest_m = 0.0;  // depth of the deepest point inside the body, before any moved, m
  int deepest_point = -1;  // its index in x; -1 when every point lies outside
};

// Finds the deepest point of x inside `body`. If it lies no deeper than `allowed_depth_m`,
// moves every point inside onto the surface along the signed distance's gradient; otherwise
// leaves x unchanged (the caller sees deepest_m > allowed_depth_m and refuses the state).
SurfaceReturn return_onto_surface(const RigidBody& body, std::vector<Vec3>& x,
                                  double allowed_depth_m);

}  // namespace tightfit
