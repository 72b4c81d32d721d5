// Placement/Kind = flat on plane: the garment's layout (its panels as cut, in one plane) laid
// flat on a plane body, centred where the plane passes nearest the origin, at a gap above it. The
// layout's x and y go along two directions in the plane whose cross product is the plane's normal,
// so the triangles' normals point away from the body.
#include "cases/parts/part_entries.h"
#include "cases/scenario.h"

#include <Eigen/Geometry>  // Vec3::cross

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tightfit {

PartEntry<PlacementMaker> flat_on_plane_placement_entry() {
  PartEntry<PlacementMaker> e;
  e.name = "flat on plane";
  e.subsection = "Flat on plane";
  e.description =
      "the panels as cut, flat on the plane body, centred where it passes nearest the origin.";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_double("Gap", 0.0, 0, 1, "Height of the garment above the plane at the start (m).");
  };
  e.parse = [](ParameterTree& prm) -> PlacementMaker {
    const double gap_m = prm.get_double("Gap");
    return [=](const Scenario& scenario) {
      const RigidBody& plane = scenario.body->body();
      if (plane.name() != "plane")
        throw std::invalid_argument("Placement/Kind = flat on plane needs Body/Kind = plane, not " +
                                    plane.name());
      const SimulationMesh& mesh = scenario.mesh;
      // The plane's point and normal, from the point nearest the origin.
      const SurfacePoint s = plane.query(Vec3::Zero());
      const Vec3 normal = s.outward_normal;
      const Vec3 seed = std::abs(normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
      const Vec3 e1 = (seed - seed.dot(normal) * normal).normalized();
      const Vec3 e2 = normal.cross(e1);
      Vec2 low = mesh.layout_positions_m.front(), high = low;
      for (const Vec2& p : mesh.layout_positions_m) {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
      }
      const Vec2 centre = 0.5 * (low + high);
      std::vector<Vec3> x(mesh.n_vertices);
      for (int u = 0; u < mesh.n_unwelded_vertices(); ++u) {
        const Vec2 p = mesh.layout_positions_m[u] - centre;
        x[mesh.welded_index[u]] = s.closest_point_m + p.x() * e1 + p.y() * e2 + gap_m * normal;
      }
      return x;
    };
  };
  return e;
}

}  // namespace tightfit
