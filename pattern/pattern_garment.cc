#include "pattern/pattern_garment.h"

#include "core/memory_budget.h"
#include "core/tube_garment.h"
#include "pattern/edge_division.h"
#include "pattern/polygon_mesher.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace tightfit::pattern {

namespace {

// A panel that is a rectangle with its sides along its grain: its size in grain axes, and
// which side of the grid (0 bottom, 1 right, 2 top, 3 left) each outline edge is.
struct GridRectangle {
  double width_m = 0, height_m = 0;
  std::array<int, 4> side_of_edge{};
};

std::optional<GridRectangle> as_grid_rectangle(const PanelOutline& panel) {
  if (panel.edges.size() != 4) return std::nullopt;
  const Eigen::Rotation2Dd to_grain(-panel.grain_angle_rad);
  GridRectangle r;
  const std::array<Vec2, 4> directions{Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0), Vec2(0, -1)};
  for (int e = 0; e < 4; ++e) {
    const auto& segments = panel.edges[e].segments;
    if (segments.size() != 1 || segments[0].kind != Segment::Kind::line) return std::nullopt;
    const Vec2 d = to_grain * (segments[0].end - segments[0].start);
    int side = -1;
    for (int s = 0; s < 4; ++s)
      if ((d.normalized() - directions[s]).norm() < 1e-9) side = s;
    if (side < 0) return std::nullopt;
    r.side_of_edge[e] = side;
    (side % 2 == 0 ? r.width_m : r.height_m) = d.norm();
  }
  for (int e = 0; e < 4; ++e)
    if (r.side_of_edge[(e + 1) % 4] != (r.side_of_edge[e] + 1) % 4) return std::nullopt;
  return r;
}

int grid_vertices(const GridRectangle& r, int edge, const MeshSpacing& spacing) {
  const bool along_x = r.side_of_edge[edge] % 2 == 0;
  const double length = along_x ? r.width_m : r.height_m;
  const double step = along_x ? spacing.along_x_m : spacing.along_y_m;
  return std::max(1, static_cast<int>(std::lround(length / step))) + 1;
}

// Rectangles kept as grids: every seam of theirs joins single edges of grid rectangles with
// equal vertex counts (else both panels go to the Delaunay mesher, until nothing changes).
std::vector<std::optional<GridRectangle>> grid_panels(const Pattern& cut,
                                                      const std::vector<SeamIndices>& seams,
                                                      const std::optional<MeshSpacing>& spacing) {
  std::vector<std::optional<GridRectangle>> grids(cut.panels.size());
  if (!spacing) return grids;
  for (std::size_t p = 0; p < cut.panels.size(); ++p) grids[p] = as_grid_rectangle(cut.panels[p]);
  for (bool changed = true; changed;) {
    changed = false;
    for (const SeamIndices& s : seams) {
      const auto& ga = grids[s.a.panel];
      const auto& gb = grids[s.b.panel];
      if (!ga && !gb) continue;
      const bool fits =
          ga && gb && s.a.edges.size() == 1 && s.b.edges.size() == 1 &&
          grid_vertices(*ga, s.a.edges[0], *spacing) == grid_vertices(*gb, s.b.edges[0], *spacing);
      if (fits) continue;
      grids[s.a.panel].reset();
      grids[s.b.panel].reset();
      changed = true;
    }
  }
  return grids;
}

Panel grid_panel(const PanelOutline& outline, const GridRectangle& r, const MeshSpacing& spacing) {
  Panel panel = make_rectangle_panel(outline.name, r.width_m, r.height_m, spacing);
  // make_rectangle_panel lists every side left to right or bottom to top; the outline walks
  // top and left backwards.
  const std::array<const char*, 4> side_name{"bottom", "right", "top", "left"};
  std::map<std::string, std::vector<int>> edges;
  for (int e = 0; e < 4; ++e) {
    std::vector<int> vertices = panel.edges.at(side_name[r.side_of_edge[e]]);
    if (r.side_of_edge[e] >= 2) std::reverse(vertices.begin(), vertices.end());
    edges[outline.edges[e].name] = vertices;
  }
  panel.edges = edges;
  if (outline.grain_angle_rad != 0.0) {
    const Eigen::Rotation2Dd to_pattern(outline.grain_angle_rad);
    for (Vec2& x : panel.rest_positions_m) x = to_pattern * x;
  }
  panel.grain_angle_rad = outline.grain_angle_rad;
  return panel;
}

