#include "body_mesh_files.h"

#include "bodies/body_mesh_error.h"
#include "bodies/mesh_body.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace tightfit::testing {

PolygonMesh revolution_surface(const std::vector<double>& z, const std::vector<double>& radius,
                               int n_round) {
  PolygonMesh mesh;
  const int n_rings = static_cast<int>(z.size());
  for (int k = 0; k < n_rings; ++k)
    for (int i = 0; i < n_round; ++i) {
      const double phi = 2.0 * M_PI * i / n_round;
      mesh.vertices.emplace_back(radius[k] * std::cos(phi), radius[k] * std::sin(phi), z[k]);
    }
  auto ring = [&](int k, int i) { return k * n_round + (i % n_round); };
  for (int k = 0; k + 1 < n_rings; ++k)
    for (int i = 0; i < n_round; ++i)
      mesh.faces.push_back({ring(k, i), ring(k, i + 1), ring(k + 1, i + 1), ring(k + 1, i)});
  const int bottom = static_cast<int>(mesh.vertices.size());
  mesh.vertices.emplace_back(0.0, 0.0, z.front());
  const int top = bottom + 1;
  mesh.vertices.emplace_back(0.0, 0.0, z.back());
  for (int i = 0; i < n_round; ++i) {
    mesh.faces.push_back({bottom, ring(0, i + 1), ring(0, i)});
    mesh.faces.push_back({top, ring(n_rings - 1, i), ring(n_rings - 1, i + 1)});
  }
  return mesh;
}

PolygonMesh regular_tetrahedron(double scale) {
  PolygonMesh mesh;
  mesh.vertices = {scale * Vec3(1, 1, 1), scale * Vec3(1, -1, -1), scale * Vec3(-1, 1, -1),
                   scale * Vec3(-1, -1, 1)};
  mesh.faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return mesh;
}

std::string temporary_path(const std::string& file_name) {
  const auto dir = std::filesystem::temp_directory_path() / "tightfit_contact_tests";
  std::filesystem::create_directories(dir);
  return (dir / file_name).string();
}

void write_obj(const std::string& path, const PolygonMesh& mesh) {
  std::ofstream out(path);
  out << std::setprecision(17);
  for (const Vec3& v : mesh.vertices) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& f : mesh.faces) {
    out << 'f';
    for (int i : f) out << ' ' << i + 1;
    out << '\n';
  }
}

void write_stl(const std::string& path, const PolygonMesh& mesh) {
  std::ofstream out(path);
  out << std::setprecision(17) << "solid test\n";
  for (const auto& f : mesh.faces)
    for (std::size_t k = 1; k + 1 < f.size(); ++k) {
      const Vec3 &a = mesh.vertices[f[0]], &b = mesh.vertices[f[k]], &c = mesh.vertices[f[k + 1]];
      const Vec3 n = (b - a).cross(c - a).normalized();
      out << "facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << "\nouter loop\n";
      for (const Vec3* p : {&a, &b, &c})
        out << "vertex " << p->x() << ' ' << p->y() << ' ' << p->z() << '\n';
      out << "endloop\nendfacet\n";
    }
  out << "endsolid test\n";
}

void write_ply(const std::string& path, const PolygonMesh& mesh) {
  std::ofstream out(path);
  out << std::setprecision(17) << "ply\nformat ascii 1.0\nelement vertex " << mesh.vertices.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nelement face "
      << mesh.faces.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3& v : mesh.vertices) out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& f : mesh.faces) {
    out << f.size();
    for (int i : f) out << ' ' << i;
    out << '\n';
  }
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

std::string mesh_refusal(const std::string& path) {
  try {
    load_mesh_body(path, {});
  } catch (const BodyMeshError& e) {
    return e.what();
  }
  return "";
}

}  // namespace tightfit::testing
