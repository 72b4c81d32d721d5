// A virtual air-pack pressure sensor (the paper's Table 1: AMI 3037-2): a flat disc lying on
// the body's surface that reads the normal force pressing through it divided by its area.
// The simulated reading integrates the garment's per-vertex contact traction, interpolated
// linearly over each deformed triangle, over the part of the garment whose projection onto
// the disc's plane falls inside the disc (docs/instruments.md, "Air-pack sensors").
#pragma once

#include "core/types.h"

#include <vector>

namespace tightfit {

// What the physical instrument can show, for the columns beside the simulated value.
struct AirPackSpecification {
  double diameter_m = 0.015;             // Table 1: 15 mm air pack
  double range_min_Pa = 0.0;             // Table 1: 0.0 gf/cm^2
  double range_max_Pa = 70.0 * 98.0665;  // Table 1: 70.0 gf/cm^2
  double accuracy_Pa = 1.5 * 98.0665;    // Table 1: +/- 1.5 gf/cm^2
};

struct DiscReading {
  double pressure_Pa = 0.0;      // force through the disc over the disc's covered area
  double force_N = 0.0;          // that pressure times the disc's area, pi d^2 / 4
  double covered_area_m2 = 0.0;  // garment area found over the disc (pi d^2 / 4 when covered)
  int n_triangles = 0;           // garment triangles that reach into the disc
  // The instrument's display: the reading clipped to its range, and whether it was inside.
  double displayed_Pa = 0.0;
  bool in_range = true;
};

// A disc of `diameter_m` centred at `centre_m` on the body, in the plane normal to `normal`.
// `pressure_Pa` holds one value per vertex of `positions_m`. Only the garment within a
// diameter of the disc's plane counts (the near side of the body). Each triangle is cut into
// sub-triangles no longer than a twentieth of the diameter, each counted when its centroid
// falls inside the disc: the covered area then matches the disc's to well under 1%.
DiscReading read_disc(const std::vector<Vec3>& positions_m, const std::vector<Triangle>& triangles,
                      const std::vector<double>& pressure_Pa, const Vec3& centre_m,
                      const Vec3& normal, const AirPackSpecification& sensor);

}  // namespace tightfit
