// What a design is asked for (docs/design.md): the measuring points of RAL-GZ 387 along the
// limb (B, B1, C, D, E, F, G) and the mean pressure wanted over each point's band, either given
// point by point or as a compression class at B with a degressive profile.
#pragma once

#include <string>
#include <vector>

namespace tightfit {

struct NamedValue {
  std::string name;
  double value = 0.0;
};

// Parses "B:0.02, C:0.2419, ..." (names are words without ':' or ','). Throws
// std::invalid_argument naming `entry` and the piece it could not read, or a name given twice.
std::vector<NamedValue> parse_named_values(const std::string& text, const std::string& entry);

// Design/Points: "B, B1, C:0.2419, ...": each point's name, with a height along the garment (m)
// or without one (its value then NaN: the height comes from the body's landmarks). Throws
// std::invalid_argument naming `entry` and the piece it could not read, or a name given twice.
std::vector<NamedValue> parse_design_points(const std::string& text, const std::string& entry);

// The measuring points' heights along the garment (m from its bottom edge), in the order given:
// a stated height as stated, a point without one (NaN) at its height in `landmark_heights` (the
// points a garment cut to the body found on it, cases/limb_tube_cut.h). Throws
// std::invalid_argument when a point has neither, or the heights do not increase or lie
// outside [0, length_m].
std::vector<NamedValue> design_point_heights(const std::vector<NamedValue>& stated_heights,
                                             double length_m,
                                             const std::vector<NamedValue>& landmark_heights = {});

struct DesignTarget {
  enum class Kind { compression_class, pressures };
  Kind kind = Kind::compression_class;
  int class_number = 2;               // RAL-GZ 387 class at B, 1 to 4
  double pressure_at_b_mmHg = 0.0;    // 0: the middle of the class's range
  std::vector<NamedValue> profile;    // share of B's pressure at each point (-)
  std::vector<NamedValue> pressures;  // mmHg at each point (Kind::pressures)
};

// The target mean pressure at each point, mmHg, in the points' order. Throws
// std::invalid_argument naming the point and entry at fault: a point without a target, a
// target for a point not in the list, a pressure that is not positive, a class pressure outside
// the class's range (class IV needs one stated), a profile that is not 1 at B or rises from one
// point to the next up the limb (not degressive).
std::vector<double> target_pressures_mmHg(const std::vector<NamedValue>& points,
                                          const DesignTarget& target);

}  // namespace tightfit
