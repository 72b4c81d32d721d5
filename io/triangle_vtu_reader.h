// A triangle mesh read back from a VTU file, such as the garment_NNNN.vtu a run writes: the
// start of a case from the state another run reached (Placement/Kind = from file,
// docs/cases.md "Starting from a previous run").
#pragma once

#include "core/types.h"

#include <string>
#include <vector>

namespace tightfit {

struct TriangleGrid {
  std::vector<Vec3> points_m;
  std::vector<Triangle> triangles;
};

// Reads an unstructured grid of triangles with VTK's XML reader. Throws std::runtime_error
// naming the file and what is wrong: missing or unreadable, not a VTU unstructured grid, the
// reader's own error, a cell that is not a triangle, a coordinate that is not finite.
TriangleGrid read_triangle_vtu(const std::string& path);

}  // namespace tightfit