Panel delaunay_panel(const PanelOutline& outline, const EdgeDivision& division, int p,
                     const PolygonMesh& mesh) {
  Panel panel;
  panel.name = outline.name;
  panel.grain_angle_rad = outline.grain_angle_rad;
  panel.rest_positions_m = mesh.points_m;
  panel.triangles = mesh.triangles;
  int first = 0;
  const int n_outline = static_cast<int>(division.outline_points(p).size());
  for (std::size_t e = 0; e < outline.edges.size(); ++e) {
    const int n = static_cast<int>(division.fractions(p, static_cast<int>(e)).size());
    auto& vertices = panel.edges[outline.edges[e].name];
    for (int k = 0; k < n; ++k) vertices.push_back((first + k) % n_outline);
    first += n - 1;
  }
  return panel;
}

// Meshes every panel that is not a grid, adding on the other side of a seam each point the
// mesher adds on one, until no mesh adds any.
std::vector<PolygonMesh> conforming_meshes(EdgeDivision& division,
                                           const std::vector<std::optional<GridRectangle>>& grids,
                                           const PatternMeshOptions& options) {
  const int n_panels = static_cast<int>(grids.size());
  std::vector<PolygonMesh> meshes(n_panels);
  // Each panel's budget from its outline before any round added points to it: a spike
  // narrower than the edge length makes every round add a few hundred more.
  std::vector<double> budget(n_panels);
  for (int p = 0; p < n_panels; ++p)
    budget[p] = mesh_vertex_budget(division.outline_points(p), options.edge_length_m);
  for (int round = 0; round < 16; ++round) {
    for (int p = 0; p < n_panels; ++p) {
      if (grids[p]) continue;
      try {
        meshes[p] = mesh_polygon(division.outline_points(p), options.edge_length_m,
                                 options.min_angle_deg, budget[p]);
      } catch (const std::invalid_argument& error) {
        throw PatternError("panel '" + division.pattern().panels[p].name + "': " + error.what());
      }
      const auto index = division.outline_index(p);
      for (const auto& added : meshes[p].added_on_outline)
        division.add_split(p, index[added.chord].edge, index[added.chord].index, added.along);
    }
    if (!division.apply_splits()) return meshes;
  }
  throw PatternError("pattern '" + division.pattern().name +
                     "': the seams' vertices did not settle after 16 meshing rounds");
}

// Negative ease: pattern coordinates scaled along the panel's weft and warp.
Mat2 ease_map(const Panel& panel, double weft, double warp) {
  const Eigen::Rotation2Dd to_grain(-panel.grain_angle_rad);
  const Mat2 R = to_grain.toRotationMatrix();
  return R.transpose() * Vec2(weft, warp).asDiagonal() * R;
}

void apply_ease(Panel& panel, double weft, double warp) {
  if (weft == 1.0 && warp == 1.0) return;
  const Mat2 map = ease_map(panel, weft, warp);
  for (Vec2& x : panel.rest_positions_m) x = map * x;
}

Vec2 box_centre(const std::vector<Vec2>& points) {
  Vec2 low = points.front(), high = low;
  for (const Vec2& x : points) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  return 0.5 * (low + high);
}

