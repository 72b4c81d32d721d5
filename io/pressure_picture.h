// A picture of a pressure map (docs/measurements.md, "Pictures"): a triangle surface seen in
// an orthographic view along a chosen direction, coloured by the pressure at its vertices
// (viridis, from zero to a top pressure; grey where there is none), shaded by the angle of each
// triangle to the view, with a colour bar labelled in kPa and mmHg. Drawn by RasterCanvas.
#pragma once

#include "core/types.h"

#include <string>
#include <vector>

namespace tightfit {

struct PressureSurface {
  std::vector<Vec3> points_m;
  std::vector<Triangle> triangles;
  std::vector<double> pressure_Pa;  // one per point
  std::vector<char> has_pressure;   // 0: drawn grey (no garment there)
};

struct PictureView {
  Vec3 direction = -Vec3::UnitZ();  // the eye looks along it
  Vec3 up = Vec3::UnitY();          // shown upwards (its part across `direction`)
};

struct PictureStyle {
  int width = 800, height = 600;  // pixels
  double top_pressure_Pa = 0.0;   // the colour bar's top; 0: the largest pressure drawn
  std::string title;
};

// The viridis colour at t in [0, 1] (clamped).
Vec3 viridis(double t);

// Throws std::invalid_argument when the view's direction is zero or along `up`, or the arrays
// do not match the points; std::runtime_error naming `path` when it cannot be written.
void write_pressure_picture(const std::string& path, const PressureSurface& surface,
                            const PictureView& view, const PictureStyle& style);

}  // namespace tightfit
