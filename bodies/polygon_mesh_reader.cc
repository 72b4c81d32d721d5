// Body files by their extension: OBJ and PLY through tightfit's own readers, which check each
// line as they read it; STL through VTK's reader (VTK stays inside this file). What was read is
// checked the same way whatever the reader.
#include "bodies/body_mesh_error.h"
#include "bodies/obj_file_reader.h"
#include "bodies/ply_file_reader.h"
#include "bodies/polygon_mesh.h"
#include "io/vtk_reader_run.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
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

// STL repeats each vertex in every facet: VTK's reader, merging, welds them into a connected
// surface. Its reports (a truncated or malformed file) are refused in its own words.
PolygonMesh read_stl_file(const std::string& path) {
  check_stl_size(path);
  auto reader = vtkSmartPointer<vtkSTLReader>::New();
  reader->SetFileName(path.c_str());
  reader->MergingOn();
  const std::string messages = update_reader_quietly(*reader);
  if (!messages.empty())
    throw BodyMeshError("body mesh '" + path + "': the stl reader failed: " + messages);
  vtkPolyData* data = reader->GetOutput();
  const vtkIdType n_other = data->GetNumberOfLines() + data->GetNumberOfStrips();
  if (n_other > 0)
    throw BodyMeshError("body mesh '" + path + "': " + std::to_string(n_other) +
                        " lines or strips besides the faces (a surface of polygons only)");
  PolygonMesh mesh;
  mesh.vertices.resize(data->GetNumberOfPoints());
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i) {
    double p[3];
    data->GetPoint(i, p);
    mesh.vertices[i] = Vec3(p[0], p[1], p[2]);
  }
  vtkCellArray* polys = data->GetPolys();
  auto ids = vtkSmartPointer<vtkIdList>::New();
  polys->InitTraversal();
  while (polys->GetNextCell(ids)) {
    std::vector<int> face(ids->GetNumberOfIds());
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) face[k] = static_cast<int>(ids->GetId(k));
    mesh.faces.push_back(std::move(face));
  }
  return mesh;
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
