#include "bodies/mesh_import.h"
#include "core/closest_names.h"

#include <stdexcept>

namespace tightfit {
namespace {

// The rotation that turns the file's up direction onto +z.
Mat3 up_axis_rotation(const std::string& up) {
  using Eigen::AngleAxisd;
  if (up == "+z") return Mat3::Identity();
  if (up == "-z") return AngleAxisd(M_PI, Vec3::UnitX()).toRotationMatrix();
  if (up == "+y") return AngleAxisd(M_PI / 2, Vec3::UnitX()).toRotationMatrix();
  if (up == "-y") return AngleAxisd(-M_PI / 2, Vec3::UnitX()).toRotationMatrix();
  if (up == "+x") return AngleAxisd(-M_PI / 2, Vec3::UnitY()).toRotationMatrix();
  if (up == "-x") return AngleAxisd(M_PI / 2, Vec3::UnitY()).toRotationMatrix();
  throw std::invalid_argument("Body/Up axis: '" + up + "' is not one of +x, -x, +y, -y, +z, -z" +
                              did_you_mean(up, {"+x", "-x", "+y", "-y", "+z", "-z"}, 0));
}

}  // namespace

Mat3 import_rotation(const MeshImportOptions& o) {
  using Eigen::AngleAxisd;
  const Vec3 r = o.rotation_deg * M_PI / 180.0;
  const Mat3 user = (AngleAxisd(r.z(), Vec3::UnitZ()) * AngleAxisd(r.y(), Vec3::UnitY()) *
                     AngleAxisd(r.x(), Vec3::UnitX()))
                        .toRotationMatrix();
  return user * up_axis_rotation(o.up_axis);
}

TriangleSurface import_surface(const PolygonMesh& mesh, const MeshImportOptions& options) {
  if (!(options.metres_per_unit > 0))
    throw std::invalid_argument("Body/Metres per unit: the unit scale must be positive");
  const Mat3 rotation = import_rotation(options);
  TriangleSurface s;
  s.vertices_m.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices)
    s.vertices_m.push_back(rotation * (options.metres_per_unit * v) + options.translation_m);
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f) {
    const std::vector<int>& p = mesh.faces[f];
    for (std::size_t k = 1; k + 1 < p.size(); ++k) {
      s.triangles.push_back({p[0], p[k], p[k + 1]});
      s.source_face.push_back(f);
    }
  }
  return s;
}

}  // namespace tightfit
