// Garments in pattern space.
//
// A garment is cut from flat panels. Each panel vertex has rest coordinates X in the panel's
// own plane (metres, x along the weft, y along the warp), and seams identify vertices of
// different panels (or two edges of one panel). Both backends simulate the welded
// SimulationMesh built from it; the FE backend also reads the panels' layout in one plane.
#pragma once

#include "core/types.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tightfit {

struct Panel {
  std::string name;
  // Rest coordinates in the panel's plane, metres.
  std::vector<Vec2> rest_positions_m;
  // Angle from the panel's x axis to the weft (course) direction, radians: 0 puts the weft
  // along x and the warp along y. The material law sees coordinates in these grain axes.
  double grain_angle_rad = 0.0;
  // Counter-clockwise in the panel plane.
  std::vector<Triangle> triangles;
  // Named boundary edges ("left", "right", "bottom", "top" for a rectangle), each an
  // ordered list of panel vertex indices; seams and end conditions refer to them.
  std::map<std::string, std::vector<int>> edges;
  // Where the panel lies in the common 2D layout plane (the FE reference domain), metres:
  // layout position = rest position + offset.
  Vec2 layout_offset_m = Vec2::Zero();
  // Where the panel lies in 3D as its pattern file arranges it round the file's own body
  // (GarmentCode's panels; docs/arrangement.md "Arrangement from the pattern file"): the rest
  // position (x, y) goes to rotation (x, y, 0) + translation, in the file's frame (its up axis,
  // metres). Absent when the file does not say.
  struct Arrangement {
    Mat3 rotation = Mat3::Identity();
    Vec3 translation_m = Vec3::Zero();
  };
  std::optional<Arrangement> arrangement;
};

// Sews edge `edge_a` of panel `panel_a` to edge `edge_b` of panel `panel_b`, vertex by vertex
// in the order the edges list them, or with edge_b's list walked backwards when `reversed`
// (the edges must have equal vertex counts).
struct Seam {
  int panel_a = 0;
  std::string edge_a;
  int panel_b = 0;
  std::string edge_b;
  bool reversed = false;
};

struct Garment {
  std::string name;
  std::vector<Panel> panels;
  std::vector<Seam> seams;
  // One line for the case header: what the garment is cut from and how it is sewn.
  std::string description;
};

// The garment with its seams closed: every seam vertex pair is one vertex.
struct SimulationMesh {
  int n_vertices = 0;
  std::vector<Triangle> triangles;  // welded vertex indices
  // Rest coordinates of each triangle's three corners in its panel's grain axes (x weft,
  // y warp), metres.
  std::vector<std::array<Vec2, 3>> rest_triangles;
  std::vector<int> triangle_panel;
  // Panel vertices ("unwelded") are numbered panel by panel from panel_vertex_offset[p].
  std::vector<int> panel_vertex_offset;
  std::vector<int> welded_index;         // unwelded index -> welded index
  std::vector<Vec2> layout_positions_m;  // unwelded index -> position in the layout plane
  // Welded vertex groups by panel edge name ("bottom", "top", ...): the union over panels of
  // the edge's vertices, sorted and unique.
  std::map<std::string, std::vector<int>> vertex_groups;

  int n_unwelded_vertices() const { return static_cast<int>(welded_index.size()); }
};

// Closes every seam. Throws std::invalid_argument when a seam names an unknown panel or edge
// or joins edges of different vertex counts.
SimulationMesh weld(const Garment& garment);

// Rest area of one triangle from its rest corners, of every triangle, m^2, and their sum.
double rest_triangle_area(const std::array<Vec2, 3>& rest_m);
std::vector<double> rest_triangle_areas(const SimulationMesh& mesh);
double rest_area(const SimulationMesh& mesh);

// Barycentric rest area of every welded vertex, m^2: a third of each adjacent triangle's rest
// area, so the areas sum to the garment's rest area.
std::vector<double> rest_vertex_areas_m2(const SimulationMesh& mesh);

// Mean length of the mesh's rest edges (each edge counted once), m: the length scale of stop
// rules and of the penalty stiffness.
double mean_rest_edge_length_m(const SimulationMesh& mesh);

}  // namespace tightfit
