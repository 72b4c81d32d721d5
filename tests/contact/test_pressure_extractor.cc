// The pressure extractor on fields whose pressure is known, and its summaries.
#include "contact/pressure_extractor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tightfit {
namespace {

// A tube of n_round x n_along vertices on a cylinder of radius r round the z axis. Each
// rectangle between neighbouring vertices is cut along alternating diagonals (a union-jack
// pattern), so every vertex, including those on the tube's two rims, has as many triangles on
// each side of it: the area-weighted vertex normal is then exactly radial. Every rectangle is
// planar (two parallel axial edges), and its triangles have the same area: half of
// chord * dz, with chord = 2 r sin(pi / n_round).
struct Tube {
  int n_round = 24, n_along = 7;
  double radius_m = 0.05, dz_m = 0.01;
  std::vector<Vec3> positions_m;
  std::vector<Triangle> triangles;
  std::vector<Vec3> radial;  // exact outward normal at each vertex

  Tube() {
    for (int j = 0; j < n_along; ++j)
      for (int i = 0; i < n_round; ++i) {
        const double phi = 2.0 * M_PI * i / n_round;
        radial.emplace_back(std::cos(phi), std::sin(phi), 0.0);
        positions_m.push_back(radius_m * radial.back() + Vec3(0, 0, j * dz_m));
      }
    for (int j = 0; j + 1 < n_along; ++j)
      for (int i = 0; i < n_round; ++i) {
        const int a = j * n_round + i, b = j * n_round + (i + 1) % n_round;
        const int c = b + n_round, d = a + n_round;
        if ((i + j) % 2 == 0) {
          triangles.push_back({a, b, c});
          triangles.push_back({a, c, d});
        } else {
          triangles.push_back({a, b, d});
          triangles.push_back({b, c, d});
        }
      }
  }
  int n_vertices() const { return static_cast<int>(positions_m.size()); }
  double triangle_area_m2() const { return 0.5 * 2.0 * radius_m * std::sin(M_PI / n_round) * dz_m; }
  // A third of every adjacent triangle.
  std::vector<double> barycentric_area_m2() const {
    std::vector<double> area(n_vertices(), 0.0);
    for (const Triangle& t : triangles)
      for (int v : t) area[v] += triangle_area_m2() / 3.0;
    return area;
  }
};

// Equilibrium under a uniform pressure p on the body: the body pushes p A_v n_v on each
// vertex and the garment's own force -p A_v n_v balances it.
SurfaceState pressed_state(const Tube& tube, double pressure_Pa) {
  SurfaceState state;
  state.positions_m = tube.positions_m;
  const auto area = tube.barycentric_area_m2();
  for (int v = 0; v < tube.n_vertices(); ++v) {
    state.internal_force_N.push_back(-pressure_Pa * area[v] * tube.radial[v]);
    state.contact_force_N.push_back(pressure_Pa * area[v] * tube.radial[v]);
  }
  state.in_contact.assign(tube.n_vertices(), 1);
  return state;
}

TEST(PressureExtractor, BothDefinitionsReadTheUniformPressureAtEquilibrium) {
  const Tube tube;
  const Cylinder body(Vec3::Zero(), Vec3::UnitZ(), tube.radius_m);
  const double p = 640.0;
  for (PressureDefinition definition :
       {PressureDefinition::contact_traction, PressureDefinition::garment_force}) {
    const PressureField field =
        extract_pressure(tube.triangles, pressed_state(tube, p), VertexAreaDefinition::barycentric,
                         &body, definition);
    EXPECT_EQ(field.definition, definition);
    for (int v = 0; v < tube.n_vertices(); ++v) {
      EXPECT_NEAR(field.pressure_Pa[v], p, 1e-9 * p) << to_string(definition) << ", vertex " << v;
      EXPECT_NEAR(field.friction_traction_Pa[v], 0.0, 1e-9 * p);
    }
  }
}

TEST(PressureExtractor, ContactTractionSplitsTheContactForceIntoPressureAndFriction) {
  // The body pushes p A n and rubs tau A along the axis; the garment's own force is some other
  // force (here nothing balances: gravity or an unfinished solve). The contact traction reads p
  // and tau whatever the garment's force; the paper's definition reads that force.
  const Tube tube;
  const Cylinder body(Vec3::Zero(), Vec3::UnitZ(), tube.radius_m);
  const double p = 300.0, tau = 45.0, garment_Pa = 120.0;
  SurfaceState state = pressed_state(tube, p);
  const auto area = tube.barycentric_area_m2();
  for (int v = 0; v < tube.n_vertices(); ++v) {
    state.contact_force_N[v] += tau * area[v] * Vec3::UnitZ();
    state.internal_force_N[v] = -garment_Pa * area[v] * tube.radial[v];
  }
  const PressureField contact =
      extract_pressure(tube.triangles, state, VertexAreaDefinition::barycentric, &body);
  const PressureField paper =
      extract_pressure(tube.triangles, state, VertexAreaDefinition::barycentric, &body,
                       PressureDefinition::garment_force);
  EXPECT_EQ(contact.definition, PressureDefinition::contact_traction);  // the default
  for (int v = 0; v < tube.n_vertices(); ++v) {
    EXPECT_NEAR(contact.pressure_Pa[v], p, 1e-9 * p);
    EXPECT_NEAR(contact.normal_force_N[v], p * area[v], 1e-9 * p * area[v]);
    EXPECT_NEAR(contact.friction_traction_Pa[v], tau, 1e-9 * p);
    EXPECT_NEAR(paper.pressure_Pa[v], garment_Pa, 1e-9 * p);
    EXPECT_NEAR(paper.friction_traction_Pa[v], tau, 1e-9 * p);
  }
}

TEST(PressureExtractor, TubeReadsTheUniformPressureAtEveryVertex) {
  const Tube tube;
  const Cylinder body(Vec3::Zero(), Vec3::UnitZ(), tube.radius_m);
  const double p = 1234.5;
  const PressureField field = extract_pressure(tube.triangles, pressed_state(tube, p),
                                               VertexAreaDefinition::barycentric, &body);
  const auto area = tube.barycentric_area_m2();
  ASSERT_EQ(field.pressure_Pa.size(), std::size_t(tube.n_vertices()));
  EXPECT_STREQ(to_string(field.area_definition), "barycentric");
  for (int v = 0; v < tube.n_vertices(); ++v) {
    EXPECT_NEAR(field.pressure_Pa[v], p, 1e-9 * p) << "vertex " << v;
    EXPECT_NEAR(field.vertex_area_m2[v], area[v], 1e-12 * area[v]);
    EXPECT_NEAR(field.normal_force_N[v], p * area[v], 1e-9 * p * area[v]);
    EXPECT_NEAR((field.normal[v] - tube.radial[v]).norm(), 0.0, 1e-12);
    EXPECT_TRUE(field.contact[v]);
  }
}

TEST(PressureExtractor, PapersAdjacentTrianglesDefinitionReadsAThird) {
  const Tube tube;
  const Cylinder body(Vec3::Zero(), Vec3::UnitZ(), tube.radius_m);
  const double p = 800.0;
  const PressureField field = extract_pressure(tube.triangles, pressed_state(tube, p),
                                               VertexAreaDefinition::adjacent_triangles, &body);
  for (int v = 0; v < tube.n_vertices(); ++v)
    EXPECT_NEAR(field.pressure_Pa[v], p / 3.0, 1e-9 * p) << "vertex " << v;
}

TEST(PressureExtractor, BodyOrientsTheNormalsWhateverTheWinding) {
  Tube tube;
  for (Triangle& t : tube.triangles) std::swap(t[1], t[2]);  // normals now point inwards
  const Cylinder body(Vec3::Zero(), Vec3::UnitZ(), tube.radius_m);
  const double p = 500.0;
  const SurfaceState state = pressed_state(tube, p);
  const PressureField oriented =
      extract_pressure(tube.triangles, state, VertexAreaDefinition::barycentric, &body);
  const PressureField by_winding =
      extract_pressure(tube.triangles, state, VertexAreaDefinition::barycentric, nullptr);
  for (int v = 0; v < tube.n_vertices(); ++v) {
    EXPECT_NEAR(oriented.pressure_Pa[v], p, 1e-9 * p);
    EXPECT_NEAR(by_winding.pressure_Pa[v], -p, 1e-9 * p);
  }
}

PressureField hand_made_field() {
  PressureField field;
  field.pressure_Pa = {100, 200, 300, 999, 400};
  field.contact = {1, 1, 1, 0, 1};
  return field;
}

TEST(PressureSummary, MeanAndSpreadOverTheContactVertices) {
  const PressureSummary s = summarize(hand_made_field());
  // Contact pressures 100, 200, 300, 400: mean 250, deviations -150, -50, 50, 150, population
  // variance (22500 + 2500 + 2500 + 22500) / 4 = 12500.
  EXPECT_EQ(s.n_contact, 4);
  EXPECT_DOUBLE_EQ(s.contact_fraction, 0.8);
  EXPECT_DOUBLE_EQ(s.mean_Pa, 250.0);
  EXPECT_NEAR(s.std_Pa, std::sqrt(12500.0), 1e-10);
  EXPECT_DOUBLE_EQ(s.min_Pa, 100.0);
  EXPECT_DOUBLE_EQ(s.max_Pa, 400.0);
}

TEST(PressureSummary, NoContactGivesZeros) {
  PressureField field = hand_made_field();
  field.contact.assign(5, 0);
  const PressureSummary s = summarize(field);
  EXPECT_EQ(s.n_contact, 0);
  EXPECT_EQ(s.contact_fraction, 0.0);
  EXPECT_EQ(s.mean_Pa, 0.0);
  EXPECT_EQ(s.std_Pa, 0.0);
  EXPECT_EQ(s.min_Pa, 0.0);
  EXPECT_EQ(s.max_Pa, 0.0);
}

TEST(PressureAgainstAngle, ContactVerticesAreAveragedInTheirSector) {
  const Cylinder cylinder(Vec3(0, 0, 0), Vec3::UnitZ(), 0.05);
  auto at = [](double deg) {
    const double rad = deg * M_PI / 180.0;
    return Vec3(0.05 * std::cos(rad), 0.05 * std::sin(rad), 0.01);
  };
  PressureField field;
  const std::vector<Vec3> x = {at(10), at(80), at(100), at(200), at(300), at(359.9), at(0)};
  field.pressure_Pa = {1, 3, 5, 99, 7, 9, 11};
  field.contact = {1, 1, 1, 0, 1, 1, 1};
  const AngularProfile profile = pressure_against_angle(field, x, cylinder, 4);
  EXPECT_EQ(profile.theta_deg, (std::vector<double>{45, 135, 225, 315}));
  EXPECT_EQ(profile.n_vertices, (std::vector<int>{3, 1, 0, 2}));
  EXPECT_DOUBLE_EQ(profile.pressure_Pa[0], (1.0 + 3.0 + 11.0) / 3.0);
  EXPECT_DOUBLE_EQ(profile.pressure_Pa[1], 5.0);
  EXPECT_TRUE(std::isnan(profile.pressure_Pa[2]));  // only a vertex out of contact there
  EXPECT_DOUBLE_EQ(profile.pressure_Pa[3], 8.0);
}

}  // namespace
}  // namespace tightfit
