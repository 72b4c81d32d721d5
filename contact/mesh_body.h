// A rigid body given by a closed triangle mesh (a scanned or modelled human body): the signed
// distance to its flat faces, signed by angle-weighted pseudo-normals, and a smooth normal
// field over the surface (docs/bodies.md "Mesh bodies").
#pragma once

#include "contact/mesh_import.h"
#include "contact/rigid_body.h"
#include "contact/triangle_bvh.h"
#include "contact/triangle_surface.h"

#include <memory>
#include <string>
#include <vector>

namespace tightfit {

struct MeshBodyOptions {
  MeshImportOptions import;
  // The contact surface lies this far outside the mesh, along its normal (skin, padding or an
  // undergarment), m; >= 0.
  double skin_offset_m = 0.0;
};

class MeshBody final : public RigidBody {
 public:
  // Checks the surface (check_body_surface, `what` names it in messages) and builds its BVH.
  // Throws BodyMeshError for a surface that fails, std::invalid_argument for a negative skin.
  MeshBody(TriangleSurface surface, const MeshBodyOptions& options,
           const std::string& what = "body mesh");

  std::string name() const override { return "mesh"; }
  // The closest point of the flat faces gives the distance; its sign comes from the
  // pseudo-normal of the face, edge or vertex it lies on (Baerentzen and Aanaes, "Signed
  // distance computation using the angle weighted pseudonormal", IEEE TVCG 11(3), 2005). The
  // outward normal is the vertex normals interpolated with the closest point's barycentric
  // coordinates, which the location holds (face = triangle, coordinates = (b0, b1, b2)).
  SurfacePoint query(const Vec3& x) const override;
  DisplayMesh display_mesh() const override;
  Vec3 surface_point_m(const SurfaceLocation& location) const override;

  // New vertex positions, same triangles (a morph or a growth step): the faces' areas and the
  // volume's sign are checked again (check_body_geometry), the normals recomputed and the BVH
  // rebuilt.
  void set_vertex_positions(const std::vector<Vec3>& vertices_m);

  const TriangleSurface& surface() const { return surface_; }
  // Unit angle-weighted vertex normals: the vertices' pseudo-normals and the smooth field's
  // values at the vertices.
  const std::vector<Vec3>& vertex_normals() const { return vertex_normals_; }
  double skin_offset_m() const { return skin_offset_m_; }

 private:
  void update_geometry();
  Vec3 interpolated_normal(int triangle, const Vec3& barycentric, double* length = nullptr) const;

  TriangleSurface surface_;
  std::string what_;
  bool open_;
  double skin_offset_m_;
  std::vector<Vec3> face_normals_;
  std::vector<Vec3> vertex_normals_;
  std::vector<std::array<int, 3>> neighbours_;  // across edge k (corners k, k+1); -1 on a border
  TriangleBvh bvh_;
};

// Reads (read_polygon_mesh), imports (import_surface) and checks a body mesh file.
std::unique_ptr<MeshBody> load_mesh_body(const std::string& path, const MeshBodyOptions& options);

}  // namespace tightfit
