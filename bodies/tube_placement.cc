#include "bodies/tube_placement.h"

#include "bodies/axis_frame.h"
#include "bodies/surface_slice.h"
#include "core/tube_garment.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace tightfit {

namespace {

// Where one ring of a tube goes: its centre, and its radius in each direction normal to the
// axis (a circle: the same in every direction).
struct RingShape {
  Vec3 centre_m;
  std::function<double(const Vec3& direction)> radius_m;
};

RingShape circle(const Vec3& centre_m, double radius_m) {
  return {centre_m, [radius_m](const Vec3&) { return radius_m; }};
}

// Each ring's shape from its height along the axis (m from the tube's middle) and its rest
// girth.
using RingPlacement = std::function<RingShape(double height_m, double girth_m)>;

std::vector<Vec3> place_rings(const Garment& garment, const SimulationMesh& mesh, const Vec3& a,
                              const RingPlacement& ring_at) {
  const std::vector<RingCoordinate> ring = ring_coordinates(garment);
  if (ring.empty() || static_cast<int>(ring.size()) != mesh.n_unwelded_vertices())
    throw std::invalid_argument("garment '" + garment.name + "' is not a closed tube");
  double v_min = mesh.layout_positions_m.front().y(), v_max = v_min;
  for (const Vec2& p : mesh.layout_positions_m) {
    v_min = std::min(v_min, p.y());
    v_max = std::max(v_max, p.y());
  }
  std::vector<Vec3> x(mesh.n_vertices);
  std::map<std::pair<double, double>, RingShape> rings;  // one per row
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u) {
    const double height_m = mesh.layout_positions_m[u].y() - 0.5 * (v_min + v_max);
    const auto row = std::make_pair(height_m, ring[u].girth_m);
    auto found = rings.find(row);
    if (found == rings.end()) found = rings.emplace(row, ring_at(height_m, ring[u].girth_m)).first;
    const RingShape& shape = found->second;
    const Vec3 d = radial_direction(a, 2.0 * M_PI * ring[u].share);
    x[mesh.welded_index[u]] = shape.centre_m + shape.radius_m(d) * d;
  }
  return x;
}

Vec3 unit_axis(const Vec3& axis) {
  if (!(axis.norm() > 0)) throw std::invalid_argument("the tube's axis must not be zero");
  return axis.normalized();
}

}  // namespace

std::vector<Vec3> place_tube_round_axis(const Garment& garment, const SimulationMesh& mesh,
                                        const Vec3& centre_m, const Vec3& axis, double radius_m,
                                        double stretch) {
  const Vec3 a = unit_axis(axis);
  return place_rings(garment, mesh, a, [&](double height_m, double girth_m) {
    const double r = stretch > 0 ? stretch * girth_m / (2.0 * M_PI) : radius_m;
    return circle(centre_m + height_m * a, r);
  });
}

std::vector<Vec3> place_tube_round_limb(const Garment& garment, const SimulationMesh& mesh,
                                        const Vec3& centre_m, const Vec3& axis,
                                        const TriangleSurface& surface, double clearance_m) {
  const Vec3 a = unit_axis(axis);
  return place_rings(garment, mesh, a, [&](double height_m, double) {
    const Vec3 on_axis = centre_m + height_m * a;
    SliceLoop section;
    try {
      section = slice_surface(surface, a, a.dot(on_axis), on_axis);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("the ring " + std::to_string(height_m) +
                                  " m from the tube's middle: " + e.what());
    }
    // A circle round the section where it stays `clearance_m` clear of the plane's other
    // loops too; else (a thigh's ring near the crotch would reach into the other thigh) the
    // section itself offset by the clearance along each ray from its centroid.
    if (section.reach_m + 2.0 * clearance_m <= section.other_loops_distance_m)
      return circle(section.centroid_m, section.reach_m + clearance_m);
    return RingShape{section.centroid_m, [section, clearance_m](const Vec3& direction) {
                       return boundary_distance_m(section, direction) + clearance_m;
                     }};
  });
}

std::vector<Vec3> place_tube_round_cylinder(const Garment& garment, const SimulationMesh& mesh,
                                            const Cylinder& cylinder, double radius_m) {
  return place_tube_round_axis(garment, mesh, cylinder.point_on_axis_m(), cylinder.axis(),
                               radius_m);
}

}  // namespace tightfit
