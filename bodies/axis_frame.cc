#include "bodies/axis_frame.h"

namespace tightfit {

DisplayMesh revolution_display_mesh(const RigidBody& body, double length_m) {
  const int n_round = 22, n_along = 5;
  DisplayMesh mesh;
  for (int j = 0; j < n_along; ++j)
    for (int i = 0; i < n_round; ++i) {
      SurfaceLocation l;
      l.coordinates =
          Vec3(length_m * (double(j) / (n_along - 1) - 0.5), 2.0 * M_PI * i / n_round, 0.0);
      mesh.vertices_m.push_back(body.surface_point_m(l));
    }
  for (int j = 0; j + 1 < n_along; ++j)
    for (int i = 0; i < n_round; ++i) {
      const int a = j * n_round + i, b = j * n_round + (i + 1) % n_round;
      mesh.triangles.push_back({a, b, b + n_round});
      mesh.triangles.push_back({a, b + n_round, a + n_round});
    }
  return mesh;
}

}  // namespace tightfit
