// The paper's Eq. 3 (Section 3, after Lee 2005): the pressure under a stamp from its principal
// membrane tensions and the body's curvature along their directions,
//   P = sigma_max t / r_max + sigma_min t / r_min,
// with sigma t the tension per unit current length (N/m) and 1 / r the body's normal
// curvature along each principal direction of stress (zero along a straight line).
#pragma once

#include "bodies/rigid_body.h"
#include "core/material.h"
#include "instruments/stamp.h"

namespace tightfit {

struct Eq3Estimate {
  double tension_max_N_per_m = 0.0, tension_min_N_per_m = 0.0;  // principal, per current length
  Vec3 direction_max = Vec3::UnitX(), direction_min = Vec3::UnitY();
  double curvature_max_per_m = 0.0, curvature_min_per_m = 0.0;  // the body's, along them
  double pressure_Pa = 0.0;
};

// The stresses come from `law` at the stamp's fitted deformation; the curvatures from the body's
// normal field at the point of its surface closest to the stamp's centre.
Eq3Estimate eq3_pressure(const StampFit& fit, const MaterialLaw& law, const RigidBody& body);

}  // namespace tightfit
