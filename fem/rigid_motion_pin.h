// The rigid motions a frictionless body leaves the garment free to make, and the one vertex
// that is pinned against them so that Newton's tangent is not singular. The reaction of the
// pin vanishes at equilibrium (no force acts along a free rigid motion), so no pressure
// changes.
#pragma once

#include "contact/rigid_body.h"
#include "core/constrained_directions.h"

#include <vector>

namespace tightfit {

struct RigidMotionPin {
  int vertex = -1;               // welded vertex pinned; -1: none
  std::vector<Vec3> directions;  // unit directions along which it may not move
};

// A cylinder leaves the tube free to turn about its axis and (when no vertex is constrained)
// to slide along it: the vertex nearest the garment's mean axial position, not itself
// constrained, is pinned along the turn (and the axis). Other bodies: no pin.
RigidMotionPin rigid_motion_pin(const RigidBody& body, const std::vector<Vec3>& positions_m,
                                const ConstrainedDirections& constrained, bool any_constraint);

}  // namespace tightfit
