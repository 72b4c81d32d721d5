// A rigid body given by a closed triangle mesh (a scanned or modelled human body): the signed
// distance to its flat faces, signed by angle-weighted pseudo-normals, and a smooth normal
// field over the surface (docs/bodies.md "Mesh bodies").
#pragma once

#include "bodies/blended_quadric_field.h"
#include "bodies/mesh_import.h"
#include "bodies/rigid_body.h"
#include "bodies/triangle_bvh.h"
#include "bodies/triangle_surface.h"

#include <memory>
#include <string>
#include <vector>

namespace tightfit {

struct MeshBodyOptions {
  MeshImportOptions import;
  // The contact surface lies this far outside the mesh, along its normal (skin, padding or an
  // undergarment), m; >= 0.
  double skin_offset_m = 0.0;
  // The surface the garment touches (docs/bodies.md "The smooth contact surface"):
  // `faceted`, the flat faces' distance with the force along the interpolated vertex normals;
  // `smooth`, the blended osculating quadrics' signed-distance field (blended_quadric_field.h),
  // a C2 field whose gradient is the contact normal, so that the contact force derives from an
  // energy and Newton's tangent is its symmetric Hessian.
  // Faceted here, the flat-face geometry the unit tests check; a case file's
  // Body/Mesh/Contact surface defaults to smooth.
  enum class ContactSurface { faceted, smooth };
  ContactSurface contact_surface = ContactSurface::faceted;
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
  // query(x) from the faces kept in `near`: a point that moved no farther than their reach
  // from where they were found has its closest point on one of them (below), so only those
  // are searched; beyond the reach, or on a new shape, the tree finds them again.
  SurfacePoint query_near(const Vec3& x, NearFaces& near) const override {
    return query_parts(x, near, QueryParts{});
  }
  // query_near without the smooth surface's location walk when `parts.location` is off, and
  // without its closest point's further Newton steps when `parts.closest_point` is off (the
  // faceted answer's closest point and location, and every dn/dx, come with the rest). On the
  // smooth surface the answer without both (a frame's contact force) is kept in `near`, and a
  // point within `expansion_reach_m()` of where it was found takes its own from it
  // (expanded_answer) without the blend.
  SurfacePoint query_parts(const Vec3& x, NearFaces& near, QueryParts parts) const override;
  // How far a point may move from a kept smooth answer and still be answered by its expansion,
  // m: a hundredth of the kept faces' reach (about 10 micrometres on the MakeHuman bodies), where
  // the expansion is off the blend by at most 4.4e-10 m in the gap and 2.5e-6 in the normal
  // (tests/bodies/test_near_faces.cc).
  static constexpr double expansion_reach_over_near_reach = 0.01;
  double expansion_reach_m() const { return expansion_reach_over_near_reach * near_reach_m_; }
  bool costly_queries() const override { return true; }
  DisplayMesh display_mesh() const override;
  Vec3 surface_point_m(const SurfaceLocation& location) const override {
    return surface_point_near_m(location, nullptr);
  }
  // The smooth surface's Newton steps out along the normal take their flat answers from
  // `near`'s faces where the steps lie within their reach (faceted_near), else from the tree;
  // the point is kept in `near` and given again for the same anchor on the same shape.
  Vec3 surface_point_near_m(const SurfaceLocation& location, const NearFaces* near) const override;

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
  SurfacePoint faceted_query(const Vec3& x) const { return faceted_answer(x, bvh_.closest(x)); }
  // The faceted answer at x whose closest point of the flat faces is `hit`.
  SurfacePoint faceted_answer(const Vec3& x, const TriangleBvh::Hit& hit) const;
  // The contact surface's answer (the skin, or the smooth field) from the faceted one.
  // `near` (when given) answers the smooth surface's Newton steps as it does x's query.
  SurfacePoint finished(const Vec3& x, SurfacePoint faceted, QueryParts parts = QueryParts{},
                        NearFaces* near = nullptr) const;
  // The faceted answer at x, from `near`'s faces when x lies within their reach (the same
  // closest point as the tree's), else from the tree.
  SurfacePoint faceted_near(const Vec3& x, const NearFaces* near) const;
  // Replaces the faceted answer's distance, normal and derivatives by the smooth field's where
  // the field covers x (blended back to the faceted ones as its weights fade, far off the
  // surface), with the closest point on the smooth surface moved out by the skin (the level
  // set g = skin offset); the distance is returned before the skin is taken off.
  bool smooth_query(const Vec3& x, SurfacePoint& s, bool closest_point = true,
                    const NearFaces* near = nullptr, Mat3* gap_hessian = nullptr) const;
  // smooth_query's distance, normal and derivatives alone, with the closest point one Newton
  // step x - g n onto the surface; the blend takes `near`'s vertices where x lies within their
  // reach (the same value as the field's grid gives). True where the blend alone answers (the
  // faceted gap not blended in) and every vertex in it faces fully (no facing factor or screen
  // between 0 and 1); `gap_hessian` (if given) gets the gap's Hessian where the blend answers.
  bool smooth_field(const Vec3& x, SurfacePoint& s, const NearFaces* near = nullptr,
                    Mat3* gap_hessian = nullptr) const;
  // The force's answer at x from the one kept in `near` at x0 = near.expanded_at_m, to second
  // order in the step d = x - x0 for the gap and first order for the normal:
  //   g = g0 + grad g0 . d + d^T Hg d / 2,  grad g = grad g0 + Hg d,  n = (n0 + dn/dx d) / |...|,
  // dn/dx kept (Hg the gap's Hessian at x0, eq. in smooth_field). The smooth field is C2, so
  // over the few micrometres a vertex moves in a frame the expansion is off the blend by the
  // field's third derivatives times d^3 (d^2 for the normal): tests/bodies/test_near_faces.cc.
  SurfacePoint expanded_answer(const Vec3& x, const NearFaces& near) const;
  // The face and barycentric coordinates b of the point y = c(b) + t N(b), c the flat point
  // and N = sum b_i n_i the interpolated vertex normal: the flat surface's coordinates carried
  // out to the smooth one along the normal field, a map that is continuous across edges
  // (docs/bodies.md). `face` starts the walk.
  SurfaceLocation smooth_location(const Vec3& y, int face) const;

  TriangleSurface surface_;
  std::string what_;
  bool open_;
  double skin_offset_m_;
  MeshBodyOptions::ContactSurface contact_surface_;
  BlendedQuadricField field_;
  std::vector<Vec3> face_normals_;
  std::vector<Vec3> vertex_normals_;
  std::vector<std::array<int, 3>> neighbours_;  // across edge k (corners k, k+1); -1 on a border
  TriangleBvh bvh_;
  // This shape's number, unique in the process (NearFaces::shape), and how far a point may
  // move before its near faces are found again, m (a tenth of the mean edge length).
  std::uint64_t shape_id_ = 0;
  double near_reach_m_ = 0.0;
};

// Reads (read_polygon_mesh), imports (import_surface) and checks a body mesh file.
std::unique_ptr<MeshBody> load_mesh_body(const std::string& path, const MeshBodyOptions& options);

}  // namespace tightfit