// The file's 3D placement of the panel's outline (GarmentCode: p = R (x, y, 0) + t, R from the
// XYZ Euler angles as Rz Ry Rx, Maya's convention, which GarmentCode's own reader uses) carried
// to the panel's rest coordinates after the ease: the rest mesh lies where the outline does
// up to a shift (a grid panel starts at its corner), read off the two boxes' centres, and the
// eased panel keeps its centre where the outline's was.
Panel::Arrangement arrangement(const PanelOutline& outline, const Vec2& rest_centre_before_ease,
                               const Mat2& ease) {
  const PanelPlacement3D& placement = *outline.placement;
  const Vec3 a = placement.rotation_xyz_deg * (M_PI / 180.0);
  const Mat3 R = (Eigen::AngleAxisd(a.z(), Vec3::UnitZ()) *
                  Eigen::AngleAxisd(a.y(), Vec3::UnitY()) * Eigen::AngleAxisd(a.x(), Vec3::UnitX()))
                     .toRotationMatrix();
  const Mat3 mirror = Vec3(placement.outline_mirrored ? -1.0 : 1.0, 1.0, 1.0).asDiagonal();
  std::vector<Vec2> outline_points;
  for (const Edge& edge : outline.edges)
    for (const Segment& segment : edge.segments)
      for (int k = 0; k < 16; ++k) outline_points.push_back(point_at(segment, k / 16.0));
  const Vec2 shift = box_centre(outline_points) - ease * rest_centre_before_ease;
  Panel::Arrangement placed;
  placed.rotation = R * mirror;
  placed.translation_m = placement.translation_m + placed.rotation * Vec3(shift.x(), shift.y(), 0);
  return placed;
}

// A seam side as a named vertex list of its panel, and whether the walk runs against it.
std::pair<std::string, bool> seam_edge(Garment& garment, const Pattern& cut,
                                       const SideIndices& side, const std::string& group) {
  Panel& panel = garment.panels[side.panel];
  const auto& outline = cut.panels[side.panel];
  if (side.edges.size() == 1) return {outline.edges[side.edges[0]].name, side.reversed};
  std::vector<int> walk;
  for (int e : side.edges) {
    std::vector<int> vertices = panel.edges.at(outline.edges[e].name);
    if (side.reversed) std::reverse(vertices.begin(), vertices.end());
    walk.insert(walk.end(), vertices.begin() + (walk.empty() ? 0 : 1), vertices.end());
  }
  panel.edges[group] = walk;
  return {group, false};
}

// The vertex of panel_b a seam's first vertex of panel_a meets.
std::pair<int, int> first_stitch(const Garment& garment, const Seam& seam) {
  const auto& a = garment.panels[seam.panel_a].edges.at(seam.edge_a);
  const auto& b = garment.panels[seam.panel_b].edges.at(seam.edge_b);
  return {a.front(), seam.reversed ? b.back() : b.front()};
}

void lay_out(Garment& garment) {
  const int n = static_cast<int>(garment.panels.size());
  if (ring_circumference_m(garment) > 0) {
    // Round the ring, each panel's left edge on the previous one's right edge.
    std::map<int, const Seam*> next;
    for (const Seam& seam : garment.seams) next[seam.panel_a] = &seam;
    int p = 0;
    for (int k = 0; k + 1 < n; ++k) {
      const Seam& seam = *next.at(p);
      const auto [va, vb] = first_stitch(garment, seam);
      garment.panels[seam.panel_b].layout_offset_m =
          garment.panels[p].layout_offset_m + garment.panels[p].rest_positions_m[va] -
          garment.panels[seam.panel_b].rest_positions_m[vb];
      p = seam.panel_b;
    }
    return;
  }
  double cursor = 0.0;
  for (Panel& panel : garment.panels) {
    Vec2 low = panel.rest_positions_m.front(), high = low;
    for (const Vec2& x : panel.rest_positions_m) {
      low = low.cwiseMin(x);
      high = high.cwiseMax(x);
    }
    panel.layout_offset_m = Vec2(cursor - low.x(), -low.y());
    cursor += high.x() - low.x() + 0.1 * std::max(high.x() - low.x(), high.y() - low.y());
  }
}

