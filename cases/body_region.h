// Named regions of space for reading the pressure by body region (docs/measurements.md): each
// a union of simple shapes (a slab between two heights along an axis, an axis-aligned box, a
// ball round a point), written in the case file as one line of text,
//
//   NAME: SHAPE [+ SHAPE ...]; NAME: ...
//   SHAPE = slab AXIS LOW HIGH        AXIS: x, y, z or a direction a,b,c; LOW < HIGH, m
//         | box XMIN,YMIN,ZMIN XMAX,YMAX,ZMAX                          min < max, m
//         | ball X,Y,Z RADIUS                                          RADIUS > 0, m
//         | NAMED [left|right] [front|back] [WIDTH]                    WIDTH > 0, m
//   NAMED = bust | under-bust band | waist band | hip band | scapulae | B | C | G | knee |
//           calf | thigh     (from the body's landmarks: body/anatomical_regions.h)
//
// e.g. "calf: slab z 0.25 0.45; knees: ball 0.1,0,0.5 0.06 + ball -0.1,0,0.5 0.06;
//       ankle: B left; under bust: under-bust band front 0.04".
// A named shape is resolved on the body (resolve_named_regions) before the region is used.
#pragma once

#include "body/anatomical_regions.h"
#include "core/types.h"

#include <string>
#include <vector>

namespace tightfit {

struct RegionShape {
  enum class Kind { slab, box, ball, tube, named };
  Kind kind = Kind::slab;
  Vec3 a = Vec3::Zero();  // slab: unit axis; box: min corner; ball: centre; tube: a point
  Vec3 b = Vec3::Zero();  // box: max corner; tube: its unit axis
  double low = 0.0;       // slab: lower height along the axis, m; ball, tube: radius, m
  double high = 0.0;      // slab: upper height, m
  double tube_low = 0.0, tube_high = 0.0;  // tube: heights along b from a, m
  AnatomyRequest named;                    // named: what to build from the landmarks
  std::string text;                        // as written, for messages

  // Throws std::logic_error for a named shape not yet resolved.
  bool contains(const Vec3& x_m) const;
};

struct BodyRegion {
  std::string name;
  std::vector<RegionShape> shapes;  // the region is their union

  bool contains(const Vec3& x_m) const;
};

// Parses the definitions above. Throws std::invalid_argument saying which region and shape is
// at fault and why: a malformed shape, a negative radius, a minimum above its maximum, a region
// that is empty by construction (zero radius, zero thickness), a name given twice, no region.
std::vector<BodyRegion> parse_body_regions(const std::string& definitions);

// Whether any region has a named shape, which needs the body's landmarks.
bool has_named_shapes(const std::vector<BodyRegion>& regions);

// Replaces every named shape by the boxes and tubes it stands for on `body` (its text then
// reads "NAMED = box ... + tube ..."). Throws BodyMeasureError naming the region.
void resolve_named_regions(std::vector<BodyRegion>& regions, const BodyMeasurements& body);

}  // namespace tightfit
