// RigidBody::query_parts: a body that skips the parts a caller does not ask for still gives
// the whole answer's signed distance, normal and gap gradient (bit for bit on the cylinder, to
// round-off on a mesh body), and the parts it is asked for; on the MakeHuman female's smooth
// surface the Newton steps to the closest point, answered from the kept faces, land where the
// tree's answer does; the kept faces' closest point is the brute-force nearest point over every
// face.
#include "bodies/cylinder.h"
#include "bodies/mesh_body.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace tightfit {
namespace {

const std::string female =
    std::string(TIGHTFIT_BODIES_DIR) + "/makehuman_default_female_body_m.obj";

QueryParts force_only() {
  QueryParts parts;
  parts.closest_point = parts.normal_derivative = parts.location = false;
  return parts;
}

// The nearest point of triangle (a, b, c) to p: the plane's foot when it falls inside, else
// the nearest of the three edges' clamped projections.
Vec3 nearest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto on_segment = [&](const Vec3& s, const Vec3& e) {
    const double t = std::clamp((p - s).dot(e - s) / (e - s).squaredNorm(), 0.0, 1.0);
    return Vec3(s + t * (e - s));
  };
  const Vec3 n = (b - a).cross(c - a).normalized();
  const Vec3 q = p - n.dot(p - a) * n;
  if (n.dot((b - a).cross(q - a)) >= 0 && n.dot((c - b).cross(q - b)) >= 0 &&
      n.dot((a - c).cross(q - c)) >= 0)
    return q;
  Vec3 best = on_segment(a, b);
  for (const Vec3& candidate : {on_segment(b, c), on_segment(c, a)})
    if ((candidate - p).squaredNorm() < (best - p).squaredNorm()) best = candidate;
  return best;
}

TEST(QueryParts, CylinderSkipsOnlyWhatIsNotAsked) {
  const Cylinder cylinder(Vec3(0.01, -0.02, 0.0), Vec3(1.0, 0.2, 0.1), 0.05);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-0.08, 0.08);
  NearFaces unused;
  for (int k = 0; k < 200; ++k) {
    const Vec3 x(u(random), u(random), u(random));
    const SurfacePoint all = cylinder.query(x);
    const SurfacePoint parts = cylinder.query_parts(x, unused, QueryParts{});
    const SurfacePoint force = cylinder.query_parts(x, unused, force_only());
    // The whole answer from the kept frame is the answer from the frame built per query.
    EXPECT_EQ(parts.location.coordinates, all.location.coordinates);
    EXPECT_EQ(parts.normal_derivative_per_m, all.normal_derivative_per_m);
    EXPECT_EQ(force.signed_distance_m, all.signed_distance_m);
    EXPECT_EQ(force.outward_normal, all.outward_normal);
    EXPECT_EQ(force.gap_gradient, all.gap_gradient);
    // The angle is the one angle_deg measures (degrees there, radians here).
    double angle = all.location.coordinates[1] * 180.0 / M_PI;
    if (angle < 0) angle += 360.0;
    EXPECT_NEAR(angle, cylinder.angle_deg(x), 1e-10);
  }
}

