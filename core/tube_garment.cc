#include "core/tube_garment.h"

#include <algorithm>
#include <stdexcept>

namespace tightfit {

Garment make_tube_garment(const std::string& name, double panel_width_m, double panel_height_m,
                          int n_panels, const MeshSpacing& spacing) {
  if (n_panels < 1) throw std::invalid_argument("Garment/Number of panels must be at least 1");
  Garment garment;
  garment.name = name;
  for (int p = 0; p < n_panels; ++p) {
    Panel panel = make_rectangle_panel(name + " panel " + std::to_string(p + 1), panel_width_m,
                                       panel_height_m, spacing);
    panel.layout_offset_m = Vec2(p * panel_width_m, 0.0);
    garment.panels.push_back(std::move(panel));
    garment.seams.push_back({p, "right", (p + 1) % n_panels, "left"});
  }
  return garment;
}

namespace {

// x of the vertex of edge `edge` with the smallest y (0 when the panel has no such edge).
double lowest_x(const Panel& panel, const std::string& edge) {
  const auto found = panel.edges.find(edge);
  if (found == panel.edges.end() || found->second.empty()) return 0.0;
  const auto& rest = panel.rest_positions_m;
  const int lowest = *std::min_element(found->second.begin(), found->second.end(),
                                       [&](int a, int b) { return rest[a].y() < rest[b].y(); });
  return rest[lowest].x();
}

}  // namespace

double ring_circumference_m(const Garment& garment) {
  const int n = static_cast<int>(garment.panels.size());
  if (n == 0 || static_cast<int>(garment.seams.size()) != n) return 0.0;
  // Each panel's right edge sewn to the next one's left edge, round the whole garment.
  std::vector<int> next(n, -1);
  for (const Seam& seam : garment.seams) {
    if (seam.edge_a != "right" || seam.edge_b != "left") return 0.0;
    if (seam.panel_a < 0 || seam.panel_a >= n || next[seam.panel_a] >= 0) return 0.0;
    next[seam.panel_a] = seam.panel_b;
  }
  int panel = 0;
  double circumference = 0.0;
  for (int visited = 0; visited < n; ++visited) {
    if (panel < 0 || panel >= n || (visited > 0 && panel == 0)) return 0.0;
    // The panel's width round the ring: from its left edge to its right edge along x, at the
    // lowest vertex of each (a rectangle's full width; also right for side edges curved alike).
    circumference +=
        lowest_x(garment.panels[panel], "right") - lowest_x(garment.panels[panel], "left");
    panel = next[panel];
  }
  return panel == 0 ? circumference : 0.0;
}

}  // namespace tightfit
