// Named regions of space for reading the pressure by body region (docs/measurements.md): each
// a union of simple shapes (a slab between two heights along an axis, an axis-aligned box, a
// ball round a point), written in the case file as one line of text,
//
//   NAME: SHAPE [+ SHAPE ...]; NAME: ...
//   SHAPE = slab AXIS LOW HIGH        AXIS: x, y, z or a direction a,b,c; LOW < HIGH, m
//         | box XMIN,YMIN,ZMIN XMAX,YMAX,ZMAX                          min < max, m
//         | ball X,Y,Z RADIUS                                          RADIUS > 0, m
//
// e.g. "calf: slab z 0.25 0.45; knees: ball 0.1,0,0.5 0.06 + ball -0.1,0,0.5 0.06".
#pragma once

#include "core/types.h"

#include <string>
#include <vector>

namespace tightfit {

struct RegionShape {
  enum class Kind { slab, box, ball };
  Kind kind = Kind::slab;
  Vec3 a = Vec3::Zero();  // slab: unit axis; box: min corner; ball: centre
  Vec3 b = Vec3::Zero();  // box: max corner
  double low = 0.0;       // slab: lower height along the axis, m; ball: radius, m
  double high = 0.0;      // slab: upper height, m
  std::string text;       // as written, for messages

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

}  // namespace tightfit