// Refuses, before any outline is divided, a pattern whose mesh at `edge_length_m` would not fit
// in memory: each panel's outline polygon (16 points a segment) gives its area A and perimeter
// L, and a mesh of near-equilateral triangles of side h holds about 2 A / (sqrt(3) h^2) + L / h
// vertices.
void require_mesh_fits(const Pattern& cut, double edge_length_m) {
  const double h = edge_length_m;
  double n_vertices = 0.0;
  for (const PanelOutline& panel : cut.panels) {
    std::vector<Vec2> polygon;
    for (const Edge& edge : panel.edges)
      for (const Segment& segment : edge.segments)
        for (int k = 0; k < 16; ++k) polygon.push_back(point_at(segment, k / 16.0));
    double twice_area = 0.0, perimeter = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Vec2& a = polygon[i];
      const Vec2& b = polygon[(i + 1) % polygon.size()];
      twice_area += a.x() * b.y() - b.x() * a.y();
      perimeter += (b - a).norm();
    }
    n_vertices += std::abs(twice_area) / (std::sqrt(3.0) * h * h) + perimeter / h;
  }
  require_memory(
      "pattern '" + cut.name + "' meshed at edge length " + std::to_string(h) + " m: a run",
      n_vertices, "vertices", run_bytes_per_garment_vertex);
}

}  // namespace

Garment pattern_garment(const Pattern& pattern, const PatternMeshOptions& options) {
  if (!(options.edge_length_m > 0)) throw PatternError("the mesh edge length must be positive (m)");
  validate(pattern);
  const Pattern cut = cut_pieces(pattern);
  require_mesh_fits(cut, options.edge_length_m);
  EdgeDivision division(cut, options.edge_length_m);
  const auto grids = grid_panels(cut, division.seams(), options.rectangle_grid);
  const std::vector<PolygonMesh> meshes = conforming_meshes(division, grids, options);

  Garment garment;
  garment.name = pattern.name;
  for (std::size_t p = 0; p < cut.panels.size(); ++p) {
    Panel panel = grids[p]
                      ? grid_panel(cut.panels[p], *grids[p], *options.rectangle_grid)
                      : delaunay_panel(cut.panels[p], division, static_cast<int>(p), meshes[p]);
    const Vec2 rest_centre = box_centre(panel.rest_positions_m);
    apply_ease(panel, pattern.ease_weft, pattern.ease_warp);
    if (cut.panels[p].placement)
      panel.arrangement = arrangement(cut.panels[p], rest_centre,
                                      ease_map(panel, pattern.ease_weft, pattern.ease_warp));
    garment.panels.push_back(std::move(panel));
  }
  for (std::size_t k = 0; k < division.seams().size(); ++k) {
    const SeamIndices& s = division.seams()[k];
    const std::string group = "seam " + std::to_string(k + 1);
    const auto [edge_a, against_a] = seam_edge(garment, cut, s.a, group + " a");
    const auto [edge_b, against_b] = seam_edge(garment, cut, s.b, group + " b");
    garment.seams.push_back({s.a.panel, edge_a, s.b.panel, edge_b, against_a != against_b});
  }
  lay_out(garment);
  return garment;
}

std::vector<SeamLengths> seam_lengths(const Pattern& cut) {
  std::vector<SeamLengths> lengths;
  auto describe = [](const EdgeRange& r) {
    std::string text = r.panel + ":";
    for (std::size_t k = 0; k < r.edges.size(); ++k) text += (k ? "+" : "") + r.edges[k];
    return text + (r.reversed ? " (reversed)" : "");
  };
  for (const SeamSpec& s : cut.seams)
    lengths.push_back({describe(s.a) + " -- " + describe(s.b),
                       length_m(range_segments(find_panel(cut, s.a.panel), s.a)),
                       length_m(range_segments(find_panel(cut, s.b.panel), s.b))});
  return lengths;
}

}  // namespace tightfit::pattern
