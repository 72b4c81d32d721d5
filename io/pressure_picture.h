// A picture of a pressure map (docs/measurements.md, "Pictures"): a triangle surface seen in
// an orthographic view along a chosen direction, coloured by the pressure at its vertices
// (viridis, from zero to a top pressure; grey where there is none; red above the top, which the
// colour bar then marks with the largest pressure drawn), shaded by the angle of each triangle
// to the view, with a colour bar labelled in kPa and mmHg. The garment's outline may be drawn
// over it as dark lines, and the view may be framed round some of the points (the garment's)
// rather than the whole surface. Drawn by RasterCanvas.
#pragma once

#include "core/types.h"

#include <array>
#include <string>
#include <vector>

namespace tightfit {

struct PressureSurface {
  std::vector<Vec3> points_m;
  std::vector<Triangle> triangles;
  std::vector<double> pressure_Pa;  // one per point
  std::vector<char> has_pressure;   // 0: drawn grey (no garment there)
  // Segments drawn as dark lines over the surface (the garment's edge, boundary_segments),
  // where the surface drawn there is not nearer the eye than `outline_depth_tolerance_m` (the
  // garment lies on the body, a little outside it).
  std::vector<std::array<Vec3, 2>> outline_m;
  double outline_depth_tolerance_m = 0.0;
  // The picture is framed round these points (with a 5% margin) when there are any, round the
  // whole surface otherwise; what lies outside the frame is cut off.
  std::vector<Vec3> frame_m;
  std::string grey_means = "no garment on the skin";  // the legend's words for grey
};

// The edges of `triangles` that belong to one triangle alone (a garment's hem and openings),
// as segments between `points`.
std::vector<std::array<Vec3, 2>> boundary_segments(const std::vector<Vec3>& points,
                                                   const std::vector<Triangle>& triangles);

// The colour drawn where the pressure is above the colour bar's top.
Vec3 above_top_colour();

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

// Several surfaces side by side on one scale and one colour bar (load steps of a run, the
// paper's Figure 6), each with its caption below it (none if `captions` is empty). Throws as
// write_pressure_picture.
void write_pressure_panels(const std::string& path, const std::vector<PressureSurface>& panels,
                           const std::vector<std::string>& captions, const PictureView& view,
                           const PictureStyle& style);

}  // namespace tightfit
