// The cut of a designed tubular garment (docs/design.md, "The method"): its relaxed circumference
// at every height, and its outline as one flat piece, the tube opened along a seam, for
// garment CAD.
//
// Between the measuring points the relaxed circumference follows the limb: the negative ease
// e_k = 1 - c_k / g_k found at each point is interpolated linearly in the height and applied to
// the limb's girth table g(H) (c(H) = g(H) (1 - e(H)); constant ease below the first point and
// above the last), so the garment follows the limb's shape between the points.
#pragma once

#include "cases/design/design_target.h"
#include "core/tapered_tube_garment.h"

#include <string>
#include <vector>

namespace tightfit {

struct CutKnot {
  double height_m = 0.0;         // along the garment from its bottom edge
  double girth_m = 0.0;          // the limb's
  double circumference_m = 0.0;  // the garment's, relaxed
  std::string point;             // the measuring point at this height, if one is
};

// The knots: the limb girth table's heights and the points' heights, increasing.
std::vector<CutKnot> design_cut(const PiecewiseLinear& limb_girths_m,
                                const std::vector<NamedValue>& points,
                                const std::vector<double>& circumferences_m);

// "H:c, H:c, ...": the relaxed girths as Garment/Tapered tube/Girths reads them.
std::string relaxed_girths_setting(const std::vector<CutKnot>& knots);

// cut.csv: height_m, girth_m, circumference_m, negative_ease, point.
void write_cut_csv(const std::string& path, const std::vector<CutKnot>& knots);

// The outline, in mm, of the tube opened along its seam: width c(H) at height H, symmetric
// about the middle line (the warp, along the limb), counter-clockwise from the bottom left
// corner; the four corners are the first, the last of the left side, and so on.
struct CutOutline {
  std::vector<Vec2> points_mm;
  std::vector<int> corners;  // indices into points_mm
  double width_mm = 0.0, height_mm = 0.0;
};
CutOutline cut_outline(const std::vector<CutKnot>& knots);

// An SVG drawing of the outline (<path class="fabric">, mm, as `tightfit pattern` reads
// FreeSewing's), with the measuring points marked. Throws std::runtime_error naming the file
// when it cannot be written.
void write_cut_svg(const std::string& path, const std::string& piece,
                   const std::vector<CutKnot>& knots);

// The outline as AAMA DXF (docs/patterns.md): one BLOCK, its boundary a closed POLYLINE on
// layer 1, the corners as POINTs on layer 2, the grain line (along the limb) on layer 7,
// "PIECE NAME: piece" as TEXT, $INSUNITS 4 (mm). Throws std::runtime_error naming the file when
// it cannot be written.
void write_cut_dxf(const std::string& path, const std::string& piece,
                   const std::vector<CutKnot>& knots);

}  // namespace tightfit
