// RigidBody::query_near on the MakeHuman female (26756 triangles): points walking round the
// body, each step from where the last one was, get the same answer as a fresh query and the
// distance of a brute-force search over every triangle, whether they stay within the faces
// kept or move beyond them; a new shape of the body is not answered from the old faces.
#include "bodies/mesh_body.h"
#include "bodies/scaled_body.h"
#include "bodies/triangle_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

// The smooth surface (the case files' default) kept from frame to frame as a garment vertex
// keeps it, on points built to catch a warm start out: walkers that creep 5 um a frame and
// every seventh frame jump 2 cm (beyond the kept faces and blend vertices), and points on the
// mesh's features, where faces tie for the closest point (the body's vertices and edge
// midpoints, 0 to 0.3 mm out along the vertex normal). Every answer of query_near and of the
// force's query_parts is compared with the tree's query() at the same point. Away from ties the
// same faces and the same quadrics in the same order give the same numbers; where faces tie,
// the tree and the kept faces may take the other face of the edge (its location then names
// that face), and the answers differ by round-off: measured gap 7.6e-17 m, unit normal and gap
// gradient 1.1e-14, closest point (m) and dn/dx (relative) 1.0e-14; 6 of the 2000 whole
// answers locate on the other face. Bound 1e-12, a hundred times the largest.
TEST(NearFaces, SmoothSurfaceWarmAnswersAreTheTreesOnJumpsAndTies) {
  MeshBodyOptions options;
  options.contact_surface = MeshBodyOptions::ContactSurface::smooth;
  const auto body = load_mesh_body(female, options);
  const TriangleSurface& surface = body->surface();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> vertex(0, int(surface.vertices_m.size()) - 1);
  std::uniform_int_distribution<int> triangle(0, int(surface.triangles.size()) - 1);
  QueryParts force;
  force.closest_point = force.location = force.normal_derivative = false;
  double worst_gap_m = 0.0, worst_normal = 0.0, worst_rest = 0.0;
  int answers = 0, jumps = 0, location_differs = 0;
  const auto compare = [&](const Vec3& x, NearFaces& near, bool whole) {
    const SurfacePoint fresh = body->query(x);
    // The force's answer kept for its expansion is forgotten: here the blend is asked
    // (SmoothSurfaceExpansionIsTheBlendWithinItsReach checks the expansion).
    near.expansion_shape = 0;
    const SurfacePoint got = whole ? body->query_near(x, near) : body->query_parts(x, near, force);
    ++answers;
    worst_gap_m = std::max(worst_gap_m, std::abs(got.signed_distance_m - fresh.signed_distance_m));
    worst_normal = std::max({worst_normal, (got.outward_normal - fresh.outward_normal).norm(),
                             (got.gap_gradient - fresh.gap_gradient).norm()});
    if (whole) {
      worst_rest = std::max({worst_rest, (got.closest_point_m - fresh.closest_point_m).norm(),
                             (got.normal_derivative_per_m - fresh.normal_derivative_per_m).norm() /
                                 std::max(1.0, fresh.normal_derivative_per_m.norm())});
      location_differs += got.location.face != fresh.location.face;
    }
  };
  for (int walker = 0; walker < 60; ++walker) {
    const int v = vertex(random);
    Vec3 x = surface.vertices_m[v] + 2e-4 * unit(random) * body->vertex_normals()[v];
    NearFaces near;
    for (int frame = 0; frame < 40; ++frame) {
      compare(x, near, frame % 2 == 0);
      const bool jump = frame % 7 == 6;
      jumps += jump;
      x += (jump ? 0.02 : 5e-6) * Vec3(unit(random), unit(random), unit(random)).normalized();
    }
  }
  for (int k = 0; k < 400; ++k) {
    const Triangle& t = surface.triangles[triangle(random)];
    const Vec3 &a = surface.vertices_m[t[0]], &b = surface.vertices_m[t[1]];
    const Vec3 out = body->vertex_normals()[t[0]];
    const double lift_m = 3e-4 * std::abs(unit(random));
    NearFaces near;
    compare(a + lift_m * out, near, true);              // on a vertex: its faces tie
    compare(0.5 * (a + b) + lift_m * out, near, true);  // on an edge: its two faces tie
    compare(0.5 * (a + b) + lift_m * out, near, false);
  }
  std::printf(
      "%d answers (%d jumps): largest differences gap %.3g m, normal %.3g, closest point "
      "and dn/dx %.3g; %d locations on another face\n",
      answers, jumps, worst_gap_m, worst_normal, worst_rest, location_differs);
  EXPECT_LT(worst_gap_m, 1e-12);
  EXPECT_LT(worst_normal, 1e-12);
  EXPECT_LT(worst_rest, 1e-12);
}

