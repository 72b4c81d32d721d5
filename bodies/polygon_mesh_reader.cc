// VTK's readers for OBJ, STL and PLY; VTK stays inside this file.
#include "bodies/body_mesh_error.h"
#include "bodies/ply_file_check.h"
#include "bodies/polygon_mesh.h"
#include "io/vtk_reader_run.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
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

vtkSmartPointer<vtkPolyDataAlgorithm> reader_for(const std::string& path, const std::string& ext) {
  if (ext == "obj") {
    auto r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(path.c_str());
    return r;
  }
  if (ext == "stl") {
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(path.c_str());
    r->MergingOn();  // STL repeats each vertex in every facet: weld them into a connected surface
    return r;
  }
  if (ext == "ply") {
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(path.c_str());
    return r;
  }
  throw BodyMeshError("body mesh '" + path + "': unknown file type '." + ext +
                      "' (expected .obj, .stl or .ply)");
}

// VTK's OBJ reader takes "v 1 x 0" or "v 0 0" without a word (it reads what it can): every
// vertex line must hold three numbers. It also follows a face's texture and normal indices
// ("f 1/2/3 ...") without checking them: one past the file's "vt" lines is a null pointer
// read (found by fuzz_body_mesh_obj), so every index of a face must name a line the file has.
void check_obj_lines(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::map<std::string, long> count;  // "v", "vt", "vn" lines
  std::vector<std::pair<int, std::string>> faces;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "v" || keyword == "vt" || keyword == "vn") ++count[keyword];
    if (keyword == "f") faces.emplace_back(number, line);
    if (keyword != "v") continue;
    std::string word;
    for (int k = 0; k < 3; ++k) {
      if (!(words >> word))
        throw body_mesh_line_error(path, number,
                                   "a vertex needs three coordinates: '" + line + "'");
      // VTK's OBJ reader takes "nan" and "inf" for 0 (a silent wrong vertex): refused here.
      char* end = nullptr;
      const double value = std::strtod(word.c_str(), &end);
      if (end == word.c_str() || *end != '\0' || !std::isfinite(value))
        throw body_mesh_line_error(path, number,
                                   "'" + word + "' is not a finite number: '" + line + "'");
    }
  }
  const char* kinds[3] = {"v", "vt", "vn"};
  for (const auto& [number, face] : faces) {
    std::istringstream words(face.substr(1));
    for (std::string corner; words >> corner;) {
      // "26/": VTK takes the missing index after the slash for one (a null read).
      if (corner.back() == '/')
        throw body_mesh_line_error(path, number, "face corner '" + corner + "' ends with '/'");
      std::istringstream parts(corner);
      std::string part;
      for (int k = 0; k < 3 && std::getline(parts, part, '/'); ++k) {
        if (part.empty() && k > 0) continue;  // "1//3": no texture coordinate
        char* end = nullptr;
        const long index = std::strtol(part.c_str(), &end, 10);
        if (end == part.c_str() || *end != '\0' || index < 1 || index > count[kinds[k]])
          throw body_mesh_line_error(
              path, number,
              "face corner '" + corner + "': '" + part + "' is not one of the " +
                  std::to_string(count[kinds[k]]) + " '" + kinds[k] +
                  "' lines (indices count from 1; relative ones are not read)");
      }
    }
  }
}

