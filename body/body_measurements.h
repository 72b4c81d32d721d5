// What a tailor reads off a body: landmarks, the axes of its parts and the standard girths
// (ISO 8559-1 names them), found on a body mesh alone (docs/measuring-bodies.md).
// The body stands in tightfit's frame: z up, its front towards -y, its left towards +x; the
// arms apart from the torso below the armpits and the legs apart below the crotch (A-pose,
// T-pose).
#pragma once

#include "bodies/triangle_surface.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace tightfit {

// A body on which a landmark or girth cannot be found, or that is no standing person at the
// size it was read: the message names the landmark and why.
class BodyMeasureError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct BodyLandmark {
  std::string name;  // "crotch", "armpit left", ...
  Vec3 point_m = Vec3::Zero();
};

struct BodyGirth {
  std::string name;              // "bust", "waist", "calf left", ...
  double girth_m = 0.0;          // the convex hull's perimeter, as a tape pulled tight reads it
  double section_m = 0.0;        // along the section itself
  double level_m = 0.0;          // the plane's centre's height above the floor
  Vec3 centre_m = Vec3::Zero();  // the section's centroid
  Vec3 normal = Vec3::UnitZ();   // the plane's
  std::vector<Vec3> hull_m;      // the tape's path, for pictures
};

struct BodyLength {
  std::string name;  // "height", "shoulder width", "arm length left", "waist height", ...
  double length_m = 0.0;
};

// A body part's frame: its axis (the line through the centroids of its sections) and two
// directions across it.
struct PartFrame {
  std::string name;              // torso, arm left, arm right, leg left, leg right
  Vec3 origin_m = Vec3::Zero();  // the axis's point at the part's root
  Vec3 along = Vec3::UnitZ();    // torso and legs upwards, arms from the shoulder out
  Vec3 lateral = Vec3::UnitX();  // across the axis towards the body's left
  Vec3 front = -Vec3::UnitY();   // along x lateral: the third direction
  double length_m = 0.0;         // from the origin to the part's end along the axis
};

struct BodyMeasurements {
  double floor_m = 0.0, top_m = 0.0;  // lowest and highest z
  std::vector<BodyLandmark> landmarks;
  std::vector<BodyGirth> girths;
  std::vector<BodyLength> lengths;
  std::vector<PartFrame> parts;
  bool bust_points_present = false;  // a hollow between the breasts at the bust line

  // Throw std::out_of_range naming what is missing.
  const BodyLandmark& landmark(const std::string& name) const;
  const BodyGirth& girth(const std::string& name) const;
  const BodyLength& length(const std::string& name) const;
  const PartFrame& part(const std::string& name) const;
};

// Finds everything above. Throws BodyMeasureError naming the landmark that cannot be found
// and why (no legs apart, arms against the torso, ...), or the size that makes the body no
// standing person (body_size.h).
BodyMeasurements measure_body(const TriangleSurface& surface);

}  // namespace tightfit
