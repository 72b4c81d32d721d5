// Rigid bodies behind one query, so that every backend and the pressure extractor can treat a
// cylinder, a plane or (later) a body mesh alike.
#pragma once

#include "core/types.h"

#include <string>
#include <vector>

namespace tightfit {

// The body's surface as seen from a point in space.
struct SurfacePoint {
  double signed_distance_m = 0.0;  // negative inside the body
  Vec3 closest_point_m = Vec3::Zero();
  Vec3 outward_normal = Vec3::UnitZ();  // unit, at the closest point, pointing out of the body
};

// A triangulated surface for drawing the body (ParaView output); not used for contact.
struct DisplayMesh {
  std::vector<Vec3> vertices_m;
  std::vector<Triangle> triangles;
};

class RigidBody {
 public:
  virtual ~RigidBody() = default;
  virtual std::string name() const = 0;
  virtual SurfacePoint query(const Vec3& x) const = 0;
  virtual DisplayMesh display_mesh() const = 0;
};

}  // namespace tightfit
