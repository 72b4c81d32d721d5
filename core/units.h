// Unit conversions used on screen and in tables. Everything inside tightfit is SI.
#pragma once

namespace tightfit::units {

// 1 gf/cm^2 = 9.80665e-3 N / 1e-4 m^2 (the paper's pressure unit).
inline constexpr double pascal_per_gf_per_cm2 = 98.0665;
// 1 mmHg, the unit compression garments are classed in.
inline constexpr double pascal_per_mmHg = 133.322387415;
// 1 N/cm = 100 N/m (the paper's unit for Et).
inline constexpr double newton_per_metre_per_newton_per_cm = 100.0;

inline double to_gf_per_cm2(double pressure_Pa) {
  return pressure_Pa / pascal_per_gf_per_cm2;
}
inline double to_mmHg(double pressure_Pa) {
  return pressure_Pa / pascal_per_mmHg;
}

}  // namespace tightfit::units
