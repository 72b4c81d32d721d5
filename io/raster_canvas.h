// A small off-screen picture: an RGB canvas with a depth buffer, filled triangle by triangle
// (a z-buffer rasteriser), with text drawn by VTK's FreeType renderer and written as PNG by
// VTK's PNG writer. tightfit draws its pressure pictures with it because the VTK of Debian
// renders only through an X display (no OSMesa or EGL window).
//
// Pixel coordinates: x to the right, y downwards, (0, 0) the top left corner; a pixel's centre
// is at (i + 0.5, j + 0.5). Colours are RGB in [0, 1].
#pragma once

#include "core/types.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace tightfit {

class RasterCanvas {
 public:
  RasterCanvas(int width, int height, const Vec3& background);

  int width() const { return width_; }
  int height() const { return height_; }

  // The triangle with corners (x, y, depth) in pixels, a smaller depth nearer the eye; every
  // pixel whose centre it covers and that is nearer than what is drawn there takes the colour
  // `colour_of(barycentric coordinates)`.
  void fill_triangle(const std::array<Vec3, 3>& corners,
                     const std::function<Vec3(const Vec3& barycentric)>& colour_of);
  // The segment from a to b ((x, y, depth) in pixels as for triangles), `width` pixels wide,
  // on every pixel where what is drawn is not nearer than the segment by more than
  // `depth_tolerance` (the depth buffer is left as it is).
  void draw_line(const Vec3& a, const Vec3& b, double width, const Vec3& colour,
                 double depth_tolerance);
  // Triangles and lines are drawn inside [x0, x1) x [y0, y1) alone from now on (the whole
  // canvas at first); rectangles and text anywhere.
  void set_clip(int x0, int y0, int x1, int y1);
  // A rectangle over everything, [x0, x1) x [y0, y1).
  void fill_rectangle(int x0, int y0, int x1, int y1, const Vec3& colour);

  enum class Align { left, right, centre };
  // `text` in black, its baseline at row y, starting (left), ending (right) or centred at x.
  void draw_text(const std::string& text, int x, int y, int font_size, Align align);

  // Throws std::runtime_error naming `path` when it cannot be written.
  void write_png(const std::string& path) const;

  const Vec3& pixel(int x, int y) const { return rgb_[y * width_ + x]; }

 private:
  int width_, height_;
  std::vector<Vec3> rgb_;
  std::vector<double> depth_;
  int clip_x0_ = 0, clip_y0_ = 0, clip_x1_, clip_y1_;
};

}  // namespace tightfit
