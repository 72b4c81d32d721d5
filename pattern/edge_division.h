// Where the outline vertices go: each edge of each cut panel divided into chords of about the
// target length, the two sides of every seam into the same number, so that the meshes of the
// panels weld vertex to vertex. Corners and segment joints stay vertices.
#pragma once

#include "pattern/pattern.h"

#include <vector>

namespace tightfit::pattern {

// A seam side by indices into the cut pattern.
struct SideIndices {
  int panel = 0;
  std::vector<int> edges;  // in walking order
  bool reversed = false;
};
struct SeamIndices {
  SideIndices a, b;
};
std::vector<SeamIndices> seam_indices(const Pattern& cut_pattern);

class EdgeDivision {
 public:
  // `cut_pattern` as cut_pieces returns it, validated.
  EdgeDivision(const Pattern& cut_pattern, double edge_length_m);

  // Fractions of the edge's length (outline direction, 0 and 1 included) where vertices sit.
  const std::vector<double>& fractions(int panel, int edge) const {
    return fractions_[panel][edge];
  }
  // The panel's outline points: each edge's vertices but its last (the next edge's first).
  std::vector<Vec2> outline_points(int panel) const;
  // For outline point k: its edge and its index in that edge's fractions.
  struct OutlinePoint {
    int edge = 0, index = 0;
  };
  std::vector<OutlinePoint> outline_index(int panel) const;

  // A point the mesher added on the outline, `along` chord `index` of the edge (0 to 1):
  // recorded with the point at the same place on the seam's other side.
  void add_split(int panel, int edge, int index, double along);
  // Inserts the recorded points; false when there was none new.
  bool apply_splits();

  const std::vector<SeamIndices>& seams() const { return seams_; }
  const Pattern& pattern() const { return pattern_; }

 private:
  void divide_seam(const SeamIndices& seam, double edge_length_m);

  const Pattern& pattern_;
  std::vector<SeamIndices> seams_;
  std::vector<std::vector<double>> edge_length_m_;        // [panel][edge]
  std::vector<std::vector<std::vector<double>>> joints_;  // segment joints, fractions
  std::vector<std::vector<std::vector<double>>> fractions_;
  // A point the mesher added (or its copy): `along` chord `chord` of the edge, 0 to 1.
  struct Split {
    int panel, edge, chord;
    double along;
  };
  std::vector<Split> pending_;
};

}  // namespace tightfit::pattern
