// The paper's 11 measuring points (Section 4.1): printed stamps on two orthogonally crossing
// lines, one running along the cylinder's axis on top, the sensor at each stamp's centre. The
// paper gives no coordinates; tightfit's reading (docs/instruments.md): a line of 7 points
// along the axis (warp), 3 cm apart, crossed at its middle by a line of 5 points round the
// tube (weft), 2.75 cm apart, which keeps every 2 cm stamp inside one 15.7 cm panel.
#pragma once

#include "core/types.h"

#include <string>
#include <vector>

namespace tightfit {

struct CrossPoint {
  std::string name;  // "A-3" .. "A+3" along the axis, "H-2" .. "H+2" round it ("A0" the crossing)
  // Offsets from the crossing, m: round the tube (arc length, or weft in the pattern) and
  // along the axis (warp in the pattern).
  double hoop_m = 0.0;
  double axial_m = 0.0;
};

inline std::vector<CrossPoint> paper_cross_points() {
  std::vector<CrossPoint> points;
  for (int k = -3; k <= 3; ++k)
    points.push_back({"A" +
                          std::string(k < 0   ? "-"
                                      : k > 0 ? "+"
                                              : "") +
                          std::to_string(std::abs(k)),
                      0.0, 0.03 * k});
  for (int k : {-2, -1, 1, 2})
    points.push_back(
        {"H" + std::string(k < 0 ? "-" : "+") + std::to_string(std::abs(k)), 0.0275 * k, 0.0});
  return points;
}

}  // namespace tightfit
