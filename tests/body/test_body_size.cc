// The size check of a loaded body: a body in millimetres read as metres, one in metres read as
// millimetres and one lying down are each refused with a message that names the cause and the
// entry to change; a person of ordinary size passes.
#include "body/body_measurements.h"
#include "body/body_size.h"

#include <gtest/gtest.h>

namespace tightfit {
namespace {

BodyExtent box(const Vec3& size) {
  BodyExtent e;
  e.max_m = size;
  return e;
}

std::string refusal(const BodyExtent& e) {
  try {
    check_standing_person(e, "body 'x.obj'");
  } catch (const BodyMeasureError& error) {
    return error.what();
  }
  return "";
}

TEST(BodySize, PersonOfOrdinarySizePasses) {
  EXPECT_EQ(refusal(box(Vec3(0.6, 0.3, 1.7))), "");
}

TEST(BodySize, MillimetresReadAsMetresAreRefusedNamingTheUnits) {
  const std::string m = refusal(box(Vec3(600, 300, 1700)));
  EXPECT_NE(m.find("1700.000 m tall"), std::string::npos) << m;
  EXPECT_NE(m.find("Unit scale"), std::string::npos) << m;
  EXPECT_NE(m.find("0.001 for millimetres"), std::string::npos) << m;
}

TEST(BodySize, MetresReadAsMillimetresAreRefusedNamingTheUnits) {
  const std::string m = refusal(box(Vec3(0.0006, 0.0003, 0.0017)));
  EXPECT_NE(m.find("under 1 cm"), std::string::npos) << m;
  EXPECT_NE(m.find("--units"), std::string::npos) << m;
}

TEST(BodySize, PersonLyingDownIsRefusedNamingTheUpAxis) {
  const std::string m = refusal(box(Vec3(0.6, 1.7, 0.3)));
  EXPECT_NE(m.find("lies down along y"), std::string::npos) << m;
  EXPECT_NE(m.find("Up axis"), std::string::npos) << m;
}

TEST(BodySize, LimbAndCubeOfACaseAreNotPeopleButPass) {
  // check_body_size alone (any case body): a leg, a 2 m cube.
  EXPECT_NO_THROW(check_body_size(box(Vec3(0.15, 0.15, 0.9)), "leg"));
  EXPECT_NO_THROW(check_body_size(box(Vec3(2, 2, 2)), "cube"));
  EXPECT_THROW(check_body_size(box(Vec3(200, 200, 200)), "cube"), BodyMeasureError);
  // A leg in metres read as millimetres: 0.9 mm long.
  EXPECT_THROW(check_body_size(box(Vec3(0.00015, 0.00015, 0.0009)), "leg"), BodyMeasureError);
}

}  // namespace
}  // namespace tightfit
