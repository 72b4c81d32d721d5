// Dressing round a skeleton (docs/arrangement.md "Arrangement from the pattern file", "The body
// shrunk about its skeleton"): a person built of cylinders (tests/body/synthetic_body.h), the
// bones from its own landmarks (body/garment_arrangement.h), and a garment of three tubes and
// two trouser legs, each tube two flat panels placed in front of and behind its body part as a
// pattern file's arrangement places them. Every panel starts outside the body shrunk about its
// skeleton; the dressing closes every seam; each sleeve ends round its own arm.
#include "bodies/skeleton_shrink.h"
#include "bodies/skeleton_shrunk_body.h"
#include "body/anatomical_regions.h"
#include "body/body_measurements.h"
#include "body/garment_arrangement.h"
#include "contact/penalty_contact.h"
#include "core/material.h"
#include "core/rectangle_panel.h"
#include "massspring/dressing.h"
#include "synthetic_body.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tightfit {
namespace {

using testing::SyntheticPerson;

const PartFrame& part_named(const BodyMeasurements& body, const std::string& name) {
  return body.part(name);
}

TEST(SkeletonShrink, ScaleOneIsTheIdentity) {
  const TriangleSurface person = testing::synthetic_person(45.0);
  const SkeletonShrink shrink(person.vertices_m, skeleton_bones(measure_body(person)));
  const std::vector<Vec3> same = shrink.positions_m(1.0);
  for (std::size_t i = 0; i < same.size(); ++i) EXPECT_EQ(same[i], person.vertices_m[i]) << i;
}

TEST(SkeletonShrink, ALimbsVertexMovesTowardsItsOwnAxisOnly) {
  // Points on each limb's surface (its radius round its bone's axis), 30 to 70 % of the way
  // along the bone (no other bone within the blend width there): shrunk by s, each moves across
  // the bone's axis only (no component along it) and its distance from the axis becomes s times
  // what it was. Exact up to round-off: 1e-12 m allowed.
  const TriangleSurface person = testing::synthetic_person(45.0);
  const std::vector<SkeletonBone> bones = skeleton_bones(measure_body(person));
  std::vector<Vec3> points;
  std::vector<int> limb;
  for (int k = 0; k < static_cast<int>(bones.size()); ++k) {
    const SkeletonBone& bone = bones[k];
    if (bone.name == "torso") continue;
    const Vec3 a = (bone.end_m - bone.root_m).normalized();
    const Vec3 u = a.unitOrthogonal(), v = a.cross(u);
    const double r =
        bone.name.rfind("arm", 0) == 0 ? SyntheticPerson::arm_r : SyntheticPerson::leg_r;
    for (double t = 0.3; t <= 0.7; t += 0.1)
      for (int j = 0; j < 12; ++j) {
        const double phi = 2 * M_PI * j / 12;
        points.push_back(bone.root_m + t * (bone.end_m - bone.root_m) +
                         r * (std::cos(phi) * u + std::sin(phi) * v));
        limb.push_back(k);
      }
  }
  const SkeletonShrink shrink(points, bones);
  const double s = 0.6;
  const std::vector<Vec3> shrunk = shrink.positions_m(s);
  ASSERT_EQ(points.size(), 4u * 5u * 12u);  // four limbs, five places along, twelve round
  for (std::size_t i = 0; i < points.size(); ++i) {
    const SkeletonBone& bone = bones[limb[i]];
    EXPECT_EQ(shrink.nearest_bone()[i], limb[i]) << "point " << i;
    const Vec3 a = (bone.end_m - bone.root_m).normalized();
    const Vec3 y = points[i] - bone.root_m;
    const Vec3 moved = shrunk[i] - points[i];
    EXPECT_NEAR(moved.dot(a), 0.0, 1e-12) << bone.name << " point " << i;
    const Vec3 y_new = shrunk[i] - bone.root_m;
    EXPECT_NEAR((y_new - y_new.dot(a) * a).norm(), s * (y - y.dot(a) * a).norm(), 1e-12)
        << bone.name << " point " << i;
  }
}

TEST(SkeletonShrink, ARaisedArmTurnsAboutItsShoulderAwayFromTheTorso) {
  // With an arm raise, a point on an arm (away from the joints) shrunk to s keeps its distance
  // from the bone's root apart from the shrink across the axis (a rotation about the root keeps
  // lengths: |T(y) - root| = |y_s - root|, 1e-12 m), and the arm's end rises (its height above
  // the root grows, as a turn towards a T-pose must).
  const TriangleSurface person = testing::synthetic_person(45.0);
  const std::vector<SkeletonBone> bones = skeleton_bones(measure_body(person));
  std::vector<Vec3> points;
  std::vector<int> arm;
  for (int k = 0; k < static_cast<int>(bones.size()); ++k)
    if (bones[k].name.rfind("arm", 0) == 0) {
      points.push_back(bones[k].root_m + 0.6 * (bones[k].end_m - bones[k].root_m) +
                       SyntheticPerson::arm_r * Vec3(0, -1, 0));
      arm.push_back(k);
    }
  SkeletonShrink shrink(points, bones);
  const double s = 0.6, raise = (30 * M_PI / 180) / (1 - s);
  shrink.set_arm_raise(raise);
  const std::vector<Vec3> plain = SkeletonShrink(points, bones).positions_m(s);
  const std::vector<Vec3> raised = shrink.positions_m(s);
  ASSERT_EQ(points.size(), 2u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3& root = bones[arm[i]].root_m;
    EXPECT_NEAR((raised[i] - root).norm(), (plain[i] - root).norm(), 1e-12);
    EXPECT_GT(raised[i].z() - root.z(), plain[i].z() - root.z() + 0.05) << bones[arm[i]].name;
  }
}

// The synthetic person's parts (synthetic_body.cc) as one surface of separate closed pieces,
// not their union (whose corefinement leaves faces of no area, which a contact body refuses).
TriangleSurface person_of_pieces(double angle_deg) {
  using P = SyntheticPerson;
  const double t = angle_deg * M_PI / 180;
  std::vector<TriangleSurface> parts;
  parts.push_back(testing::elliptic_cylinder(Vec3(0, 0, P::crotch_m), Vec3::UnitZ(), Vec3::UnitX(),
                                             1.40 - P::crotch_m, P::torso_a, P::torso_b, 96));
  for (const double x : {0.09, -0.09})
    parts.push_back(testing::elliptic_cylinder(Vec3(x, 0, 0), Vec3::UnitZ(), Vec3::UnitX(), 0.85,
                                               P::leg_r, P::leg_r, 48));
  for (const double side : {1.0, -1.0})
    parts.push_back(testing::elliptic_cylinder(Vec3(side * P::joint_x, 0, P::joint_z),
                                               Vec3(side * std::sin(t), 0, -std::cos(t)),
                                               Vec3::UnitY(), 0.6, P::arm_r, P::arm_r, 48));
  TriangleSurface all;
  for (const TriangleSurface& part : parts) {
    const int offset = static_cast<int>(all.vertices_m.size());
    all.vertices_m.insert(all.vertices_m.end(), part.vertices_m.begin(), part.vertices_m.end());
    for (Triangle tri : part.triangles) {
      for (int& v : tri) v += offset;
      all.triangles.push_back(tri);
    }
  }
  return all;
}

TEST(NamedRegions, UpperArmIsABandRoundEachArmAtItsGirthLine) {
  // A point on each arm's surface at its upper-arm girth line lies in that side's band (within
  // its radius of the axis, between its ends); the torso's side at that height does not.
  const BodyMeasurements body = measure_body(testing::synthetic_person(45.0));
  const auto inside = [](const RegionPiece& p, const Vec3& x) {
    const Vec3 d = x - p.point_m;
    const double t = d.dot(p.axis);
    return t >= p.low_m && t <= p.high_m && (d - t * p.axis).norm() <= p.radius_m;
  };
  for (int side = 0; side < 2; ++side) {
    const std::string s = side == 0 ? " left" : " right";
    AnatomyRequest request;
    request.name = "upper arm";
    request.side = side;
    const std::vector<RegionPiece> band = anatomical_region(body, request);
    ASSERT_EQ(band.size(), 1u);
    const BodyGirth& line = body.girth("upper arm" + s);
    const Vec3 on_arm = line.centre_m + SyntheticPerson::arm_r * Vec3(0, -1, 0);
    EXPECT_TRUE(inside(band[0], on_arm)) << s;
    const Vec3 torso_side(0, -SyntheticPerson::torso_b, line.centre_m.z());
    EXPECT_FALSE(inside(band[0], torso_side)) << s;
  }
  AnatomyRequest both;
  both.name = "upper arm";
  EXPECT_EQ(anatomical_region(body, both).size(), 2u);
}

// A rectangle panel `width` round by `length` along, placed flat: rest (x, y) at
// centre + offset n + (x - width / 2) e1 + y e2, e1 = e2 x n, so its triangles face along n.
Panel placed_panel(const std::string& name, double width, double length, const Vec3& centre,
                   const Vec3& e2, const Vec3& n, double offset) {
  Panel panel = make_rectangle_panel(name, width, length, MeshSpacing{0.025, 0.025});
  const Vec3 e1 = e2.cross(n);
  Panel::Arrangement placed;
  placed.rotation.col(0) = e1;
  placed.rotation.col(1) = e2;
  placed.rotation.col(2) = n;
  placed.translation_m = centre + offset * n - 0.5 * width * e1;
  panel.arrangement = placed;
  return panel;
}

// A tube of two panels round the line from `start` along `along`, the front panel facing
// `front` at `offset` from the line and the back one facing away, sewn at both sides (the
// front's right edge to the back's left, its left to the back's right).
void add_tube(Garment& garment, const std::string& name, double circumference, double length,
              const Vec3& start, const Vec3& along, const Vec3& front, double offset) {
  const int f = static_cast<int>(garment.panels.size());
  garment.panels.push_back(
      placed_panel(name + " front", circumference / 2, length, start, along, front, offset));
  garment.panels.push_back(
      placed_panel(name + " back", circumference / 2, length, start, along, -front, offset));
  garment.seams.push_back({f, "right", f + 1, "left", false});
  garment.seams.push_back({f, "left", f + 1, "right", false});
}

// The dressing of three tubes and two trouser legs on the person of cylinders, each tube 5 %
// shorter round than its part (a tight garment), its flat panels `offset` outside the part's
// surface in front of and behind it, the torso's below the armpits, the sleeves on the arms'
// middles, the legs on the shins and knees. Checks what every such dressing must give: every
// panel starts outside the shrunk body, every seam closes, no welded vertex is put back from
// deeper than a quarter edge, each sleeve ends round its own arm, and no triangle edge is
// stretched past `max_edge_stretch` times its rest length (a seam vertex pulled out of its
// panel leaves edges many times their rest length).
void dress_tubes_round_limbs(double offset_m, double max_edge_stretch) {
  const BodyMeasurements measured = measure_body(testing::synthetic_person(45.0));
  const TriangleSurface person = person_of_pieces(45.0);
  MeshBodyOptions faceted;
  const MeshBody body(person, faceted, "synthetic person");

  Garment garment;
  const double torso_perimeter =
      M_PI * (3 * (0.16 + 0.11) - std::sqrt((3 * 0.16 + 0.11) * (0.16 + 3 * 0.11)));
  const double armpit = SyntheticPerson::armpit_z(45.0);
  add_tube(garment, "torso", 0.95 * torso_perimeter, armpit - 0.05 - 0.85, Vec3(0, 0, 0.85),
           Vec3::UnitZ(), -Vec3::UnitY(), SyntheticPerson::torso_b + offset_m + 0.02);
  for (const char* side : {"left", "right"}) {
    const PartFrame& arm = part_named(measured, std::string("arm ") + side);
    add_tube(garment, std::string("sleeve ") + side, 0.95 * 2 * M_PI * SyntheticPerson::arm_r, 0.25,
             arm.origin_m + 0.15 * arm.along, arm.along, -Vec3::UnitY(),
             SyntheticPerson::arm_r + offset_m);
    const PartFrame& leg = part_named(measured, std::string("leg ") + side);
    add_tube(garment, std::string("leg ") + side, 0.95 * 2 * M_PI * SyntheticPerson::leg_r, 0.3,
             leg.origin_m + 0.55 * leg.along, -leg.along, -Vec3::UnitY(),
             SyntheticPerson::leg_r + offset_m);
  }
  const SimulationMesh mesh = weld(garment);
  FabricParameters fabric;
  const std::unique_ptr<MaterialLaw> law = make_material_law("linear biot", fabric);
  Problem problem;
  problem.mesh = &mesh;
  problem.law = law.get();
  problem.fabric = &fabric;
  problem.body = &body;
  problem.contact_stiffness_Pa_per_m =
      penalty_stiffness_Pa_per_m(50.0, law->stiffness_scale(), mean_rest_edge_length_m(mesh));

  const std::vector<Vec3> start =
      arranged_positions(garment, mesh, unfitted_arrangement(Mat3::Identity()));
  DressingSettings settings;
  draw_seams_from_afar(settings);  // as Placement/Kind = pattern arrangement dresses
  settings.skeleton = skeleton_bones(measured);
  settings.start_scale = 0.6;
  settings.growth_frames = 1500;
  settings.seam_ramp_frames = 500;

  // Every panel vertex starts outside the body shrunk about its skeleton.
  SkeletonShrunkBody shrunk(person, settings.skeleton);
  shrunk.set_scale(settings.start_scale);
  for (std::size_t u = 0; u < start.size(); ++u)
    EXPECT_GT(shrunk.query(start[u]).signed_distance_m, 0.0) << "panel vertex " << u;

  const DressingResult dressed = dress(problem, garment, start, settings);
  EXPECT_LT(dressed.largest_seam_gap_m, dressed.closed_below_m);
  // dress() refuses a welded vertex deeper than a quarter edge; none is put back deeper.
  EXPECT_LE(dressed.deepest_m, 0.25 * mean_rest_edge_length_m(mesh));

  // Each sleeve ends round its own arm: every vertex within 1.5 cm of the arm's surface (the
  // tube is 5 % smaller round than the arm: it touches it, the seams' ridges stand off a few
  // mm; 1.5 cm is the margin).
  for (const char* side : {"left", "right"}) {
    const PartFrame& arm = part_named(measured, std::string("arm ") + side);
    const std::string sleeve = std::string("sleeve ") + side;
    for (int p = 0; p < static_cast<int>(garment.panels.size()); ++p) {
      if (garment.panels[p].name.rfind(sleeve, 0) != 0) continue;
      for (int i = 0; i < static_cast<int>(garment.panels[p].rest_positions_m.size()); ++i) {
        const Vec3& x =
            dressed.welded_positions_m[mesh.welded_index[mesh.panel_vertex_offset[p] + i]];
        const Vec3 d = x - arm.origin_m;
        const double r = (d - d.dot(arm.along) * arm.along).norm();
        EXPECT_NEAR(r, SyntheticPerson::arm_r, 0.015) << sleeve << " vertex " << i;
      }
    }
  }
  double stretch = 0.0;
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const double rest = (mesh.rest_triangles[k][j] - mesh.rest_triangles[k][i]).norm();
      const double now = (dressed.welded_positions_m[mesh.triangles[k][j]] -
                          dressed.welded_positions_m[mesh.triangles[k][i]])
                             .norm();
      stretch = std::max(stretch, now / rest);
    }
  std::printf("panels %.2f m out: %d frames, the longest edge %.3f times its rest length\n",
              offset_m, dressed.frames, stretch);
  EXPECT_LT(stretch, max_edge_stretch);
}

TEST(SkeletonDressing, TubeSleevesAndLegsPlacedFlatCloseRoundTheirLimbs) {
  // Panels 4 cm out; a tube 5 % smaller round than its part stretches about 5 % round it, more
  // along the seams' ridges: 1.5 times the rest length allowed.
  dress_tubes_round_limbs(0.04, 1.5);
}

TEST(SkeletonDressing, PanelsFarApartAreDrawnTogetherWithoutTearing) {
  // Panels 15 cm out, so that each seam starts 0.3 to 0.5 m open across its limb, as a
  // GarmentCode file arranges a garment's front and back: the seams close while the body waits
  // at its start scale and no seam vertex is pulled out of its panel (no edge past 1.5 times its
  // rest length, as for the near start).
  dress_tubes_round_limbs(0.15, 1.5);
}

}  // namespace
}  // namespace tightfit
