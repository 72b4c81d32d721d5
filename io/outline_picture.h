// A drawing of a garment's panels laid out flat (`tightfit pattern`'s outlines.png,
// docs/patterns.md): each panel's outline in grey with its name at its middle, each seam's two
// edges in the seam's colour, one label per sewn edge listing the numbers of the seams on it
// (two seams on one edge, as a mirrored fold's, share a label instead of overlapping), and a
// 100 mm scale bar. Drawn by RasterCanvas, as the pressure pictures are.
#pragma once

#include "core/types.h"

#include <string>
#include <vector>

namespace tightfit {

struct OutlineDrawing {
  struct Panel {
    std::string name;
    std::vector<std::vector<Vec2>> edges_m;  // its boundary, as polylines in the layout plane
  };
  struct SeamEdge {
    int seam = 1;      // the seam's number, from 1
    int panel = 0;     // which panel the edge is on
    std::string edge;  // the edge's name on that panel: seams on one edge share a label
    std::vector<Vec2> points_m;
  };
  std::vector<Panel> panels;
  std::vector<SeamEdge> seam_edges;
  std::string title;
};

// A seam label's text and where its baseline's centre is, in pixels (y downwards).
struct PlacedLabel {
  std::string text;
  int x = 0, y = 0;
};

// The labels with none drawn twice or over another: a label whose text is already drawn less
// than two font heights away is left out (a dart's two legs carry the same seam number, and a
// narrow dart sets both labels side by side); one that would overlap a different label is moved
// down a line until it does not. Widths are estimated as 0.6 font heights a character.
std::vector<PlacedLabel> labels_without_overlap(const std::vector<PlacedLabel>& labels,
                                                int font_px);

// The colour seam `number` (from 1) is drawn in.
Vec3 seam_colour(int number);

// Throws std::runtime_error naming `path` when it cannot be written.
void write_outline_picture(const std::string& path, const OutlineDrawing& drawing, int width = 1200,
                           int height = 900);

}  // namespace tightfit
