// A body surface as a file gives it: vertices and polygons (triangles and quads), before any
// unit, axis or placement is applied.
#pragma once

#include "core/types.h"

#include <string>
#include <vector>

namespace tightfit {

struct PolygonMesh {
  std::vector<Vec3> vertices;           // file units
  std::vector<std::vector<int>> faces;  // vertex indices from 0, in the file's order
};

// Reads an OBJ, STL or PLY file by its extension, any case (OBJ, PLY: bodies/*_file_reader.h).
// Throws BodyMeshError naming the file and what is wrong: a missing or unreadable file, an
// unknown extension, a reader's error (truncated or malformed numbers), no faces, a vertex
// index out of range, a face with fewer than 3 or more than 4 vertices, a coordinate that is
// not finite.
PolygonMesh read_polygon_mesh(const std::string& path);

}  // namespace tightfit
