// Placements read off the body's landmarks (docs/dressing.md, "The frame from the landmarks";
// docs/stocking.md): the dressing's frame on a person of cylinders and spheres whose torso is an
// elliptic cylinder (tests/body/synthetic_body.h: its axis, semi-axes and armpits known by
// construction), and the line along a leg built as a tilted frustum (its axis known).
#include "../body/synthetic_body.h"
#include "body/body_measurements.h"
#include "cases/dressing_frame.h"
#include "cases/limb_tube_cut.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

namespace tightfit {
namespace {

using testing::SyntheticLegs;
using testing::SyntheticPerson;

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(DressingFrame, TheTorsosFrameAndSemiAxesOfAnEllipticTorso) {
  const BodyMeasurements body = measure_body(testing::synthetic_person(45));
  const DressingFrameSpec spec = parse_dressing_frame("torso", "torso", "torso", "bust + 0.01",
                                                      "waist + 0.02", "armpit - 0.3");
  ASSERT_TRUE(spec.needs_landmarks());
  const double scale = 0.7;
  const PanelWrap wrap = resolve_dressing_frame(spec, &body, scale);
  std::printf("centre (%.6f, %.6f, %.6f) axis (%.6f, %.6f, %.6f) semi-axes %.6f %.6f hem %.6f\n",
              wrap.centre_m.x(), wrap.centre_m.y(), wrap.centre_m.z(), wrap.axis.x(), wrap.axis.y(),
              wrap.axis.z(), wrap.semi_axis_side_m, wrap.semi_axis_front_m, wrap.hem_height_m);
  // The torso is the elliptic cylinder round the z axis (x = y = 0) from the crotch up: its axis
  // through the centroids of its 256-gon sections, symmetric about x = 0 and y = 0, lies on it
  // to round-off (1e-9 m and 1e-9 asked); the centre at the crotch, which the scan bisects to
  // 1e-3 m (tests/body/test_synthetic_person.cc).
  EXPECT_NEAR(wrap.centre_m.x(), 0.0, 1e-9);
  EXPECT_NEAR(wrap.centre_m.y(), 0.0, 1e-9);
  EXPECT_NEAR(wrap.centre_m.z(), SyntheticPerson::crotch_m, 1e-3);
  EXPECT_NEAR(wrap.axis.dot(Vec3::UnitZ()), 1.0, 1e-12);
  EXPECT_NEAR(wrap.front.dot(-Vec3::UnitY()), 1.0, 1e-12);
  // The semi-axes: the ellipse's own (0.16 m across, 0.11 m deep; the 256-gon has vertices at
  // both ends of each) times the start scale, plus the clearance: 1e-9 m.
  EXPECT_NEAR(wrap.semi_axis_side_m, scale * SyntheticPerson::torso_a + 0.01, 1e-9);
  EXPECT_NEAR(wrap.semi_axis_front_m, scale * SyntheticPerson::torso_b + 0.02, 1e-9);
  // The hem 0.3 m below the armpits, from the centre at the crotch: the armpit found to 3 mm and
  // the crotch to 1 mm (the same margins as the landmark tests).
  EXPECT_NEAR(wrap.hem_height_m, SyntheticPerson::armpit_z(45) - 0.3 - SyntheticPerson::crotch_m,
              4e-3);

  // The centre at a line: the axis's point at the waist's height; a vertical axis is z.
  const DressingFrameSpec at_waist =
      parse_dressing_frame("torso at waist", "vertical", "torso", "0.2", "0.15", "waist");
  const PanelWrap w = resolve_dressing_frame(at_waist, &body, scale);
  EXPECT_NEAR(w.centre_m.z(), body.girth("waist").centre_m.z(), 1e-9);
  EXPECT_NEAR(w.centre_m.x(), 0.0, 1e-9);
  EXPECT_NEAR(w.hem_height_m, 0.0, 1e-9);
  EXPECT_EQ(w.axis, Vec3::UnitZ());
  EXPECT_EQ(w.semi_axis_side_m, 0.2);
}

TEST(DressingFrame, NumbersAloneNeedNoBody) {
  const DressingFrameSpec spec =
      parse_dressing_frame("0, -0.05, 0", "0,0,2", "0,-1,0", "0.12", "0.135", "0.02");
  EXPECT_FALSE(spec.needs_landmarks());
  const PanelWrap wrap = resolve_dressing_frame(spec, nullptr, 0.7);
  EXPECT_EQ(wrap.centre_m, Vec3(0, -0.05, 0));
  EXPECT_EQ(wrap.axis, Vec3::UnitZ());
  EXPECT_EQ(wrap.semi_axis_side_m, 0.12);
  EXPECT_EQ(wrap.semi_axis_front_m, 0.135);
  EXPECT_EQ(wrap.hem_height_m, 0.02);
}

TEST(DressingFrame, UnknownNamesAreRefusedWithTheNearestName) {
  const auto parse = [](const char* centre, const char* axis, const char* side, const char* hem) {
    return message_of([&] { parse_dressing_frame(centre, axis, "torso", side, "bust", hem); });
  };
  EXPECT_NE(parse("torsoo", "torso", "bust", "0").find("did you mean 'torso'"), std::string::npos);
  EXPECT_NE(parse("torso at wiast", "torso", "bust", "0").find("did you mean 'waist'"),
            std::string::npos);
  EXPECT_NE(parse("torso", "torso", "busts + 0.01", "0").find("did you mean 'bust'"),
            std::string::npos);
  EXPECT_NE(parse("torso", "torso", "bust", "armpits - 0.3").find("did you mean 'armpit'"),
            std::string::npos);
  EXPECT_NE(parse("torso", "torso", "bust", "armpit - 3 cm").find("Hem height"), std::string::npos);
  EXPECT_NE(parse("torso", "torso", "-0.1", "0").find("must be positive"), std::string::npos);
  EXPECT_NE(parse("torso", "0,0,0", "0.1", "0").find("must not be zero"), std::string::npos);
  // A frame that needs landmarks on a body without them.
  const DressingFrameSpec spec = parse_dressing_frame("torso", "torso", "torso", "0.1", "0.1", "0");
  EXPECT_NE(message_of([&] { resolve_dressing_frame(spec, nullptr, 0.7); }).find("landmarks"),
            std::string::npos);
}

TEST(LegLine, AlongATiltedFrustumLeg) {
  // Legs as frusta tapering from 7 cm at the top to 4 cm at the floor, tilted 8 degrees out.
  SyntheticLegs legs;
  legs.tilt_deg = 8;
  legs.foot_r = 0.04;
  legs.top_r = 0.07;
  const TriangleSurface person = testing::synthetic_person(45, legs);
  const BodyMeasurements body = measure_body(person);
  for (const int side : {0, 1}) {
    const LegLine line = leg_line(person, body, side, "B", "G");
    const Vec3 up = legs.up(side), foot = legs.foot(side);
    // The distance of the line's point from the frustum's axis, and its direction's angle from
    // it: the centroids of sections normal to the leg's fitted axis (the fit through the
    // horizontal sections' centroids, each an ellipse whose centre lies off the cone's axis by
    // up to r tan(taper) tan(tilt), 0.2 mm here, the offsets growing evenly along the leg, so
    // the fitted line turns by little). Measured 2.5e-7 m and 2.1e-7 rad; 1e-5 m and 1e-5 rad
    // asked.
    const Vec3 off = (line.point_m - foot) - (line.point_m - foot).dot(up) * up;
    const double angle = std::acos(std::min(1.0, line.up.dot(up)));
    std::printf("leg %d: %.3g m off the axis, %.3g rad from it\n", side, off.norm(), angle);
    EXPECT_LT(off.norm(), 1e-5) << side;
    EXPECT_LT(angle, 1e-5) << side;
    // The measuring points in order up the leg, B low and G high: B within 15 % of the height
    // above the floor, G an eighth of the crotch height below the crotch (along the axis).
    LimbTubeEnd b{"B", 0.0}, g{"G", 0.0};
    const double height = SyntheticPerson::top_m;
    EXPECT_LT(line.at(line.axial_at(b, "From")).z(), 0.15 * height + 1e-3) << side;
    EXPECT_NEAR(line.at(line.axial_at(g, "To")).z(), SyntheticPerson::crotch_m * 7 / 8, 0.01)
        << side;
  }
}

}  // namespace
}  // namespace tightfit
