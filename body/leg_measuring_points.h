// The measuring points of RAL-GZ 387 on a leg, along its axis (docs/stocking.md, "The measuring
// points"): B the ankle's smallest girth, B1 where the Achilles tendon passes into the calf,
// C the calf's largest girth, D below the knee, E the knee, F the middle of the thigh, G the
// upper thigh. B, C, E (the knee) and G are the body's landmarks (body_measurements.h); B1, D
// and F are found here from the girths between them.
#pragma once

#include "body/body_measurements.h"

#include <string>
#include <vector>

namespace tightfit {

struct LegPoint {
  std::string name;    // B, B1, C, D, E, F, G
  double axial_m = 0;  // up the leg's axis: up . x, up = -PartFrame::along
  double girth_m = 0;  // the tape girth normal to the axis there
};

// The names in order up the leg.
const std::vector<std::string>& leg_point_names();

// The points of leg `side` (0 left, 1 right) in order up the leg:
//   B, C, E (= the knee landmark), G: the landmarks' axial coordinates;
//   B1: where the girth rises fastest between B and C (the tendon flaring into the calf
//       muscle), the slope taken over 2 cm;
//   D: the smallest girth between C and E (the narrowing below the knee);
//   F: half way between E and G.
// Throws BodyMeasureError naming the point when a section it needs misses the leg.
std::vector<LegPoint> leg_measuring_points(const TriangleSurface& surface,
                                           const BodyMeasurements& body, int side);

}  // namespace tightfit