TEST(QueryParts, SmoothFemaleGivesTheWholeAnswersForceToRoundOff) {
  MeshBodyOptions options;
  options.contact_surface = MeshBodyOptions::ContactSurface::smooth;
  const auto body = load_mesh_body(female, options);
  const auto& surface = body->surface();
  std::mt19937 random(17);
  std::uniform_int_distribution<int> vertex(0, int(surface.vertices_m.size()) - 1);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int compared = 0, differing = 0;
  double largest = 0.0, largest_closest_point_difference_m = 0.0;
  for (int walker = 0; walker < 60; ++walker) {
    const int v = vertex(random);
    // From 3 mm inside to 3 mm outside, a little sideways: in contact and not.
    Vec3 x = surface.vertices_m[v] + 0.003 * unit(random) * body->vertex_normals()[v] +
             0.002 * Vec3(unit(random), unit(random), unit(random));
    NearFaces near_all, near_force;
    for (int step = 0; step < 10; ++step, ++compared) {
      const SurfacePoint fresh = body->query(x);
      const SurfacePoint all = body->query_parts(x, near_all, QueryParts{});
      const SurfacePoint force = body->query_parts(x, near_force, force_only());
      // Distances in m, unit normals, dn/dx in 1/m against its size (tens per m).
      const double difference =
          std::max({std::abs(force.signed_distance_m - fresh.signed_distance_m),
                    (force.outward_normal - fresh.outward_normal).norm(),
                    (force.gap_gradient - fresh.gap_gradient).norm(),
                    (all.normal_derivative_per_m - fresh.normal_derivative_per_m).norm() /
                        std::max(1.0, fresh.normal_derivative_per_m.norm())});
      differing += difference > 0.0;
      largest = std::max(largest, difference);
      largest_closest_point_difference_m = std::max(
          largest_closest_point_difference_m, (all.closest_point_m - fresh.closest_point_m).norm());
      x += 2e-4 * Vec3(unit(random), unit(random), unit(random));
    }
  }
  // Bit for bit (measured at all 600 points): the blend's vertices do not depend on the face
  // that names the closest point. Where that point lies on an edge or corner two faces share,
  // the kept faces and the tree may name different faces, whose interpolated normals (the
  // blend's facing factor, the faceted part) can differ by round-off: 1e-13 allows for that.
  std::printf("%d of %d points differ, by %.3g at most\n", differing, compared, largest);
  EXPECT_LT(largest, 1e-13) << differing << " of " << compared << " points differ";
  EXPECT_LT(differing, compared / 20);
  // The Newton steps from the kept faces meet the tree's faces: the same closest point up to
  // that order (1e-13 m).
  EXPECT_LT(largest_closest_point_difference_m, 1e-13) << compared << " points";
}

// Friction's anchor point on the smooth female (surface_point_near_m) from a vertex's kept
// faces: the point the tree's answers give (surface_point_m), for anchors taken from where the
// vertex was a few steps before (the Newton steps out along the normal then start up to a
// millimetre from the kept faces' centre, inside or beyond their reach). Measured: equal at
// every point; 1e-13 m allows for an edge two faces share naming either face.
TEST(QueryParts, AnchorPointFromKeptFacesIsTheTreesOnTheSmoothFemale) {
  MeshBodyOptions options;
  options.contact_surface = MeshBodyOptions::ContactSurface::smooth;
  const auto body = load_mesh_body(female, options);
  const auto& surface = body->surface();
  std::mt19937 random(29);
  std::uniform_int_distribution<int> vertex(0, int(surface.vertices_m.size()) - 1);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  double largest_m = 0.0;
  int compared = 0;
  for (int walker = 0; walker < 40; ++walker) {
    const int v = vertex(random);
    Vec3 x = surface.vertices_m[v] + 0.001 * unit(random) * body->vertex_normals()[v];
    NearFaces near;
    SurfaceLocation anchor = body->query(x).location;
    for (int step = 0; step < 8; ++step, ++compared) {
      body->query_parts(x, near, QueryParts{});
      largest_m = std::max(
          largest_m,
          (body->surface_point_near_m(anchor, &near) - body->surface_point_m(anchor)).norm());
      if (step % 3 == 2) anchor = body->query(x).location;
      x += 3e-4 * Vec3(unit(random), unit(random), unit(random));
    }
  }
  std::printf("%d anchors: kept faces' point within %.3g m of the tree's\n", compared, largest_m);
  EXPECT_LT(largest_m, 1e-13);
}

