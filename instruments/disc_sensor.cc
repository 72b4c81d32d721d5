#include "instruments/disc_sensor.h"

#include <algorithm>
#include <cmath>

namespace tightfit {

DiscReading read_disc(const std::vector<Vec3>& positions_m, const std::vector<Triangle>& triangles,
                      const std::vector<double>& pressure_Pa, const Vec3& centre_m,
                      const Vec3& normal, const AirPackSpecification& sensor) {
  const double radius = 0.5 * sensor.diameter_m;
  const Vec3 n = normal.normalized();
  // In the disc: within the radius across the normal, within a diameter along it.
  auto inside = [&](const Vec3& x) {
    const Vec3 d = x - centre_m;
    const double along = d.dot(n);
    return std::abs(along) < 2.0 * radius && (d - along * n).norm() < radius;
  };
  DiscReading reading;
  double force_N = 0.0;
  for (const Triangle& t : triangles) {
    const Vec3 &a = positions_m[t[0]], &b = positions_m[t[1]], &c = positions_m[t[2]];
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    // Skip triangles that cannot reach the disc.
    if ((a - centre_m).norm() > radius + longest + 2.0 * radius) continue;
    const int m = std::max(1, static_cast<int>(std::ceil(20.0 * longest / sensor.diameter_m)));
    const double sub_area = 0.5 * (b - a).cross(c - a).norm() / (m * m);
    bool reached = false;
    // The m^2 sub-triangles of a barycentric grid: (i, j) upright and (i, j) inverted.
    for (int i = 0; i < m; ++i)
      for (int j = 0; i + j < m; ++j)
        for (int inverted = 0; inverted < (i + j + 1 < m ? 2 : 1); ++inverted) {
          // Centroid in grid units: upright (i + 1/3, j + 1/3), inverted (i + 2/3, j + 2/3).
          const double shift = inverted ? 2.0 / 3.0 : 1.0 / 3.0;
          const double u = (i + shift) / m, v = (j + shift) / m, w = 1.0 - u - v;
          const Vec3 x = w * a + u * b + v * c;
          if (!inside(x)) continue;
          reached = true;
          reading.covered_area_m2 += sub_area;
          force_N +=
              sub_area * (w * pressure_Pa[t[0]] + u * pressure_Pa[t[1]] + v * pressure_Pa[t[2]]);
        }
    if (reached) ++reading.n_triangles;
  }
  if (reading.covered_area_m2 > 0) reading.pressure_Pa = force_N / reading.covered_area_m2;
  reading.force_N = reading.pressure_Pa * M_PI * radius * radius;
  reading.in_range =
      reading.pressure_Pa >= sensor.range_min_Pa && reading.pressure_Pa <= sensor.range_max_Pa;
  reading.displayed_Pa = std::clamp(reading.pressure_Pa, sensor.range_min_Pa, sensor.range_max_Pa);
  return reading;
}

}  // namespace tightfit
