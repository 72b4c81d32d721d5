// The rigid part of a displacement field: the translation t and small rotation w (about the
// points' centroid c) whose field t + w x (p - c) is closest to the displacements in the least
// squares sense. A Newton increment that is mostly rigid is a garment following a motion its
// body barely resists (a tube turning round a limb that is nearly of revolution), the mode
// behind a slow or stalled load step (docs/backends.md, "Newton's line search").
#pragma once

#include "core/types.h"

#include <string>
#include <vector>

namespace tightfit {

struct RigidMotionFit {
  Vec3 centre_m = Vec3::Zero();       // the points' centroid
  Vec3 translation_m = Vec3::Zero();  // t
  Vec3 rotation_rad = Vec3::Zero();   // w: axis times angle
  // Share of sum |d_i|^2 the rigid field carries, 0 to 1 (0 without displacement).
  double explained = 0.0;
};

// positions and displacements alike in size (throws std::invalid_argument otherwise). Fewer than
// three points not on a line leave the rotation undetermined: its least-norm value is returned.
RigidMotionFit fit_rigid_motion(const std::vector<Vec3>& positions_m,
                                const std::vector<Vec3>& displacements_m);

// One line for a solver's message: the share, the rotation's axis and angle, the translation.
std::string text(const RigidMotionFit& fit);

}  // namespace tightfit
