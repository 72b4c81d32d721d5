// Regions of the body named by anatomy instead of coordinates (docs/measuring-bodies.md, "Named
// regions"): bands of a stated width round the girth lines, patches of the torso's front or
// back, and bands round each leg at RAL-GZ 387's measuring points B, C and G, each built from the
// body's landmarks (body_measurements.h) as boxes and tubes.
#pragma once

#include "body/body_measurements.h"

#include <string>
#include <vector>

namespace tightfit {

// A region's piece: a box, or a tube (the points within `radius_m` of the line through
// `point_m` along the unit `axis`, at heights along it between `low_m` and `high_m` from
// `point_m`).
struct RegionPiece {
  enum class Kind { box, tube };
  Kind kind = Kind::box;
  Vec3 min_m = Vec3::Zero(), max_m = Vec3::Zero();  // box
  Vec3 point_m = Vec3::Zero(), axis = Vec3::UnitZ();
  double low_m = 0.0, high_m = 0.0, radius_m = 0.0;  // tube
};

struct AnatomyRequest {
  std::string name;      // one of anatomical_region_names()
  int side = -1;         // legs and arms: -1 both, 0 left, 1 right
  int facing = 0;        // torso bands: 0 all round, 1 the front, -1 the back
  double width_m = 0.0;  // 0: the name's default
};

// bust, under-bust band, waist band, hip band, scapulae, B, C, G, knee, calf, thigh, upper arm.
const std::vector<std::string>& anatomical_region_names();
// The default width of each (m), as docs/measuring-bodies.md ("Named regions") lists them.
double default_region_width_m(const std::string& name);

// Throws BodyMeasureError for an unknown name or a side or facing the region does not have.
std::vector<RegionPiece> anatomical_region(const BodyMeasurements& body,
                                           const AnatomyRequest& request);

}  // namespace tightfit
