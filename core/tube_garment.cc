#include "core/tube_garment.h"

#include <stdexcept>

namespace tightfit {

Garment make_tube_garment(const std::string& name, double panel_width_m, double panel_height_m,
                          int n_panels, const MeshSpacing& spacing) {
  if (n_panels < 1) throw std::invalid_argument("Garment/Number of panels must be at least 1");
  Garment garment;
  garment.name = name;
  garment.ring_circumference_m = n_panels * panel_width_m;
  for (int p = 0; p < n_panels; ++p) {
    Panel panel = make_rectangle_panel(name + " panel " + std::to_string(p + 1), panel_width_m,
                                       panel_height_m, spacing);
    panel.layout_offset_m = Vec2(p * panel_width_m, 0.0);
    garment.panels.push_back(std::move(panel));
    garment.seams.push_back({p, "right", (p + 1) % n_panels, "left"});
  }
  return garment;
}

}  // namespace tightfit
