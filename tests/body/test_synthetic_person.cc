// Landmarks and girths of a person built from cylinders and spheres (synthetic_body.h), whose
// crotch, armpits, height and girths are known by construction; the same person in A-pose and
// T-pose gives the same girths; a person without legs is refused naming the crotch.
#include "body/body_measurements.h"
#include "synthetic_body.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit {
namespace {

using testing::SyntheticPerson;
constexpr double pi = 3.14159265358979323846;

double ramanujan_perimeter(double a, double b) {
  return pi * (3 * (a + b) - std::sqrt((3 * a + b) * (a + 3 * b)));
}

class SyntheticPersonTest : public ::testing::TestWithParam<double> {};

TEST_P(SyntheticPersonTest, LandmarksAndGirthsAsBuilt) {
  const double angle = GetParam();
  const BodyMeasurements m = measure_body(testing::synthetic_person(angle));
  // The floor, the top and the crotch are flat caps and a pole: the scan's bisection finds the
  // crotch to 1e-3 m (its levels are 2 mm apart; measured within 1e-5 m).
  EXPECT_NEAR(m.length("height").length_m, SyntheticPerson::top_m, 1e-9);
  EXPECT_NEAR(m.landmark("crotch").point_m.z(), SyntheticPerson::crotch_m, 1e-3);
  // The armpit where the arm's underside meets the torso's side (1.2434 m in A-pose, 1.30 m in
  // T-pose): 3 mm allows for the 96-gon arm's flats (r (1 - cos(pi/96)) = 2e-5 m) and the
  // scan's 2 mm levels before the bisection.
  for (const char* side : {"armpit left", "armpit right"})
    EXPECT_NEAR(m.landmark(side).point_m.z(), SyntheticPerson::armpit_z(angle), 3e-3) << side;
  // Every torso girth is the torso's ellipse (a 256-gon: 1e-4 relative below Ramanujan's).
  const double torso = ramanujan_perimeter(SyntheticPerson::torso_a, SyntheticPerson::torso_b);
  for (const char* g : {"bust", "under-bust", "waist", "hips"})
    EXPECT_NEAR(m.girth(g).girth_m, torso, 1e-4 * torso) << g;
  // The legs' and arms' girths are their circles' 128-gon and 96-gon, cut normal to the axis.
  const double leg = 2 * 128 * SyntheticPerson::leg_r * std::sin(pi / 128);
  for (const char* g : {"B left", "C left", "knee left", "G left", "thigh left", "B right"})
    EXPECT_NEAR(m.girth(g).girth_m, leg, 1e-6) << g;
  const double arm = 2 * 96 * SyntheticPerson::arm_r * std::sin(pi / 96);
  for (const char* g : {"wrist left", "upper arm left", "wrist right", "upper arm right"})
    EXPECT_NEAR(m.girth(g).girth_m, arm, 1e-4) << g;
  // The arm's axis along the arm as built.
  const double t = angle * pi / 180;
  EXPECT_NEAR(m.part("arm left").along.dot(Vec3(std::sin(t), 0, -std::cos(t))), 1.0, 1e-4);
  EXPECT_NEAR(m.part("leg left").along.dot(-Vec3::UnitZ()), 1.0, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(APoseAndTPose, SyntheticPersonTest, ::testing::Values(45.0, 90.0));

TEST(SyntheticPerson, APoseAndTPoseGiveTheSameGirths) {
  const BodyMeasurements a = measure_body(testing::synthetic_person(45));
  const BodyMeasurements t = measure_body(testing::synthetic_person(90));
  ASSERT_EQ(a.girths.size(), t.girths.size());
  // The same body in two poses: every girth alike to 1e-4 m (the polygons' flats met at other
  // angles; measured below 2e-5 m).
  for (std::size_t i = 0; i < a.girths.size(); ++i)
    EXPECT_NEAR(a.girths[i].girth_m, t.girths[i].girth_m, 1e-4) << a.girths[i].name;
}

TEST(SyntheticPerson, NoLegsIsRefusedNamingTheCrotch) {
  try {
    measure_body(testing::synthetic_person(45, false));
    FAIL() << "a body without legs was measured";
  } catch (const BodyMeasureError& e) {
    EXPECT_NE(std::string(e.what()).find("crotch"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no two legs apart"), std::string::npos) << e.what();
  }
}

TEST(SyntheticPerson, ArmsAgainstTheTorsoAreRefusedNamingTheArmpit) {
  // Arms hanging straight down inside the torso's outline: no armpit can be found.
  try {
    measure_body(testing::synthetic_person(0.5));
    FAIL() << "a body with its arms in the torso was measured";
  } catch (const BodyMeasureError& e) {
    EXPECT_NE(std::string(e.what()).find("armpit"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tightfit
