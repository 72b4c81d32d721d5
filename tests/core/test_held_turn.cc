// The held turn (core/held_turn.h) against closed forms: a ring of vertices round the z axis,
// its masses unequal so the centre of mass is off the ring's centre.
#include "core/held_turn.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tightfit {
namespace {

struct Ring {
  std::vector<Vec3> x;
  std::vector<double> mass_kg;
  Vec3 centre = Vec3::Zero();
};

Ring ring(int n) {
  Ring r;
  double mass = 0.0;
  for (int i = 0; i < n; ++i) {
    const double phi = 2.0 * M_PI * i / n;
    r.x.push_back(Vec3(0.05 * std::cos(phi), 0.04 * std::sin(phi), 0.01 * i));
    r.mass_kg.push_back(1e-4 * (1.0 + 0.5 * (i % 3)));
    r.centre += r.mass_kg.back() * r.x.back();
    mass += r.mass_kg.back();
  }
  r.centre /= mass;
  return r;
}

VertexConstraint held_all(int n, const Vec3& direction) {
  VertexConstraint c;
  c.group = "all";
  c.direction = direction;
  for (int i = 0; i < n; ++i) c.vertices.push_back(i);
  return c;
}

double torque(const Ring& r, const std::vector<Vec3>& f) {
  double tau = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i)
    tau += Vec3::UnitZ().cross(r.x[i] - r.centre).dot(f[i]);
  return tau;
}

TEST(HeldTurn, ActiveOnlyWhenEveryVertexIsHeldAlongOneDirection) {
  EXPECT_TRUE(HeldTurn({held_all(12, Vec3(0, 0, 2))}, 12).active());
  EXPECT_FALSE(HeldTurn({held_all(12, Vec3::UnitZ())}, 13).active());  // one vertex free
  EXPECT_FALSE(HeldTurn({}, 12).active());
  VertexConstraint half = held_all(6, Vec3::UnitZ()), other = held_all(12, Vec3::UnitX());
  EXPECT_FALSE(HeldTurn({half, other}, 12).active());  // two directions: no single axis
  VertexConstraint fixed = held_all(12, Vec3::UnitZ());
  fixed.kind = VertexConstraint::Kind::fixed;
  EXPECT_FALSE(HeldTurn({fixed}, 12).active());
  EXPECT_DOUBLE_EQ(HeldTurn({held_all(12, Vec3(0, 0, 2))}, 12).axis().z(), 1.0);
}

TEST(HeldTurn, RigidTurnIsRemovedWholeAndOtherFieldsKeepTheirNetForce) {
  const Ring r = ring(12);
  const HeldTurn turn({held_all(12, Vec3::UnitZ())}, 12);
  // A pure angular acceleration of 3 rad/s^2: f_i = m_i * 3 * (z x (x_i - c)); the torque
  // removed is 3 * I, I = sum m_i |z x (x_i - c)|^2, and nothing is left.
  std::vector<Vec3> f(12);
  double inertia = 0.0;
  for (int i = 0; i < 12; ++i) {
    const Vec3 t = Vec3::UnitZ().cross(r.x[i] - r.centre);
    f[i] = r.mass_kg[i] * 3.0 * t;
    inertia += r.mass_kg[i] * t.squaredNorm();
  }
  EXPECT_NEAR(turn.remove_from_forces(r.x, r.mass_kg, f), 3.0 * inertia, 1e-15);
  for (const Vec3& fi : f) EXPECT_LT(fi.norm(), 1e-18);

  // Any field: afterwards no torque about the axis; the net force and every axial component
  // are unchanged (sum_i m_i t_i = 0 and t_i is normal to the axis).
  std::vector<Vec3> g(12), before(12);
  for (int i = 0; i < 12; ++i) g[i] = before[i] = Vec3(std::sin(i), std::cos(3.0 * i), 0.1 * i);
  turn.remove_from_forces(r.x, r.mass_kg, g);
  EXPECT_NEAR(torque(r, g), 0.0, 1e-15);
  Vec3 net_before = Vec3::Zero(), net_after = Vec3::Zero();
  for (int i = 0; i < 12; ++i) {
    net_before += before[i];
    net_after += g[i];
    EXPECT_DOUBLE_EQ(g[i].z(), before[i].z());
  }
  EXPECT_LT((net_after - net_before).norm(), 1e-14);
}

TEST(HeldTurn, VelocitiesLoseTheirAngularMomentumAboutTheAxisOnly) {
  const Ring r = ring(12);
  const HeldTurn turn({held_all(12, Vec3::UnitZ())}, 12);
  // A uniform translation has no angular momentum about the centre of mass: kept as it is.
  std::vector<Vec3> v(12, Vec3(0.2, -0.1, 0.0));
  turn.remove_from_velocities(r.x, r.mass_kg, v);
  for (const Vec3& vi : v) EXPECT_LT((vi - Vec3(0.2, -0.1, 0.0)).norm(), 1e-15);
  // A spin plus that translation: the spin goes.
  for (int i = 0; i < 12; ++i) v[i] += 5.0 * Vec3::UnitZ().cross(r.x[i] - r.centre);
  turn.remove_from_velocities(r.x, r.mass_kg, v);
  for (const Vec3& vi : v) EXPECT_LT((vi - Vec3(0.2, -0.1, 0.0)).norm(), 1e-15);
}

TEST(HeldTurn, InactiveLeavesFieldsAlone) {
  const Ring r = ring(12);
  std::vector<Vec3> f(12, Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(HeldTurn().remove_from_forces(r.x, r.mass_kg, f), 0.0);
  for (const Vec3& fi : f) EXPECT_EQ(fi, Vec3(1.0, 2.0, 3.0));
}

}  // namespace
}  // namespace tightfit
