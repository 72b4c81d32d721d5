// Small body meshes the contact tests write themselves: surfaces of revolution (a faceted
// cylinder or cone), a regular tetrahedron, and writers for OBJ, STL and PLY.
#pragma once

#include "bodies/polygon_mesh.h"

#include <string>
#include <vector>

namespace tightfit::testing {

// A closed surface of revolution about z: one ring of `n_round` vertices (the first at angle 0)
// per height z[k] with radius radius[k], lateral quads between rings, and a fan of triangles
// round a centre vertex closing each end; faces counter-clockwise seen from outside.
PolygonMesh revolution_surface(const std::vector<double>& z, const std::vector<double>& radius,
                               int n_round);

// A regular tetrahedron with vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1) times `scale`.
PolygonMesh regular_tetrahedron(double scale);

// A path under the test's temporary directory.
std::string temporary_path(const std::string& file_name);

void write_obj(const std::string& path, const PolygonMesh& mesh);
void write_stl(const std::string& path, const PolygonMesh& mesh);  // ASCII; quads split
void write_ply(const std::string& path, const PolygonMesh& mesh);  // ASCII
// Writes `text` as it stands (broken files).
void write_text(const std::string& path, const std::string& text);

// What load_mesh_body says when it refuses the file at `path` (its BodyMeshError), or an empty
// string when it reads the file.
std::string mesh_refusal(const std::string& path);

}  // namespace tightfit::testing
