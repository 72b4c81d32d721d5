// Tubes sewn from rectangular panels: the paper's cylinder garments.
#pragma once

#include "core/garment.h"
#include "core/rectangle_panel.h"

#include <vector>

namespace tightfit {

// `n_panels` equal panels, each panel_width_m (round the tube, along the weft) by
// panel_height_m (along the tube, the warp), sewn right edge to the next panel's left edge
// into a closed ring of circumference n_panels * panel_width_m. The paper's "T" is two panels
// of 0.157 m x 0.24 m, its "4 5T" two of 0.1878 m x 0.24 m (the paper's Table 3).
// Panel p lies at x offset p * panel_width_m in the layout plane; the last seam closes the
// ring across the layout (a periodic identification).
Garment make_tube_garment(const std::string& name, double panel_width_m, double panel_height_m,
                          int n_panels, const MeshSpacing& spacing);

// Circumference of a garment whose panels are sewn right edge to the next one's left edge
// round a closed ring (a tube such as make_tube_garment's): the sum of the panels' widths
// (x from the lowest vertex of the left edge to the lowest of the right), metres. Zero for
// any other garment.
double ring_circumference_m(const Garment& garment);

// The panels in their order round a ring sewn right edge to left edge, from panel 0; empty for
// any other garment.
std::vector<int> ring_order(const Garment& garment);

// Where each panel vertex lies round the ring: the share of its row's girth from the left edge
// of the first panel to it (0 to 1), and that girth (m), the row's widths at its height summed
// over the panels (each width between its panel's left and right edges, linear along them): a
// tapered tube's (core/tapered_tube_garment.h) rows. A ring of one girth at every height
// (rectangles, side edges curved alike) keeps its layout instead: its share is the layout x
// over the girth. Panel by panel, as SimulationMesh numbers unwelded vertices; empty when the
// garment is not a ring.
struct RingCoordinate {
  double share = 0.0;
  double girth_m = 0.0;
};
std::vector<RingCoordinate> ring_coordinates(const Garment& garment);

}  // namespace tightfit