// A binary STL is an 80-byte header, a facet count n and 50 bytes per facet. VTK's reader
// allocates for the larger of n and what the file can hold before reading a facet, so a count
// the file cannot hold (a bogus or hostile header) would allocate without bound: refused
// here, for any file that is not plain text (VTK may take such a file for binary even when
// its header starts with "solid", as many exporters write). Plain text is an ASCII STL, which
// VTK reads as it goes. Either way the file's size bounds the facets.
void check_stl_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const bool text = std::all_of(bytes.begin(), bytes.end(), [](unsigned char c) {
    // Not a form feed: VTK reads a file with one as binary (found by fuzz_body_mesh_stl: a
    // text file announcing 168 million facets in bytes 80 to 83, 6 GB allocated).
    return c == '\t' || c == '\n' || c == '\r' || (c >= 32 && c < 127);
  });
  if (text) {
    // An ASCII facet takes at least about 100 bytes ("facet normal", a loop of 3 vertices).
    require_body_memory(path, bytes.size() / 100.0, "facets (ASCII STL)");
    return;
  }
  if (bytes.size() < 84)
    throw BodyMeshError("body mesh '" + path + "': a binary STL of " +
                        std::to_string(bytes.size()) +
                        " bytes, shorter than its 84-byte header and facet count");
  const auto byte = [&](int k) {
    return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[k]));
  };
  const std::uint32_t count = byte(80) | byte(81) << 8 | byte(82) << 16 | byte(83) << 24;
  const double needed = 84.0 + 50.0 * count;
  if (needed > static_cast<double>(bytes.size()))
    throw BodyMeshError("body mesh '" + path + "': truncated binary STL: the header announces " +
                        std::to_string(count) + " facets, " +
                        std::to_string(static_cast<long long>(needed)) + " bytes, the file has " +
                        std::to_string(bytes.size()));
  require_body_memory(path, (bytes.size() - 84) / 50.0, "facets");
}

// OBJ: a face line and its share of the vertex lines take about 30 bytes of text.
void check_obj_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  require_body_memory(path, static_cast<double>(in.tellg()) / 30.0,
                      "faces (estimated from the file's size)");
}

}  // namespace

PolygonMesh read_polygon_mesh(const std::string& path) {
  if (!std::ifstream(path)) throw BodyMeshError("body mesh '" + path + "': cannot open the file");
  const std::string ext = lower_extension(path);
  auto reader = reader_for(path, ext);
  if (ext == "obj") check_obj_size(path);
  if (ext == "obj") check_obj_lines(path);
  if (ext == "ply") check_ply_file(path);
  if (ext == "stl") check_stl_size(path);
  const std::string messages = update_reader_quietly(*reader);
  if (!messages.empty())
    throw BodyMeshError("body mesh '" + path + "': the " + ext + " reader failed: " + messages);
  vtkPolyData* data = reader->GetOutput();
  PolygonMesh mesh;
  const vtkIdType n_points = data->GetNumberOfPoints();
  mesh.vertices.resize(n_points);
  for (vtkIdType i = 0; i < n_points; ++i) {
    double p[3];
    data->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw BodyMeshError("body mesh '" + path + "': vertex " + std::to_string(i) +
                          " has a coordinate that is not a finite number");
    mesh.vertices[i] = Vec3(p[0], p[1], p[2]);
  }
  vtkCellArray* polys = data->GetPolys();
  auto ids = vtkSmartPointer<vtkIdList>::New();
  polys->InitTraversal();
  while (polys->GetNextCell(ids)) {
    const int face = static_cast<int>(mesh.faces.size());
    const vtkIdType n = ids->GetNumberOfIds();
    if (n < 3 || n > 4)
      throw BodyMeshError("body mesh '" + path + "': face " + std::to_string(face) + " has " +
                          std::to_string(n) + " vertices (triangles and quads only)");
    std::vector<int> vertices(n);
    for (vtkIdType k = 0; k < n; ++k) {
      const vtkIdType v = ids->GetId(k);
      if (v < 0 || v >= n_points)
        throw BodyMeshError("body mesh '" + path + "': face " + std::to_string(face) +
                            " names vertex " + std::to_string(v) + " (counted from 0) of " +
                            std::to_string(n_points));
      vertices[k] = static_cast<int>(v);
    }
    mesh.faces.push_back(std::move(vertices));
  }
  if (mesh.faces.empty())
    throw BodyMeshError("body mesh '" + path +
                        "': no faces (an empty, truncated or unreadable file)");
  const vtkIdType n_other = data->GetNumberOfLines() + data->GetNumberOfStrips();
  if (n_other > 0)
    throw BodyMeshError("body mesh '" + path + "': " + std::to_string(n_other) +
                        " lines or strips besides the faces (a surface of polygons only)");
  return mesh;
}

}  // namespace tightfit
