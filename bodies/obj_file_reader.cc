#include "bodies/obj_file_reader.h"

#include "bodies/body_mesh_error.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace tightfit {
namespace {

// A number of the line ending the word, or nothing; strtod's "nan" and "inf" are refused.
bool finite_number(const std::string& word, double& value) {
  char* end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return end != word.c_str() && *end == '\0' && std::isfinite(value);
}

// The vertex index a face corner "v", "v/t", "v//n" or "v/t/n" names, from 0; every index it
// holds checked against the file's "v", "vt" and "vn" lines (`counts`).
int corner_vertex(const std::string& path, int number, const std::string& corner,
                  const long (&counts)[3]) {
  static const char* kinds[3] = {"v", "vt", "vn"};
  // "26/": VTK took the missing index after the slash for one (a null read).
  if (corner.back() == '/')
    throw body_mesh_line_error(path, number, "face corner '" + corner + "' ends with '/'");
  std::istringstream parts(corner);
  std::string part;
  long vertex = 0;
  for (int k = 0; k < 3 && std::getline(parts, part, '/'); ++k) {
    if (part.empty() && k > 0) continue;  // "1//3": no texture coordinate
    char* end = nullptr;
    const long index = std::strtol(part.c_str(), &end, 10);
    if (end == part.c_str() || *end != '\0' || index < 1 || index > counts[k])
      throw body_mesh_line_error(path, number,
                                 "face corner '" + corner + "': '" + part + "' is not one of the " +
                                     std::to_string(counts[k]) + " '" + kinds[k] +
                                     "' lines (indices count from 1; relative ones are not read)");
    if (k == 0) vertex = index - 1;
  }
  return static_cast<int>(vertex);
}

}  // namespace

PolygonMesh read_obj_file(const std::string& path) {
  // A face line and its share of the vertex lines take about 30 bytes of text.
  {
    std::ifstream sized(path, std::ios::binary | std::ios::ate);
    require_body_memory(path, static_cast<double>(sized.tellg()) / 30.0,
                        "faces (estimated from the file's size)");
  }
  std::ifstream in(path);
  PolygonMesh mesh;
  long counts[3] = {0, 0, 0};  // "v", "vt", "vn" lines
  // A face may name a vertex, texture coordinate or normal of a later line: faces are resolved
  // once the file is read.
  std::vector<std::pair<int, std::string>> faces;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "vt") ++counts[1];
    if (keyword == "vn") ++counts[2];
    if (keyword == "f") faces.emplace_back(number, line);
    if (keyword == "l")
      throw body_mesh_line_error(path, number,
                                 "a polyline ('l') besides the faces (a surface of polygons only)");
    if (keyword != "v") continue;
    ++counts[0];
    Vec3 vertex;
    std::string word;
    for (int k = 0; k < 3; ++k) {
      if (!(words >> word))
        throw body_mesh_line_error(path, number,
                                   "a vertex needs three coordinates: '" + line + "'");
      double value = 0;
      if (!finite_number(word, value))
        throw body_mesh_line_error(path, number,
                                   "'" + word + "' is not a finite number: '" + line + "'");
      // VTK's reader kept coordinates in single precision: read as it did.
      vertex[k] = static_cast<double>(static_cast<float>(value));
    }
    mesh.vertices.push_back(vertex);
  }
  mesh.faces.reserve(faces.size());
  for (const auto& [number, text] : faces) {
    std::istringstream words(text);
    std::string corner;
    words >> corner;  // "f"
    std::vector<int> face;
    while (words >> corner) face.push_back(corner_vertex(path, number, corner, counts));
    if (face.size() < 3 || face.size() > 4)
      throw body_mesh_line_error(path, number,
                                 "face " + std::to_string(mesh.faces.size()) + " has " +
                                     std::to_string(face.size()) +
                                     " vertices (triangles and quads only)");
    mesh.faces.push_back(std::move(face));
  }
  return mesh;
}

}  // namespace tightfit
