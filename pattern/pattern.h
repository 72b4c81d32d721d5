// One model of a sewing pattern, whatever file it was read from (docs/patterns.md): panels
// as closed outlines of named edges between corners, each edge a chain of line, Bezier and
// arc segments; grain per panel; pieces cut on the fold or cut twice mirrored; seams as
// pairs of edge ranges with the ends that meet; negative ease per grain direction.
// Pattern coordinates are metres.
#pragma once

#include "pattern/segment.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace tightfit::pattern {

// A broken pattern: the message names the file element and why.
class PatternError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// An edge of an outline, from one corner to the next, counter-clockwise round the panel.
struct Edge {
  std::string name;
  std::vector<Segment> segments;  // end to start, each starting where the one before ends
};

// Where a panel sits on the body in 3D, when the file says (GarmentCode's panels do).
struct PanelPlacement3D {
  Vec3 translation_m = Vec3::Zero();
  Vec3 rotation_xyz_deg = Vec3::Zero();  // Euler angles about x, then y, then z
  // The file's outline ran clockwise and was mirrored (x -> -x) to run counter-clockwise: the
  // placement applies to the file's own x.
  bool outline_mirrored = false;
};

struct PanelOutline {
  std::string name;
  std::vector<Edge> edges;  // a closed loop: edge k ends where edge k + 1 starts
  // Angle from the pattern's x axis to the weft (course) direction, radians.
  double grain_angle_rad = 0.0;
  // Cut on the fold: the edge (straight) the piece is mirrored across to make the whole panel;
  // empty when the piece is cut flat.
  std::string fold_edge;
  // Cut twice, the second piece mirrored (a left and a right): the copy is a panel of its
  // own named `name + " mirrored"`, its edges named as the original's.
  bool mirrored_copy = false;
  std::vector<Vec2> notches_m;  // marks on the outline, kept for drawing
  std::optional<PanelPlacement3D> placement;
};

// Consecutive edges of one panel, walked along the outline (or against it when reversed).
struct EdgeRange {
  std::string panel;
  std::vector<std::string> edges;  // in the order walked
  bool reversed = false;           // walked clockwise, each edge from its end to its start
};

// Two edge ranges sewn together: the start of `a` meets the start of `b`, the end the end.
// When one side is longer (ease), its extra length is spread evenly along the seam.
struct SeamSpec {
  EdgeRange a, b;
};

// What a file alone may leave open: which size of a graded file, and the unit of a file that
// does not say (AAMA DXF without $INSUNITS).
struct PatternFileOptions {
  std::string size;   // empty: the file must hold one size
  std::string units;  // empty (the file's, else mm checked for plausibility), mm, cm or inch
};

struct Pattern {
  std::string name;
  std::vector<PanelOutline> panels;
  std::vector<SeamSpec> seams;
  // Negative ease: the pattern is scaled by these factors along the weft and the warp before
  // it is sewn (0.9 cuts the garment 10 % smaller than the outline round the body).
  double ease_weft = 1.0;
  double ease_warp = 1.0;
};

// Checks that every outline is closed (to `closure_tolerance_m`), every edge has a name and a
// positive length, names are unique and fold edges straight; then that every seam names
// existing, consecutive edges of the cut pieces (cut_pieces) used by no other seam.
// Throws PatternError naming the element.
void validate(const Pattern& pattern, double closure_tolerance_m = 1e-6);

// The pieces as cut from the fabric: a piece cut on the fold unfolded into the whole panel
// (the edges that meet the fold joined to their mirror images and keeping their names, the
// other mirrored edges named `edge + " mirrored"`), and the mirrored copy of a piece cut twice
// added after it. Seams and ease are kept; seams name the cut pieces' edges.
Pattern cut_pieces(const Pattern& pattern);

// The segments of edge range `range` in walking order (reversed when the range is).
std::vector<Segment> range_segments(const PanelOutline& panel, const EdgeRange& range);

const PanelOutline& find_panel(const Pattern& pattern, const std::string& name);
// The panels' names, and "; did you mean 'front'?" (the closest of them) for a name not among
// them, to end the message that refuses it.
std::vector<std::string> panel_names(const Pattern& pattern);
std::string closest_panels(const Pattern& pattern, const std::string& unknown);
int find_edge(const PanelOutline& panel, const std::string& name);  // -1 when absent

// Length of an edge (or a chain of segments), metres.
double length_m(const std::vector<Segment>& segments);

}  // namespace tightfit::pattern
