// Body files by their extension, each read once by tightfit's own reader, which checks each
// line or value as it reads it (bodies/obj_file_reader.h, ply_file_reader.h, stl_file_reader.h).
// What was read is checked the same way whatever the reader.
#include "bodies/body_mesh_error.h"
#include "bodies/obj_file_reader.h"
#include "bodies/ply_file_reader.h"
#include "bodies/polygon_mesh.h"
#include "bodies/stl_file_reader.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>
#include <vector>

namespace tightfit {
namespace {

std::string lower_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// What any reader read: finite coordinates, triangles and quads naming vertices of the file,
// at least one face.
void check_what_was_read(const PolygonMesh& mesh, const std::string& path) {
  const std::size_t n_points = mesh.vertices.size();
  for (std::size_t i = 0; i < n_points; ++i)
    if (!mesh.vertices[i].allFinite())
      throw BodyMeshError("body mesh '" + path + "': vertex " + std::to_string(i) +
                          " has a coordinate that is not a finite number");
  for (std::size_t face = 0; face < mesh.faces.size(); ++face) {
    const std::vector<int>& vertices = mesh.faces[face];
    if (vertices.size() < 3 || vertices.size() > 4)
      throw BodyMeshError("body mesh '" + path + "': face " + std::to_string(face) + " has " +
                          std::to_string(vertices.size()) + " vertices (triangles and quads only)");
    for (const int v : vertices)
      if (v < 0 || static_cast<std::size_t>(v) >= n_points)
        throw BodyMeshError("body mesh '" + path + "': face " + std::to_string(face) +
                            " names vertex " + std::to_string(v) + " (counted from 0) of " +
                            std::to_string(n_points));
  }
  if (mesh.faces.empty())
    throw BodyMeshError("body mesh '" + path +
                        "': no faces (an empty, truncated or unreadable file)");
}

}  // namespace

PolygonMesh read_polygon_mesh(const std::string& path) {
  if (!std::ifstream(path)) throw BodyMeshError("body mesh '" + path + "': cannot open the file");
  const std::string ext = lower_extension(path);
  PolygonMesh mesh;
  if (ext == "obj")
    mesh = read_obj_file(path);
  else if (ext == "ply")
    mesh = read_ply_file(path);
  else if (ext == "stl")
    mesh = read_stl_file(path);
  else
    throw BodyMeshError("body mesh '" + path + "': unknown file type '." + ext +
                        "' (expected .obj, .stl or .ply)");
  check_what_was_read(mesh, path);
  return mesh;
}

}  // namespace tightfit
