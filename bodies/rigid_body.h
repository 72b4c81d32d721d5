// Rigid bodies behind one query, so that every backend and the pressure extractor can treat a
// cylinder, a cone, a plane or a body mesh alike (docs/bodies.md).
#pragma once

#include "core/pressure_field.h"
#include "core/types.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tightfit {

// A point of the body's own surface, in the body's own terms, so that a point can be followed
// while the body grows or morphs (friction anchors, docs/model.md "Friction"). A mesh body
// names a triangle and the barycentric coordinates in it; an analytic body leaves `face` at -1
// and gives its own surface parameters (see each body's header).
struct SurfaceLocation {
  int face = -1;
  Vec3 coordinates = Vec3::Zero();
};

// The body's surface as seen from a point in space.
struct SurfacePoint {
  double signed_distance_m = 0.0;  // negative inside the body
  Vec3 closest_point_m = Vec3::Zero();
  Vec3 outward_normal = Vec3::UnitZ();  // unit, at the closest point, pointing out of the body
  // dg/dx of the signed distance g. Equals `outward_normal` for the analytic bodies; a mesh
  // body's normal is its smooth interpolated field while g is the distance to the flat faces,
  // so the two differ by the angle between a face and that field (docs/bodies.md).
  Vec3 gap_gradient = Vec3::UnitZ();
  // dn/dx: how `outward_normal` turns as the query point x moves (1/m). For a signed distance
  // field it is its Hessian, (I - n n^T) curvature / (1 + g curvature) in the principal
  // directions; a mesh body gives the derivative of its interpolated normal field.
  Mat3 normal_derivative_per_m = Mat3::Zero();
  SurfaceLocation location;  // the closest point on the body's own surface
};

// What a body keeps for one moving point between its queries (RigidBody::query_near): a mesh
// body's faces that can hold the closest point of every x within `reach_m` of `centre_m`.
struct NearFaces {
  Vec3 centre_m = Vec3::Zero();
  double reach_m = -1.0;    // negative: nothing kept yet
  std::uint64_t shape = 0;  // the body's shape the faces were found on (MeshBody::shape_id)
  std::vector<int> faces;
  // A mesh body's smooth surface: the vertices whose quadrics can blend at any x within
  // `reach_m` of `centre_m` (BlendedQuadricField::vertices_near), ascending.
  std::vector<int> blend_vertices;
  // The triangle of the last closest point found from `faces`, where the next search starts
  // (TriangleBvh::closest_among's hint); -1 before the first.
  int last_face = -1;
  // A mesh body's point of the point's friction anchor (surface_point_near_m), found once per
  // anchor and shape: an anchor stays put through a settle while the vertex asks for its point
  // at every force evaluation, and on the smooth surface each finding takes Newton steps that
  // each take the blend. `anchor_shape` 0: nothing kept.
  mutable std::uint64_t anchor_shape = 0;
  mutable SurfaceLocation anchor;
  mutable Vec3 anchor_point_m = Vec3::Zero();
  // A mesh body's smooth surface: the force's answer (RigidBody::query_parts without closest
  // point and location) at `expanded_at_m`, with the gap's Hessian there, from which a point that
  // stays within a few micrometres of it takes its answer by Taylor's expansion instead of the
  // blend (MeshBody::expanded_answer). `expansion_shape` 0: nothing kept.
  std::uint64_t expansion_shape = 0;
  Vec3 expanded_at_m = Vec3::Zero();
  SurfacePoint expanded;
  Mat3 expanded_gap_hessian_per_m = Mat3::Zero();
};

// The parts of a SurfacePoint a caller needs beyond the signed distance, outward normal and
// gap gradient (RigidBody::query_parts). A body may skip the others' cost and leave them
// rough or at their defaults: an explicit frame's contact force without friction needs none
// of them. On the cylinder the location's angle (an atan2) and dn/dx cost more than the rest
// of the answer; on a mesh body's smooth surface the closest point takes two more Newton steps
// (a point not in contact; without them it is the first step's, x - g n) and the location a
// walk over the faces.
struct QueryParts {
  bool closest_point = true;
  bool normal_derivative = true;
  bool location = true;
};

class RigidBody {
 public:
  virtual ~RigidBody() = default;
  virtual std::string name() const = 0;
  virtual SurfacePoint query(const Vec3& x) const = 0;
  // query(x) for a point that moves a little between its queries (a garment vertex, frame
  // after frame): the same answer, found faster by a body that keeps something of the last
  // query in `near` (a mesh body: the few faces near the point). Analytic bodies ask query().
  virtual SurfacePoint query_near(const Vec3& x, NearFaces& near) const {
    (void)near;
    return query(x);
  }
  // query_near(x, near) with `parts` filled (and what every answer has); the rest may be left
  // at their defaults. By default the whole answer.
  virtual SurfacePoint query_parts(const Vec3& x, NearFaces& near, QueryParts parts) const {
    (void)parts;
    return query_near(x, near);
  }
  // Whether a query costs far more than a garment vertex's membrane and bending forces (a mesh
  // body: a tree search and the smooth field's blend), so that a solver may query once per
  // frame and carry the answer over the frame's later stages to first order.
  virtual bool costly_queries() const { return false; }
  virtual DisplayMesh display_mesh() const = 0;
  // Where a SurfaceLocation found by query() is now: after the body grew or morphed it is the
  // same point of the body's surface, carried with it.
  virtual Vec3 surface_point_m(const SurfaceLocation& location) const = 0;
  // surface_point_m(location) for a point whose query keeps `near` (friction's anchor of a
  // garment vertex): the same point, found faster by a body that searches the kept faces.
  virtual Vec3 surface_point_near_m(const SurfaceLocation& location, const NearFaces* near) const {
    (void)near;
    return surface_point_m(location);
  }
};

}  // namespace tightfit
