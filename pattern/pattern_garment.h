// A pattern cut, meshed and sewn: the project's Garment (core/garment.h), ready for either
// backend. Every seam's two sides get the same number of vertices (the longer side's extra
// length spread evenly along it) before the panels are meshed, so the welded mesh conforms.
#pragma once

#include "core/garment.h"
#include "core/rectangle_panel.h"
#include "pattern/pattern.h"

#include <optional>

namespace tightfit::pattern {

struct PatternMeshOptions {
  double edge_length_m = 0.01;  // target length of triangle edges and outline chords
  double min_angle_deg = 25.0;  // no triangle angle below this (at most 33)
  // When set, a panel that is a rectangle with its sides along its grain, all of whose seams
  // join rectangles with as many vertices, is meshed as the tube's regular grid
  // (core/rectangle_panel.h) with this spacing instead of by the Delaunay mesher.
  std::optional<MeshSpacing> rectangle_grid;
};

// Cuts (cut_pieces), meshes and scales (ease) the pattern. Panels keep their edge names as
// vertex groups; a seam side of more than one edge adds the group "seam K a" / "seam K b".
// Panels sewn round a ring of right-to-left seams are laid edge to edge in the layout plane
// (as make_tube_garment does), others side by side. Throws PatternError for a broken pattern
// and when a seam cannot be made conforming.
Garment pattern_garment(const Pattern& pattern, const PatternMeshOptions& options);

// The lengths of each seam's two sides, metres (pattern, before ease).
struct SeamLengths {
  std::string description;  // "front:side -- back:side"
  double a_m = 0.0, b_m = 0.0;
};
std::vector<SeamLengths> seam_lengths(const Pattern& cut_pattern);

}  // namespace tightfit::pattern
