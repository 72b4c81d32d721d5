// The open start of a dressing (docs/dressing.md): each panel of a garment, unsewn, wrapped on
// an elliptic cylinder round an axis, outside the body. Panel p is centred on the angle phi_p
// round the axis from the front direction f towards l = axis x f; a panel vertex at pattern
// coordinates (x, y) goes to the angle phi_p + (x - x_p) / R (x_p the middle of the panel's x
// range, R the ellipse's perimeter over 2 pi, so pattern x keeps roughly its length round the
// ellipse) and the height hem + (y - y_min) along the axis (y_min the panel's lowest point):
//   position = centre + (hem + y - y_min) axis + b cos(phi) f + a sin(phi) l,
// a the semi-axis along l (the body's side), b along f. Pattern x to the right and y up as
// seen from outside (a panel counter-clockwise seen from outside, docs/patterns.md) give
// increasing phi and the axis, so the triangles' normals point outwards.
#pragma once

#include "core/garment.h"

#include <vector>

namespace tightfit {

struct PanelWrap {
  Vec3 centre_m = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  Vec3 front = -Vec3::UnitY();  // made normal to the axis
  double semi_axis_side_m = 0.15;
  double semi_axis_front_m = 0.15;
  double hem_height_m = 0.0;  // along the axis from the centre, of every panel's lowest point
  std::vector<double> panel_angles_rad;  // one per panel
  // Each panel's own hem height, m (one per panel); empty: hem_height_m for every panel.
  std::vector<double> panel_hem_heights_m;
};

// Ramanujan's perimeter of the ellipse with semi-axes a and b (exact for a circle), m.
double ellipse_perimeter_m(double a_m, double b_m);

// Unwelded positions (mesh's panel vertex numbering), m. Throws std::invalid_argument for a
// zero axis, a front along the axis, non-positive semi-axes or a wrong count of angles or
// hem heights.
std::vector<Vec3> wrap_panels_round_axis(const Garment& garment, const SimulationMesh& mesh,
                                         const PanelWrap& wrap);

}  // namespace tightfit
