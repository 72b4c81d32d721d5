// The garment before sewing: every panel vertex its own particle, each seam vertex pair
// (the panel vertices that weld to one vertex) still apart. The paper's start (Section 4.3)
// simulates this and lets seam springs close the seams.
#pragma once

#include "core/garment.h"

#include <utility>
#include <vector>

namespace tightfit {

struct UnweldedPanels {
  // Vertices are the welded mesh's panel ("unwelded") vertices, same numbering; the
  // triangles, rest triangles and panels are the welded mesh's, so the membrane and bending
  // elements built on it see the same fabric, only with open seams.
  SimulationMesh mesh;
  // Every pair of panel vertices that weld to the same vertex, each pair once.
  std::vector<std::pair<int, int>> seam_pairs;
};

// Throws std::invalid_argument when a triangle's corners cannot be found among its panel's
// vertices (an inconsistent mesh).
UnweldedPanels unweld(const SimulationMesh& welded);

// Welded positions from unwelded ones: each welded vertex at the mean of its copies, m.
std::vector<Vec3> weld_positions(const SimulationMesh& welded,
                                 const std::vector<Vec3>& unwelded_positions_m);

}  // namespace tightfit
