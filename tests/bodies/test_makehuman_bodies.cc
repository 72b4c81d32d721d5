// The MakeHuman bodies of data/bodies against what their README states (closed single-piece
// genus-0 surfaces, 1.59 m and 1.73 m tall, one connectivity for both), the invariants of the
// import options, and the female-to-male morph.
#include "bodies/mesh_body.h"
#include "bodies/morphing_mesh_body.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace tightfit {
namespace {

const std::string female =
    std::string(TIGHTFIT_BODIES_DIR) + "/makehuman_default_female_body_m.obj";
const std::string male = std::string(TIGHTFIT_BODIES_DIR) + "/makehuman_default_male_body_m.obj";

double height_m(const MeshBody& body) {
  double low = 1e9, high = -1e9;
  for (const Vec3& v : body.surface().vertices_m) {
    low = std::min(low, v.z());
    high = std::max(high, v.z());
  }
  return high - low;
}

TEST(MakeHumanBodies, ClosedGenusZeroAndAsTallAsTheReadmeSays) {
  for (const auto& [path, height] : {std::pair{female, 1.59}, std::pair{male, 1.73}}) {
    const auto body = load_mesh_body(path, {});  // +y up in the file: z up here
    const TriangleSurface& s = body->surface();
    EXPECT_EQ(s.vertices_m.size(), 13380u);
    EXPECT_EQ(s.triangles.size(), 2u * 13378);  // every quad split in two
    // The checks passed, so every edge joins two triangles: E = 3F/2, and a sphere-like
    // surface has V - E + F = 2.
    const long V = s.vertices_m.size(), F = s.triangles.size();
    EXPECT_EQ(V - 3 * F / 2 + F, 2) << path;
    // The README gives the heights to the centimetre.
    EXPECT_NEAR(height_m(*body), height, 0.006) << path;
    // A person of that height weighs 45 to 90 kg (body-mass index 18 to 30 at 1.59 m, 19 to 30
    // at 1.73 m) at a density near that of water: 0.045 to 0.09 m^3.
    const double volume = enclosed_volume_m3(s.vertices_m, s.triangles);
    EXPECT_GT(volume, 0.045) << path;
    EXPECT_LT(volume, 0.09) << path;
  }
}

TEST(MakeHumanBodies, ImportOptionsKeepVolumeAndAreaUpToScale) {
  const auto plain = load_mesh_body(female, {});
  MeshBodyOptions moved;
  moved.import.rotation_deg = Vec3(10, -35, 120);
  moved.import.translation_m = Vec3(0.3, -2, 1);
  moved.import.metres_per_unit = 0.5;  // as if the file were in half metres
  const auto other = load_mesh_body(female, moved);
  const auto& a = plain->surface();
  const auto& b = other->surface();
  // A rigid motion keeps volume and area; the unit scale s multiplies them by s^3 and s^2.
  // Round-off: 1e-16 per vertex product over 27k triangles, far below 1e-12 relative.
  EXPECT_NEAR(enclosed_volume_m3(b.vertices_m, b.triangles),
              0.125 * enclosed_volume_m3(a.vertices_m, a.triangles),
              1e-12 * enclosed_volume_m3(a.vertices_m, a.triangles));
  EXPECT_NEAR(surface_area_m2(b.vertices_m, b.triangles),
              0.25 * surface_area_m2(a.vertices_m, a.triangles),
              1e-12 * surface_area_m2(a.vertices_m, a.triangles));
  EXPECT_NEAR(height_m(*plain), 1.59, 0.006);
}

TEST(MakeHumanBodies, MorphEndsAreTheTwoBodies) {
  const auto body = load_morphing_mesh_body(female, male, {});
  const auto alone_female = load_mesh_body(female, {});
  const auto alone_male = load_mesh_body(male, {});
  auto expect_same_vertices = [](const MeshBody& a, const MeshBody& b) {
    ASSERT_EQ(a.surface().vertices_m.size(), b.surface().vertices_m.size());
    double largest = 0.0;
    for (std::size_t i = 0; i < a.surface().vertices_m.size(); ++i)
      largest = std::max(largest, (a.surface().vertices_m[i] - b.surface().vertices_m[i]).norm());
    EXPECT_EQ(largest, 0.0);  // (1 - t) a + t b is exact at t = 0 and 1
  };
  expect_same_vertices(body->mesh(), *alone_female);
  body->set_morph(1.0);
  expect_same_vertices(body->mesh(), *alone_male);
  // The tree followed the morph: queries on the morphed body and on the male built afresh agree.
  for (const Vec3& x :
       {Vec3(0.0, 0.0, 1.0), Vec3(0.2, 0.1, 1.2), Vec3(-0.1, 0.05, 0.5), Vec3(0.05, -0.2, 1.55)}) {
    const SurfacePoint s = body->query(x), t = alone_male->query(x);
    EXPECT_NEAR(s.signed_distance_m, t.signed_distance_m, 1e-15);
    EXPECT_LT((s.outward_normal - t.outward_normal).norm(), 1e-14);
  }
  body->set_morph(0.0);
  expect_same_vertices(body->mesh(), *alone_female);
}

TEST(MakeHumanBodies, HalfwayMorphGrowsBetweenTheTwo) {
  // The male is taller and larger: halfway, the height is the mean of the two (the top and the
  // sole are the same vertices in both), the volume between theirs.
  const auto body = load_morphing_mesh_body(female, male, {});
  const double v_female =
      enclosed_volume_m3(body->mesh().surface().vertices_m, body->mesh().surface().triangles);
  body->set_morph(1.0);
  const double v_male =
      enclosed_volume_m3(body->mesh().surface().vertices_m, body->mesh().surface().triangles);
  body->set_morph(0.5);
  const double v_half =
      enclosed_volume_m3(body->mesh().surface().vertices_m, body->mesh().surface().triangles);
  EXPECT_GT(v_male, v_female);
  EXPECT_GT(v_half, v_female);
  EXPECT_LT(v_half, v_male);
  EXPECT_NEAR(height_m(body->mesh()), 0.5 * (1.59 + 1.73), 0.006);
}

TEST(MakeHumanBodies, ScalingAboutTheVerticalAxisGrowsGirthNotHeight) {
  BodyScaling about_axis;  // the z axis through the origin
  const auto body = load_morphing_mesh_body(female, "", {}, about_axis);
  const double v0 =
      enclosed_volume_m3(body->mesh().surface().vertices_m, body->mesh().surface().triangles);
  body->set_morph(0.0, 1.05);
  // Distances from the axis times 1.05, lengths along it kept: volume times 1.05^2.
  EXPECT_NEAR(
      enclosed_volume_m3(body->mesh().surface().vertices_m, body->mesh().surface().triangles),
      1.05 * 1.05 * v0, 1e-12 * v0);
  EXPECT_NEAR(height_m(body->mesh()), 1.59, 0.006);
}

}  // namespace
}  // namespace tightfit
