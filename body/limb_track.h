// A limb followed in sections normal to its axis, from its root out to its end (an arm from
// the armpit to the fingertips): each section is the loop round the point the previous one
// predicts, so the other parts the plane also cuts (the torso, the other limbs) are left out.
#pragma once

#include "body/line_fit.h"
#include "body/section_cutter.h"

#include <vector>

namespace tightfit {

struct LimbSection {
  double t_m = 0.0;  // the plane's height along the direction
  SectionLoop loop;
  double reach_m = 0.0;  // the largest distance of the loop from its centroid
};

struct LimbTrack {
  FittedLine axis;
  std::vector<LimbSection> sections;  // from the root out
};

// Follows the limb from `start_m` along `direction` in planes `step_m` apart, each loop within
// `reach_m` of the predicted centre; a loop wider than `max_radius_m` (where the plane still
// cuts the torso) is passed over. Ends where no loop is near. Then fits the axis through the
// centroids of the first `fit_share` of the sections, follows again along it, and returns the
// second pass.
LimbTrack follow_limb(const TriangleSurface& surface, const Vec3& start_m, const Vec3& direction,
                      double step_m, double reach_m, double max_radius_m, double fit_share);

}  // namespace tightfit