// The smooth surface's frame force (query_parts without closest point and location) kept in
// NearFaces: a point within MeshBody::expansion_reach_m of the kept one takes the expansion of
// that answer (second order in the gap, first in the normal) instead of the blend. Against the
// blend at the same point (query(), the tree and the grid's candidates): walkers from vertices
// anywhere on the female, from 0.3 mm inside to 0.3 mm outside, creeping 0.5 to 3 um a frame
// as a settling vertex does, and points placed at the reach itself from a kept answer, the
// farthest an expansion is taken. Measured: 3898 of 12000 walked answers expanded (the rest
// found again, or where the facing factor or the screen acts: between the knees, the fingers),
// gap 4.4e-10 m, unit normal 2.5e-6, gap gradient 9.2e-5 (its O(phi) terms, at 0.3 mm off);
// bounds about twice those.
TEST(NearFaces, SmoothSurfaceExpansionIsTheBlendWithinItsReach) {
  MeshBodyOptions options;
  options.contact_surface = MeshBodyOptions::ContactSurface::smooth;
  const auto body = load_mesh_body(female, options);
  const TriangleSurface& surface = body->surface();
  const double reach_m = body->expansion_reach_m();
  EXPECT_GT(reach_m, 5e-6);
  EXPECT_LT(reach_m, 2e-5);
  std::mt19937 random(19);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> vertex(0, int(surface.vertices_m.size()) - 1);
  QueryParts force;
  force.closest_point = force.location = false;
  double worst_gap_m = 0.0, worst_normal = 0.0, worst_gradient = 0.0;
  int answers = 0, expanded = 0;
  const auto compare = [&](const Vec3& x, NearFaces& near) {
    const Vec3 kept_at = near.expanded_at_m;
    const SurfacePoint got = body->query_parts(x, near, force);
    const SurfacePoint fresh = body->query(x);
    ++answers;
    expanded += near.expanded_at_m == kept_at && kept_at != x;
    worst_gap_m = std::max(worst_gap_m, std::abs(got.signed_distance_m - fresh.signed_distance_m));
    worst_normal = std::max(worst_normal, (got.outward_normal - fresh.outward_normal).norm());
    worst_gradient = std::max(worst_gradient, (got.gap_gradient - fresh.gap_gradient).norm());
  };
  for (int walker = 0; walker < 200; ++walker) {
    const int v = vertex(random);
    Vec3 x = surface.vertices_m[v] + 3e-4 * unit(random) * body->vertex_normals()[v];
    NearFaces near;
    for (int frame = 0; frame < 60; ++frame) {
      compare(x, near);
      x += 1e-6 * (1.75 + 1.25 * unit(random)) *
           Vec3(unit(random), unit(random), unit(random)).normalized();
    }
  }
  const int walked = answers, walked_expanded = expanded;
  for (int k = 0; k < 2000; ++k) {
    const int v = vertex(random);
    const Vec3 x = surface.vertices_m[v] + 3e-4 * unit(random) * body->vertex_normals()[v];
    NearFaces near;
    body->query_parts(x, near, force);
    compare(
        x + (1.0 - 1e-9) * reach_m * Vec3(unit(random), unit(random), unit(random)).normalized(),
        near);
  }
  std::printf(
      "%d answers, %d expanded (%d of %d walked): largest differences from the blend: gap %.3g "
      "m, unit normal %.3g, gap gradient %.3g\n",
      answers, expanded, walked_expanded, walked, worst_gap_m, worst_normal, worst_gradient);
  EXPECT_GT(walked_expanded, walked / 4);
  EXPECT_LT(worst_gap_m, 1e-9);
  EXPECT_LT(worst_normal, 5e-6);
  EXPECT_LT(worst_gradient, 2e-4);
}

// TriangleBvh::closest_among skips the triangles whose bounding sphere or plane lies beyond
// its hint's distance: with any hint of the list (the closest triangle, a random one, the first
// and the last) the answer is that without a hint, the same triangle and the same point to the
// last bit, on points near the surface and on its vertices and edges, where triangles tie.
TEST(NearFaces, ClosestAmongGivesTheSameHitWithAnyHint) {
  const auto body = load_mesh_body(female, {});
  const TriangleSurface& surface = body->surface();
  TriangleBvh bvh;
  bvh.build(surface.vertices_m, surface.triangles);
  std::mt19937 random(13);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> triangle(0, int(surface.triangles.size()) - 1);
  int points = 0, differing = 0;
  std::vector<int> kept;
  for (int k = 0; k < 600; ++k) {
    const Triangle& t = surface.triangles[triangle(random)];
    const Vec3 &a = surface.vertices_m[t[0]], &b = surface.vertices_m[t[1]],
               &c = surface.vertices_m[t[2]];
    const Vec3 out = body->vertex_normals()[t[0]];
    const double lift_m = 3e-4 * unit(random);
    for (const Vec3& x :
         {Vec3(a + lift_m * out), Vec3(0.5 * (a + b) + lift_m * out),
          Vec3((a + b + c) / 3.0 + 2e-3 * Vec3(unit(random), unit(random), unit(random)))}) {
      // The triangles within 3 mm of x, a list such as query_parts keeps.
      bvh.within(x, 3e-3, kept);
      if (kept.empty()) continue;
      ++points;
      const TriangleBvh::Hit full = bvh.closest_among(x, kept);
      std::uniform_int_distribution<int> entry(0, int(kept.size()) - 1);
      for (const int hint : {full.triangle, kept[entry(random)], kept.front(), kept.back()}) {
        const TriangleBvh::Hit hinted = bvh.closest_among(x, kept, hint);
        differing += hinted.triangle != full.triangle || hinted.point_m != full.point_m;
      }
    }
  }
  EXPECT_GT(points, 1500);
  EXPECT_EQ(differing, 0);
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
