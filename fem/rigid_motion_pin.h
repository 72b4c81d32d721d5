// The rigid motions the body leaves the garment free to make, and the vertices pinned against
// them so that Newton's tangent is not singular. Nothing here knows the body's shape: a rigid
// motion of the garment (velocity v(x) = t + omega x (x - c)) is free when it moves no vertex
// along the body's normal at the vertex's closest point (a frictionless body pushes only
// along it, so it does no work along such a motion) and moves no constrained vertex along a
// constrained direction. The membrane's energy does not change under a rigid motion either,
// so at equilibrium no force acts along a free one and the pins' reactions vanish: no pressure
// changes. A cylinder leaves the turn about its axis and (free ends) the slide along it, a
// cone the turn, a sphere three turns, a plane two slides and a turn; a mesh body, a plane
// with a garment round it or a body under friction none.
#pragma once

#include "bodies/rigid_body.h"
#include "core/constrained_directions.h"

#include <vector>

namespace tightfit {

struct RigidMotionPin {
  struct Pin {
    int vertex = -1;               // welded vertex
    std::vector<Vec3> directions;  // orthonormal directions along which it may not move
  };
  std::vector<Pin> pins;  // empty: no free rigid motion
  int n_free_motions = 0;
};

// The free rigid motions of the garment at `positions_m` (welded vertices) on `body`, and pins
// that remove them: each pin is the unconstrained vertex nearest the garment's centroid among
// those the remaining free motions move well (at least a tenth of the garment's size per unit
// of turn or slide), held along what those motions do to it; a further vertex is pinned only
// when one cannot stop them all (a sphere's three turns). With friction (`friction` true) the
// anchors hold every rigid motion where the garment touches, so nothing is pinned.
// `held_turn_axis` (may be null): the garment's mean turn about this axis through its centroid is
// held already (fem/held_turn_system.h), so it is not free and gets no pin.
RigidMotionPin rigid_motion_pin(const RigidBody& body, const std::vector<Vec3>& positions_m,
                                const ConstrainedDirections& constrained, bool friction,
                                const Vec3* held_turn_axis = nullptr);

}  // namespace tightfit
