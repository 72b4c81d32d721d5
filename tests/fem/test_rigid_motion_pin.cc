// The general rigid-motion pin (fem/rigid_motion_pin.h) against the rigid motions each body is
// known to leave free: a cylinder the turn about its axis and the slide along it, a cone the
// turn, a plane two slides and the turn about its normal; held ends take the slide away,
// friction all of them. A pin set is right when it stops each known free motion (the matrix
// of its directions against those motions has full rank) and there are exactly as many
// directions as free motions (no force-bearing motion is pinned).
#include "bodies/cone.h"
#include "bodies/cylinder.h"
#include "bodies/plane.h"
#include "fem/rigid_motion_pin.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <functional>
#include <vector>

namespace tightfit {
namespace {

using Velocity = std::function<Vec3(const Vec3&)>;

// A ring of rows round the z axis: radius r(z), 12 round by 5 along.
std::vector<Vec3> tube_points(const std::function<double(double)>& radius) {
  std::vector<Vec3> x;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 12; ++j) {
      const double z = -0.04 + 0.02 * k, phi = 2 * M_PI * j / 12;
      x.emplace_back(radius(z) * std::cos(phi), radius(z) * std::sin(phi), z);
    }
  return x;
}

// Rank of the pins' directions against the known free motions, and the directions' count.
void expect_stops_exactly(const RigidMotionPin& pin, const std::vector<Vec3>& x,
                          const std::vector<Velocity>& free) {
  int n_directions = 0;
  for (const auto& p : pin.pins) n_directions += static_cast<int>(p.directions.size());
  EXPECT_EQ(pin.n_free_motions, static_cast<int>(free.size()));
  ASSERT_EQ(n_directions, static_cast<int>(free.size()));
  Eigen::MatrixXd A(n_directions, free.size());
  int row = 0;
  for (const auto& p : pin.pins)
    for (const Vec3& d : p.directions) {
      for (std::size_t m = 0; m < free.size(); ++m) A(row, m) = d.dot(free[m](x[p.vertex]));
      ++row;
    }
  if (free.empty()) return;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A);
  // Each direction is a unit vector and each motion moves the pinned vertex by O(1) (turns
  // per unit angle by the radius, 5 cm): well away from zero.
  EXPECT_GT(svd.singularValues().minCoeff(), 1e-3);
}

const Vec3 kZ = Vec3::UnitZ();
const Velocity turn_z = [](const Vec3& x) { return Vec3(kZ.cross(x)); };
const Velocity slide_z = [](const Vec3&) { return kZ; };

TEST(RigidMotionPin, CylinderLeavesTurnAndSlide) {
  const Cylinder cylinder(Vec3::Zero(), kZ, 0.05);
  const std::vector<Vec3> x = tube_points([](double) { return 0.05; });
  const RigidMotionPin pin = rigid_motion_pin(cylinder, x, ConstrainedDirections({}, 60), false);
  expect_stops_exactly(pin, x, {turn_z, slide_z});
  ASSERT_EQ(pin.pins.size(), 1u);
  // Nearest the centroid: the middle row (z = 0).
  EXPECT_NEAR(x[pin.pins[0].vertex].z(), 0.0, 1e-12);
}

TEST(RigidMotionPin, HeldEndsLeaveOnlyTheTurn) {
  const Cylinder cylinder(Vec3::Zero(), kZ, 0.05);
  const std::vector<Vec3> x = tube_points([](double) { return 0.05; });
  VertexConstraint bottom;
  bottom.direction = kZ;
  for (int j = 0; j < 12; ++j) bottom.vertices.push_back(j);
  const ConstrainedDirections held({bottom}, 60);
  const RigidMotionPin pin = rigid_motion_pin(cylinder, x, held, false);
  expect_stops_exactly(pin, x, {turn_z});
  EXPECT_FALSE(held.constrained(pin.pins[0].vertex));
}

// Every vertex held along the axis leaves the turn about it free; when that turn is held by the
// bordered Newton system (fem/held_turn_system.h) no rigid motion is free.
TEST(RigidMotionPin, AHeldTurnIsNotPinned) {
  const Cylinder cylinder(Vec3::Zero(), kZ, 0.05);
  const std::vector<Vec3> x = tube_points([](double) { return 0.05; });
  VertexConstraint all;
  all.direction = kZ;
  for (int j = 0; j < 60; ++j) all.vertices.push_back(j);
  const ConstrainedDirections held({all}, 60);
  // The turn is found free (every vertex being held, none is left to pin it with).
  EXPECT_EQ(rigid_motion_pin(cylinder, x, held, false).n_free_motions, 1);
  const RigidMotionPin held_turn = rigid_motion_pin(cylinder, x, held, false, &kZ);
  EXPECT_EQ(held_turn.n_free_motions, 0);
  EXPECT_TRUE(held_turn.pins.empty());
}

TEST(RigidMotionPin, ConeLeavesTheTurn) {
  ConeOptions options;
  options.half_angle_deg = 10;
  options.radius_at_point_m = 0.05;
  const Cone cone(options);
  const double tan_a = std::tan(10 * M_PI / 180);
  const std::vector<Vec3> x = tube_points([&](double z) { return 0.05 + z * tan_a; });
  expect_stops_exactly(rigid_motion_pin(cone, x, ConstrainedDirections({}, 60), false), x,
                       {turn_z});
}

TEST(RigidMotionPin, PlaneLeavesTwoSlidesAndATurn) {
  const Plane plane(Vec3::Zero(), kZ);
  std::vector<Vec3> x;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) x.emplace_back(0.01 * i, 0.01 * j, 0.0);
  const Vec3 c(0.025, 0.025, 0.0);
  const Velocity slide_x = [](const Vec3&) { return Vec3(Vec3::UnitX()); };
  const Velocity slide_y = [](const Vec3&) { return Vec3(Vec3::UnitY()); };
  const Velocity turn = [&](const Vec3& p) { return Vec3(kZ.cross(p - c)); };
  const RigidMotionPin pin = rigid_motion_pin(plane, x, ConstrainedDirections({}, 36), false);
  expect_stops_exactly(pin, x, {slide_x, slide_y, turn});
  // One vertex can stop only the two slides and the turn's own motion there, which is along
  // the plane: the turn needs a second vertex.
  EXPECT_EQ(pin.pins.size(), 2u);
}

TEST(RigidMotionPin, FrictionPinsNothing) {
  const Cylinder cylinder(Vec3::Zero(), kZ, 0.05);
  const std::vector<Vec3> x = tube_points([](double) { return 0.05; });
  EXPECT_TRUE(rigid_motion_pin(cylinder, x, ConstrainedDirections({}, 60), true).pins.empty());
}

}  // namespace
}  // namespace tightfit
