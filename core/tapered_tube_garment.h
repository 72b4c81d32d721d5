// Tubes whose relaxed girth changes along their length: a graduated compression stocking or
// sleeve, cut as equal trapezoid-like panels sewn side by side (docs/model.md, "Tapered tubes").
#pragma once

#include "core/garment.h"
#include "core/rectangle_panel.h"

#include <string>
#include <vector>

namespace tightfit {

// A piecewise-linear function of the height along the tube (m from its bottom edge), given at
// strictly increasing heights and held constant below the first and above the last.
class PiecewiseLinear {
 public:
  struct Point {
    double height_m = 0.0;
    double value = 0.0;
  };
  PiecewiseLinear() = default;
  // Throws std::invalid_argument (naming `what`) for no points or heights that do not increase.
  PiecewiseLinear(std::vector<Point> points, const std::string& what);
  double at(double height_m) const;
  const std::vector<Point>& points() const { return points_; }

 private:
  std::vector<Point> points_;
};

// The relaxed girth (rest circumference, m) of every height along the tube: the given girths,
// or, with a negative ease e(H), the body's girths times (1 - e(H)) (both interpolated linearly
// in the height).
struct TaperedTubeShape {
  double length_m = 0.24;
  int n_panels = 2;
  PiecewiseLinear girths_m;
  PiecewiseLinear negative_ease;  // no points: none
  double relaxed_girth_m(double height_m) const;
  // Throws std::invalid_argument naming the entry at fault: a length or girth that is not
  // positive, an ease outside (-1, 1), heights outside [0, length].
  void validate() const;
};

// `shape.n_panels` equal panels sewn right edge to the next one's left edge into a closed ring.
// Each is a rectangle panel (core/rectangle_panel.h, the mean relaxed width across) whose rows
// are then scaled about the panel's middle to the relaxed girth of their height over the number
// of panels: rows stay straight and along the weft, each row's vertices evenly spaced, every
// panel the same symmetric trapezoid (piecewise). Vertex groups bottom, top as the tube's.
Garment make_tapered_tube_garment(const std::string& name, const TaperedTubeShape& shape,
                                  const MeshSpacing& spacing);

}  // namespace tightfit
