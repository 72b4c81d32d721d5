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

std::vector<int> ring_order(const Garment& garment) {
  const int n = static_cast<int>(garment.panels.size());
  if (n == 0 || static_cast<int>(garment.seams.size()) != n) return {};
  // Each panel's right edge sewn to the next one's left edge, round the whole garment.
  std::vector<int> next(n, -1);
  for (const Seam& seam : garment.seams) {
    if (seam.edge_a != "right" || seam.edge_b != "left") return {};
    if (seam.panel_a < 0 || seam.panel_a >= n || next[seam.panel_a] >= 0) return {};
    next[seam.panel_a] = seam.panel_b;
  }
  std::vector<int> order;
  int panel = 0;
  for (int visited = 0; visited < n; ++visited) {
    if (panel < 0 || panel >= n || (visited > 0 && panel == 0)) return {};
    order.push_back(panel);
    panel = next[panel];
  }
  if (panel != 0) return {};
  return order;
}

double ring_circumference_m(const Garment& garment) {
  double circumference = 0.0;
  // The panel's width round the ring: from its left edge to its right edge along x, at the
  // lowest vertex of each (a rectangle's full width; also right for side edges curved alike).
  for (const int panel : ring_order(garment))
    circumference +=
        lowest_x(garment.panels[panel], "right") - lowest_x(garment.panels[panel], "left");
  return circumference;
}

namespace {

// A panel's side edge as x against y: its vertices sorted by y, linear between them and
// constant beyond.
class SideEdge {
 public:
  SideEdge(const Panel& panel, const std::string& edge) {
    const auto found = panel.edges.find(edge);
    if (found != panel.edges.end())
      for (const int v : found->second) points_.push_back(panel.rest_positions_m[v]);
    std::sort(points_.begin(), points_.end(),
              [](const Vec2& a, const Vec2& b) { return a.y() < b.y(); });
  }
  double x_at(double y) const {
    if (points_.empty()) return 0.0;
    if (y <= points_.front().y()) return points_.front().x();
    if (y >= points_.back().y()) return points_.back().x();
    const auto upper = std::upper_bound(points_.begin(), points_.end(), y,
                                        [](double h, const Vec2& p) { return h < p.y(); });
    const Vec2& a = *(upper - 1);
    const Vec2& b = *upper;
    return a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
  }

 private:
  std::vector<Vec2> points_;
};

}  // namespace

std::vector<RingCoordinate> ring_coordinates(const Garment& garment) {
  const std::vector<int> order = ring_order(garment);
  if (order.empty()) return {};
  std::vector<SideEdge> left, right;
  for (const Panel& panel : garment.panels) {
    left.emplace_back(panel, "left");
    right.emplace_back(panel, "right");
  }
  std::vector<int> place(garment.panels.size());
  for (std::size_t k = 0; k < order.size(); ++k) place[order[k]] = static_cast<int>(k);
  std::vector<RingCoordinate> coordinates;
  for (std::size_t p = 0; p < garment.panels.size(); ++p)
    for (const Vec2& x : garment.panels[p].rest_positions_m) {
      // The row through x in every panel: its width, and the widths before this panel's.
      double before_m = 0.0, girth_m = 0.0;
      for (std::size_t k = 0; k < order.size(); ++k) {
        const double width_m = right[order[k]].x_at(x.y()) - left[order[k]].x_at(x.y());
        if (static_cast<int>(k) < place[p]) before_m += width_m;
        girth_m += width_m;
      }
      const double along_m = x.x() - left[p].x_at(x.y());
      coordinates.push_back({girth_m > 0 ? (before_m + along_m) / girth_m : 0.0, girth_m});
    }
  // A ring of one girth at every height (rectangles, side edges curved alike) keeps its layout:
  // the share is the layout x over the girth, so curved seams stay curved and the panels are
  // laid round the ring without shear.
  const auto [lowest, highest] = std::minmax_element(
      coordinates.begin(), coordinates.end(),
      [](const RingCoordinate& a, const RingCoordinate& b) { return a.girth_m < b.girth_m; });
  if (highest->girth_m - lowest->girth_m <= 1e-9 * highest->girth_m) {
    std::size_t u = 0;
    for (const Panel& panel : garment.panels)
      for (const Vec2& x : panel.rest_positions_m) {
        coordinates[u].share = (x + panel.layout_offset_m).x() / coordinates[u].girth_m;
        ++u;
      }
  }
  return coordinates;
}

}  // namespace tightfit
