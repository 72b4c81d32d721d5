// RigidBody::query_near on the MakeHuman female (26756 triangles): points walking round the
// body, each step from where the last one was, get the same answer as a fresh query and the
// distance of a brute-force search over every triangle, whether they stay within the faces
// kept or move beyond them; a new shape of the body is not answered from the old faces.
#include "bodies/mesh_body.h"
#include "bodies/scaled_body.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace tightfit {
namespace {

const std::string female =
    std::string(TIGHTFIT_BODIES_DIR) + "/makehuman_default_female_body_m.obj";

// The distance from p to triangle (a, b, c): the smallest of the distance to the plane (when
// the projection falls inside) and to the three edges, each a clamped segment projection.
double distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto to_segment = [&](const Vec3& s, const Vec3& e) {
    const double t = std::clamp((p - s).dot(e - s) / (e - s).squaredNorm(), 0.0, 1.0);
    return (p - (s + t * (e - s))).norm();
  };
  double best = std::min({to_segment(a, b), to_segment(b, c), to_segment(c, a)});
  const Vec3 n = (b - a).cross(c - a).normalized();
  const Vec3 q = p - n.dot(p - a) * n;
  // Inside when q is on the inner side of every edge.
  const bool inside = n.dot((b - a).cross(q - a)) >= 0 && n.dot((c - b).cross(q - b)) >= 0 &&
                      n.dot((a - c).cross(q - c)) >= 0;
  if (inside) best = std::min(best, std::abs(n.dot(p - a)));
  return best;
}

double brute_force_distance(const TriangleSurface& s, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Triangle& t : s.triangles)
    best = std::min(
        best, distance_to_triangle(p, s.vertices_m[t[0]], s.vertices_m[t[1]], s.vertices_m[t[2]]));
  return best;
}

struct Walk {
  int steps = 0, refound = 0;  // steps; of them, those beyond the kept faces' reach
  double largest_distance_error_m = 0.0, largest_normal_error = 0.0;
};

// 40 walkers from vertices of `surface` (up to 5 mm off them), 25 steps each of up to `step_m`
// in a random direction; each step compared with query() and, every fifth, with the brute
// force over `surface` when `brute_force` (the body is that surface).
Walk walk(const RigidBody& body, const TriangleSurface& surface, double step_m,
          bool brute_force = true) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> vertex(0, int(surface.vertices_m.size()) - 1);
  Walk w;
  for (int walker = 0; walker < 40; ++walker) {
    const Vec3 start = surface.vertices_m[vertex(random)];
    Vec3 x = start + 0.005 * Vec3(unit(random), unit(random), unit(random));
    NearFaces near;
    for (int step = 0; step < 25; ++step, ++w.steps) {
      const double reach_before = near.reach_m;
      const Vec3 centre_before = near.centre_m;
      const SurfacePoint got = body.query_near(x, near);
      w.refound += reach_before < 0 || near.centre_m != centre_before;
      const SurfacePoint fresh = body.query(x);
      w.largest_distance_error_m = std::max(
          w.largest_distance_error_m, std::abs(got.signed_distance_m - fresh.signed_distance_m));
      w.largest_normal_error =
          std::max(w.largest_normal_error, (got.outward_normal - fresh.outward_normal).norm());
      if (brute_force && step % 5 == 0)
        w.largest_distance_error_m =
            std::max(w.largest_distance_error_m,
                     std::abs(std::abs(got.signed_distance_m) - brute_force_distance(surface, x)));
      const Vec3 direction = Vec3(unit(random), unit(random), unit(random)).normalized();
      x += step_m * std::abs(unit(random)) * direction;
    }
  }
  return w;
}

TEST(NearFaces, WalkingPointsGetTheFreshQueryAndTheBruteForceDistance) {
  const auto body = load_mesh_body(female, {});
  // Steps of up to 0.1 mm stay mostly within the kept faces' reach (a tenth of the mean edge,
  // about 1 mm); steps of up to 1 cm leave it at almost every step.
  for (const double step_m : {1e-4, 1e-2}) {
    const Walk w = walk(*body, body->surface(), step_m);
    // Both searches project onto the same triangles in the same arithmetic; the brute force's
    // own projection differs by round-off (1e-17 m on distances of centimetres).
    EXPECT_LT(w.largest_distance_error_m, 1e-12) << "steps up to " << step_m << " m";
    EXPECT_LT(w.largest_normal_error, 1e-12) << "steps up to " << step_m << " m";
    if (step_m < 1e-3)
      EXPECT_LT(w.refound, w.steps / 4);  // the kept faces answer most steps
    else
      EXPECT_GT(w.refound, w.steps / 2);  // and the tree the rest
  }
}

TEST(NearFaces, ScaledBodyAnswersAsItsFreshQuery) {
  const auto body = load_mesh_body(female, {});
  ScaledBody scaled(*body, Vec3(0, -0.055, 0), Vec3::UnitZ());
  scaled.set_scale(0.8);
  // The walkers start at the unscaled body's vertices, up to 4 cm outside the thinner body.
  const Walk w = walk(scaled, body->surface(), 1e-4, false);
  EXPECT_LT(w.largest_distance_error_m, 1e-12);
  EXPECT_LT(w.largest_normal_error, 1e-12);
}

TEST(NearFaces, ANewShapeIsNotAnsweredFromTheOldFaces) {
  auto body = load_mesh_body(female, {});
  const Vec3 x = body->surface().vertices_m[100] + Vec3(0.001, 0.0, 0.0);
  NearFaces near;
  body->query_near(x, near);
  // The body moved 5 cm along x: the old faces would give a distance of about a millimetre.
  std::vector<Vec3> moved = body->surface().vertices_m;
  for (Vec3& v : moved) v.x() += 0.05;
  body->set_vertex_positions(moved);
  const SurfacePoint got = body->query_near(x, near);
  EXPECT_NEAR(std::abs(got.signed_distance_m), brute_force_distance(body->surface(), x), 1e-12);
  EXPECT_GT(std::abs(got.signed_distance_m), 0.01);
}

}  // namespace
}  // namespace tightfit