// The anchor's point kept in a vertex's NearFaces (surface_point_near_m): found once per anchor
// and shape, then given again while the vertex moves; a new anchor, or the same anchor on a
// moved body, is found afresh. Each answer against the tree's (surface_point_m, no kept faces)
// within 1e-13 m, as above. The body scaled by 1.01 about its centroid: the blend of the scaled
// vertices' quadrics is the scaled blend, so the anchor's point moves to c + 1.01 (a - c);
// measured 1.3e-16 m from it; 1e-13 m allowed (round-off of the field's build on a body a metre
// across). An anchor's point kept from the first shape would lie 2 mm off.
TEST(QueryParts, AnchorPointKeptForItsAnchorAndShapeOnTheSmoothFemale) {
  MeshBodyOptions options;
  options.contact_surface = MeshBodyOptions::ContactSurface::smooth;
  const auto body = load_mesh_body(female, options);
  const std::vector<Vec3> vertices = body->surface().vertices_m;
  std::mt19937 random(31);
  std::uniform_int_distribution<int> vertex(0, int(vertices.size()) - 1);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  struct Walker {
    NearFaces near;
    SurfaceLocation anchor;
    Vec3 point_m;
  };
  std::vector<Walker> walkers(20);
  double largest_m = 0.0, smallest_new_anchor_move_m = 1.0;
  for (Walker& w : walkers) {
    Vec3 x = vertices[vertex(random)];
    w.anchor = body->query(x).location;
    body->query_parts(x, w.near, QueryParts{});
    w.point_m = body->surface_point_near_m(w.anchor, &w.near);
    largest_m = std::max(largest_m, (w.point_m - body->surface_point_m(w.anchor)).norm());
    for (int step = 0; step < 5; ++step) {
      x += 3e-4 * Vec3(unit(random), unit(random), unit(random));
      body->query_parts(x, w.near, QueryParts{});
      EXPECT_EQ(body->surface_point_near_m(w.anchor, &w.near), w.point_m);  // the kept point
    }
    // The vertex's own anchor now, found afresh with the same kept faces.
    const SurfaceLocation moved = body->query(x).location;
    const Vec3 moved_point = body->surface_point_near_m(moved, &w.near);
    largest_m = std::max(largest_m, (moved_point - body->surface_point_m(moved)).norm());
    smallest_new_anchor_move_m =
        std::min(smallest_new_anchor_move_m, (moved_point - w.point_m).norm());
  }
  EXPECT_GT(smallest_new_anchor_move_m, 1e-6);  // the new anchors lie apart from the old ones

  // The walkers' last anchors, kept on this shape, asked again on the body scaled about its
  // centroid.
  std::vector<Vec3> before(walkers.size());
  for (std::size_t k = 0; k < walkers.size(); ++k) {
    walkers[k].anchor = walkers[k].near.anchor;
    before[k] = body->surface_point_near_m(walkers[k].anchor, &walkers[k].near);
  }
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& v : vertices) centroid += v;
  centroid /= double(vertices.size());
  std::vector<Vec3> scaled = vertices;
  for (Vec3& v : scaled) v = centroid + 1.01 * (v - centroid);
  body->set_vertex_positions(scaled);
  double largest_scaled_m = 0.0;
  for (std::size_t k = 0; k < walkers.size(); ++k) {
    const Vec3 after = body->surface_point_near_m(walkers[k].anchor, &walkers[k].near);
    largest_scaled_m =
        std::max(largest_scaled_m, (after - (centroid + 1.01 * (before[k] - centroid))).norm());
    largest_m = std::max(largest_m, (after - body->surface_point_m(walkers[k].anchor)).norm());
  }
  std::printf("anchor points: %.3g m from the tree's, %.3g m from the scaled point\n", largest_m,
              largest_scaled_m);
  EXPECT_LT(largest_m, 1e-13);
  EXPECT_LT(largest_scaled_m, 1e-13);
}

TEST(QueryParts, KeptFacesGiveTheBruteForceNearestPoint) {
  const auto body = load_mesh_body(female, {});  // faceted: the closest point of the faces
  const auto& surface = body->surface();
  std::mt19937 random(23);
  std::uniform_int_distribution<int> vertex(0, int(surface.vertices_m.size()) - 1);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  double largest_m = 0.0;
  for (int walker = 0; walker < 30; ++walker) {
    Vec3 x =
        surface.vertices_m[vertex(random)] + 0.004 * Vec3(unit(random), unit(random), unit(random));
    NearFaces near;
    for (int step = 0; step < 8; ++step) {
      const SurfacePoint got = body->query_parts(x, near, QueryParts{});
      double nearest = std::numeric_limits<double>::infinity();
      for (const Triangle& t : surface.triangles)
        nearest = std::min(
            nearest, (nearest_on_triangle(x, surface.vertices_m[t[0]], surface.vertices_m[t[1]],
                                          surface.vertices_m[t[2]]) -
                      x)
                         .norm());
      largest_m = std::max(largest_m, (got.closest_point_m - x).norm() - nearest);
      EXPECT_EQ(got.closest_point_m, body->query(x).closest_point_m);
      x += 1e-4 * Vec3(unit(random), unit(random), unit(random));
    }
  }
  // The brute force's own projection rounds differently: 1e-17 m measured on centimetres.
  EXPECT_LT(std::abs(largest_m), 1e-15);
}

}  // namespace
}  // namespace tightfit
