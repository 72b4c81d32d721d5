#include "bodies/morphing_mesh_body.h"

#include "bodies/body_mesh_error.h"
#include "bodies/polygon_mesh.h"

#include <stdexcept>
#include <utility>

namespace tightfit {

MorphingMeshBody::MorphingMeshBody(TriangleSurface base, std::vector<Vec3> target_vertices_m,
                                   const MeshBodyOptions& options, const BodyScaling& scaling,
                                   const std::string& what)
    : ChangingMeshBody(std::move(base), options, what),
      base_(mesh_.surface().vertices_m),
      target_(std::move(target_vertices_m)),
      scaling_(scaling) {
  if (!target_.empty() && target_.size() != base_.size())
    throw BodyMeshError(what + ": the morph target has " + std::to_string(target_.size()) +
                        " vertices, the base " + std::to_string(base_.size()));
  if (scaling_.about == BodyScaling::About::axis) {
    if (!(scaling_.axis.norm() > 0))
      throw std::invalid_argument("Body/Axis: the scaling axis is zero");
    scaling_.axis.normalize();
  }
}

void MorphingMeshBody::set_morph(double t, double scale) {
  if (!(t >= 0.0 && t <= 1.0)) throw std::invalid_argument("Body/Morph: t must lie in [0, 1]");
  if (t != 0.0 && target_.empty())
    throw std::invalid_argument("Body/Morph: t != 0 needs a morph target");
  if (!(scale > 0)) throw std::invalid_argument("Body/Scale: the body's scale must be positive");
  std::vector<Vec3> shape(base_.size());
  const Vec3& c = scaling_.centre_m;
  const Mat3 along = scaling_.about == BodyScaling::About::axis
                         ? Mat3(scaling_.axis * scaling_.axis.transpose())
                         : Mat3::Zero();
  // x' = c + P (x - c) + scale (I - P) (x - c), P the projector onto the fixed axis (zero about
  // a point).
  const Mat3 map = along + scale * (Mat3::Identity() - along);
  for (std::size_t i = 0; i < base_.size(); ++i) {
    const Vec3 blended = target_.empty() ? base_[i] : Vec3((1.0 - t) * base_[i] + t * target_[i]);
    shape[i] = c + map * (blended - c);
  }
  mesh_.set_vertex_positions(shape);
  t_ = t;
  scale_ = scale;
}

std::unique_ptr<MorphingMeshBody> load_morphing_mesh_body(const std::string& base_path,
                                                          const std::string& target_path,
                                                          const MeshBodyOptions& options,
                                                          const BodyScaling& scaling) {
  TriangleSurface base = import_surface(read_polygon_mesh(base_path), options.import);
  std::vector<Vec3> target;
  if (!target_path.empty()) {
    const TriangleSurface other = import_surface(read_polygon_mesh(target_path), options.import);
    const std::string pair = "morph between '" + base_path + "' and '" + target_path + "'";
    if (other.vertices_m.size() != base.vertices_m.size())
      throw BodyMeshError(pair + ": " + std::to_string(base.vertices_m.size()) + " and " +
                          std::to_string(other.vertices_m.size()) +
                          " vertices; a morph needs one connectivity");
    for (std::size_t t = 0; t < base.triangles.size(); ++t)
      if (t >= other.triangles.size() || other.triangles[t] != base.triangles[t])
        throw BodyMeshError(pair + ": face " + std::to_string(base.source_face[t]) +
                            " differs; a morph needs one connectivity");
    if (other.triangles.size() != base.triangles.size())
      throw BodyMeshError(pair + ": different numbers of faces; a morph needs one connectivity");
    // The target must be a valid body by itself (the blend's end).
    check_body_surface(other, options.import.allow_open_surface, "body mesh '" + target_path + "'");
    target = other.vertices_m;
  }
  return std::make_unique<MorphingMeshBody>(std::move(base), std::move(target), options, scaling,
                                            "body mesh '" + base_path + "'");
}

}  // namespace tightfit
